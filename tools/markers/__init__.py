"""The one parser of the stages' `// [step N]` ... `// [/step N]` markers (markers.py).

A package: whoever runs a script that imports it puts tools/ on PYTHONPATH (CMake's T10_PYTHON_ENV;
by hand `PYTHONPATH=tools python3 ...`), then `from markers import markers`.
"""
