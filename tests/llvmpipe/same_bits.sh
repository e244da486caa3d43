#!/usr/bin/env bash
# make test runs llvmpipe without LLVM's optimisation passes (GALLIVM_PERF=nopt) and with 128-bit
# vectors (LP_NATIVE_VECTOR_WIDTH=128), and the grader renders its small cases that way too, in the
# program's own thread (LP_NUM_THREADS=0): for small frames
# compiling the shaders costs more CPU than drawing them. That is only right while the results are the
# same bits: this renders Part 3 (frame, every dumped buffer, every captured blur pass) the default way
# and both of those, with Mesa's shader cache off so that no way can load another's compiled shaders,
# and fails on any file that differs. A render from another camera must differ from the first, so the
# comparison is shown to see a difference. usage: same_bits.sh STAGE_BINARY OUT_DIR
set -u
stage=$1 out=$2
rm -rf "$out" && mkdir -p "$out" || exit 1
render() { # render DIR ENV_SETTINGS... -- ARGS...
    local dir=$1
    shift
    local settings=()
    while [ "$1" != -- ]; do settings+=("$1"); shift; done
    shift
    mkdir -p "$dir"
    env -u GALLIVM_PERF -u LP_NATIVE_VECTOR_WIDTH -u LP_NUM_THREADS MESA_SHADER_CACHE_DISABLE=true "${settings[@]}" "$stage" --headless --backend egl \
        --frames 1 --size 128x128 --dump "$dir" --output "$dir/frame.png" "$@" >"$dir.log" 2>&1 ||
        { echo "FAIL: render into $dir (${settings[*]}) exited non-zero:"; cat "$dir.log"; exit 1; }
}
render "$out/default" -- --camera default --capture-passes "$out/default"
render "$out/make-test" GALLIVM_PERF=nopt LP_NATIVE_VECTOR_WIDTH=128 -- --camera default --capture-passes "$out/make-test"
render "$out/grader" GALLIVM_PERF=nopt LP_NATIVE_VECTOR_WIDTH=128 LP_NUM_THREADS=0 -- --camera default --capture-passes "$out/grader"
render "$out/other" -- --camera lights
files=0 differ=0
while IFS= read -r name; do
    files=$((files + 1))
    for way in make-test grader; do
        cmp -s "$out/default/$name" "$out/$way/$name" || { echo "FAIL: $name differs in the $way render"; differ=$((differ + 1)); }
    done
done < <(cd "$out/default" && find . -type f | sort)
[ -f "$out/grader/blur_pass10.pfm" ] || { echo "FAIL: no blur passes were captured"; exit 1; }
[ "$files" -ge 20 ] || { echo "FAIL: only $files files to compare"; exit 1; }
cmp -s "$out/default/frame.png" "$out/other/frame.png" && { echo "FAIL: another camera gave the same frame: the comparison sees nothing"; exit 1; }
[ "$differ" -eq 0 ] || exit 1
echo "$files files (frame, buffers, blur passes) identical by default, as make test renders (GALLIVM_PERF=nopt LP_NATIVE_VECTOR_WIDTH=128) and as the grader does (the same and LP_NUM_THREADS=0)"
