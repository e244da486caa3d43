"""The repository's one client of the Chrome DevTools protocol: headless Chromium spoken to over a pipe.

Chromium runs with --remote-debugging-pipe (JSON messages ended by NUL on file descriptors 3 and 4), so
only the Python standard library and Debian's chromium are needed. A local static server on 127.0.0.1
(a free port) serves the pages, and every other host name resolves to "not found": a page that reaches
for the network fails loudly.

Used by the site's browser tests (site/tests/browser_test.py, live_test.py, axe_test.py, keyboard_test.py,
weight_test.py; lighthouse_audit.py for its server), the web stages' tests
(tests/web/web_test.py, through web_page.py), the site build's first-frame measurement
(tools/build_site/measure_web.py), make web-serve (web_page.py), the GLSL ES translations' browser
test (tests/unit/test_glsl_es_browser.cpp, through page_value.py) and the dev container's noVNC
screenshot (tools/devcontainer_check/novnc_screenshot.py, a page the container serves itself). Each
imports it as `web.cdp`, with tools/ on PYTHONPATH (tools/web/__init__.py).
"""
import base64
import contextlib
import functools
import gzip
import http.server
import io
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


def run_main(main, prefix="FAIL: "):
    """A script's end: exits with main()'s status (None: 0), or prints a Failure after `prefix` on
    stderr and exits 1."""
    try:
        sys.exit(main())
    except Failure as e:
        print(f"{prefix}{e}", file=sys.stderr)
        sys.exit(1)


# How Chromium draws WebGL 2 without a usable GPU, by ANGLE backend. llvmpipe: ANGLE's GL ES backend
# on Mesa (EGL surfaceless), the rasteriser the goldens were rendered with. swiftshader: Chromium's own
# software renderer, what a reader's browser falls back to (it has no EXT_texture_norm16).
RENDERERS = {
    "llvmpipe": ("--use-angle=gl-egl", "--ignore-gpu-blocklist"),
    "swiftshader": ("--use-angle=swiftshader", "--enable-unsafe-swiftshader"),
}


class QuietHandler(http.server.SimpleHTTPRequestHandler):
    # WebAssembly streams only with its own MIME type; Python's table may lack it.
    extensions_map = {**http.server.SimpleHTTPRequestHandler.extensions_map, ".wasm": "application/wasm"}

    def log_message(self, fmt, *args):
        pass


class GzipHandler(QuietHandler):
    """QuietHandler that sends text (HTML, CSS, JavaScript, JSON, SVG) gzip-compressed to a client that
    accepts it, as the hosts a course site is published on do (GitHub Pages, a university's web server):
    a page's cost measured uncompressed is not what a reader pays."""
    TEXT = (".html", ".css", ".js", ".json", ".svg", ".txt", ".map")

    def send_head(self):
        path = self.translate_path(self.path)
        if os.path.isdir(path):
            path = os.path.join(path, "index.html")
        if ("gzip" not in self.headers.get("Accept-Encoding", "") or not path.endswith(self.TEXT)
                or not os.path.isfile(path)):
            return super().send_head()
        with open(path, "rb") as f:
            body = gzip.compress(f.read(), compresslevel=6)
        self.send_response(200)
        self.send_header("Content-Type", self.guess_type(path))
        self.send_header("Content-Encoding", "gzip")
        self.send_header("Content-Length", str(len(body)))
        self.end_headers()
        return io.BytesIO(body)


def start_server(root, port=0, compress=False):
    """A static server of `root` on 127.0.0.1 (port 0: a free one), in a daemon thread; with `compress`,
    text goes out gzip-compressed (GzipHandler)."""
    handler = GzipHandler if compress else QuietHandler
    server = http.server.ThreadingHTTPServer(("127.0.0.1", port), functools.partial(handler, directory=root))
    server.daemon_threads = True
    threading.Thread(target=server.serve_forever, kwargs={"poll_interval": 0.1}, daemon=True).start()
    return server


@contextlib.contextmanager
def serving(root):
    """start_server(root) for the block: yields its base URL (with a trailing /), then ends it."""
    server = start_server(root)
    try:
        yield f"http://127.0.0.1:{server.server_address[1]}/"
    finally:
        server.shutdown()
        server.server_close()


def seconds_left(deadline):
    """Seconds until `deadline` (time.monotonic(); None: no limit); Failure once it has passed."""
    if deadline is None:
        return float("inf")
    left = deadline - time.monotonic()
    if left <= 0:
        raise Failure("time limit reached")
    return left


