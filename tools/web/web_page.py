#!/usr/bin/env python3
"""Loads a web stage's page (make web) in headless Chromium and reports what the page reports.

The page's interface (common/platform/web/index.html.in): document.body.dataset.t10 becomes
"rendered" or "error" (the message in #t10-error), dataset.t10Frames counts the frames drawn, and the
canvas keeps its pixels. This script serves --root on 127.0.0.1 (a free port), opens --page (a path
under --root with its query, e.g. "tutorial10_part0_start/index.html?size=640x360&frames=1"), waits
for rendered or error, runs each --eval expression in order (each may return a promise; after each
that changes a setting, the page is waited on again), and prints one JSON object: state, error,
frames, firstFrameMs, the evals' results; --png FILE writes the canvas (canvas.toDataURL) as a PNG.
Exit status: 0 rendered, 1 error or a time-out, 2 bad usage.

Chromium drives WebGL 2 through SwiftShader here (no GPU): --use-angle=swiftshader with
--enable-unsafe-swiftshader. The DevTools protocol runs over a pipe (--remote-debugging-pipe), so
only the Python standard library and Debian's chromium are needed. Importable: render_page() is the
entry point other tests use (tests of issue 36).
"""
import argparse
import base64
import functools
import http.server
import json
import os
import select
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time


class Failure(Exception):
    pass


class _Handler(http.server.SimpleHTTPRequestHandler):
    # WebAssembly streams only with its own MIME type; Python's table may lack it.
    extensions_map = {**http.server.SimpleHTTPRequestHandler.extensions_map, ".wasm": "application/wasm"}

    def log_message(self, fmt, *args):
        pass


def serve(root, port=0):
    """A static server of `root` on 127.0.0.1 (port 0: a free one), in a daemon thread."""
    server = http.server.ThreadingHTTPServer(("127.0.0.1", port), functools.partial(_Handler, directory=root))
    server.daemon_threads = True
    threading.Thread(target=server.serve_forever, kwargs={"poll_interval": 0.1}, daemon=True).start()
    return server


def find_chromium():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


class Browser:
    """Headless Chromium with WebGL 2 on SwiftShader, spoken to over the DevTools pipe."""

    def __init__(self, chromium, profile, log_path, width=1280, height=900):
        to_r, self._to = os.pipe()
        self._from, from_w = os.pipe()

        def child_fds():  # Chromium reads commands on fd 3 and writes replies on fd 4
            a, b = os.dup(to_r), os.dup(from_w)
            os.dup2(a, 3)
            os.dup2(b, 4)

        self._log = open(log_path, "w")
        args = [chromium, "--headless=new", "--no-sandbox", "--remote-debugging-pipe",
                "--enable-unsafe-swiftshader", "--use-angle=swiftshader", "--ignore-gpu-blocklist",
                f"--user-data-dir={profile}", "--no-first-run", "--no-default-browser-check",
                "--disable-extensions", "--disable-background-networking", "--disable-component-update",
                "--disable-sync", "--disable-default-apps", "--disable-dev-shm-usage", "--mute-audio",
                "--force-device-scale-factor=1", f"--window-size={width},{height}",
                "--host-resolver-rules=MAP * ~NOTFOUND , EXCLUDE 127.0.0.1"]
        args += os.environ.get("T10_CHROMIUM_FLAGS", "").split() + ["about:blank"]
        # Its own process group, so that it and its helpers end together (close()).
        self.proc = subprocess.Popen(args, stdin=subprocess.DEVNULL, stdout=self._log, stderr=self._log,
                                     preexec_fn=child_fds, close_fds=False, start_new_session=True)
        os.close(to_r)
        os.close(from_w)
        self._buffer = b""
        self._id = 0
        self._messages = []

    def _read(self, timeout):
        ready, _, _ = select.select([self._from], [], [], timeout)
        if not ready:
            return
        chunk = os.read(self._from, 1 << 20)
        if not chunk:
            raise Failure(f"chromium closed the DevTools pipe (exit code {self.proc.poll()})")
        self._buffer += chunk
        while b"\0" in self._buffer:
            raw, self._buffer = self._buffer.split(b"\0", 1)
            self._messages.append(json.loads(raw))

    def send(self, method, params=None, session=None, timeout=60):
        self._id += 1
        message = {"id": self._id, "method": method, "params": params or {}}
        if session:
            message["sessionId"] = session
        data = json.dumps(message).encode() + b"\0"
        while data:
            data = data[os.write(self._to, data):]
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            for i, reply in enumerate(self._messages):
                if reply.get("id") == self._id:
                    del self._messages[i]
                    if "error" in reply:
                        raise Failure(f"{method}: {reply['error']}")
                    return reply.get("result", {})
            self._read(0.1)
        raise Failure(f"{method}: no reply within {timeout} s")

    def console(self):
        """The page's console lines and browser log entries (WebGL's warnings) so far."""
        lines = []
        for message in self._messages:
            params = message.get("params", {})
            if message.get("method") == "Runtime.consoleAPICalled":
                lines.append(" ".join(str(a.get("value", a.get("description", ""))) for a in params.get("args", [])))
            elif message.get("method") == "Log.entryAdded":
                lines.append(params.get("entry", {}).get("text", ""))
        self._messages = [m for m in self._messages if "id" in m]
        return lines

    def close(self):
        try:
            if self.proc.poll() is None:
                try:
                    self.send("Browser.close", timeout=5)
                    self.proc.wait(timeout=5)
                except Exception:
                    pass
        finally:
            for sig in (signal.SIGTERM, signal.SIGKILL):
                try:
                    os.killpg(self.proc.pid, sig)
                except ProcessLookupError:
                    break
            self._log.close()


