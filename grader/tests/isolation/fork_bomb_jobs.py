#!/usr/bin/env python3
"""Jobs that cannot starve each other (issue 38): a Part 1 that forks until refused is graded beside
honest copies of the reference by a grader that is not root, two jobs at a time, ROUNDS times (one
bomb and two honest copies per round, all in one t10-grade run so that the reference renders once);
every honest copy must score 100 and every bomb be held to its job's process limit.

Not root, every job runs as the grader's user. The grader then sets each sandbox's process limit
inside the sandbox's own user namespace, where the kernel counts that job's processes alone
(sandbox.hpp, probeOwnProcessLimit); where it cannot, it says so and grades one at a time. Before
that, the jobs shared one count: here honest copies timed out or failed with an empty log.

usage: fork_bomb_jobs.py SOURCE_DIR T10_GRADE FLIP OUT_DIR ROUNDS
Run as root, the grader runs as an unprivileged uid of no account (setpriv). Exit 0 when every
expectation holds, 1 with the failures, 77 (skipped) where bubblewrap cannot create namespaces, FLIP
is missing, or (as root) the checkout is out of other users' reach. T10_KEEP=1 keeps OUT_DIR when all
holds (it is removed then, else kept for the failures' reports)."""
import json
import os
import re
import shutil
import subprocess
import sys

if len(sys.argv) != 6:
    sys.exit(__doc__)
SOURCE, GRADER, FLIP, OUT = (os.path.abspath(p) for p in sys.argv[1:5])
ROUNDS = int(sys.argv[5])
STAGE = os.path.join(SOURCE, "tutorial10_part1_tonemap")
USER = 1500000322  # the grader's user when the test runs as root: an unprivileged uid of no account
AS_USER = ["setpriv", f"--reuid={USER}", f"--regid={USER}", "--clear-groups", "--"] if os.geteuid() == 0 else []
# The bomb holds its processes this long in every case (its children sleep, it waits for them), then
# renders as the reference would: longer than the compiler's retries of a refused fork (7 s).
HOLD_SECONDS = 20


def skip(reason):
    print("SKIP: " + reason)
    sys.exit(77)


if not os.access(FLIP, os.X_OK):
    skip("FLIP is not installed (make grade-deps)")
if not shutil.which("bwrap"):
    skip("bubblewrap is not installed")
probe = subprocess.run(AS_USER + ["bwrap", "--unshare-all", "--ro-bind", "/usr", "/usr", "--symlink", "usr/lib", "/lib",
                                  "--symlink", "usr/lib64", "/lib64", "--proc", "/proc", "--dev", "/dev", "/usr/bin/true"],
                       capture_output=True, text=True)
if probe.returncode != 0:
    skip("bubblewrap cannot create namespaces here: " + probe.stderr.strip())
if AS_USER:
    # FLIP's venv runs the interpreter it was made with (make grade-deps says when others cannot).
    interpreter = os.path.realpath(os.path.join(os.path.dirname(FLIP), "python3"))
    for path in (GRADER, FLIP, interpreter, os.path.join(STAGE, "Tutorial10.cpp")):
        if subprocess.run(AS_USER + ["test", "-r", path]).returncode != 0:
            skip(f"{path} is out of other users' reach (a checkout in a 0700 folder): the test's user cannot run it")

shutil.rmtree(OUT, ignore_errors=True)
SUBS = os.path.join(OUT, "submissions")
os.makedirs(SUBS)
host = open(os.path.join(STAGE, "Tutorial10.cpp")).read()
# Runs before main() in every case: forks until refused, every child sleeping, and waits for them.
BOMB = ("#include <cstdio>\n#include <sys/wait.h>\n#include <unistd.h>\nnamespace { struct Bomb { Bomb() {\n"
        "    int forks = 0;\n"
        f"    for (; forks < 5000; ++forks) {{ const pid_t pid = ::fork(); if (pid == 0) {{ ::sleep({HOLD_SECONDS}); ::_exit(0); }} if (pid < 0) break; }}\n"
        "    std::printf(\"FORKS:%d\\n\", forks); std::fflush(stdout);\n"
        "    while (::wait(nullptr) > 0) {}\n"
        "} } bomb; }\n")
