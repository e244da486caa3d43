#!/usr/bin/env python3
"""A checkout inside a folder no one else may enter (/root, a home made 0700): the grader's environment
must never be the student's fault. In a private mount namespace (so that nothing else on the machine
sees it) the checkout's parent folder is hidden under a 0700 tmpfs with the checkout bound back at
its path; then an honest Part 1 submission (the reference's shaders) is graded there
  - as root with the namespaces isolation: graded 100 (the project files the job uid cannot reach
    are staged where it can);
  - as root with --isolation uid: exit 1, grader-error on every platform result, and one line naming
    the folder and what to do (student code there sees host paths, which cannot move);
  - as an unprivileged user who owns the 0700 folder (namespaces): graded 100.
usage: private_checkout.py SOURCE_DIR BINARY_DIR OUT_DIR CASE   (CASE: root-namespaces, root-uid or user)
Exit 0 when the case holds, 1 with the failures, 77 (skipped, saying why) when it cannot run here: not
root, without unshare/bwrap, with no folder outside the checkout's parent to keep it reachable at, or
(user) where the user cannot reach the checkout's parent at all (a clone two levels below /root: /root
is 0700, so no user could own a folder there). Any checkout path works: directly under /tmp (the
parent is then /tmp itself, so the handle on it is kept elsewhere), under a home folder, below /root,
with spaces (every path is quoted for the shell).
Shown to fail without the staging (grade.cpp's stageUnreachableMounts call removed): as root with
namespaces the reference host code does not build ("bwrap: Can't find source path ...: Permission
denied"), and with uid the compiler cannot read common/'s headers instead of one line naming /work."""
import json
import os
import shlex
import shutil
import subprocess
import sys
import tempfile

CASES = ("root-namespaces", "root-uid", "user")
if len(sys.argv) != 5 or sys.argv[4] not in CASES:
    sys.exit(__doc__)
SOURCE, BINARY, OUT = (os.path.realpath(p) for p in sys.argv[1:4])
CASE = sys.argv[4]
GRADER = os.path.join(BINARY, "bin", "t10-grade")
STAGE = os.path.join(SOURCE, "tutorial10_part1_tonemap")
USER = 1500000321  # an unprivileged uid of no account (the test's "user")
FAILURES = []


def fail(text):
    FAILURES.append(text)
    print("FAIL " + text)


if os.geteuid() != 0:
    print("SKIP: the private mount namespace needs root")
    sys.exit(77)
for tool in ("unshare", "setpriv", "bwrap"):
    if not shutil.which(tool):
        print(f"SKIP: {tool} is not installed")
        sys.exit(77)
probe = subprocess.run(["unshare", "--mount", "true"], capture_output=True, text=True)
if probe.returncode != 0:
    print("SKIP: no private mount namespace here: " + probe.stderr.strip())
    sys.exit(77)
if not os.access(os.path.join(BINARY, "grade-venv", "bin", "flip"), os.X_OK):
    print("SKIP: FLIP is not installed (make grade-deps)")
    sys.exit(77)
PARENT = os.path.dirname(SOURCE)
if PARENT == "/" or not BINARY.startswith(PARENT + "/") or not OUT.startswith(BINARY + "/"):
    print(f"SKIP: needs SOURCE and BINARY below a folder other than /, and OUT in BINARY ({SOURCE}, {BINARY}, {OUT})")
    sys.exit(77)


def outside_parent():
    """A writable folder outside PARENT to keep a handle on it in (the tmpfs hides everything below
    PARENT, /tmp's own temporary folders when the clone is directly under /tmp)."""
    for folder in (tempfile.gettempdir(), "/dev/shm", "/run", "/var/tmp", "/mnt"):
        real = os.path.realpath(folder)
        if os.path.isdir(real) and os.access(real, os.W_OK) and not (real + "/").startswith(PARENT + "/"):
            return real
    return None


HOLDER = outside_parent()
if HOLDER is None:
    print(f"SKIP: no writable folder outside {PARENT} (tried $TMPDIR, /dev/shm, /run, /var/tmp, /mnt) to keep it reachable from")
    sys.exit(77)
if CASE == "user":
    # The user owns the 0700 folder at PARENT: it must be able to reach PARENT's parent to get there.
    folder = os.path.dirname(PARENT)
    blocked = None
    while True:
        if subprocess.run(["setpriv", f"--reuid={USER}", f"--regid={USER}", "--clear-groups", "--", "test", "-x", folder]).returncode:
            blocked = folder
        if folder == "/":
            break
        folder = os.path.dirname(folder)
    if blocked:
        mode = oct(os.stat(blocked).st_mode & 0o777)
        print(f"SKIP: user {USER} cannot enter {blocked} (mode {mode}), so no user could own a folder at {PARENT}")
        sys.exit(77)

shutil.rmtree(OUT, ignore_errors=True)
os.makedirs(OUT)
SUB = os.path.join(OUT, "honest")
os.makedirs(SUB)
for name in ("PostProcess.frag", "PostProcessInit.frag"):
    shutil.copy(os.path.join(STAGE, name), SUB)
