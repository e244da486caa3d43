#!/usr/bin/env python3
"""The web stages (make web, out/web/<stage>/index.html) driven in headless Chromium like the binaries.

usage: web_test.py COMMAND --web OUT_WEB --out DIR [options]

Chromium is driven over the DevTools protocol (site/tests/browser_test.py's Browser: a pipe, a local
server on 127.0.0.1, nothing else reachable). A page is loaded with the command line as its query
(?size=640x360&camera=default&frames=1, the goldens' settings), and the test waits for
document.body.dataset.t10 to become "rendered" or "error" (the page's interface, WEB_CONTRACT.md).
The frame is read with gl.readPixels from the default framebuffer, as --output reads it, and written
as an RGB PNG; the project's imgcompare judges it, so the metric is the golden tests' own.

Commands:
  golden   --stage S --golden G [--reject R ...] [--query Q]: S's frame matches tests/golden/G.png under
           --tolerance, and does NOT match each R.png (the neighbouring part: the test can fail).
  live     --stage S --golden G --set NAME=VALUE --then GOLDEN [--reject R ...]: the frame matches G, then
           Module.t10Set(NAME, VALUE) redraws it (t10Frames grows) and it matches GOLDEN, rejects each R.
  nofloat  --stage S: with EXT_color_buffer_float hidden from the page (a script run before the page's
           own, so getExtension returns null as in a browser without float render targets) the page
           ends in "error" and shows the message, and draws no frame.
  compare  --stage S --expect pass|fail: S's ?compare=1 page sets dataset.t10Verdict to the expected verdict.

--renderer: llvmpipe (ANGLE on Mesa's GL ES: the goldens' rasteriser, with EXT_texture_norm16 for the
stages' GL_R16 key) or swiftshader (ANGLE on SwiftShader; it has no EXT_texture_norm16).
Exit 0: passed; 1: failed (what and why on stderr); 77: cannot run here (no such page), said why.
"""
import argparse
import base64
import json
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import time
import zlib

sys.dont_write_bytecode = True
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "site", "tests"))
import browser_test  # noqa: E402  (the site's DevTools driver: Browser, start_server, evaluate)

Failure = browser_test.Failure
GOLDEN_QUERY = "size=640x360&camera=default&frames=1"  # tests/golden/render_args.sh, as a query
RENDERERS = {
    # ANGLE's GL ES backend on Mesa (EGL surfaceless): llvmpipe, as the goldens were rendered.
    "llvmpipe": ("--use-angle=gl-egl", "--ignore-gpu-blocklist"),
    "swiftshader": ("--use-angle=swiftshader", "--enable-unsafe-swiftshader"),
}

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

