#!/usr/bin/env bash
# Runs t10-grade for a test, or skips it (exit 77) when FLIP is not installed, so that a machine
# without the venv reports the grader's tests as skipped, not passed. usage: run_grader.sh FLIP T10_GRADE ARGS...
flip=$1
shift
if [ ! -x "$flip" ]; then
    echo "SKIP: $flip is not installed (make grade-deps installs FLIP into a venv under build/)"
    exit 77
fi
exec "$@"
