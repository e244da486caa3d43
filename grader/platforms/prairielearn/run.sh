#!/usr/bin/env bash
# PrairieLearn's external grader entrypoint: grades the student's files in $GRADE_ROOT/student (default
# /grade/student) and writes $GRADE_ROOT/results/results.json, also when the submission does not build
# or crashes. The image holds a checkout built with `make grader` at T10_SOURCE (default /opt/t10;
# T10_BUILD defaults to its build/). Networking can stay off: nothing is downloaded when grading.
set -uo pipefail
root=${GRADE_ROOT:-/grade}
here=$(cd "$(dirname "$0")" && pwd)
. "$here/t10.conf" || exit 1
export T10_PART T10_SOURCE=${T10_SOURCE:-/opt/t10}
export T10_BUILD=${T10_BUILD:-$T10_SOURCE/build}
exec "$here/grade_one.sh" prairielearn "$root/student" "$root/results/results.json"
