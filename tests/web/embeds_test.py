#!/usr/bin/env python3
"""The stage pages as embeds a student can rely on (issue 50, item 4), in headless Chromium on llvmpipe.

usage: embeds_test.py --web OUT_WEB --out DIR [--stage S ...] [--faults] [--queries all|quick]

--faults (on Part 0 and extras) checks each fault the issue found, every one of which this test
reported on the pages before the fix (run against main's out/web at 7296bec; the failure is quoted
in each check's comment):
  - ?help and ?version answer on the page (dataset.t10 "answered", the text in #t10-text);
  - extras' --key exact (a compute shader) is never offered (Module.t10Options' choices) and refused
    by name in the URL and through Module.t10Set, with no build machine's path in any message, and a
    refused change keeps the page running with its last frame;
  - the wheel zooms out one notch (2 degrees of field of view) towards the user and in away from
    him, each notch drawing a new frame;
  - ?frames=1000000 and ?size=8192x8192 are refused at once, naming the limit;
  - ?view=bloom0 on Part 0 is an error with no frame shown; ?input=/etc/passwd is "not available";
  - "rendered" is set after a readback of the frame (the GL calls the page makes, recorded by a
    script run before the page's own: a readPixels after the last draw).
--queries: hostile queries (sizes, counts, names, markup, very long values, unknown and repeated
options; QUERIES below, 50) on each --stage: each reaches "rendered", "error" or "answered" within
10 s, with the tab answering the test within RESPONSIVE_S all along, no markup run (alert and friends
recorded, no element the page does not make), nothing fetched but the page's own four files, and no
message naming a path of the build machine. Before the fix, on Part 0: ?frames=1000000, ?help&size=
8192x8192 no verdict in 10 s; ?size=8192x8192 the tab took 19.8 s to answer. `quick` is the subset make test runs (QUICK); `all` is make site-audit's.
Exit 0 passed, 1 failed (each problem on stderr), 77 no page or no Chromium.
"""
import argparse
import json
import os
import shutil
import sys
import tempfile
import time
import urllib.parse

sys.dont_write_bytecode = True
from web import cdp  # noqa: E402  (the DevTools client; tools/ on PYTHONPATH)
from web import web_page  # noqa: E402  (a stage's page in one tab)

Failure = cdp.Failure
BUILD_ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
VERDICT_S = 10.0      # the bound for a verdict
# The longest the tab may take to answer the test. A load at 1280x720 (no ?size) keeps the page busy
# 0.8-1.2 s here (the shaders' compile, the frame and its readback on llvmpipe), 3.1 s once while
# other builds loaded the machine; a frozen tab is far longer (?size=8192x8192 before the fix: 19.8 s).
RESPONSIVE_S = 5.0

# Run before the page's own scripts: dialogs recorded instead of shown (a query's markup that ran would
# call them), and the page's draws and readbacks in order, kept when dataset.t10 first says "rendered".
PROBES = r"""
(() => {
  window.__t10Dialogs = [];
  for (const name of ["alert", "confirm", "prompt"]) window[name] = (m) => { window.__t10Dialogs.push(String(m)); };
  const calls = window.__t10GlCalls = [];
  window.__t10AtRendered = null;
  const proto = window.WebGL2RenderingContext && WebGL2RenderingContext.prototype;
  if (proto) {
    for (const [name, kind] of [["drawElements", "draw"], ["drawArrays", "draw"], ["readPixels", "read"]]) {
      const original = proto[name];
      proto[name] = function (...args) { calls.push(kind); return original.apply(this, args); };
    }
  }
  new MutationObserver(() => {
    if (window.__t10AtRendered === null && document.body && document.body.dataset.t10 === "rendered")
      window.__t10AtRendered = calls.slice(-50);
  }).observe(document, {attributes: true, subtree: true, attributeFilter: ["data-t10"]});
})();
"""

