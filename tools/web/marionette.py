"""The repository's Firefox client: Firefox ESR on its own Xvfb display, spoken to over Marionette.

Marionette is the remote protocol Firefox itself serves (started with --marionette): JSON over a local
TCP socket, each message prefixed by its length in bytes and a colon; a command is
[0, id, name, parameters] and its reply [1, id, error, result]. geckodriver translates WebDriver to
exactly this, so without it (Debian ships none) only the standard library and Debian's firefox-esr
and xvfb are needed. The port is a free one that Firefox picks (marionette.port 0) and writes to
MarionetteActivePort in its profile.

A display, because headless Firefox on Mesa has no WebGL here, while Firefox under Xvfb draws WebGL 2
with llvmpipe. Xvfb picks a free display number (-displayfd). Pages come from cdp.py's local static
server; every other host goes to a proxy that refuses (a page reaching for the network fails loudly).

Used by the web stages' Firefox test (tests/web/web_test.py, through web_page.py's FirefoxStagePage).
"""
import base64
import contextlib
import json
import os
import select
import shutil
import socket
import struct
import subprocess
import tempfile
import time

from web.cdp import Failure, end_group, seconds_left, serving

# Written to the profile's user.js. Marionette adds its own recommended preferences (no updates, no
# telemetry, no first-run pages) when it starts.
PREFERENCES = {
    "marionette.port": 0,                        # a free port, written to MarionetteActivePort
    "webgl.force-enabled": True,                 # llvmpipe is a software GL that Firefox may blocklist
    "devtools.console.stdout.content": True,     # the page's console (and script errors) in the log
    "layout.css.devPixelsPerPx": "1.0",          # one canvas pixel per screen pixel, as in Chromium
    "network.proxy.type": 1,                     # everything but 127.0.0.1 (never proxied: Firefox's
    "network.proxy.http": "127.0.0.1",           # network.proxy.allow_hijacking_localhost is false)
    "network.proxy.http_port": 9,                # goes to the discard port, which nothing serves
    "network.proxy.ssl": "127.0.0.1",
    "network.proxy.ssl_port": 9,
    "network.proxy.share_proxy_settings": True,
    "browser.sessionstore.resume_from_crash": False,
}


def find_firefox():
    for name in ("firefox-esr", "firefox"):
        path = shutil.which(name)
        if path:
            return path
    return None


def start_xvfb(log, fbdir, size=(1920, 1200)):
    """An Xvfb on a free display number, its screen kept in fbdir/Xvfb_screen0 (an XWD image); returns
    (process, DISPLAY)."""
    read_fd, write_fd = os.pipe()
    proc = subprocess.Popen(["Xvfb", "-displayfd", str(write_fd), "-screen", "0", f"{size[0]}x{size[1]}x24",
                             "-nolisten", "tcp", "-noreset", "-fbdir", fbdir],
                            stdin=subprocess.DEVNULL, stdout=log, stderr=log, pass_fds=(write_fd,),
                            start_new_session=True)
    os.close(write_fd)
    number = b""
    try:
        while not number.endswith(b"\n"):
            # Xvfb writes the number once it accepts connections.
            chunk = os.read(read_fd, 16) if select.select([read_fd], [], [], 30)[0] else b""
            if not chunk:
                end_group(proc)
                raise Failure(f"Xvfb opened no display within 30 s (exit code {proc.poll()}); see its log")
            number += chunk
    finally:
        os.close(read_fd)
    return proc, ":" + number.decode().strip()


def write_screen_png(xwd_path, png_path, box):
    """The region box (x, y, width, height) of an Xvfb screen file (XWD, 32-bit pixels) as an RGB PNG."""
    from web.web_page import write_png  # the one PNG writer (web_page imports this module)
    with open(xwd_path, "rb") as f:
        data = f.read()
    header = struct.unpack(">25I", data[:100])
    header_size, width, height, byte_order, bits, stride, colours = (header[0], header[4], header[5], header[7],
                                                                       header[11], header[12], header[19])
    if bits != 32:
        raise Failure(f"{xwd_path}: {bits}-bit pixels, not 32")
    x, y = max(0, box[0]), max(0, box[1])
    w, h = min(box[2], width - x), min(box[3], height - y)
    if w <= 0 or h <= 0:
        raise Failure(f"the region {box} is not on the {width}x{height} screen")
    pixels = data[header_size + colours * 12:]
    red, green, blue = (2, 1, 0) if byte_order == 0 else (1, 2, 3)  # LSBFirst: B G R x; MSBFirst: x R G B
    rgba = bytearray()
    for row in range(y + h - 1, y - 1, -1):  # write_png takes the bottom row first
        line = pixels[row * stride + x * 4:row * stride + (x + w) * 4]
        out = bytearray(w * 4)
        out[0::4], out[1::4], out[2::4] = line[red::4], line[green::4], line[blue::4]
        rgba += out
    write_png(png_path, w, h, bytes(rgba))


