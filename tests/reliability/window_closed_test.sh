#!/usr/bin/env bash
# A window destroyed by another X client: the stage must end cleanly (no Xlib "BadDrawable" or
# "X Error"), exit 0 when no output was asked for, and exit 1 naming the outputs when some were.
# Run under xvfb-run. usage: window_closed_test.sh X_DESTROY_WINDOW STAGE_BINARY STAGE_NAME OUT_DIR
set -uo pipefail
destroy=$1 stage=$2 name=$3 out=$4
mkdir -p "$out"
failures=0
run() { # run DELAY_MS EXPECTED_CODE REGEX ARGS...
    local delay=$1 expected=$2 regex=$3
    shift 3
    "$stage" --backend window --size 320x200 "$@" >"$out/window_closed.log" 2>&1 &
    local pid=$!
    "$destroy" "$name" 20 "$delay"
    wait "$pid"
    local rc=$?
    cat "$out/window_closed.log"
    echo "exit $rc (expected $expected)"
    if [ "$rc" -ne "$expected" ] || grep -Eq "BadDrawable|X Error" "$out/window_closed.log" ||
        ! grep -Eq -- "$regex" "$out/window_closed.log"; then
        echo "FAIL"
        failures=$((failures + 1))
    fi
}
# Destroyed while the stage starts up (0.5 s), and in the frame loop (8 s: start-up takes 2-5 s).
run 500 0 "window: an X request failed" --frames 1000000
run 8000 0 "window: an X request failed" --frames 1000000
run 8000 1 "outputs asked for were not written: the window was closed" --frames 1000000 --output "$out/never.png"
echo "$failures failure(s)"
[ "$failures" -eq 0 ]
