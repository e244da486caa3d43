#!/usr/bin/env bash
# A window destroyed by another X client: the stage must end cleanly (no Xlib "BadDrawable" or
# "X Error"), exit 0 when no output was asked for, and exit 1 naming the outputs when some were: once
# while it starts up, and twice in its frame loop (after its second frame).
# Run under xvfb-run. usage: window_closed_test.sh X_DESTROY_WINDOW STAGE_BINARY STAGE_NAME OUT_DIR
set -uo pipefail
destroy=$1 stage=$2 name=$3 out=$4
mkdir -p "$out"
failures=0
run() { # run WHEN EXPECTED_CODE REGEX ARGS...: WHEN is "start-up" or "frame-loop"
    local when=$1 expected=$2 regex=$3
    shift 3
    "$stage" --backend window --size 320x200 --verbose "$@" >"$out/window_closed.log" 2>&1 &
    local pid=$!
    if [ "$when" = start-up ]; then
        # 0.5 s after the window appears, while the stage compiles its shaders or draws its first frames.
        # (Destroyed within its first milliseconds, while GLFW still sets the window up, Xlib's default
        # handler ends the stage with BadWindow: not handled, not tested.)
        "$destroy" "$name" 20 500
    else
        # --verbose prints a line per frame: once frame 1 is done the stage is in its frame loop.
        local waited=0
        until grep -q '^frame 1:' "$out/window_closed.log"; do
            if ! kill -0 "$pid" 2>/dev/null || [ "$waited" -ge 300 ]; then
                echo "FAIL: the stage printed no second frame in 30 s"
                break
            fi
            sleep 0.1
            waited=$((waited + 1))
        done
        "$destroy" "$name" 20 100
    fi
    wait "$pid"
    local rc=$?
    grep -v '^frame [0-9]*:' "$out/window_closed.log"
    echo "exit $rc (expected $expected), $(grep -c '^frame [0-9]*:' "$out/window_closed.log") frames drawn"
    if [ "$rc" -ne "$expected" ] || grep -Eq "BadDrawable|X Error" "$out/window_closed.log" ||
        ! grep -Eq -- "$regex" "$out/window_closed.log"; then
        echo "FAIL"
        failures=$((failures + 1))
    fi
}
run start-up 0 "window: an X request failed" --frames 1000000
run frame-loop 0 "window: an X request failed" --frames 1000000
run frame-loop 1 "outputs asked for were not written: the window was closed" --frames 1000000 --output "$out/never.png"
echo "$failures failure(s)"
[ "$failures" -eq 0 ]
