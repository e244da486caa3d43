#!/usr/bin/env python3
"""Loads a web stage's page (make web) in headless Chromium and reports what the page reports.

The page's interface (common/platform/web/index.html.in): document.body.dataset.t10 becomes
"rendered" or "error" (the message in #t10-error), dataset.t10Frames counts the frames drawn, and the
canvas keeps its pixels. This script serves --root on 127.0.0.1 (a free port), opens --page (a path
under --root with its query, e.g. "tutorial10_part0_start/index.html?size=640x360&frames=1"), waits
for rendered or error, runs each --eval expression in order (each may return a promise; after each
that changes a setting, the page is waited on again), and prints one JSON object: state, error,
frames, firstFrameMs, the evals' results; --png FILE writes the frame as an RGB PNG, read with
gl.readPixels as the binaries' --output reads it.
Exit status: 0 rendered, 1 error or a time-out, 2 bad usage.

Chromium drives WebGL 2 through SwiftShader here (no GPU): --use-angle=swiftshader with
--enable-unsafe-swiftshader (T10_CHROMIUM_FLAGS adds flags). The DevTools client is cdp.py, beside
this file. Importable: StagePage is one tab on the stages' pages, which the web stages' tests
(tests/web/web_test.py) drive; render_page() is this script's report.
"""
import argparse
import base64
import contextlib
import json
import os
import struct
import sys
import tempfile
import time
import zlib

sys.dont_write_bytecode = True
from web import cdp  # noqa: E402  (the DevTools client; tools/ on PYTHONPATH)

Failure = cdp.Failure

# Records when the page's state changes, before any of the page's own scripts run.
WATCH_STATE = r"""
(() => {
  window.__t10States = [];
  new MutationObserver(() => {
    const state = document.body && document.body.dataset.t10;
    const last = window.__t10States[window.__t10States.length - 1];
    if (state && (!last || last.state !== state)) window.__t10States.push({state, at: performance.now()});
  }).observe(document, {attributes: true, subtree: true, attributeFilter: ['data-t10']});
})();
"""

# The canvas' drawing buffer as --output reads it: glReadPixels of the default framebuffer (bottom
# row first), RGBA bytes in base64. The page keeps it (preserveDrawingBuffer).
READ_PIXELS = r"""
(() => {
  const canvas = document.getElementById('canvas');
  const gl = canvas.getContext('webgl2');
  if (!gl) return JSON.stringify({error: 'the canvas has no WebGL2 context'});
  const framebuffer = gl.getParameter(gl.READ_FRAMEBUFFER_BINDING);
  const packBuffer = gl.getParameter(gl.PIXEL_PACK_BUFFER_BINDING);
  gl.bindFramebuffer(gl.READ_FRAMEBUFFER, null);
  gl.bindBuffer(gl.PIXEL_PACK_BUFFER, null);
  const w = gl.drawingBufferWidth, h = gl.drawingBufferHeight;
  const pixels = new Uint8Array(w * h * 4);
  gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
  const error = gl.getError();
  gl.bindFramebuffer(gl.READ_FRAMEBUFFER, framebuffer);
  gl.bindBuffer(gl.PIXEL_PACK_BUFFER, packBuffer);
  let text = '';
  for (let i = 0; i < pixels.length; i += 0x8000) text += String.fromCharCode.apply(null, pixels.subarray(i, i + 0x8000));
  return JSON.stringify({width: w, height: h, glError: error, data: btoa(text)});
})()
"""

PAGE_STATE = r"""JSON.stringify({state: document.body ? document.body.dataset.t10 || '' : '',
  frames: document.body ? document.body.dataset.t10Frames || '' : '',
  verdict: document.body ? document.body.dataset.t10Verdict || '' : '',
  error: (document.getElementById('t10-error') || {}).textContent || '',
  states: window.__t10States || []})"""


def write_png(path, width, height, rgba_bottom_first):
    """An 8-bit RGB PNG, top row first, from RGBA rows bottom first (alpha dropped, as --output)."""
    rows = []
    stride = width * 4
    for y in range(height - 1, -1, -1):
        row = rgba_bottom_first[y * stride:(y + 1) * stride]
        rgb = bytearray(width * 3)
        rgb[0::3], rgb[1::3], rgb[2::3] = row[0::4], row[1::4], row[2::4]
        rows.append(b"\0" + bytes(rgb))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
           chunk(b"IDAT", zlib.compress(b"".join(rows), 6)) + chunk(b"IEND", b""))
    with open(path + ".tmp", "wb") as f:
        f.write(png)
    os.replace(path + ".tmp", path)


