#!/usr/bin/env python3
"""Measures the web stages (make web: out/web/<stage>/) for the site: the time from opening each
stage's page to its first drawn frame (document.body.dataset.t10 turning "rendered", read with a
MutationObserver installed before the page's own scripts; the page sets it after a one-pixel readback
of the frame, so the time includes the GPU's drawing, not only the calls that queue it: issue 50), in headless Chromium drawing WebGL2 with
ANGLE on SwiftShader (Chromium's software renderer), served from 127.0.0.1 with the browser cache
off; the median of --runs loads per stage.
Writes a JSON file that build_site.py reads (web_stages.py) and prints one line per stage.

Each stage's entry carries a fingerprint of its files, so the site states a time only for the files
that were measured. Where there are no web stages it says so and writes nothing (exit 0); a stage
whose page reports an error, or draws nothing in time, fails the measurement (exit 1).

  measure_web.py --web out/web --stages a,b,c --out build/site-web/measurements.json [--chromium chromium]
"""

import argparse
import json
import os
import platform
import shutil
import statistics
import sys
import time

sys.dont_write_bytecode = True
import web_stages  # noqa: E402  (beside this script)
from web import cdp  # noqa: E402  (the DevTools client; tools/ on PYTHONPATH)
from web.cdp import Failure, evaluate  # noqa: E402

# WebGL2 as Chromium draws it without a usable GPU: ANGLE on SwiftShader, its own software renderer
# (what a reader's browser falls back to; no EXT_texture_norm16, so the pages emulate GL_R16).
WEBGL_ARGS = cdp.RENDERERS["swiftshader"]

# Installed before the page's scripts: the moment dataset.t10 first leaves "loading".
OBSERVER = r"""
window.__t10Measure = {state: null, ms: null, error: ""};
new MutationObserver(() => {
  const body = document.body, m = window.__t10Measure;
  if (!body || m.ms !== null) return;
  const state = body.dataset.t10;
  if (state === "rendered" || state === "error") {
    m.ms = performance.now();  // since the navigation started
    m.state = state;
    const e = document.getElementById("t10-error");
    m.error = e ? e.textContent : "";
  }
}).observe(document, {attributes: true, subtree: true, attributeFilter: ["data-t10"]});
"""

RENDERER = r"""
(() => {
  const gl = document.createElement("canvas").getContext("webgl2");
  if (!gl) return "no WebGL2";
  const info = gl.getExtension("WEBGL_debug_renderer_info");
  return String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
})()
"""


def load_once(browser, url, timeout):
    """Opens url in a fresh tab; returns (milliseconds to the first frame, bytes received)."""
    target, session = cdp.open_tab(browser, ("Page", "Network", "Runtime"), scripts=(OBSERVER,))
    try:
        browser.send("Network.setCacheDisabled", {"cacheDisabled": True}, session)
        browser.drain()
        browser.send("Page.navigate", {"url": url}, session)
        m = cdp.wait_until(lambda: evaluate(browser, session, "window.__t10Measure || null"),
                           lambda m: m and m["ms"] is not None, timeout, f"{url}: no frame", interval=0.05)
        if m["state"] == "error":
            raise Failure(f"{url}: the page reports an error: {m['error']}")
        received = sum(e["params"].get("encodedDataLength", 0) for e in browser.drain()
                       if e.get("method") == "Network.loadingFinished" and e.get("sessionId") == session)
        renderer = evaluate(browser, session, RENDERER)
        return m["ms"], received, renderer
    finally:
        browser.send("Target.closeTarget", {"targetId": target})


def cpu_name():
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as f:
            for line in f:
                if line.startswith("model name"):
                    return f"{line.split(':', 1)[1].strip()}, {os.cpu_count()} cores"
    except OSError:
        pass
    return f"{platform.machine()}, {os.cpu_count()} cores"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--web", required=True, help="the web stages (make web: out/web)")
    ap.add_argument("--stages", required=True, help="stage names, comma-separated")
    ap.add_argument("--out", required=True, help="the JSON file to write")
    ap.add_argument("--chromium", default="chromium")
    ap.add_argument("--runs", type=int, default=3, help="loads per stage (the median is stated)")
    ap.add_argument("--size", default="1280x720", help="the frame size the pages render at")
    ap.add_argument("--timeout", type=float, default=90, help="seconds for one load")
    args = ap.parse_args()

    names = web_stages.available(args.web, [n for n in args.stages.split(",") if n])
    if not names:
        print(f"[site] measure_web: no web stages in {args.web} (make web builds them): nothing measured")
        return 0
    if not shutil.which(args.chromium):
        raise Failure(f"{args.chromium}: not found (apt-get install chromium)")
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else 0.0
    result = {"browser": "", "renderer": "", "cpu": cpu_name(), "size": args.size, "runs": args.runs,
              "date": time.strftime("%Y-%m-%d", time.gmtime()),
              "note": (f"The machine was shared with other work (load average {load:.1f} on "
                       f"{os.cpu_count()} cores when the measurement started)." if load > 0.5 else ""),
              "stages": {}}
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    with cdp.browsing(os.path.abspath(args.web), args.chromium, os.path.abspath(args.out) + ".chromium.log",
                      time.monotonic() + args.timeout * args.runs * len(names) + 60, WEBGL_ARGS) as (browser, base):
        result["browser"] = browser.send("Browser.getVersion")["product"].replace("HeadlessChrome/", "Chromium ").replace("Chrome/", "Chromium ")
        for name in names:
            runs, received = [], 0
            for _ in range(args.runs):
                ms, received, renderer = load_once(browser, f"{base}{name}/index.html?size={args.size}&frames=1",
                                                   args.timeout)
                runs.append(round(ms))
                result["renderer"] = renderer
            median = statistics.median(runs)
            result["stages"][name] = {"fingerprint": web_stages.fingerprint(os.path.join(args.web, name)),
                                      "runs_ms": runs, "median_ms": median, "received_bytes": received}
            print(f"[site] {name}: first frame {median / 1000:.2f} s (runs {', '.join(f'{r / 1000:.2f}' for r in runs)} s), "
                  f"{web_stages.megabytes(received)} received", flush=True)
    with open(args.out, "w", encoding="utf-8") as f:
        json.dump(result, f, indent=1)
    print(f"[site] measured in {result['browser']}, {result['renderer']}; {result['cpu']}; written to {args.out}")
    return 0


if __name__ == "__main__":
    cdp.run_main(main, "[site] measure_web: ")
