#!/usr/bin/env bash
# Runs a command and checks its exit code and (optionally) that its output matches a regex.
# usage: expect.sh CODE REGEX -- COMMAND [ARGS...]    (REGEX "" skips the output check;
#        CODE "nonzero" accepts any failure, e.g. Catch2's count of failed assertions)
set -uo pipefail
code=$1 regex=$2
shift 2
[ "$1" = "--" ] && shift
output=$("$@" 2>&1)
actual=$?
printf '%s\n' "$output"
if [ "$code" = nonzero ]; then
    if [ "$actual" -eq 0 ]; then
        echo "FAIL: exit code 0, expected a failure"
        exit 1
    fi
elif [ "$actual" -ne "$code" ]; then
    echo "FAIL: exit code $actual, expected $code"
    exit 1
fi
if [ -n "$regex" ] && ! grep -Eq -- "$regex" <<<"$output"; then
    echo "FAIL: output does not match /$regex/"
    exit 1
fi
echo "ok: exit code $code${regex:+, output matches /$regex/}"
