#!/usr/bin/env bash
# A full disk while writing --output (PNG), --exr and --dump (PFM): each run must exit 1 with the
# system's reason ("No space left on device"), leave the file that was there before unchanged, and
# leave no temporary file behind. The disk is "full" through full_disk_shim.so (LD_PRELOAD).
# usage: full_disk_test.sh SHIM STAGE_BINARY WORK_DIR
set -uo pipefail
shim=$1 stage=$2 work=$3
rm -rf "$work" && mkdir -p "$work/dump"
# gcc's ASan runtime wants to be first in the library list; the shim only wraps write().
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0"
failures=0
check() { # check NAME TARGET_FILE ARGS...
    local name=$1 target=$2
    shift 2
    printf 'the old %s\n' "$name" >"$target"
    cp "$target" "$work/expected"
    output=$(T10_FULL_DISK_DIR=$work LD_PRELOAD=$shim "$stage" --headless --backend egl --size 64x64 --frames 1 "$@" 2>&1)
    rc=$?
    printf '%s: exit %d: %s\n' "$name" "$rc" "$(grep -E 'error|wrote' <<<"$output" | head -n 3)"
    local ok=1
    [ "$rc" -eq 1 ] || { echo "FAIL: $name: exit $rc, expected 1"; ok=0; }
    grep -q "No space left on device" <<<"$output" || { echo "FAIL: $name: the message lacks the system's reason"; ok=0; }
    grep -q "^wrote $target" <<<"$output" && { echo "FAIL: $name: claims to have written $target"; ok=0; }
    cmp -s "$target" "$work/expected" || { echo "FAIL: $name: the old file was changed"; ok=0; }
    leftovers=$(find "$work" -name '*.tmp*')
    [ -z "$leftovers" ] || { echo "FAIL: $name: temporary files left: $leftovers"; ok=0; }
    [ "$ok" -eq 1 ] || failures=$((failures + 1))
}
check PNG "$work/frame.png" --output "$work/frame.png"
check EXR "$work/hdr.exr" --exr "$work/hdr.exr"
check PFM "$work/dump/unit15_level0.pfm" --dump "$work/dump"
# The shim must be what fails these runs: without it the same command writes every file.
"$stage" --headless --backend egl --size 64x64 --frames 1 --output "$work/frame.png" --exr "$work/hdr.exr" \
    --dump "$work/dump" >/dev/null 2>&1 || { echo "FAIL: the run fails without the shim too"; failures=$((failures + 1)); }
echo "$failures failure(s)"
[ "$failures" -eq 0 ]