class Firefox:
    """One Firefox (a fresh profile at `profile`) on its own Xvfb, with a Marionette session; its window
    `window` (width, height); `prefs`: more preferences. deadline (time.monotonic()) bounds every wait."""

    def __init__(self, firefox, profile, log_path, deadline=None, window=(1400, 1000), prefs=None):
        self.deadline = deadline
        self.log_path = log_path
        self.log = open(log_path, "w")
        self.sock = self.firefox = self.xvfb = None
        self.next_id = 0
        with open(os.path.join(profile, "user.js"), "w") as f:
            f.writelines(f"user_pref({json.dumps(k)}, {json.dumps(v)});\n"
                         for k, v in {**PREFERENCES, **(prefs or {})}.items())
        self.screen_file = os.path.join(profile, "Xvfb_screen0")
        try:
            self.xvfb, display = start_xvfb(self.log, profile)
            env = dict(os.environ, DISPLAY=display, MOZ_CRASHREPORTER_DISABLE="1")
            env.pop("WAYLAND_DISPLAY", None)
            args = [firefox, "--marionette", "--no-remote", "--profile", profile, "about:blank"]
            self.firefox = subprocess.Popen(args, stdin=subprocess.DEVNULL, stdout=self.log, stderr=self.log, env=env,
                                            start_new_session=True)
            port = self._wait_port(os.path.join(profile, "MarionetteActivePort"), min(60, self.remaining()))
            self.sock = socket.create_connection(("127.0.0.1", port), timeout=30)
            self.reader = self.sock.makefile("rb")
            hello = self._receive(30)
            if hello.get("marionetteProtocol") != 3:
                raise Failure(f"Firefox speaks Marionette protocol {hello.get('marionetteProtocol')}, not 3")
            self.send("WebDriver:NewSession", {"pageLoadStrategy": "normal"})
            self.send("WebDriver:SetWindowRect", {"x": 0, "y": 0, "width": window[0], "height": window[1]})
        except BaseException:
            self.close()
            raise

    def remaining(self):
        return seconds_left(self.deadline)

    def _wait_port(self, port_file, timeout):
        """The port Firefox's Marionette listens on, once it has written it to `port_file`."""
        end = time.monotonic() + timeout
        while True:
            try:
                with open(port_file) as f:
                    return int(f.read())
            except (FileNotFoundError, ValueError):  # not there yet, or not written whole yet
                pass
            if self.firefox.poll() is not None or time.monotonic() > end:
                raise Failure(f"Firefox did not start Marionette (exit code {self.firefox.poll()}); "
                              f"see {self.log_path}")
            time.sleep(0.05)

    def _receive(self, timeout):
        self.sock.settimeout(timeout)
        try:
            length = b""
            while not length.endswith(b":"):
                byte = self.reader.read(1)
                if not byte:
                    raise Failure(f"Firefox closed the Marionette connection (exit code {self.firefox.poll()}); "
                                  f"see {self.log_path}")
                length += byte
            return json.loads(self.reader.read(int(length[:-1])))
        except socket.timeout:
            raise Failure(f"no reply from Firefox within {timeout:.0f} s") from None

    def send(self, name, params=None, timeout=60):
        """The result of Marionette command `name`, or Failure with Firefox's error."""
        self.next_id += 1
        data = json.dumps([0, self.next_id, name, params or {}]).encode()
        self.sock.sendall(str(len(data)).encode() + b":" + data)
        while True:
            reply = self._receive(min(timeout, self.remaining()))
            if reply[0] == 1 and reply[1] == self.next_id:
                break
        if reply[2]:
            raise Failure(f"{name}: {reply[2].get('error')}: {reply[2].get('message')}")
        return reply[3]

    def evaluate(self, expression, timeout=60):
        """The value of a JavaScript expression in the page (a promise's value once it settles)."""
        return self.send("WebDriver:ExecuteScript", {"script": f"return ({expression});", "args": []},
                         timeout)["value"]

    def navigate(self, url, timeout=120):
        """Opens `url` and returns once it has loaded (its load event)."""
        self.send("WebDriver:Navigate", {"url": url}, timeout)

    def screenshot(self, path):
        """The whole page as a PNG, as Firefox draws it for WebDriver (a WebGL canvas in an iframe comes
        out black there: display_screenshot() shows one)."""
        shot = self.send("WebDriver:TakeScreenshot", {"full": True, "hash": False}, 90)["value"]
        with open(path, "wb") as f:
            f.write(base64.b64decode(shot))

    def display_screenshot(self, path, selector):
        """The first element that matches the CSS `selector`, scrolled into view, as the display shows it
        (Xvfb's screen), as a PNG."""
        box = self.evaluate(f"""new Promise(done => {{
            const e = document.querySelector({json.dumps(selector)});
            e.scrollIntoView();
            requestAnimationFrame(() => requestAnimationFrame(() => {{  // drawn after the scroll
              const r = e.getBoundingClientRect();
              done([mozInnerScreenX + r.left, mozInnerScreenY + r.top, r.width, r.height].map(Math.round));
            }}));
        }})""")
        time.sleep(0.3)  # the compositor presents the frame to the X server a moment later
        write_screen_png(self.screen_file, path, box)

    def log_lines(self):
        """Firefox's log so far (the page's console lines among its own), as text lines."""
        self.log.flush()
        with open(self.log_path, errors="replace") as f:
            return f.read().splitlines()

    def close(self):
        try:
            if self.sock:
                try:
                    self.send("Marionette:Quit", {"flags": ["eForceQuit"]}, timeout=10)
                except Exception:
                    pass
                self.sock.close()
            if self.firefox and self.firefox.poll() is None:
                try:
                    self.firefox.wait(timeout=10)
                except subprocess.TimeoutExpired:
                    pass
        finally:
            for proc in (self.firefox, self.xvfb):
                if proc:
                    end_group(proc)
            self.log.close()


@contextlib.contextmanager
def browsing(root, firefox, log_path, deadline=None, window=(1400, 1000), prefs=None):
    """A Firefox (a fresh profile, its own display) and a local server of `root`: yields (browser, base
    URL with a trailing /); afterwards ends both and removes the profile."""
    profile = tempfile.mkdtemp(prefix="t10-firefox-")
    browser = None
    try:
        browser = Firefox(firefox, profile, log_path, deadline, window, prefs)
        with serving(root) as base:
            yield browser, base
    finally:
        if browser:
            browser.close()
        shutil.rmtree(profile, ignore_errors=True)