# What the page made that a query's markup could have made instead.
FOREIGN = r"""JSON.stringify({dialogs: window.__t10Dialogs || [],
  elements: [...document.querySelectorAll("img, svg, iframe, object, embed, video, audio, a, b, i")].map(e => e.outerHTML.slice(0, 80)),
  scripts: document.scripts.length})"""

# What the last frame was drawn with (a page without Module.t10Drawn: nothing known).
DRAWN = "JSON.stringify(Module.t10Drawn ? Module.t10Drawn() : {args: ['(no Module.t10Drawn)'], fov: null})"

LONG = "a" * 10000
# 50 queries: sizes, counts, names, markup, very long values, unknown and repeated options. Each is
# written as it goes into the URL (percent-encoded where a browser would encode it).
QUERIES = [
    # sizes
    "size=8192x8192", "size=16384x16384", "size=4097x2", "size=4096x2", "size=2x2", "size=0x0", "size=1x1",
    "size=-640x360", "size=99999999999999999999x2", "size=640x", "size=abc", "size=640x360x2", "size=1e3x2",
    # counts
    "size=640x360&frames=1000000", "frames=0", "frames=-1", "frames=1.5", "frames=nan",
    "frames=99999999999999999999", "frames=", "size=320x180&frames=20",
    # names
    "view=bloom0", "view=nope", "view=", "camera=nope", "camera=..%2F..%2F..%2F..%2Fetc%2Fpasswd",
    "input=%2Fetc%2Fpasswd", "scene=http%3A%2F%2Fexample.com%2Fa.gltf", "shader-dir=%2F", "output=%2Ftmp%2Fx.png",
    "exr=a.exr", "bench=5", "key=exact",
    # markup
    "view=%3Cimg%20src%3Dx%20onerror%3Dalert(1)%3E", "camera=%3Cscript%3Ealert(1)%3C%2Fscript%3E",
    "%3Csvg%20onload%3Dalert(1)%3E=1", "size=%3Cb%3E640%3C%2Fb%3Ex360",
    "camera=%22%3E%3Cimg%20src%3Dx%20onerror%3Dalert(1)%3E",
    # very long values and names
    "camera=" + LONG, "view=" + "b" * 50000, "c" * 5000 + "=1", "size=" + "9" * 5000 + "x2",
    # unknown and repeated options
    "nope=1", "=1", "frames=1&frames=1&frames=1", "size=640x360&size=320x180", "view=hdr&view=final",
    "then=1", "%FF=%FE", "help&size=8192x8192",
]
assert len(QUERIES) == 50, len(QUERIES)
# make test's share, about 2 s on one page: one or two of each kind.
QUICK = ["size=8192x8192", "size=640x360&frames=1000000", "view=nope", "input=%2Fetc%2Fpasswd",
         "view=%3Cimg%20src%3Dx%20onerror%3Dalert(1)%3E", "camera=" + LONG, "nope=1", "%FF=%FE"]


# The site's embed script (site/assets/js/live.js) around extras' page, as the tutorial page holds it
# (site/_includes), its picture 320 px wide so that the embed draws 320x180.
HARNESS = """<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>live.js around extras</title></head><body>
<div class="live" data-src="extras/index.html" data-stage="extras" data-size-text="3 MB" style="width: 320px">
<figure class="render"><img src="data:," alt="extras" width="320" height="180"></figure>
<button class="live-start">Run live</button><p class="live-note"></p><div class="live-controls"></div>
</div>
<script src="live.js"></script>
</body></html>
"""

# One control of the embed set as a reader sets it (the events a browser fires), to each value in turn,
# `gap` ms apart (a key held on a slider repeats every 30-50 ms): quicker than the frames.
QUICK_CHANGES = r"""
((name, values, gap) => {
  const input = document.querySelector(`.live-controls [data-option="${name}"]:not(label)`);
  if (!input) return "no control for --" + name;
  values.forEach((value, i) => setTimeout(() => {
    input.value = value;
    input.dispatchEvent(new Event("input"));
    input.dispatchEvent(new Event("change"));
  }, i * gap));
  return "";
})
"""