# A browser without float render targets: the extensions are hidden from the page, so they are
# never enabled and an RGBA16F colour attachment stays incomplete, as there.
NO_FLOAT_TARGETS = r"""
(() => {
  const hidden = /^EXT_color_buffer_(half_)?float$/;
  for (const type of [window.WebGL2RenderingContext, window.WebGLRenderingContext]) {
    if (!type) continue;
    const get = type.prototype.getExtension;
    type.prototype.getExtension = function (name) { return hidden.test(name) ? null : get.call(this, name); };
    const list = type.prototype.getSupportedExtensions;
    type.prototype.getSupportedExtensions = function () {
      const names = list.call(this);
      return names && names.filter(name => !hidden.test(name));
    };
  }
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


class Page:
    """One Chromium with one tab on a local server over out/web."""

    def __init__(self, args, scripts=()):
        self.args = args
        self.profile = tempfile.mkdtemp(prefix="t10-web-")
        self.browser = self.server = None
        deadline = time.monotonic() + args.timeout
        self.browser = browser_test.Browser(args.chromium, self.profile, os.path.join(args.out, "chromium.log"),
                                            deadline, gpu_args=RENDERERS[args.renderer])
        self.server = browser_test.start_server(args.web)
        self.base = f"http://127.0.0.1:{self.server.server_address[1]}/"
        target = self.browser.send("Target.createTarget", {"url": "about:blank"})["targetId"]
        self.session = self.browser.send("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
        for domain in ("Page", "Runtime", "Log", "Network"):
            self.browser.send(f"{domain}.enable", {}, self.session)
        self.browser.send("Emulation.setDeviceMetricsOverride",
                          {"width": 1400, "height": 1000, "deviceScaleFactor": 1, "mobile": False}, self.session)
        for script in (WATCH_STATE,) + tuple(scripts):
            self.browser.send("Page.addScriptToEvaluateOnNewDocument", {"source": script}, self.session)

    def close(self):
        try:
            if self.browser:
                self.browser.close()
        finally:
            if self.server:
                self.server.shutdown()
                self.server.server_close()
            shutil.rmtree(self.profile, ignore_errors=True)

    def evaluate(self, expression, await_promise=False):
        return browser_test.evaluate(self.browser, self.session, expression, await_promise)

    def state(self):
        return json.loads(self.evaluate(PAGE_STATE))

    def open(self, stage, query):
        url = f"{self.base}{stage}/index.html?{query}"
        print(f"loading {url} ({self.args.renderer})", flush=True)
        self.browser.send("Page.navigate", {"url": url}, self.session)

    def wait(self, done, what, timeout):
        end = time.monotonic() + timeout
        while True:
            state = self.state()
            if done(state):
                return state
            if time.monotonic() > end:
                raise Failure(f"{what} within {timeout:.0f} s; the page says state={state['state']!r} "
                              f"frames={state['frames']!r} error={state['error']!r}{self.problems()}")
            time.sleep(0.1)

    def settled(self, timeout=None):
        return self.wait(lambda s: s["state"] in ("rendered", "error"), "no 'rendered' or 'error'",
                         timeout or self.args.timeout * 0.8)

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
        frame = json.loads(self.evaluate(READ_PIXELS))
        if "error" in frame:
            raise Failure(frame["error"])
        if frame["glError"]:
            raise Failure(f"gl.readPixels failed: GL error 0x{frame['glError']:04x}")
        write_png(path, frame["width"], frame["height"], base64.b64decode(frame["data"]))
        return frame["width"], frame["height"]

    def screenshot(self, path):
        """The whole page, as a reader scrolling it would see it."""
        browser_test.screenshot(self.browser, self.session, path, 1400, 1000)


def page_folder(args, stage):
    folder = os.path.join(args.web, stage)
    if not os.path.isfile(os.path.join(folder, "index.html")):
        print(f"SKIP: {folder}/index.html does not exist: build it with make web"
              f"{' STAGE=' + stage if stage.startswith('student_') else ''}", file=sys.stderr)
        sys.exit(77)
    return folder


def download_size(folder):
    return sum(os.path.getsize(os.path.join(folder, name)) for name in os.listdir(folder)
               if os.path.isfile(os.path.join(folder, name)))


def judge(args, actual, golden, reject):
    """imgcompare: `actual` matches golden.png and each reject.png is told apart from it."""
    tolerance = args.tolerance
    golden_png = os.path.join(args.goldens, golden + ".png")
    stem = os.path.splitext(actual)[0]
    result = subprocess.run([args.imgcompare, golden_png, actual, tolerance, "--diff-prefix", stem],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    print(result.stdout.strip(), flush=True)
    if result.returncode != 0:
        raise Failure(f"the frame differs from {golden}.png beyond {os.path.basename(tolerance)} "
                      f"(imgcompare exit {result.returncode}; the frame and heat-map: {stem}.actual.png, {stem}.diff.png)")
    for other in reject:
        result = subprocess.run([args.imgcompare, os.path.join(args.goldens, other + ".png"), actual, tolerance,
                                 "--expect-reject"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        print(result.stdout.strip(), flush=True)
        if result.returncode != 0:
            raise Failure(f"the tolerance cannot tell this frame from {other}.png: the comparison proves nothing")


def rendered(page, stage):
    state = page.settled()
    if state["state"] != "rendered":
        raise Failure(f"{stage} ended in {state['state']!r}: {state['error']!r}{page.problems()}")
    first = next((s["at"] for s in state["states"] if s["state"] == "rendered"), None)
    return state, first


def run_golden(args, page):
    folder = page_folder(args, args.stage)
    page.open(args.stage, "&".join(q for q in (GOLDEN_QUERY, args.query) if q))
    _, first = rendered(page, args.stage)
    actual = os.path.join(args.out, f"{args.name or args.stage}.png")
    width, height = page.capture(actual)
    print(f"{args.stage}: {width}x{height}, rendered {first / 1000:.2f} s after navigation started; "
          f"download {download_size(folder) / 1e6:.2f} MB (uncompressed)", flush=True)
    judge(args, actual, args.golden, args.reject)


def run_live(args, page):
    page_folder(args, args.stage)
    page.open(args.stage, GOLDEN_QUERY)
    state, _ = rendered(page, args.stage)
    before = os.path.join(args.out, f"{args.stage}-live-before.png")
    page.capture(before)
    judge(args, before, args.golden, [])
    name, _, value = args.set.partition("=")
    message = page.evaluate(f"Module.t10Set({json.dumps(name)}, {json.dumps(value)})")
    if message:
        raise Failure(f"Module.t10Set({name!r}, {value!r}) refused: {message}")
    frames = state["frames"]
    state = page.wait(lambda s: s["frames"] != frames and s["state"] in ("rendered", "error"),
                      f"no new frame after t10Set({name!r}, {value!r})", args.timeout * 0.5)
    if state["state"] != "rendered":
        raise Failure(f"after t10Set the page ended in {state['state']!r}: {state['error']!r}")
    after = os.path.join(args.out, f"{args.stage}-live-{name}-{value}.png")
    page.capture(after)
    judge(args, after, args.then, args.reject)


def run_nofloat(args, page):
    page_folder(args, args.stage)
    page.open(args.stage, GOLDEN_QUERY)
    state = page.settled()
    shot = os.path.join(args.out, f"{args.stage}-nofloat.png")
    page.screenshot(shot)
    print(f"state {state['state']!r}, message {state['error']!r}; screenshot {shot}", flush=True)
    if state["state"] != "error":
        raise Failure(f"without EXT_color_buffer_float the page reached {state['state']!r}, not 'error'")
    if "EXT_color_buffer_float" not in state["error"] and "float" not in state["error"].lower():
        raise Failure(f"the message does not say that float render targets are missing: {state['error']!r}")
    shown = page.evaluate("(() => { const e = document.getElementById('t10-error');"
                          " const r = e.getBoundingClientRect(); const s = getComputedStyle(e);"
                          " return r.width > 0 && r.height > 0 && s.visibility !== 'hidden' && s.display !== 'none'; })()")
    if not shown:
        raise Failure("the message is in the page but not shown (#t10-error has no size or is hidden)")
    if state["frames"] not in ("", "0"):
        raise Failure(f"the page drew {state['frames']} frame(s) without float render targets")


def run_compare(args, page):
    page_folder(args, args.stage)
    page.open(args.stage, "compare=1&" + GOLDEN_QUERY)
    state = page.wait(lambda s: s["verdict"] in ("pass", "fail"), "no verdict (dataset.t10Verdict)", args.timeout * 0.8)
    shot = os.path.join(args.out, f"{args.stage}-compare.png")
    page.screenshot(shot)
    text = page.evaluate("(document.getElementById('t10-verdict') || {}).textContent || ''")
    figures = page.evaluate("(document.getElementById('t10-compare-figures') || {}).textContent || ''")
    print(f"{args.stage}: verdict {state['verdict']!r}: {text}\n  {figures}\n  screenshot {shot}", flush=True)
    if state["verdict"] != args.expect:
        raise Failure(f"the compare page's verdict is {state['verdict']!r}, expected {args.expect!r}: {text}"
                      f"{page.problems()}")
    if args.expect == "fail" and "beyond" not in text:
        raise Failure(f"the verdict is fail, but not from the comparison: {text}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("command", choices=["golden", "live", "nofloat", "compare"])
    ap.add_argument("--web", required=True, help="the built pages (out/web)")
    ap.add_argument("--out", required=True, help="folder for frames, screenshots and Chromium's log")
    ap.add_argument("--stage", required=True)
    ap.add_argument("--name", help="file name for the frame (default: the stage)")
    ap.add_argument("--query", default="", help="more query parameters (the stage's options)")
    ap.add_argument("--golden", help="the golden the frame must match (a stage name)")
    ap.add_argument("--reject", action="append", default=[], help="a golden the frame must not match")
    ap.add_argument("--set", help="NAME=VALUE for Module.t10Set (live)")
    ap.add_argument("--then", help="the golden after --set (live)")
    ap.add_argument("--expect", choices=["pass", "fail"], help="the compare page's verdict (compare)")
    ap.add_argument("--goldens", default=os.path.join(HERE, "..", "golden"))
    ap.add_argument("--tolerance", default=os.path.join(HERE, "..", "golden", "web.tolerance"))
    ap.add_argument("--imgcompare", help="the project's imgcompare program")
    ap.add_argument("--chromium", default="chromium")
    ap.add_argument("--renderer", choices=sorted(RENDERERS), default="llvmpipe")
    ap.add_argument("--timeout", type=float, default=120, help="seconds for the whole test")
    args = ap.parse_args()
    if args.command in ("golden", "live") and not (args.golden and args.imgcompare):
        ap.error(f"{args.command} needs --golden and --imgcompare")
    if args.command == "live" and not (args.set and args.then and "=" in args.set):
        ap.error("live needs --set NAME=VALUE and --then GOLDEN")
    if args.command == "compare" and not args.expect:
        ap.error("compare needs --expect pass|fail")
    if not shutil.which(args.chromium):
        print(f"SKIP: {args.chromium}: not found (apt-get install chromium)", file=sys.stderr)
        return 77
    os.makedirs(args.out, exist_ok=True)
    page_folder(args, args.stage)
    page = Page(args, scripts=(NO_FLOAT_TARGETS,) if args.command == "nofloat" else ())
    try:
        {"golden": run_golden, "live": run_live, "nofloat": run_nofloat, "compare": run_compare}[args.command](args, page)
    finally:
        page.close()
    print("ok")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except Failure as e:
        print(f"FAIL: {e}", file=sys.stderr)
        sys.exit(1)
