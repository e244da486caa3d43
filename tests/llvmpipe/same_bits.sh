#!/usr/bin/env bash
# make test and the grader run llvmpipe without LLVM's optimisation passes (GALLIVM_PERF=nopt: small
# renders spend more CPU compiling shaders than drawing). That is only right while the results are the
# same bits: this renders Part 3 (frame, every dumped buffer, every captured blur pass) both ways, with
# Mesa's shader cache off so that neither way can load the other's compiled shaders, and fails on any
# file that differs. A third render from another camera must differ from the first, so the comparison
# is shown to see a difference. usage: same_bits.sh STAGE_BINARY OUT_DIR
set -u
stage=$1 out=$2
rm -rf "$out" && mkdir -p "$out/optimised" "$out/nopt" "$out/other" || exit 1
render() { # render WAY DIR ARGS...
    local way=$1 dir=$2
    shift 2
    if [ "$way" = nopt ]; then set -- env GALLIVM_PERF=nopt "$@"; else set -- env -u GALLIVM_PERF "$@"; fi
    MESA_SHADER_CACHE_DISABLE=true "$@" --headless --backend egl --frames 1 --size 128x128 --dump "$dir" \
        --output "$dir/frame.png" >"$dir.log" 2>&1 || { echo "FAIL: $way render exited $?:"; cat "$dir.log"; exit 1; }
}
render optimised "$out/optimised" "$stage" --camera default --capture-passes "$out/optimised"
render nopt "$out/nopt" "$stage" --camera default --capture-passes "$out/nopt"
render optimised "$out/other" "$stage" --camera lights
files=0 differ=0
while IFS= read -r name; do
    files=$((files + 1))
    cmp -s "$out/optimised/$name" "$out/nopt/$name" || { echo "FAIL: $name differs with GALLIVM_PERF=nopt"; differ=$((differ + 1)); }
done < <(cd "$out/optimised" && find . -type f | sort)
[ -f "$out/nopt/blur_pass10.pfm" ] || { echo "FAIL: no blur passes were captured"; exit 1; }
[ "$files" -ge 20 ] || { echo "FAIL: only $files files to compare"; exit 1; }
cmp -s "$out/optimised/frame.png" "$out/other/frame.png" && { echo "FAIL: another camera gave the same frame: the comparison sees nothing"; exit 1; }
[ "$differ" -eq 0 ] || exit 1
echo "$files files (frame, buffers, blur passes) identical with and without LLVM's optimisation passes"
