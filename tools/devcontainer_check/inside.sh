#!/usr/bin/env bash
# make devcontainer-check's steps inside the dev container's root, as the container's user, from the
# clone at the workspace (devcontainer_check.sh enters the root with a network of its own, after the
# image's steps and postCreateCommand, and sets the image's ENV). Each step prints one line:
# "devcontainer-check: STEP: ok|FAILED (what was seen), N.N s". Screenshots and logs go to OUT.
#   usage: inside.sh OUT POST_START_COMMAND
# Exit 1 when any step failed.
set -u
out=$1 post_start=$2
here=$(dirname "$0")
status=0
mkdir -p "$out"

# step NAME COMMAND...: runs COMMAND (a shell function) timed; it sets $seen to what it found.
step() {
    local name=$1 start rc ms
    shift
    seen=""
    start=$(date +%s%N)
    "$@" >>"$out/steps.log" 2>&1
    rc=$?
    ms=$(( ($(date +%s%N) - start) / 1000000 ))
    if [ $rc -eq 0 ]; then word=ok; else word=FAILED; status=1; fi
    printf 'devcontainer-check: %-22s %s%s, %d.%d s\n' "$name:" "$word" "${seen:+ ($seen)}" $((ms / 1000)) $((ms % 1000 / 100))
    echo "--- $name: $word ($seen)" >>"$out/steps.log"
    return $rc
}

desktop() {
    bash -c "$post_start" || { seen="postStartCommand '$post_start' exited $?"; return 1; }
    local depth
    depth=$(xdpyinfo | sed -n 's/^ *depth of root window: *\([0-9]*\) planes.*/\1/p')
    seen="display $DISPLAY, root window depth $depth"
    [ "$depth" = 24 ] || return 1
    # noVNC's page answers on its port.
    python3 -c "import urllib.request,sys; sys.exit(0 if b'vnc.html' in urllib.request.urlopen('http://127.0.0.1:$NOVNC_PORT/').read() else 1)" ||
        { seen="$seen; http://127.0.0.1:$NOVNC_PORT/ is not noVNC's page"; return 1; }
}

gl_context() {
    glxinfo -B >"$out/glxinfo.txt" 2>&1 || { seen="glxinfo -B failed: $(tail -n 1 "$out/glxinfo.txt")"; return 1; }
    local renderer core
    renderer=$(sed -n 's/^OpenGL renderer string: //p' "$out/glxinfo.txt")
    core=$(sed -n 's/^OpenGL core profile version string: //p' "$out/glxinfo.txt")
    seen="core profile $core, renderer $renderer"
    case $renderer in llvmpipe*) ;; *) return 1 ;; esac
    # 4.3 or later: the major.minor at the start of the version string.
    python3 -c "import sys; v=tuple(int(x) for x in sys.argv[1].split()[0].split('.')[:2]); sys.exit(0 if v >= (4, 3) else 1)" "$core"
}

# The window of a running stage: its title ends in "fps) - view NAME (V)" once it draws frames.
stage_window() { xwininfo -root -tree | grep -m 1 'fps) - view' | awk '{print $1}'; }

make_run() {
    make run >"$out/make-run.log" 2>&1 &
    local tries=600 window=""
    while [ $tries -gt 0 ]; do
        window=$(stage_window)
        [ -z "$window" ] || break
        kill -0 $! 2>/dev/null || { seen="make run ended (exit status in $out/make-run.log): $(tail -n 1 "$out/make-run.log")"; return 1; }
        sleep 0.2
        tries=$((tries - 1))
    done
    [ -n "$window" ] || { seen="no stage window after 120 s"; return 1; }
    sleep 3 # a few more frames, and the title's frame time
    local info depth title
    info=$(xwininfo -id "$window")
    depth=$(sed -n 's/^ *Depth: *//p' <<<"$info")
    title=$(sed -n 's/^xwininfo: Window id: [^ ]* "\(.*\)"$/\1/p' <<<"$info")
    xwd -root -silent | xwdtopnm 2>/dev/null | pamdepth 255 >"$out/desktop.ppm" && pnmtopng <"$out/desktop.ppm" >"$out/desktop.png" 2>/dev/null
    seen="window \"$title\", depth $depth; screenshot $out/desktop.png"
    [ "$depth" = 24 ] && [ -s "$out/desktop.png" ]
}

novnc_page() {
    # The page at the port's root redirects to vnc.html, which connects and draws the desktop;
    # novnc_screenshot.py waits for that in real time, through the DevTools client copied beside it
    # (web/cdp.py).
    local said
    said=$(PYTHONPATH="$here" python3 "$here/novnc_screenshot.py" "http://127.0.0.1:$NOVNC_PORT/" "$out/novnc.png" 1280x800)
    local rc=$?
    seen=$said
    [ $rc -eq 0 ] || return 1
    pngtopnm "$out/novnc.png" >"$out/novnc.ppm" || { seen="$seen; no screenshot"; return 1; }
    # The same picture as the X server's own screenshot, but for noVNC's control-bar handle and the
    # frames drawn between the two shots: at most 10% of the pixels differ (a page that shows no
    # desktop, or another picture, differs far more).
    local same
    same=$(python3 "$here/same_picture.py" "$out/novnc.ppm" "$out/desktop.ppm" 0.10)
    rc=$?
    seen="$seen; screenshot $out/novnc.png; $same"
    return $rc
}

# isolation: the isolation the last make check's report.json names.
isolation() {
    python3 -c "import json,sys; print(json.load(open(sys.argv[1])).get('isolation'))" build/check/part1/part1/report.json 2>/dev/null
}

student_check() {
    make student PART=1 >"$out/make-student.log" 2>&1 || { seen="make student PART=1 failed: $(tail -n 1 "$out/make-student.log")"; return 1; }
    # A student who has done Part 1's steps: the reference's files in the student's folder.
    cp tutorial10_part1_tonemap/*.frag tutorial10_part1_tonemap/Tutorial10.cpp student/part1/
    make check PART=1 >"$out/make-check.log" 2>&1
    local rc=$? score
    score=$(grep -o -m 1 'score [0-9]*/100' "$out/make-check.log")
    seen="${score:-no score}, isolation $(isolation), make exit $rc"
    [ $rc -eq 0 ] && [ "$score" = "score 100/100" ] && [ "$(isolation)" = namespaces ]
}

docker_defaults() {
    python3 "$here/docker_seccomp.py" make check PART=1 >"$out/make-check-docker.log" 2>&1
    local rc=$?
    grep -q "refuses the grader's sandbox" "$out/make-check-docker.log" && grep -q 'ISOLATION=none' "$out/make-check-docker.log" ||
        { seen="no clear message: $(tail -n 1 "$out/make-check-docker.log")"; return 1; }
    [ $rc -ne 0 ] || { seen="exit 0 without a sandbox"; return 1; }
    python3 "$here/docker_seccomp.py" make check PART=1 ISOLATION=none >"$out/make-check-none.log" 2>&1
    local rc_none=$? score
    score=$(grep -o -m 1 'score [0-9]*/100' "$out/make-check-none.log")
    seen="refused with the choices, make exit $rc; with ISOLATION=none: ${score:-no score}, isolation $(isolation), make exit $rc_none"
    [ $rc_none -eq 0 ] && [ "$score" = "score 100/100" ] && [ "$(isolation)" = none ]
}

step "desktop (postStart)" desktop || true
step "glxinfo -B" gl_context
step "make run" make_run
step "noVNC in Chromium" novnc_page
step "make check PART=1" student_check
step "Docker's seccomp" docker_defaults
exit $status
