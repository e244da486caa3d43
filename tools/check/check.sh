#!/usr/bin/env bash
# `make check PART=N [DIR=folder]` once everything is built: grades FOLDER against Part N with t10-grade
# and prints the short summary (summary.py). The Makefile builds first (the student's program by its
# target, so compiler errors name their file and line); the tests call this script directly.
#   usage: check.sh T10_GRADE PART REPORT_DIR FOLDER
# Exit 0 only at score 100; 1 for any other score, status or grader failure; 2 for bad usage.
set -u
if [ $# -ne 4 ]; then
    echo "usage: check.sh T10_GRADE PART REPORT_DIR FOLDER" >&2
    exit 2
fi
grader=$1 part=$2 report=$3 folder=$4
here=$(dirname "$0")
case $part in 1|2|3) ;; *) echo "make check: PART=$part: choose 1, 2 or 3" >&2; exit 2 ;; esac
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
"$grader" --part "$part" --report "$report" "$folder" >"$log" 2>&1
code=$?
if [ $code -ne 0 ] || [ ! -f "$report/$name/report.json" ]; then
    cat "$log" >&2
    echo "make check: t10-grade failed (exit $code) before it could grade $folder; its output is above and in $log" >&2
    exit 1
fi
exec python3 "$here/summary.py" "$report/$name/report.json"