EMBED = r"""JSON.stringify((() => {
  const live = document.querySelector(".live"), frame = live.querySelector("iframe.live-frame");
  const page = frame && frame.contentDocument && frame.contentDocument.body;
  return {state: live.dataset.state, page: page ? page.dataset.t10 : "", frames: page ? Number(page.dataset.t10Frames) : 0,
          status: (live.querySelector(".live-control-status") || {}).textContent || "",
          drawn: page && frame.contentWindow.Module && frame.contentWindow.Module.calledRun &&
          frame.contentWindow.Module.t10Drawn ? frame.contentWindow.Module.t10Drawn().args : null};
})())"""


def served_root(web, live_js, folder):
    """A folder to serve: each page of `web` (a link) and the harness with a copy of live.js."""
    for name in os.listdir(web):
        os.symlink(os.path.abspath(os.path.join(web, name)), os.path.join(folder, name))
    shutil.copy(live_js, os.path.join(folder, "live.js"))
    with open(os.path.join(folder, "live-harness.html"), "w") as f:
        f.write(HARNESS)
    return folder


class Tab(web_page.StagePage):
    """One Chromium on llvmpipe with the probes, on a local server over `root` (out/web's pages)."""

    def __init__(self, args, root):
        super().__init__(root, args.chromium, os.path.join(args.out, "chromium.log"), cdp.RENDERERS["llvmpipe"],
                         None, (PROBES,))

    def load(self, stage, query):
        """Opens the stage with `query`; returns (state, seconds to the verdict, the longest answer, the
        URLs fetched)."""
        self.browser.drain()
        started = time.monotonic()
        self.open(f"{stage}/index.html?{query}")
        slowest = 0.0
        while True:
            asked = time.monotonic()
            state = self.state()
            slowest = max(slowest, time.monotonic() - asked)
            if state["state"] in ("rendered", "error", "answered"):
                break
            if time.monotonic() - started > VERDICT_S:
                break
            time.sleep(0.05)
        seconds = time.monotonic() - started
        fetched = [e["params"]["request"]["url"] for e in self.browser.drain()
                   if e.get("method") == "Network.requestWillBeSent" and e.get("sessionId") == self.session]
        return state, seconds, slowest, fetched

    def js(self, expression):
        return self.evaluate(expression)


def page_folder(web, stage):
    if not os.path.isfile(os.path.join(web, stage, "index.html")):
        print(f"SKIP: {web}/{stage}/index.html does not exist: build it with make web", file=sys.stderr)
        sys.exit(77)


def own_files(tab, stage):
    return {tab.base + f"{stage}/{name}" for name in ("index.html", f"{stage}.js", f"{stage}.wasm", f"{stage}.data")}


def check_query(tab, stage, query):
    """One hostile query: the problems found (none: it passed)."""
    state, seconds, slowest, fetched = tab.load(stage, query)
    shown = query if len(query) < 60 else query[:40] + f"... ({len(query)} characters)"
    problems = []
    if state["state"] not in ("rendered", "error", "answered"):
        problems.append(f"no verdict within {VERDICT_S:.0f} s (state {state['state']!r})")
    if slowest > RESPONSIVE_S:
        problems.append(f"the tab took {slowest:.1f} s to answer")
    foreign = [url for url in fetched if urllib.parse.urldefrag(url)[0].split("?")[0] not in own_files(tab, stage)
               and not url.startswith("data:")]
    if foreign:
        problems.append(f"fetched {foreign[:3]}")
    made = json.loads(tab.js(FOREIGN))
    if made["dialogs"] or made["elements"] or made["scripts"] != 2:
        problems.append(f"markup ran: dialogs {made['dialogs']}, elements {made['elements']}, {made['scripts']} scripts")
    text = state["error"] + (tab.js("(document.getElementById('t10-text') || {}).textContent") or "")
    if BUILD_ROOT in text or "/work/" in text:
        problems.append(f"a build machine's path in the message: {text[:200]!r}")
    if state["state"] == "error" and not state["error"].strip():
        problems.append("an error without a message")
    print(f"{stage}?{shown}: {state['state']} in {seconds:.2f} s (slowest answer {slowest:.2f} s) "
          f"{state['error'][:110]!r}", flush=True)
    return [f"{stage}?{shown}: {p}" for p in problems]