# Each round is one t10-grade run of three submissions, two jobs at a time (the cache is shared, so
# the reference renders once and the bomb is built once): the bomb and an honest copy start together.
# From the second round on the bomb's build is cached, so it forks while the honest copy beside it
# compiles, whose compiler then starts its next process (the assembler, the linker). Before issue 38
# the jobs shared one count, so those were refused: the compiler gives up after 7 s of retries, and
# the bomb holds its processes for 20 s. The second honest copy follows the first beside the bomb.
failures = []
honest_ok = bombs_held = 0
REPORTS = os.path.join(OUT, "reports")
for r in range(ROUNDS):
    submissions = []
    for kind in ("bomb", "honest_a", "honest_b"):
        sub = os.path.join(SUBS, f"r{r:02d}_{kind}")
        os.makedirs(sub)
        submissions.append(sub)
        if kind == "bomb":
            with open(os.path.join(sub, "Tutorial10.cpp"), "w") as f:
                f.write(BOMB + host)
            continue
        for name in ("PostProcess.frag", "PostProcessInit.frag"):
            shutil.copy(os.path.join(STAGE, name), sub)
        # Its own host code (a comment apart, so that the build cache has none of it).
        with open(os.path.join(sub, "Tutorial10.cpp"), "w") as f:
            f.write(f"// honest copy {r} {kind}\n" + host)
    for folder in [OUT, SUBS] + submissions:
        os.chmod(folder, 0o755)
        if AS_USER:
            os.chown(folder, USER, USER)
    # An honest copy's slowest case renders in a few seconds on 2 loaded cores: 60 s is a starved job.
    run = subprocess.run(AS_USER + [GRADER, "--part", "1", "--jobs", "2", "--timeout", "60", "--fill-from-reference", "all",
                                    "--cache", os.path.join(OUT, "cache"), "--report", os.path.join(REPORTS, str(r))]
                         + submissions, capture_output=True, text=True, timeout=1200)
    if r == 0:
        mechanism = re.search(r"student code runs with isolation .*", run.stderr)
        print("grader: " + (mechanism.group(0) if mechanism else "(no isolation line)") + (" as uid %d" % USER if AS_USER else ""))
        for line in run.stderr.splitlines():
            if "warning" in line:
                print("grader: " + line)
    if run.returncode != 0:
        failures.append(f"round {r}: t10-grade exit {run.returncode}: {run.stderr[-1500:]}")
    for path in submissions:
        name = os.path.basename(path)
        report_path = os.path.join(REPORTS, str(r), name, "report.json")
        report = json.load(open(report_path)) if os.path.exists(report_path) else {}
        if "honest" in name:
            if report.get("status") == "graded" and report.get("score") == 100:
                honest_ok += 1
            else:
                failed = [f"{c.get('id')}: {c.get('measured')}" for c in report.get("checks", []) if not c.get("passed")]
                failures.append(f"{name}: expected graded 100, got {report.get('status')} {report.get('score')}: "
                                f"{report.get('message', '')[:300]} {failed[:3]}")
            continue
        logs = [os.path.join(d, f) for d, _, fs in os.walk(os.path.join(REPORTS, str(r), name)) for f in fs if f.endswith(".log")]
        forks = [int(m) for log in logs for m in re.findall(r"FORKS:(\d+)", open(log, errors="replace").read())]
        if report.get("status") in (None, "grader-error"):
            failures.append(f"{name}: the bomb was not graded: {report.get('status')} {report.get('message', '')[:300]}")
        elif not forks or max(forks) > 64:
            failures.append(f"{name}: expected every case to fork until refused at the job's 64 processes, got {forks}")
        else:
            bombs_held += 1
    print(f"round {r + 1}: {honest_ok} of {2 * (r + 1)} honest copies scored 100 so far, {bombs_held} of {r + 1} bombs held",
          flush=True)
print(f"{ROUNDS} rounds: {honest_ok} of {2 * ROUNDS} honest copies scored 100, {bombs_held} of {ROUNDS} bombs held to "
      f"their job's limit")
for failure in failures:
    print("FAIL " + failure)
if not failures and not os.environ.get("T10_KEEP"):
    shutil.rmtree(OUT, ignore_errors=True)
sys.exit(1 if failures else 0)
