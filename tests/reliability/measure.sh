#!/usr/bin/env bash
# Runs a command that must refuse its input: exit CODE, output matching REGEX, within MAX_SECONDS
# of wall time and MAX_MIB of peak resident memory (GNU time's "maximum resident set size").
# usage: measure.sh CODE REGEX MAX_SECONDS MAX_MIB -- COMMAND [ARGS...]
set -uo pipefail
code=$1 regex=$2 max_seconds=$3 max_mib=$4
shift 4
[ "$1" = "--" ] && shift
stats=$(mktemp)
output=$(/usr/bin/time -f '%e %M' -o "$stats" "$@" 2>&1)
rc=$?
# GNU time puts "Command exited with non-zero status N" before the format line.
read -r seconds kib < <(tail -n 1 "$stats")
rm -f "$stats"
mib=$((kib / 1024))
printf '%s\n' "$output"
echo "exit $rc, wall ${seconds} s, peak RSS ${mib} MiB (limits: exit $code, ${max_seconds} s, ${max_mib} MiB)"
status=0
[ "$rc" -eq "$code" ] || { echo "FAIL: exit $rc, expected $code"; status=1; }
grep -Eq -- "$regex" <<<"$output" || { echo "FAIL: output does not match /$regex/"; status=1; }
awk -v s="$seconds" -v m="$max_seconds" 'BEGIN { exit !(s <= m) }' || { echo "FAIL: took ${seconds} s"; status=1; }
[ "$mib" -le "$max_mib" ] || { echo "FAIL: peak RSS ${mib} MiB"; status=1; }
exit $status
