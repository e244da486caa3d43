#!/usr/bin/env bash
# --then (app.hpp): t10-grade renders a submission's cases in one process. That is only right while
# each run writes what a process of its own writes: this renders the grader's four Part 3 cases
# (128x128 default camera, 160x90 lights, the 64x64 ramp and the 128x128 hot block, each with its
# dump and blur passes) one process each, then all in one process in that order and in the reverse
# order, and fails on any file that differs (blur_passes.txt compared without its GL program name,
# which counts the objects made before). The frame of the first case must differ from the second's, so
# the comparison is shown to see a difference. Also: the log's run markers, and --then refused with
# another backend, and in extras (whose own options the runs would share). usage:
# then_runs.sh STAGE_BINARY MAKE_TEST_IMAGES EXTRAS_BINARY OUT_DIR
set -u
stage=$1 make_images=$2 extras=$3 out=$4
rm -rf "$out" && mkdir -p "$out/inputs" || exit 1
"$make_images" "$out/inputs" >/dev/null || { echo "FAIL: $make_images"; exit 1; }
export GALLIVM_PERF=nopt LP_NATIVE_VECTOR_WIDTH=128 LP_NUM_THREADS=0 MESA_SHADER_CACHE_DISABLE=true
ids=(pot npot ramp hot)
case_args() { # case_args WAY ID: the arguments of one case, writing into $out/WAY/ID
    local dir=$out/$1/$2
    mkdir -p "$dir"
    local common=(--headless --backend egl --frames 1 --dump "$dir" --output "$dir/frame.png" --capture-passes "$dir")
    case $2 in
        pot) echo "${common[@]} --size 128x128 --camera default" ;;
        npot) echo "${common[@]} --size 160x90 --camera lights" ;;
        ramp) echo "${common[@]} --input $out/inputs/ramp.exr" ;;
        hot) echo "${common[@]} --input $out/inputs/hot.exr" ;;
    esac
}
for id in "${ids[@]}"; do
    # shellcheck disable=SC2046 # the arguments hold no spaces (OUT_DIR is a build folder)
    "$stage" $(case_args alone "$id") >"$out/alone-$id.log" 2>&1 || { echo "FAIL: $id alone:"; cat "$out/alone-$id.log"; exit 1; }
done
together() { # together WAY ID...: one process, the cases in the order given
    local way=$1 args=() first=1
    shift
    for id in "$@"; do
        [ $first -eq 1 ] || args+=(--then)
        first=0
        # shellcheck disable=SC2207
        args+=($(case_args "$way" "$id"))
    done
    "$stage" "${args[@]}" >"$out/$way.log" 2>&1 || { echo "FAIL: $way:"; cat "$out/$way.log"; exit 1; }
}
together forward pot npot ramp hot
together reverse hot ramp npot pot
files=0 differ=0
while IFS= read -r name; do
    files=$((files + 1))
    for way in forward reverse; do
        if [ "${name##*/}" = blur_passes.txt ]; then
            cmp -s <(cut -d' ' -f1,2,4,5 "$out/alone/$name") <(cut -d' ' -f1,2,4,5 "$out/$way/$name")
        else
            cmp -s "$out/alone/$name" "$out/$way/$name"
        fi || { echo "FAIL: $name differs in the $way run"; differ=$((differ + 1)); }
    done
done < <(cd "$out/alone" && find . -type f | sort)
[ "$files" -ge 60 ] || { echo "FAIL: only $files files to compare"; exit 1; }
cmp -s "$out/alone/pot/frame.png" "$out/alone/npot/frame.png" && { echo "FAIL: two cases gave the same frame: the comparison sees nothing"; exit 1; }
for n in 2 3 4; do
    grep -qx "t10: run $n of 4" "$out/forward.log" || { echo "FAIL: no 't10: run $n of 4' line in the log:"; cat "$out/forward.log"; exit 1; }
done
"$stage" --headless --backend egl --frames 1 --then --backend osmesa >"$out/refused.log" 2>&1
code=$?
[ $code -eq 2 ] && grep -q -- "--then: run 2 asks for another --backend" "$out/refused.log" ||
    { echo "FAIL: --then with another backend: exit $code, said:"; cat "$out/refused.log"; exit 1; }
"$extras" --headless --backend egl --frames 1 --then --blur-passes 0 >"$out/extras.log" 2>&1
code=$?
[ $code -eq 2 ] && grep -q -- "has options of its own" "$out/extras.log" ||
    { echo "FAIL: --then in extras: exit $code, said:"; cat "$out/extras.log"; exit 1; }
[ "$differ" -eq 0 ] || exit 1
echo "$files files (frames, buffers, blur passes) of four cases identical alone, in one process, and in one process in reverse order"
