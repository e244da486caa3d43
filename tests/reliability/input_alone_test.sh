#!/usr/bin/env bash
# --input alone renders the image without reading the room: --verbose prints a "scene:" line only when
# the scene is read. Fails when the room is loaded anyway (that costs an input render about 40 % of its
# CPU time: the textures, their mip levels and the scene's shaders).
# usage: input_alone_test.sh STAGE INPUT.exr OUTPUT.png
set -uo pipefail
stage=$1 input=$2 output=$3
out=$("$stage" --headless --backend egl --verbose --input "$input" --output "$output" 2>&1)
code=$?
printf '%s\n' "$out"
[ "$code" -eq 0 ] || { echo "FAIL: exit code $code"; exit 1; }
grep -q '^wrote ' <<<"$out" || { echo "FAIL: no frame written"; exit 1; }
if grep -q '^scene:' <<<"$out"; then echo "FAIL: the room was read for an --input render"; exit 1; fi
echo "ok: the frame was written and no scene was read"
