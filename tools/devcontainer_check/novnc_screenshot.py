#!/usr/bin/env python3
"""A screenshot of noVNC's page once it shows the desktop: headless Chromium driven over the DevTools
protocol on a pipe (--remote-debugging-pipe: JSON messages ended by NUL on file descriptors 3 and 4),
so that the shot waits in real time for noVNC to connect and draw, which Chromium's --screenshot
cannot (it shoots at the load event, before the WebSocket has delivered a frame).

usage: novnc_screenshot.py URL OUT.png [WIDTHxHEIGHT]
Opens URL, waits up to 60 s for noVNC's "connected" state (the class noVNC_connected on the page's
root element), then 3 s for the desktop's frames, and writes the page as OUT.png. Prints the page's
title (noVNC shows the desktop's name there). Exit 1 when Chromium fails or noVNC never connects."""
import base64
import fcntl
import json
import os
import subprocess
import sys
import time


class Browser:
    def __init__(self, width, height):
        to_chrome_r, self.to_chrome = os.pipe()
        self.from_chrome, from_chrome_w = os.pipe()
        # Chromium reads the protocol on fd 3 and writes on fd 4: the child's ends, moved there after
        # fork (from copies above 10, so that neither dup2 overwrites the other's source).
        child_r = fcntl.fcntl(to_chrome_r, fcntl.F_DUPFD_CLOEXEC, 10)
        child_w = fcntl.fcntl(from_chrome_w, fcntl.F_DUPFD_CLOEXEC, 10)
        for fd in (to_chrome_r, from_chrome_w):
            os.close(fd)

        def move_fds():
            os.dup2(child_r, 3)
            os.dup2(child_w, 4)

        self.process = subprocess.Popen(
            ["chromium", "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
             f"--window-size={width},{height}", "--remote-debugging-pipe", "about:blank"],
            preexec_fn=move_fds, pass_fds=(3, 4), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        for fd in (child_r, child_w):
            os.close(fd)
        self.buffer = b""
        self.next_id = 0
        self.session = None

    def call(self, method, **params):
        self.next_id += 1
        message = {"id": self.next_id, "method": method, "params": params}
        if self.session:
            message["sessionId"] = self.session
        os.write(self.to_chrome, json.dumps(message).encode() + b"\0")
        while True:
            while b"\0" not in self.buffer:
                chunk = os.read(self.from_chrome, 1 << 20)
                if not chunk:
                    raise RuntimeError("Chromium closed the DevTools pipe")
                self.buffer += chunk
            raw, self.buffer = self.buffer.split(b"\0", 1)
            reply = json.loads(raw)
            if reply.get("id") == self.next_id:
                if "error" in reply:
                    raise RuntimeError(f"{method}: {reply['error'].get('message')}")
                return reply.get("result", {})

    def evaluate(self, expression):
        return self.call("Runtime.evaluate", expression=expression, returnByValue=True)["result"].get("value")

    def close(self):
        self.process.kill()
        self.process.wait()


def main():
    if len(sys.argv) not in (3, 4):
        print(__doc__, file=sys.stderr)
        return 2
    url, out = sys.argv[1], sys.argv[2]
    width, height = (int(v) for v in (sys.argv[3] if len(sys.argv) == 4 else "1280x800").split("x"))
    browser = Browser(width, height)
    try:
        target = browser.call("Target.createTarget", url="about:blank", width=width, height=height)["targetId"]
        browser.session = browser.call("Target.attachToTarget", targetId=target, flatten=True)["sessionId"]
        browser.call("Emulation.setDeviceMetricsOverride", width=width, height=height, deviceScaleFactor=1, mobile=False)
        browser.call("Page.navigate", url=url)
        deadline = time.monotonic() + 60
        connected = False
        while time.monotonic() < deadline and not connected:
            time.sleep(0.5)
            connected = bool(browser.evaluate("document.documentElement.classList.contains('noVNC_connected')"))
        title = browser.evaluate("document.title")
        if not connected:
            print(f"noVNC did not connect within 60 s; the page's title: {title!r}")
            return 1
        time.sleep(3)
        shot = browser.call("Page.captureScreenshot", format="png")["data"]
        with open(out, "wb") as handle:
            handle.write(base64.b64decode(shot))
        print(f"connected; the page's title: {title!r}")
        return 0
    except (OSError, RuntimeError, KeyError, ValueError) as error:
        print(f"novnc_screenshot: {error}")
        return 1
    finally:
        browser.close()


if __name__ == "__main__":
    sys.exit(main())
