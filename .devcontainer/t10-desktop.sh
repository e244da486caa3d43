#!/usr/bin/env bash
# t10-desktop: the dev container's desktop. TigerVNC's X server on $DISPLAY (default :1) at 24-bit
# colour and $VNC_GEOMETRY (default 1280x800), the openbox window manager, and noVNC (websockify) on
# port $NOVNC_PORT (default 6080) serving that desktop to a browser. Whatever already runs is left
# alone, so running it again is harmless. It returns once the desktop answers (devcontainer.json's
# postStartCommand), or with --foreground stays until the X server ends (the image's CMD).
# The VNC server listens on localhost only and asks no password: the forwarded port is the way in,
# and Codespaces keeps it private to the codespace's owner.
# Logs: ~/.local/state/t10-desktop/.
set -u
display=${DISPLAY:-:1}
number=${display#:}
number=${number%%.*}
geometry=${VNC_GEOMETRY:-1280x800}
web_port=${NOVNC_PORT:-6080}
vnc_port=$((5900 + number))
logs=${XDG_STATE_HOME:-$HOME/.local/state}/t10-desktop
mkdir -p "$logs" || exit 1

# wait_for WHAT SECONDS COMMAND...: polls COMMAND every 0.2 s; a message and exit 1 after SECONDS.
wait_for() {
    local what=$1 tries=$(($2 * 5))
    shift 2
    until "$@" >/dev/null 2>&1; do
        tries=$((tries - 1))
        if [ $tries -le 0 ]; then
            echo "t10-desktop: $what did not start; its log: $logs" >&2
            exit 1
        fi
        sleep 0.2
    done
}
x_answers() { xdpyinfo -display "$display"; }
port_open() { (exec 3<>"/dev/tcp/127.0.0.1/$1") 2>/dev/null; }

if ! x_answers >/dev/null 2>&1; then
    # setsid: the servers outlive the shell that started them (postStartCommand's).
    setsid Xtigervnc "$display" -geometry "$geometry" -depth 24 -rfbport "$vnc_port" -localhost \
        -SecurityTypes None -AlwaysShared -desktop "Tutorial 10" </dev/null >"$logs/Xtigervnc.log" 2>&1 &
    wait_for "the X server (Xtigervnc $display)" 15 x_answers
    DISPLAY=$display setsid openbox </dev/null >"$logs/openbox.log" 2>&1 &
fi
if ! port_open "$web_port"; then
    setsid websockify --web /usr/share/novnc "$web_port" "127.0.0.1:$vnc_port" </dev/null >"$logs/websockify.log" 2>&1 &
    wait_for "noVNC (websockify on port $web_port)" 15 port_open "$web_port"
fi
echo "t10-desktop: desktop $display (${geometry}, 24-bit) in the browser at http://localhost:$web_port/"
if [ "${1:-}" = --foreground ]; then
    # The X server is not this shell's child: wait while it answers.
    while x_answers >/dev/null 2>&1; do sleep 5; done
    echo "t10-desktop: the X server on $display has stopped" >&2
    exit 1
fi