def end_group(proc, wait=3):
    """Ends `proc` and every process in its group (started with start_new_session), by group id: TERM,
    then KILL for any helper that outlives it."""
    for sig in (signal.SIGTERM, signal.SIGKILL):
        try:
            os.killpg(proc.pid, sig)
        except ProcessLookupError:
            return
        try:
            proc.wait(timeout=wait)
        except subprocess.TimeoutExpired:
            pass


def find_chromium():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


class Browser:
    """One headless Chromium. gpu_args: how it draws (RENDERERS' flags for WebGL; the default draws
    pages without WebGL). deadline (time.monotonic()) bounds every wait, when given."""

    def __init__(self, chromium, profile, log_path, deadline=None, gpu_args=("--disable-gpu",), window=(1280, 900)):
        self.deadline = deadline
        to_chrome_r, self.to_chrome = os.pipe()
        self.from_chrome, from_chrome_w = os.pipe()

        def child_fds():  # Chromium reads commands on fd 3 and writes replies on fd 4
            a, b = os.dup(to_chrome_r), os.dup(from_chrome_w)
            os.dup2(a, 3)
            os.dup2(b, 4)

        self.log = open(log_path, "w")
        args = [chromium, "--headless", "--no-sandbox", *gpu_args, "--remote-debugging-pipe",
                f"--user-data-dir={profile}", "--no-first-run", "--no-default-browser-check",
                "--disable-extensions", "--disable-background-networking", "--disable-component-update",
                "--disable-sync", "--disable-default-apps", "--disable-dev-shm-usage", "--mute-audio",
                "--hide-scrollbars", "--force-device-scale-factor=1", f"--window-size={window[0]},{window[1]}",
                # Everything but the local server is unreachable: a CDN link would fail loudly.
                "--host-resolver-rules=MAP * ~NOTFOUND , EXCLUDE 127.0.0.1",
                "about:blank"]
        # preexec_fn is not thread-safe: start the browser before the server's thread (browsing()).
        # Its own process group, so that it and all its helper processes can be ended together.
        self.proc = subprocess.Popen(args, stdin=subprocess.DEVNULL, stdout=self.log, stderr=self.log,
                                     preexec_fn=child_fds, close_fds=False, start_new_session=True)
        os.close(to_chrome_r)
        os.close(from_chrome_w)
        self.buffer = b""
        self.next_id = 0
        self.events = []

    def remaining(self):
        return seconds_left(self.deadline)

    def _read(self, timeout):
        ready, _, _ = select.select([self.from_chrome], [], [], timeout)
        if not ready:
            return False
        chunk = os.read(self.from_chrome, 1 << 20)
        if not chunk:
            raise Failure(f"chromium closed the DevTools pipe (exit code {self.proc.poll()}); see its log")
        self.buffer += chunk
        while b"\0" in self.buffer:
            raw, self.buffer = self.buffer.split(b"\0", 1)
            self.events.append(json.loads(raw))
        return True

    def send(self, method, params=None, session=None, timeout=30):
        self.next_id += 1
        message = {"id": self.next_id, "method": method, "params": params or {}}
        if session:
            message["sessionId"] = session
        data = json.dumps(message).encode() + b"\0"
        while data:
            data = data[os.write(self.to_chrome, data):]
        end = time.monotonic() + min(timeout, self.remaining())
        while True:
            for i, event in enumerate(self.events):
                if event.get("id") == self.next_id:
                    del self.events[i]
                    if "error" in event:
                        raise Failure(f"{method}: {event['error']}")
                    return event.get("result", {})
            if time.monotonic() > end:
                raise Failure(f"{method}: no reply within {timeout} s")
            self._read(0.1)

    def wait_event(self, method, session=None, timeout=30):
        end = time.monotonic() + min(timeout, self.remaining())
        while True:
            for i, event in enumerate(self.events):
                if event.get("method") == method and (session is None or event.get("sessionId") == session):
                    del self.events[i]
                    return event.get("params", {})
            if time.monotonic() > end:
                raise Failure(f"no {method} within {timeout} s")
            self._read(0.1)

    def drain(self):
        """The events (not replies) received so far, which are then forgotten."""
        while self._read(0):
            pass
        events, self.events = [e for e in self.events if "method" in e], [e for e in self.events if "id" in e]
        return events

    def close(self):
        try:
            if self.proc.poll() is None:
                try:
                    self.send("Browser.close", timeout=5)
                except Exception:
                    pass
                try:
                    self.proc.wait(timeout=5)
                except subprocess.TimeoutExpired:
                    pass
        finally:
            end_group(self.proc)  # whatever is left of it (helpers included)
            for fd in (self.to_chrome, self.from_chrome):
                try:
                    os.close(fd)
                except OSError:
                    pass
            self.log.close()


