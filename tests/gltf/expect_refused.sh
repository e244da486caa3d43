#!/usr/bin/env bash
# A stage must refuse a bad --scene file: exit code 1, a message matching REGEX, and no output file.
# usage: expect_refused.sh STAGE_BINARY FILE REGEX OUTPUT.png
set -uo pipefail
stage=$1 file=$2 regex=$3 output=$4
rm -f "$output"
mkdir -p "$(dirname "$output")"
message=$("$stage" --backend egl --size 64x64 --frames 1 --scene "$file" --output "$output" 2>&1)
code=$?
printf '%s\n' "$message"
if [ "$code" -ne 1 ]; then echo "FAIL: exit code $code, expected 1"; exit 1; fi
if ! grep -Eq -- "$regex" <<<"$message"; then echo "FAIL: output does not match /$regex/"; exit 1; fi
if [ -e "$output" ]; then echo "FAIL: $output was written"; exit 1; fi
echo "ok: refused with exit code 1, /$regex/, no output file"