def settle(tab, what, done, timeout=10):
    return cdp.wait_until(tab.state, done, timeout, what, lambda s: f" (state {s['state']!r}, error {s['error']!r})")


def check_help(tab):
    # Before: "no 'rendered' or 'error' within 30 s; the page says state='loading'" (the text in the console).
    problems = []
    for query, expect in (("help", "--size"), ("version", "1.")):
        state, _, _, _ = tab.load("tutorial10_part0_start", query)
        text = tab.js("(document.getElementById('t10-text') || {}).textContent") or ""
        if state["state"] != "answered" or expect not in text:
            problems.append(f"?{query}: state {state['state']!r}, text on the page {text[:80]!r}")
    return problems


def check_refusals(tab):
    """The URL's refusals, each at once and by name, without a frame or a path."""
    # Before: ?key=exact "error: /work/.../ExactKey.comp: shader not found"; ?input=/etc/passwd "File does not
    # exist"; ?frames=1000000 no verdict (17.8 s for 1000 frames at 640x360); ?size=8192x8192 rendered,
    # then the tab frozen at 2.7 GB; ?view=bloom0 on Part 0: the error under a full frame.
    cases = [("extras", "size=640x360&key=exact", "--key: exact is not available in the web build"),
             ("tutorial10_part0_start", "size=640x360&input=%2Fetc%2Fpasswd", "--input is not available in the web build"),
             ("tutorial10_part0_start", "size=640x360&frames=1000000", "at most 16,000,000 pixels"),
             ("tutorial10_part0_start", "size=8192x8192", "at most 8,294,400 pixels a frame"),
             ("tutorial10_part0_start", "size=640x360&view=bloom0", "this stage has no bloom0")]
    problems = []
    for stage, query, expect in cases:
        state, seconds, _, _ = tab.load(stage, query)
        canvas = tab.js("(() => { const r = document.getElementById('canvas').getBoundingClientRect();"
                        " return r.width * r.height; })()")
        print(f"{stage}?{query}: {state['state']} in {seconds:.2f} s: {state['error'][:120]!r}", flush=True)
        if state["state"] != "error" or expect not in state["error"] or "/work/" in state["error"]:
            problems.append(f"{stage}?{query}: state {state['state']!r}, message {state['error']!r} "
                            f"(expected one saying {expect!r})")
        if canvas:
            problems.append(f"{stage}?{query}: the canvas is shown ({canvas:.0f} pixels) beside the error")
    return problems


def check_live_changes(tab):
    """--key exact is not offered; a refused change keeps the page and its frame."""
    # Before: t10Options' --key listed "TEXT:{mip,exact}" (the site made a control of it), and
    # t10Set('key', 'exact') took the page to "error" with the build machine's path; only a reload helped.
    problems = []
    state, _, _, _ = tab.load("extras", "size=320x180")
    if state["state"] != "rendered":
        return [f"extras?size=320x180: {state['state']!r} {state['error']!r}"]
    key = json.loads(tab.js("JSON.stringify(Module.t10Options().options.find(o => o.name === 'key'))"))
    if key.get("choices") != ["mip"]:
        problems.append(f"extras: t10Options offers --key {key.get('choices') or key.get('type')}, not only mip")
    for name, value in (("key", "exact"), ("camera", "nope"), ("view", "nope"), ("size", "8192x8192")):
        # t10Set answers at once; a change it put back has set "loading" before it returns.
        message = tab.js(f"Module.t10Set({json.dumps(name)}, {json.dumps(value)})")
        state = settle(tab, f"t10Set({name}, {value}) settled", lambda s: s["state"] in ("rendered", "error"))
        drawn = json.loads(tab.js(DRAWN))
        print(f"extras: t10Set({name!r}, {value!r}) -> {message[:110]!r}; page {state['state']}, "
              f"frame {state['frames']} drawn with {drawn['args']}", flush=True)
        if not message or "/work/" in message or state["state"] != "rendered" or f"--{name}={value}" in drawn["args"]:
            problems.append(f"extras: t10Set({name!r}, {value!r}) answered {message!r}; the page is "
                            f"{state['state']!r} ({state['error']!r}), drawn with {drawn['args']}")
    # A change that is honoured after the refusals draws a new frame with it.
    frames = int(state["frames"])
    tab.js("Module.t10Set('white-point', '0.5')")
    state = settle(tab, "a frame after the refusals", lambda s: s["state"] == "rendered" and int(s["frames"]) > frames)
    if "--white-point=0.5" not in json.loads(tab.js(DRAWN))["args"]:
        problems.append("extras: after the refused changes --white-point 0.5 was not drawn")
    return problems


