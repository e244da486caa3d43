#!/usr/bin/env python3
"""Honest inputs (issues 19 and 20): the copy-in lists every file with its source and gives empty and
incomplete submissions their status. Writes an empty folder, a README-only folder, a Part 1 with its
shader named in the wrong case, one with a FIFO and a too-large file, then grades them (default
--fill-from-reference) and checks report.json and the gradebook.

usage: inputs_check.py SOURCE_DIR T10_GRADE FLIP OUT_DIR   (exit 77 where FLIP is not installed)"""
import json
import os
import shutil
import subprocess
import sys

SOURCE, GRADER, FLIP, OUT = sys.argv[1:5]
if not os.access(FLIP, os.X_OK):
    print(f"SKIP: {FLIP} is not installed (make grade-deps)")
    sys.exit(77)
STAGE = os.path.join(SOURCE, "tutorial10_part1_tonemap")
shutil.rmtree(OUT, ignore_errors=True)
SUBS = os.path.join(OUT, "submissions")


def folder(name, files):
    path = os.path.join(SUBS, name)
    os.makedirs(path)
    for target, source in files.items():
        shutil.copy(os.path.join(STAGE, source), os.path.join(path, target)) if source else None
    return path


folder("empty", {})
with open(os.path.join(folder("readme_only", {}), "README.md"), "w") as f:
    f.write("my part 1\n")
folder("wrong_case", {"Tutorial10.cpp": "Tutorial10.cpp", "postprocess.frag": "PostProcess.frag",
                      "PostProcessInit.frag": "PostProcessInit.frag"})
odd = folder("odd_files", {"Tutorial10.cpp": "Tutorial10.cpp", "PostProcessInit.frag": "PostProcessInit.frag"})
os.mkfifo(os.path.join(odd, "PostProcess.frag"))
with open(os.path.join(odd, "notes.txt"), "w") as f:
    f.write("x" * (300 * 1024))

reports = os.path.join(OUT, "reports")
names = ["empty", "readme_only", "wrong_case", "odd_files"]
run = subprocess.run([GRADER, "--part", "1", "--report", reports] + [os.path.join(SUBS, n) for n in names],
                     capture_output=True, text=True, timeout=600)
print(run.stdout + run.stderr)
failures = []


def expect(name, status, file_checks):
    report = json.load(open(os.path.join(reports, name, "report.json")))
    files = {}
    for f in report["files"]:  # a name can be listed twice: ignored (as found) and missing
        files.setdefault(f["name"], []).append(f)
    if report["status"] != status or report["score"] != 0:
        failures.append(f"{name}: {report['status']} {report['score']}, expected {status} 0")
    for file, (source, reason) in file_checks.items():
        got = files.get(file, [])
        if not any(f["source"] == source and reason in f["reason"] for f in got):
            failures.append(f"{name}: {file} listed as {got}, expected {source} with '{reason}'")
    if report["fill_from_reference"] != "unchanged":
        failures.append(f"{name}: fill_from_reference {report['fill_from_reference']}")
    print(f"{name}: {report['status']}, files {[(f['name'], f['source']) for f in report['files']]}")


expect("empty", "empty", {"Tutorial10.cpp": ("missing", "asks you to write it")})
expect("readme_only", "empty", {"README.md": ("ignored", "not a file of this part")})
expect("wrong_case", "missing-files", {"postprocess.frag": ("ignored", "wrong case, did you mean PostProcess.frag"),
                                       "Tutorial10.cpp": ("submission", ""), "PostProcess.frag": ("missing", "")})
expect("odd_files", "missing-files", {"PostProcess.frag": ("ignored", "a FIFO"), "notes.txt": ("ignored", "")})
rows = open(os.path.join(reports, "gradebook.csv")).read().splitlines()
if not rows[0].endswith(",isolation,fill_from_reference") or len(rows) != 1 + len(names):
    failures.append(f"gradebook: {rows}")
if run.returncode != 0:
    failures.append(f"t10-grade exit {run.returncode}")
for failure in failures:
    print("FAIL " + failure)
sys.exit(1 if failures else 0)
