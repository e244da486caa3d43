#!/usr/bin/env python3
"""The dev container check's noVNC screenshot (tools/devcontainer_check/novnc_screenshot.py) on a
stand-in for noVNC's page, served here on 127.0.0.1: the page at the root redirects to vnc.html, as
noVNC's does, which "connects" 1.5 s later (the class noVNC_connected on the root element, the
desktop's name as the title) and only then paints the desktop a colour of its own.

usage: PYTHONPATH=tools novnc_screenshot_test.py NOVNC_SCREENSHOT_PY SCRATCH_DIR

Passes when the script waits for the connection and shoots the painted desktop (a shot at the load
event, as Chromium's --screenshot takes it, would be white: the check rejects that), prints the
desktop's name, fails with exit 1 and says so for a page that never connects (and writes no
screenshot), and refuses a malformed size with exit 2. The real noVNC, its VNC server and the
container around them are proven by make devcontainer-check (CI), not here.
"""
import os
import struct
import subprocess
import sys
import zlib

sys.dont_write_bytecode = True
from web import cdp  # noqa: E402  (its static server; tools/ on PYTHONPATH)

DESKTOP = (200, 40, 90)
PAGES = {
    "index.html": "<!DOCTYPE html><title>noVNC</title><script>setTimeout(() => location.replace('vnc.html'), 200);</script>",
    "vnc.html": """<!DOCTYPE html><html><head><title>noVNC</title></head><body style="margin:0;background:#fff">
<script>setTimeout(() => {
  document.body.style.background = 'rgb(%d, %d, %d)';
  document.title = 't10 desktop';
  document.documentElement.classList.add('noVNC_connected');
}, 1500);</script></body></html>""" % DESKTOP,
    "never.html": "<!DOCTYPE html><title>waiting</title><body>no desktop</body>",
}


def read_png(path):
    """(width, height, rows of (r, g, b)) of an 8-bit, non-interlaced RGB or RGBA PNG."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise AssertionError(f"{path}: not a PNG")
    at, idat, header = 8, b"", None
    while at < len(data):
        length, kind = struct.unpack(">I4s", data[at:at + 8])
        body = data[at + 8:at + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        at += 12 + length
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or colour not in (2, 6) or interlace:
        raise AssertionError(f"{path}: depth {depth}, colour type {colour}, interlace {interlace}: not read here")
    channels = 3 if colour == 2 else 4
    raw, stride, rows, previous = zlib.decompress(idat), width * channels, [], bytearray(width * channels)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            left = line[i - channels] if i >= channels else 0
            up, up_left = previous[i], previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + left) & 255
            elif kind == 2:
                line[i] = (line[i] + up) & 255
            elif kind == 3:
                line[i] = (line[i] + (left + up) // 2) & 255
            elif kind == 4:
                p = left + up - up_left
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - up_left)
                line[i] = (line[i] + (left if pa <= pb and pa <= pc else up if pb <= pc else up_left)) & 255
        rows.append([tuple(line[x * channels:x * channels + 3]) for x in range(width)])
        previous = line
    return width, height, rows


def start(script, *args):
    return subprocess.Popen([sys.executable, script, *args], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


def finish(process):
    said, _ = process.communicate(timeout=150)
    return process.returncode, said


def run(script, *args):
    return finish(start(script, *args))


def main():
    script, scratch = sys.argv[1], sys.argv[2]
    site = os.path.join(scratch, "site")
    os.makedirs(site, exist_ok=True)
    for name, text in PAGES.items():
        with open(os.path.join(site, name), "w") as f:
            f.write(text)
    server = cdp.start_server(site)
    base = f"http://127.0.0.1:{server.server_address[1]}/"
    problems = []
    try:
        shot = os.path.join(scratch, "novnc.png")
        never = os.path.join(scratch, "never.png")
        for old in (shot, never):
            if os.path.exists(old):
                os.remove(old)
        # The two runs mostly wait (for the page to connect, for the wait to run out): side by side.
        connecting = start(script, base, shot, "320x200", "--settle", "0.5")
        never_connecting = start(script, base + "never.html", never, "320x200", "--wait", "2")
        code, said = finish(connecting)
        if code != 0 or "connected; the page's title: 't10 desktop'" not in said:
            problems.append(f"the connecting page: exit {code}, said {said.strip()!r}")
        elif not os.path.isfile(shot):
            problems.append("the connecting page: no screenshot written")
        else:
            width, height, rows = read_png(shot)
            centre = rows[height // 2][width // 2]
            # The page paints one flat colour: Chromium's encoder is lossless, so 2 levels are room
            # only for colour management rounding, far from white (255, 255, 255).
            if (width, height) != (320, 200) or any(abs(a - b) > 2 for a, b in zip(centre, DESKTOP)):
                problems.append(f"the screenshot is {width}x{height} with {centre} in its centre, not 320x200 "
                                f"with the connected desktop's {DESKTOP}: shot before noVNC connected?")

        code, said = finish(never_connecting)
        if code != 1 or "noVNC did not connect within 2 s" not in said or "'waiting'" not in said:
            problems.append(f"a page that never connects: exit {code} (1 expected), said {said.strip()!r}")
        if os.path.exists(never):
            problems.append("a page that never connects: a screenshot was written anyway")

        code, said = run(script, base, shot, "320by200")
        if code != 2 or "is not WIDTHxHEIGHT" not in said:
            problems.append(f"a malformed size: exit {code} (2 expected), said {said.strip()!r}")
    finally:
        server.shutdown()
        server.server_close()
    for problem in problems:
        print(f"FAIL: {problem}")
    if not problems:
        print("ok: novnc_screenshot.py waited for the connection, shot the desktop, and failed on a page that never connects")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
