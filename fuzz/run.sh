#!/usr/bin/env bash
# Runs the libFuzzer targets built in BUILD_DIR (fuzz/CMakeLists.txt) for SECONDS each, one after
# the other, and prints each one's executions, coverage (cov: edges, ft: features) and findings.
# usage: fuzz/run.sh BUILD_DIR SECONDS [TARGET...]      (no TARGET: every line of targets.txt)
# New inputs go to BUILD_DIR/corpus/<target>/, findings (crash-, leak-, oom-, timeout-) to
# BUILD_DIR/findings/<target>/, the log to BUILD_DIR/logs/<target>.log. Exit 1 if any target found
# something.
set -uo pipefail
build=$1 seconds=$2
shift 2
wanted=" $* "
status=0
while read -r name seeds; do
    [ -n "$name" ] || continue
    [ "$wanted" = "  " ] || [[ "$wanted" == *" $name "* ]] || continue
    mkdir -p "$build/corpus/$name" "$build/findings/$name" "$build/logs"
    log=$build/logs/$name.log
    echo "fuzz: $name for ${seconds}s (log $log)"
    # -rss_limit_mb and -malloc_limit_mb: an input that needs more than 2 GiB is a finding (unbounded
    # memory); -timeout: one that takes more than 10 s is one too.
    # shellcheck disable=SC2086
    "$build/${name}_fuzzer" -max_total_time="$seconds" -rss_limit_mb=2048 -malloc_limit_mb=2048 -timeout=10 \
        -max_len=65536 -print_final_stats=1 -artifact_prefix="$build/findings/$name/" \
        "$build/corpus/$name" $seeds >"$log" 2>&1
    rc=$?
    execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$')
    last=$(grep -E '^#[0-9]+' "$log" | tail -n 1)
    cov=$(grep -o 'cov: [0-9]*' <<<"$last" | grep -o '[0-9]*')
    ft=$(grep -o 'ft: [0-9]*' <<<"$last" | grep -o '[0-9]*')
    findings=$(find "$build/findings/$name" -type f | wc -l)
    echo "fuzz: $name: exit $rc, ${execs:-?} executions, cov ${cov:-?}, ft ${ft:-?}, corpus $(find "$build/corpus/$name" -type f | wc -l) files, $findings finding(s)"
    if [ "$rc" -ne 0 ] || [ "$findings" -ne 0 ]; then
        status=1
        grep -E 'ERROR|SUMMARY|deadly|Test unit written' "$log" | head -n 20
    fi
done <"$build/targets.txt"
exit $status