def check_wheel(tab):
    """A notch towards the reader zooms out by one step (2 degrees) and draws; away zooms in."""
    # Before: no new frame within 5 s after a notch (and the field of view at its 20-degree limit).
    state, _, _, _ = tab.load("tutorial10_part0_start", "size=320x180")
    if state["state"] != "rendered":
        return [f"Part 0 ?size=320x180: {state['state']!r}"]
    problems = []
    fov = tab.js("Module.t10Drawn ? Module.t10Drawn().fov : null")
    for delta, notches, expect in ((100, 1, 2.0), (-100, 3, -6.0)):
        frames = int(tab.state()["frames"])
        # All in one task, so that one frame shows them all.
        tab.js(f"for (let i = 0; i < {notches}; ++i) document.getElementById('canvas').dispatchEvent("
               f"new WheelEvent('wheel', {{deltaY: {delta}, deltaMode: 0, bubbles: true, cancelable: true}}))")
        try:
            settle(tab, f"a frame after {notches} notch(es) of the wheel",
                   lambda s: s["state"] == "rendered" and int(s["frames"]) > frames, 5)
        except Failure as failure:
            problems.append(str(failure))
            break
        now = json.loads(tab.js(DRAWN))["fov"]
        print(f"wheel deltaY {delta} x{notches}: field of view {fov} -> {now} degrees", flush=True)
        if fov is None or now is None or abs(now - (fov + expect)) > 0.01:
            problems.append(f"wheel deltaY {delta} x{notches}: field of view {fov} -> {now}, expected {expect:+} degrees")
        fov = now
    return problems


def check_readback(tab):
    """'rendered' comes after a readback that follows the last draw, for every part."""
    # Before (Parts 0-3): the last GL calls before "rendered" were draws ['draw', 'draw'], no readPixels.
    problems = []
    for stage in ("tutorial10_part0_start", "tutorial10_part3_gaussian", "extras"):
        state, _, _, _ = tab.load(stage, "size=320x180")
        calls = tab.js("window.__t10AtRendered") or []
        last_draw = max((i for i, c in enumerate(calls) if c == "draw"), default=-1)
        last_read = max((i for i, c in enumerate(calls) if c == "read"), default=-1)
        print(f"{stage}: the GL calls before 'rendered' end {calls[-4:]}", flush=True)
        if state["state"] != "rendered" or last_draw < 0 or last_read < last_draw:
            problems.append(f"{stage}: 'rendered' set with no readback after the last draw (calls {calls[-6:]})")
    return problems