@contextlib.contextmanager
def browsing(root, chromium, log_path, deadline=None, gpu_args=("--disable-gpu",), window=(1280, 900)):
    """A Chromium (a fresh profile) and a local server of `root`: yields (browser, base URL with a
    trailing /); afterwards ends both and removes the profile. root None: no server (base URL None),
    for a page served by someone else on 127.0.0.1."""
    profile = tempfile.mkdtemp(prefix="t10-chromium-")
    browser = None
    try:
        browser = Browser(chromium, profile, log_path, deadline, gpu_args, window)
        with serving(root) if root is not None else contextlib.nullcontext() as base:
            yield browser, base
    finally:
        if browser:
            browser.close()
        shutil.rmtree(profile, ignore_errors=True)


def open_tab(browser, domains=("Page", "Runtime"), size=None, scripts=()):
    """A new tab on about:blank with the protocol's `domains` enabled, its viewport `size` (width,
    height) when given, and `scripts` run before each page's own; returns (target id, session id)."""
    target = browser.send("Target.createTarget", {"url": "about:blank"})["targetId"]
    session = browser.send("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
    for domain in domains:
        browser.send(f"{domain}.enable", {}, session)
    if size:
        browser.send("Emulation.setDeviceMetricsOverride",
                     {"width": size[0], "height": size[1], "deviceScaleFactor": 1, "mobile": False}, session)
    for script in scripts:
        browser.send("Page.addScriptToEvaluateOnNewDocument", {"source": script}, session)
    return target, session


def evaluate(browser, session, expression, await_promise=False, timeout=60):
    """The value of a JavaScript expression in the tab (a promise's, with await_promise)."""
    result = browser.send("Runtime.evaluate", {"expression": expression, "returnByValue": True,
                                               "awaitPromise": await_promise}, session, timeout=timeout)
    if "exceptionDetails" in result:
        details = result["exceptionDetails"]
        raise Failure(f"script error: {details.get('exception', {}).get('description') or details.get('text')}")
    return result["result"].get("value")


def wait_until(read, done, timeout, what, describe=lambda value: "", interval=0.1):
    """Calls read() until done(its value) holds and returns that value. After `timeout` seconds raises
    Failure("<what> within <timeout> s") followed by describe(the last value)."""
    end = time.monotonic() + timeout
    while True:
        value = read()
        if done(value):
            return value
        if time.monotonic() > end:
            raise Failure(f"{what} within {timeout:.0f} s{describe(value)}")
        time.sleep(interval)


def screenshot(browser, session, path, clip=None, timeout=90):
    """The viewport, or the page's region `clip` ({x, y, width, height} in page pixels), as a PNG, or
    as a JPEG (quality 85) where `path` ends in .jpg or .jpeg: Chromium encodes a 1280x32000 page in
    about 1 s as a JPEG and 3-4 s as a PNG, on one core."""
    jpeg = path.lower().endswith((".jpg", ".jpeg"))
    params = {"format": "jpeg", "quality": 85} if jpeg else {"format": "png"}
    params["fromSurface"] = True
    if clip:
        params["clip"] = dict(clip, scale=1)
    shot = browser.send("Page.captureScreenshot", params, session, timeout=timeout)
    with open(path, "wb") as f:
        f.write(base64.b64decode(shot["data"]))


def full_page_screenshot(browser, session, path, width, view_height=900):
    """The whole page as a PNG or JPEG (by `path`, as screenshot()): the viewport is made as tall as the
    page for the capture (sticky and viewport-sized elements then render as in one tall window), then
    restored. Returns the height."""
    metrics = browser.send("Page.getLayoutMetrics", {}, session)
    height = int(metrics["cssContentSize"]["height"])
    browser.send("Emulation.setDeviceMetricsOverride",
                 {"width": width, "height": height, "deviceScaleFactor": 1, "mobile": False}, session)
    try:
        screenshot(browser, session, path, {"x": 0, "y": 0, "width": width, "height": height}, timeout=60)
    finally:
        browser.send("Emulation.setDeviceMetricsOverride",
                     {"width": width, "height": view_height, "deviceScaleFactor": 1, "mobile": False}, session)
    return height
