#!/usr/bin/env bash
# Runs the glTF loader's fuzzer for SECONDS, seeded with the loader's test fixtures (.gltf and .glb
# from tools/make_gltf_fixtures, written into FIXTURES), and prints executions and findings.
# usage: fuzz/gltf/run.sh BUILD_DIR FIXTURES SECONDS
# New inputs go to BUILD_DIR/corpus/, findings (crash-, leak-, oom-, timeout-) to BUILD_DIR/findings/,
# the log to BUILD_DIR/fuzz.log. Exit 1 if anything was found.
set -uo pipefail
build=$1 fixtures=$2 seconds=$3
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$build/corpus" "$build/seeds" "$build/findings"
cp "$fixtures"/*.gltf "$fixtures"/*.glb "$build/seeds/"
rm -f "$build/seeds/deep_chain.gltf" # 1.7 MB: slows every run, and max_len would cut it anyway
# -rss_limit_mb / -malloc_limit_mb: more than 2 GiB is a finding (unbounded memory); -timeout: so is
# more than 10 s for one input.
"$build/gltf_fuzzer" -max_total_time="$seconds" -rss_limit_mb=2048 -malloc_limit_mb=2048 -timeout=10 \
    -max_len=65536 -dict="$here/gltf.dict" -print_final_stats=1 -artifact_prefix="$build/findings/" \
    "$build/corpus" "$build/seeds" >"$build/fuzz.log" 2>&1
rc=$?
execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$build/fuzz.log" | grep -o '[0-9]*$')
last=$(grep -E '^#[0-9]+' "$build/fuzz.log" | tail -n 1)
findings=$(find "$build/findings" -type f | wc -l)
echo "fuzz gltf: ${seconds}s, ${execs:-?} executions, last status: ${last:-?}"
echo "fuzz gltf: $findings finding(s) in $build/findings (libFuzzer exit $rc; log $build/fuzz.log)"
[ "$findings" -eq 0 ] && [ "$rc" -eq 0 ]
