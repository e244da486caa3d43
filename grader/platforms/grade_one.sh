#!/usr/bin/env bash
# Grades one submission for a platform and always leaves a result where the platform reads it.
#   grade_one.sh gradescope|prairielearn SUBMISSION_DIR RESULTS_JSON
# Reads T10_PART, T10_SOURCE and T10_BUILD from the environment (run_autograder and run.sh set them), and
# T10_FILL_FROM_REFERENCE (t10-grade --fill-from-reference; default unchanged: the student hands in the part's files).
# Only the part's files are copied out of the submission (regular files, no links), so a student's
# upload cannot point the grader elsewhere. A submission without any of them gets a result saying
# so: graded as it is, the reference stage would fill in every file and score 100. When t10-grade
# leaves no result (it was killed or could not start), the result says that the grader failed
# (PrairieLearn: gradable false, the student keeps the attempt). The exit status is 0 whenever a
# result was written.
set -uo pipefail
format=$1 submission=$2 results=$3
: "${T10_PART:?T10_PART is not set}" "${T10_BUILD:?T10_BUILD is not set}"
# The whole run stays within Gradescope's default 10 minutes: builds get 300 s, each render this many.
render_timeout=${T10_RENDER_TIMEOUT:-30}
whole_timeout=${T10_WHOLE_TIMEOUT:-540}

# fallback KIND MESSAGE: KIND is student (nothing to grade) or grader (the grader's own failure).
fallback() {
    python3 - "$format" "$1" "$2" "$results" <<'PY'
import json, os, sys
fmt, kind, message, path = sys.argv[1:]
if fmt == "gradescope":
    result = {"score": 0, "execution_time": 0, "output": message, "output_format": "text",
              "visibility": "visible", "stdout_visibility": "hidden", "tests": []}
else:
    # Not gradable either way: nothing to grade is a format error (the student keeps the attempt), and
    # the grader's failure is not the student's fault.
    result = {"gradable": False, "score": 0.0, "format_errors": [message], "message": message, "output": message,
              "images": [], "tests": []}
with open(path + ".tmp", "w", encoding="utf-8") as f:
    json.dump(result, f, indent=2)
os.replace(path + ".tmp", path)
PY
}

mkdir -p "$(dirname "$results")" || exit 1
files="Tutorial10.cpp PostProcess.frag PostProcessInit.frag"
[ "$T10_PART" = 3 ] && files="$files Gauss.frag"
work=$(mktemp -d "${TMPDIR:-/tmp}/t10-grade.XXXXXX") || { echo "grade_one.sh: cannot create a temporary folder" >&2; exit 1; }
trap 'rm -rf "$work"' EXIT
mkdir "$work/submission"
found=""
for f in $files; do
    if [ -f "$submission/$f" ] && [ ! -L "$submission/$f" ]; then
        cp "$submission/$f" "$work/submission/$f" && found="$found $f"
    fi
done
if [ -z "$found" ]; then
    echo "grade_one.sh: nothing to grade in $submission (expected any of: $files)"
    fallback student "Nothing to grade: the submission has none of $files (for Part $T10_PART). Upload your Tutorial10.cpp and shaders themselves, not a folder or an archive of them."
    exit 0
fi
echo "grading Part $T10_PART:$found"
timeout -k 10 "$whole_timeout" "$T10_BUILD/bin/t10-grade" --part "$T10_PART" --timeout "$render_timeout" --format "$format" \
    --fill-from-reference "${T10_FILL_FROM_REFERENCE:-unchanged}" --report "$work/report" "$work/submission"
code=$?
produced="$work/report/submission/$format-results.json"
if [ -f "$produced" ]; then
    cp "$produced" "$results.tmp" && mv "$results.tmp" "$results" && exit 0
    echo "grade_one.sh: cannot write $results" >&2
    exit 1
fi
what="t10-grade exited with status $code"
[ "$code" = 124 ] && what="t10-grade ran past $whole_timeout s and was stopped"
fallback grader "The grader itself failed ($what) and wrote no result: this is not your submission's fault; tell your instructor."
exit 0