def check_quick_changes(tab):
    """The site's embed: quick changes are applied in order, the last one wins, the status names it."""
    # Before (live.js at 7296bec, each change re-queued on its own 50 ms timer), 4 runs of 4: "the control
    # shows 0, the frame was drawn with ['--blur-passes=1'], the status says '--blur-passes 1: frame 9 drawn.'"
    tab.open("live-harness.html")
    cdp.wait_until(lambda: tab.js("typeof t10Live"), lambda v: v == "object", 10, "live.js loaded")
    tab.js("t10Live.start('extras')")
    embed = cdp.wait_until(lambda: json.loads(tab.js(EMBED)), lambda e: e["state"] in ("rendered", "error"), 30,
                           "the embed drew its first frame")
    values = ["3", "1", "4", "2", "5", "1", "3", "0"]
    problem = tab.js(f"{QUICK_CHANGES}('blur-passes', {json.dumps(values)}, 23)")
    time.sleep(len(values) * 0.023)
    if problem:
        return [f"live.js: {problem}"]
    # Settled: the embed rendered, and no change is still queued (live.js at 7296bec re-queued on 50 ms
    # timers: looked at again 0.5 s later).
    first = embed["frames"]
    done = lambda e: e["state"] == "rendered" and e["page"] == "rendered" and e["frames"] > first
    for pause in (0.5, 0):
        embed = cdp.wait_until(lambda: json.loads(tab.js(EMBED)), done, 30, "the embed settled after the changes")
        time.sleep(pause)
    drawn = [a for a in embed["drawn"] or [] if a.startswith("--blur-passes=")]
    shown = tab.js("document.querySelector('[data-option=\"blur-passes\"]:not(label)').value")
    print(f"live.js: blur passes {', '.join(values)} 23 ms apart: the control shows {shown}, the frame was drawn with "
          f"{drawn[-1:] or 'the default'}, the status says {embed['status']!r}", flush=True)
    if shown != "0" or drawn[-1:] != ["--blur-passes=0"] or "--blur-passes 0" not in embed["status"]:
        return [f"live.js: after blur passes {values} 23 ms apart the control shows {shown}, the frame was drawn with "
                f"{drawn[-1:] or embed['drawn']}, the status says {embed['status']!r}"]
    return []


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--web", required=True, help="the built pages (out/web)")
    ap.add_argument("--out", required=True, help="folder for Chromium's log")
    ap.add_argument("--stage", action="append", default=[], help="a stage page for the hostile queries")
    ap.add_argument("--queries", choices=["all", "quick"], help="which hostile queries (none without)")
    ap.add_argument("--faults", action="store_true", help="check each fault the issue found")
    ap.add_argument("--chromium", default="chromium")
    ap.add_argument("--live-js", default=os.path.join(BUILD_ROOT, "site", "assets", "js", "live.js"),
                    help="the site's embed script (--faults)")
    args = ap.parse_args()
    if not shutil.which(args.chromium):
        print(f"SKIP: {args.chromium}: not found (apt-get install chromium)", file=sys.stderr)
        return 77
    for stage in args.stage + (["tutorial10_part0_start", "tutorial10_part3_gaussian", "extras"] if args.faults else []):
        page_folder(args.web, stage)
    os.makedirs(args.out, exist_ok=True)
    started = time.monotonic()
    scratch = tempfile.TemporaryDirectory(prefix="t10-embeds-")
    tab = Tab(args, served_root(args.web, args.live_js, scratch.name))
    problems = []
    try:
        if args.faults:
            for check in (check_help, check_refusals, check_live_changes, check_wheel, check_readback,
                          check_quick_changes):
                try:
                    problems += check(tab)
                except Failure as failure:  # a wait that ran out: the check failed, the others still run
                    problems.append(f"{check.__name__}: {failure}")
        queries = {"all": QUERIES, "quick": QUICK, None: []}[args.queries]
        for stage in args.stage:
            for query in queries:
                problems += check_query(tab, stage, query)
    finally:
        tab.close()
        scratch.cleanup()
    print(f"finished in {time.monotonic() - started:.1f} s", flush=True)
    if problems:
        raise Failure(f"{len(problems)} problem(s):\n  " + "\n  ".join(problems))
    print("ok")
    return 0


if __name__ == "__main__":
    cdp.run_main(main)
