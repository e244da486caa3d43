#!/usr/bin/env bash
# The grader's own failure: t10-grade with a cache folder it cannot create must exit 1 and still write
# every platform's result. usage: grader_error.sh RUN_GRADER FLIP T10_GRADE PYTHON CHECK_PLATFORMS SUBMISSION OUT
run_grader=$1 flip=$2 t10_grade=$3 python=$4 check=$5 submission=$6 out=$7
rm -rf "$out"
"$run_grader" "$flip" "$t10_grade" --part 3 --cache /dev/null/cache --format gradescope --format prairielearn \
    --format classroom --report "$out" "$submission"
code=$?
[ "$code" = 77 ] && exit 77
[ "$code" = 1 ] || { echo "FAIL t10-grade exited $code, expected 1"; exit 1; }
exec "$python" "$check" grader-error "$out/$(basename "$submission")"