os.chmod(OUT, 0o755)
USER_OUT = os.path.join(OUT, "user")
os.makedirs(USER_OUT)
os.chown(USER_OUT, USER, USER)

# Inside the namespace: keep a handle on the parent, hide it under a 0700 tmpfs owned by $OWNER, bind
# the checkout (and the build folder, when it is not inside the checkout) back at their paths.
binds = [SOURCE] + ([BINARY] if not BINARY.startswith(SOURCE + "/") else [])
KEEP = tempfile.mkdtemp(prefix="t10-private-checkout.", dir=HOLDER)  # outside PARENT, so that it stays reachable
q = shlex.quote
script = f'mount --rbind {q(PARENT)} {q(KEEP)} && mount -t tmpfs -o mode=0700,uid=$OWNER,gid=$OWNER t10-private {q(PARENT)}'
for path in binds:
    rel = os.path.relpath(path, PARENT)
    script += f' && mkdir -p {q(path)} && mount --bind {q(os.path.join(KEEP, rel))} {q(path)}'
script += ' && exec "$@"'


def grade(owner, run_as, isolation, report):
    command = ["unshare", "--mount", "--propagation", "private", "sh", "-c", script, "private"]
    if run_as:
        command += ["setpriv", f"--reuid={run_as}", f"--regid={run_as}", "--clear-groups", "--"]
    command += [GRADER, "--part", "1", "--isolation", isolation, "--fill-from-reference", "all", "--format", "prairielearn",
                "--cache", os.path.join(report, "cache"), "--report", os.path.join(report, "reports"), SUB]
    # The grader's own temporary folders go where the tmpfs does not hide them (HOLDER is /tmp itself
    # unless the checkout's parent is /tmp, which the tmpfs makes a 0700 folder no job uid may enter).
    run = subprocess.run(command, env=dict(os.environ, OWNER=str(owner), TMPDIR=HOLDER), capture_output=True, text=True,
                         timeout=600)
    return run


def expect_graded(label, run, report):
    path = os.path.join(report, "reports", "honest", "report.json")
    result = json.load(open(path)) if os.path.exists(path) else {}
    if run.returncode == 0 and result.get("status") == "graded" and result.get("score") == 100:
        print(f"ok   {label}: graded 100")
    else:
        fail(f"{label}: expected graded 100, got exit {run.returncode}, {result.get('status')} {result.get('score')}: "
             + (run.stdout + run.stderr)[-1500:])


def root_namespaces():
    run = grade(0, None, "namespaces", os.path.join(OUT, "root-namespaces"))
    expect_graded("root, namespaces, checkout in a 0700 folder", run, os.path.join(OUT, "root-namespaces"))


def root_uid():
    run = grade(0, None, "uid", os.path.join(OUT, "root-uid"))
    lines = [line for line in run.stderr.splitlines() if "cannot read" in line]
    result_path = os.path.join(OUT, "root-uid", "reports", "honest", "prairielearn-results.json")
    result = json.load(open(result_path)) if os.path.exists(result_path) else {}
    if (run.returncode == 1 and len(lines) == 1 and PARENT in lines[0] and "chmod o+x" in lines[0]
            and result.get("gradable") is False):
        print(f"ok   root, uid: exit 1, not gradable, one line: {lines[0]}")
    else:
        fail(f"root, uid: expected exit 1, one line naming {PARENT} and what to do, a not-gradable result; got exit "
             f"{run.returncode}, {result}: {run.stderr[-1500:]}")


def user():
    # FLIP's venv runs the interpreter it was made with: one under /root (pyenv) is out of the user's reach,
    # and then the run must stop as the grader's failure, naming FLIP, never score the student.
    flip_python = os.path.realpath(os.path.join(BINARY, "grade-venv", "bin", "python3"))
    user_runs_flip = subprocess.run(["setpriv", f"--reuid={USER}", f"--regid={USER}", "--clear-groups", "--", "test", "-x",
                                     flip_python]).returncode == 0
    run = grade(USER, USER, "namespaces", USER_OUT)
    label = f"user {USER} owning the 0700 folder, namespaces"
    if user_runs_flip:
        expect_graded(label, run, USER_OUT)
    elif run.returncode == 1 and "flip cannot be run" in run.stderr and "score" not in run.stdout:
        print(f"ok   {label}: FLIP's interpreter {flip_python} is out of this user's reach: grader-error, not the student's score")
    else:
        fail(f"{label}: FLIP's interpreter {flip_python} is out of the user's reach: expected exit 1 naming FLIP; got exit "
             f"{run.returncode}: {(run.stdout + run.stderr)[-1500:]}")


try:
    {"root-namespaces": root_namespaces, "root-uid": root_uid, "user": user}[CASE]()
finally:
    os.rmdir(KEEP)
if not FAILURES:
    shutil.rmtree(OUT, ignore_errors=True)
print(f"{len(FAILURES)} failure(s)")
sys.exit(1 if FAILURES else 0)
