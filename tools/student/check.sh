#!/usr/bin/env bash
# `make check PART=N [DIR=folder]` once everything is built: grades FOLDER against Part N with t10-grade
# and prints the short summary (summary.py). The Makefile builds first (the student's program by its
# target, so compiler errors name their file and line); the tests call this script directly.
#   usage: check.sh T10_GRADE PART REPORT_DIR FOLDER [ISOLATION]
# ISOLATION (make check's ISOLATION=): auto (the default), namespaces, uid, or none (t10-grade's
# --no-sandbox: the student's own code, run as the student, with only the time and size limits).
# Where no sandbox can be had (a container started with Docker's default seccomp profile, as a user
# other than root), the grader refuses to run student code: this script then says why in one line and
# what the student can do, instead of the grader's whole message.
# Exit 0 only at score 100; 1 for any other score, status or grader failure; 2 for bad usage.
set -u
if [ $# -ne 4 ] && [ $# -ne 5 ]; then
    echo "usage: check.sh T10_GRADE PART REPORT_DIR FOLDER [ISOLATION]" >&2
    exit 2
fi
grader=$1 part=$2 report=$3 folder=$4 isolation=${5:-auto}
here=$(dirname "$0")
case $part in 1|2|3) ;; *) echo "make check: PART=$part: choose 1, 2 or 3" >&2; exit 2 ;; esac
case $isolation in
    auto|namespaces|uid) isolation_args=(--isolation "$isolation") ;;
    none) isolation_args=(--no-sandbox) ;;
    *) echo "make check: ISOLATION=$isolation: choose auto, namespaces, uid or none" >&2; exit 2 ;;
esac
if [ ! -d "$folder" ]; then
    echo "make check: $folder/: no such folder (make student PART=$part creates student/part$part/)" >&2
    exit 2
fi
if [ ! -x "$grader" ]; then
    echo "make check: $grader: not built (make build)" >&2
    exit 1
fi
name=$(basename "$(cd "$folder" && pwd)")
mkdir -p "$report" || exit 1
log=$report/grade.log
echo "Grading $folder against Part $part ..."
"$grader" --part "$part" --report "$report" "${isolation_args[@]}" "$folder" >"$log" 2>&1
code=$?
if [ $code -ne 0 ] && grep -q 'no sandbox can be had here' "$log"; then
    # bwrap's own complaint (e.g. "No permissions to create new namespace") names the kernel's refusal.
    why=$(grep -o 'bwrap: [^)]*' "$log" | tail -n 1)
    cat >&2 <<EOF
make check: this machine refuses the grader's sandbox (bubblewrap cannot create user namespaces${why:+; $why}),
and its other isolation, one uid per job, needs root. Docker's default seccomp profile does this. Either
  - start the container as .devcontainer/devcontainer.json does (Codespaces and VS Code do it for you):
      docker run --security-opt seccomp=unconfined --security-opt apparmor=unconfined \\
                 --security-opt systempaths=unconfined ...
  - or check your own code without the sandbox (it runs as you, with only time and size limits):
      make check PART=$part ISOLATION=none
(the grader's output: $log; the site's "Building, running and testing" page, "Dev containers")
EOF
    exit 1
fi
if [ $code -ne 0 ] || [ ! -f "$report/$name/report.json" ]; then
    cat "$log" >&2
    echo "make check: t10-grade failed (exit $code) before it could grade $folder; its output is above and in $log" >&2
    exit 1
fi
exec python3 "$here/summary.py" "$report/$name/report.json"