class StagePage:
    """One Chromium with one tab (size: its viewport) on a local server over `root` (out/web);
    scripts run before each page's own. Ends with close()."""

    def __init__(self, root, chromium, log_path, gpu_args, deadline=None, scripts=(), size=(1400, 1000)):
        self.size = size
        self._stack = contextlib.ExitStack()
        try:
            self.browser, self.base = self._stack.enter_context(
                cdp.browsing(root, chromium, log_path, deadline, gpu_args, size))
            _, self.session = cdp.open_tab(self.browser, ("Page", "Runtime", "Log", "Network"), size,
                                           (WATCH_STATE,) + tuple(scripts))
        except BaseException:
            self._stack.close()
            raise

    def close(self):
        self._stack.close()

    def evaluate(self, expression, await_promise=False):
        return cdp.evaluate(self.browser, self.session, expression, await_promise)

    def state(self):
        """state (dataset.t10), frames, verdict, error (#t10-error) and states (WATCH_STATE's record)."""
        return json.loads(self.evaluate(PAGE_STATE))

    def open(self, path):
        """Opens `path` (below the root, with its query); returns its URL."""
        url = self.base + path
        self.browser.send("Page.navigate", {"url": url}, self.session)
        return url

    def wait(self, done, what, timeout):
        return cdp.wait_until(self.state, done, timeout, what,
                              lambda s: f"; the page says state={s['state']!r} frames={s['frames']!r} "
                                        f"error={s['error']!r}{self.problems()}")

    def settled(self, timeout):
        return self.wait(lambda s: s["state"] in ("rendered", "error"), "no 'rendered' or 'error'", timeout)

    def problems(self):
        """Script errors and console errors so far, for a failure message."""
        found = []
        for event in self.browser.drain():
            method, params = event.get("method"), event.get("params", {})
            if method == "Runtime.exceptionThrown":
                found.append("script error: " + params["exceptionDetails"].get("exception", {}).get(
                    "description", params["exceptionDetails"].get("text", "")))
            elif method == "Log.entryAdded" and params["entry"]["level"] == "error" and \
                    not params["entry"].get("url", "").endswith("/favicon.ico"):  # Chromium asks for it by itself
                found.append("console: " + params["entry"].get("text", ""))
            elif method == "Log.entryAdded" and "WebGL" in params["entry"].get("text", "")[:40]:
                found.append("WebGL: " + params["entry"].get("text", ""))  # which call a GL error came from
            elif method == "Runtime.consoleAPICalled" and params.get("type") == "error":
                found.append("console: " + " ".join(str(a.get("value", a.get("description", "")))
                                                    for a in params.get("args", [])))
        return "".join(f"\n  {line[:400]}" for line in found[:10])

    def capture(self, path):
        """The frame as --output writes it (an RGB PNG at `path`); returns (width, height)."""
        frame = json.loads(self.evaluate(READ_PIXELS))
        if "error" in frame:
            raise Failure(frame["error"])
        if frame["glError"]:
            raise Failure(f"gl.readPixels failed: GL error 0x{frame['glError']:04x}")
        write_png(path, frame["width"], frame["height"], base64.b64decode(frame["data"]))
        return frame["width"], frame["height"]

    def screenshot(self, path):
        """The whole page, as a reader scrolling it would see it."""
        cdp.full_page_screenshot(self.browser, self.session, path, self.size[0], self.size[1])


def console_lines(events):
    """The page's console lines and the browser's log entries (WebGL's warnings) among `events`."""
    lines = []
    for event in events:
        params = event.get("params", {})
        if event.get("method") == "Runtime.consoleAPICalled":
            lines.append(" ".join(str(a.get("value", a.get("description", ""))) for a in params.get("args", [])))
        elif event.get("method") == "Log.entryAdded":
            lines.append(params.get("entry", {}).get("text", ""))
    return lines


def render_page(root, page, evals=(), png=None, timeout=120, chromium=None):
    """Serves `root`, loads `page` and returns the page's report (see the module's text)."""
    chromium = chromium or cdp.find_chromium()
    if not chromium:
        raise Failure("no chromium found (Debian package chromium)")
    gpu_args = cdp.RENDERERS["swiftshader"] + ("--ignore-gpu-blocklist",) + tuple(
        os.environ.get("T10_CHROMIUM_FLAGS", "").split())

    def drawn(frames_above):  # "error", or "rendered" with more than frames_above frames
        return lambda s: s["state"] == "error" or (s["state"] == "rendered" and int(s["frames"] or 0) > frames_above)

    with tempfile.TemporaryDirectory(prefix="t10-web-") as scratch:
        tab = StagePage(root, chromium, os.path.join(scratch, "chromium.log"), gpu_args, size=(1280, 900))
        try:
            started = time.monotonic()
            tab.open(page)
            state = tab.wait(drawn(-1), "the page was not rendered", timeout)
            report = {"wallMs": round((time.monotonic() - started) * 1000)}
            results = []
            for expression in evals:
                if state["state"] != "rendered":
                    break
                frames = int(tab.state()["frames"] or 0)
                results.append(tab.evaluate(expression, await_promise=True))
                # A setting applied redraws: wait for the frame after it.
                if tab.state()["state"] != "rendered":
                    state = tab.wait(drawn(frames), "the page was not rendered", timeout)
            final = tab.state()
            report.update(state=state["state"], evals=results, error=final["error"],
                          frames=int(final["frames"] or 0),
                          firstFrameMs=tab.evaluate("window.Module && Module.t10FirstFrameMs"),
                          console=console_lines(tab.browser.drain()))
            if png and state["state"] == "rendered":
                tab.capture(png)
            return report
        finally:
            tab.close()


def serve_forever(root, port):
    """make web-serve: the static server alone, until Ctrl-C."""
    try:
        server = cdp.start_server(root, port)
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
    parser.add_argument("--png", help="write the frame here once rendered")
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
