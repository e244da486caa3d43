#!/usr/bin/env bash
# Renders inf_nan.exr (+inf, -inf and NaN in three pixels) through a stage for three frames: the
# run must succeed with exactly one warning counting the 3 pixels, and check_finite must find every
# dumped texture level finite and the +inf pixel (1, 1) saturated.
# usage: nonfinite_test.sh BIN STAGE INPUT OUT_DIR [EXTRA_ARGS...]
set -uo pipefail
bin=$1 stage=$2 input=$3 out=$4
shift 4
rm -rf "$out"
output=$("$bin/$stage" --headless --backend egl --frames 3 --input "$input" --dump "$out" --output "$out/frame.png" "$@" 2>&1)
rc=$?
printf '%s\n' "$output"
[ "$rc" -eq 0 ] || { echo "FAIL: exit $rc"; exit 1; }
warnings=$(grep -c "warning: .*$(basename "$input"): 3 pixels hold NaN or infinity" <<<"$output")
echo "$warnings warning(s) about the non-finite pixels"
"$bin/check_finite" "$out" 1 1 || exit 1
# --keep-non-finite gives no warning by design; otherwise exactly one.
if [[ " $* " != *" --keep-non-finite "* ]] && [ "$warnings" -ne 1 ]; then
    echo "FAIL: expected exactly one warning"
    exit 1
fi
