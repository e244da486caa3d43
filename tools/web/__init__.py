"""The tools' browser library: headless Chromium through the one DevTools-protocol client.

cdp         the client (Chromium over a pipe, a local static server, tabs, evaluate, screenshots)
web_page    a web stage's page in one tab (its state, its frame as --output reads it); make web-serve
page_value  a page of a folder opened and one JavaScript value printed as JSON (the GLSL ES browser test)

A package: whoever runs a script that imports it puts tools/ on PYTHONPATH (CMake's T10_PYTHON_ENV,
the Makefile's commands; by hand `PYTHONPATH=tools python3 ...`), then `from web import cdp`.
"""
