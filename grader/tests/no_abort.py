#!/usr/bin/env python3
"""t10-grade and t10-grade-tga never abort (issue 38): a folder they cannot look at ends in their one
handler, which prints one line naming the path and the system's reason, writes a grader-error result
where it can, and exits 1; never "terminate called after throwing" (exit -6).
  - t10-grade whose --report folder is inside a folder it may not enter (a clone two levels below /root
    graded as another user did this: std::filesystem::filesystem_error escaped parse());
  - t10-grade given a submission inside such a folder: also a grader-error result, in report.json and
    the platform's result, in the (reachable) report folder;
  - t10-grade-tga given such a submission, with --report: a grader-error report there.
The folder is made unreadable to the grader whoever runs the test: as root, owned by another uid with
the grader run without capabilities (setpriv --bounding-set -all), so that root's override does not
apply; as a user, mode 000.
usage: no_abort.py T10_GRADE T10_GRADE_TGA SOURCE_DIR OUT_DIR
Exit 0 when all hold, 1 with the failures. Shown to fail on main before the fix: each of the three
ended with "terminate called after throwing an instance of 'std::filesystem::__cxx11::filesystem_error'"
and exit -6."""
import json
import os
import shutil
import subprocess
import sys

GRADE, GRADE_TGA, SOURCE, OUT = (os.path.abspath(p) for p in sys.argv[1:5])
USER = 1500000321  # an unprivileged uid of no account
FAILURES = []


def fail(text):
    FAILURES.append(text)
    print("FAIL " + text)


shutil.rmtree(OUT, ignore_errors=True)
os.makedirs(OUT)
os.chmod(OUT, 0o755)
honest = os.path.join(OUT, "open", "honest")
locked = os.path.join(OUT, "locked")
os.makedirs(honest)
os.makedirs(os.path.join(locked, "honest"))
for name in ("PostProcess.frag", "PostProcessInit.frag"):
    shutil.copy(os.path.join(SOURCE, "tutorial10_part1_tonemap", name), honest)
    shutil.copy(os.path.join(SOURCE, "tutorial10_part1_tonemap", name), os.path.join(locked, "honest"))
if os.geteuid() == 0:
    if not shutil.which("setpriv"):
        print("SKIP: setpriv is not installed (util-linux)")
        sys.exit(77)
    os.chown(locked, USER, USER)
    os.chmod(locked, 0o700)
    prefix = ["setpriv", "--bounding-set", "-all", "--inh-caps", "-all", "--"]
else:
    os.chmod(locked, 0o000)
    prefix = []
probe = subprocess.run(prefix + ["ls", locked], capture_output=True, text=True)
if probe.returncode == 0:
    print(f"SKIP: {locked} stays readable here (a capability or an ACL overrides its mode)")
    sys.exit(77)


def run(label, command, path, result=None):
    """Runs COMMAND; expects exit 1, an error line naming PATH and the system's reason, no abort, and the
    grader-error RESULT (a file, and the JSON key that says so) when given."""
    done = subprocess.run(prefix + command, capture_output=True, text=True, errors="replace", timeout=120)
    errors = [line for line in done.stderr.splitlines() if ": error: " in line]
    ok = True
    if done.returncode != 1 or "terminate called" in done.stderr:
        fail(f"{label}: expected exit 1, got {done.returncode}: {done.stderr[-800:]}")
        ok = False
    elif not errors or path not in errors[0] or "Permission denied" not in errors[0]:
        fail(f"{label}: the first error line does not name {path} and 'Permission denied': {done.stderr[-800:]}")
        ok = False
    if result is not None:
        file, key, value = result
        try:
            with open(file, encoding="utf-8") as f:
                got = json.load(f).get(key)
        except (OSError, ValueError) as error:
            got = f"unreadable ({error})"
        if got != value:
            fail(f"{label}: {file}: {key} is {got!r}, expected {value!r}")
            ok = False
    if ok:
        print(f"ok   {label}: exit 1, {errors[0]}")


try:
    reports = os.path.join(locked, "reports")
    run("t10-grade, --report in a folder it may not enter",
        [GRADE, "--part", "1", "--format", "prairielearn", "--report", reports, honest], reports)
    reports = os.path.join(OUT, "reports")
    run("t10-grade, a submission in a folder it may not enter",
        [GRADE, "--part", "1", "--format", "prairielearn", "--report", reports, os.path.join(locked, "honest")],
        os.path.join(locked, "honest"), (os.path.join(reports, "honest", "prairielearn-results.json"), "gradable", False))
    if os.path.exists(os.path.join(reports, "honest", "report.json")):
        status = json.load(open(os.path.join(reports, "honest", "report.json"), encoding="utf-8")).get("status")
        if status != "grader-error":
            fail(f"t10-grade, a submission in a folder it may not enter: report.json status {status}")
    tga_report = os.path.join(OUT, "tga-report.json")
    run("t10-grade-tga, a submission in a folder it may not enter",
        [GRADE_TGA, "--report", tga_report, os.path.join(locked, "honest")], os.path.join(locked, "honest"),
        (tga_report, "status", "grader-error"))
finally:
    os.chmod(locked, 0o700)
if not FAILURES:
    shutil.rmtree(OUT, ignore_errors=True)
print(f"{len(FAILURES)} failure(s)")
sys.exit(1 if FAILURES else 0)