class Page:
    def __init__(self, browser, url):
        self.browser = browser
        target = browser.send("Target.createTarget", {"url": "about:blank"})["targetId"]
        self.session = browser.send("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
        browser.send("Runtime.enable", session=self.session)
        browser.send("Log.enable", session=self.session)
        browser.send("Page.enable", session=self.session)
        browser.send("Page.navigate", {"url": url}, session=self.session)

    def eval(self, expression, timeout=60):
        result = self.browser.send("Runtime.evaluate", {"expression": expression, "awaitPromise": True,
                                                        "returnByValue": True}, session=self.session,
                                   timeout=timeout)
        if "exceptionDetails" in result:
            raise Failure(f"{expression}: {result['exceptionDetails'].get('exception', {}).get('description')}")
        return result.get("result", {}).get("value")

    def wait_state(self, timeout, frames_above=-1):
        """Waits until dataset.t10 is "error", or "rendered" with more than `frames_above` frames."""
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            state = self.eval("document.body ? [document.body.dataset.t10 || '', "
                              "Number(document.body.dataset.t10Frames || 0)] : ['', 0]")
            if state[0] == "error" or (state[0] == "rendered" and state[1] > frames_above):
                return state[0]
            time.sleep(0.1)
        raise Failure(f"the page was not rendered within {timeout} s")


def render_page(root, page, evals=(), png=None, timeout=120, chromium=None):
    """Serves `root`, loads `page` and returns the page's report (see the module's text)."""
    chromium = chromium or find_chromium()
    if not chromium:
        raise Failure("no chromium found (Debian package chromium)")
    server = serve(root)
    profile = tempfile.mkdtemp(prefix="t10-web-")
    browser = Browser(chromium, profile, os.path.join(profile, "chromium.log"))
    try:
        started = time.monotonic()
        page_ = Page(browser, f"http://127.0.0.1:{server.server_address[1]}/{page}")
        state = page_.wait_state(timeout)
        report = {"state": state, "wallMs": round((time.monotonic() - started) * 1000)}
        results = []
        for expression in evals:
            if state != "rendered":
                break
            frames = page_.eval("Number(document.body.dataset.t10Frames)")
            value = page_.eval(expression)
            results.append(value)
            # A setting applied redraws: wait for the frame after it.
            if page_.eval("document.body.dataset.t10") != "rendered":
                state = page_.wait_state(timeout, frames)
        report["state"] = state
        report["evals"] = results
        report["error"] = page_.eval("(document.getElementById('t10-error') || {}).textContent || ''")
        report["frames"] = page_.eval("Number(document.body.dataset.t10Frames || 0)")
        report["firstFrameMs"] = page_.eval("window.Module && Module.t10FirstFrameMs")
        report["console"] = browser.console()
        if png and state == "rendered":
            data = page_.eval("document.getElementById('canvas').toDataURL('image/png')")
            with open(png, "wb") as out:
                out.write(base64.b64decode(data.split(",", 1)[1]))
        return report
    finally:
        browser.close()
        server.shutdown()
        shutil.rmtree(profile, ignore_errors=True)


def serve_forever(root, port):
    """make web-serve: the static server alone, until Ctrl-C."""
    try:
        server = serve(root, port)
    except OSError as error:
        print(f"127.0.0.1:{port}: {error.strerror} (WEB_PORT=N picks another port)", file=sys.stderr)
        return 1
    try:
        while True:
            time.sleep(3600)
    except KeyboardInterrupt:
        server.shutdown()
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--serve", metavar="DIR", help="only serve DIR on 127.0.0.1:--port until Ctrl-C (make web-serve)")
    parser.add_argument("--port", type=int, default=8000, help="--serve's port (default 8000)")
    parser.add_argument("--root", help="the folder to serve (out/web)")
    parser.add_argument("--page", help="the page under --root, with its query")
    parser.add_argument("--eval", action="append", default=[], help="a JavaScript expression to run once rendered")
    parser.add_argument("--png", help="write the canvas here once rendered")
    parser.add_argument("--timeout", type=float, default=120, help="seconds to wait for each state (default 120)")
    args = parser.parse_args()
    if args.serve:
        return serve_forever(args.serve, args.port)
    if not args.root or not args.page:
        parser.error("--root and --page are needed (or --serve DIR)")
    if not os.path.isdir(args.root):
        print(f"{args.root}: no such folder (run make web)", file=sys.stderr)
        return 2
    try:
        report = render_page(args.root, args.page, args.eval, args.png, args.timeout)
    except Failure as failure:
        print(json.dumps({"state": "failure", "error": str(failure)}))
        return 1
    print(json.dumps(report))
    return 0 if report["state"] == "rendered" else 1


if __name__ == "__main__":
    sys.exit(main())
