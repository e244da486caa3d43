#!/usr/bin/env python3
"""The web stages (make web, out/web/<stage>/index.html) driven in Chromium and Firefox like the binaries.

usage: web_test.py COMMAND --web OUT_WEB --out DIR [options]

Chromium is driven over the DevTools protocol (tools/web/cdp.py: a pipe, a local server on
127.0.0.1, nothing else reachable; tools/web/web_page.py's StagePage: one tab on the stages'
pages). A page is loaded with the command line as its query
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
  compares --verdict STAGE pass|fail ...: compare for each in turn, in one browser; every page is judged,
           then the failures are reported.
  goldens  --case STAGE GOLDEN REJECTS ...: golden for each case in turn, in one browser (REJECTS: goldens
           separated by commas, - for none; STAGE?QUERY adds the stage's options, the frame then named
           STAGE-QUERY); every case is judged, then the failures are reported.

--browser firefox (golden and goldens): Firefox ESR on its own Xvfb display, driven over Marionette
(tools/web/marionette.py; the same local server), WebGL 2 on Mesa llvmpipe without ANGLE. Headless
Firefox has no WebGL here, hence the display. It never runs a script before the page's own.

--renderer: llvmpipe (ANGLE on Mesa's GL ES: the goldens' rasteriser, with EXT_texture_norm16 for the
stages' GL_R16 key) or swiftshader (ANGLE on SwiftShader; it has no EXT_texture_norm16).
Exit 0: passed; 1: failed (what and why on stderr); 77: cannot run here (no such page, no browser or
Xvfb), said why.
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import time

sys.dont_write_bytecode = True
HERE = os.path.dirname(os.path.abspath(__file__))
from web import cdp  # noqa: E402  (the DevTools client; tools/ on PYTHONPATH)
from web import web_page  # noqa: E402  (a stage's page in one tab: its state, its frame)

Failure = cdp.Failure
GOLDEN_QUERY = "size=640x360&camera=default&frames=1"  # tests/golden/render_args.sh, as a query

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


class Announced:
    """A stage's page opened by stage and query, said on stdout; waits bounded by --timeout."""

    def open(self, stage, query):
        url = super().open(f"{stage}/index.html?{query}")
        print(f"loading {url} ({self.engine})", flush=True)

    def settled(self, timeout=None):
        return super().settled(timeout or self.args.timeout * 0.8)


class Page(Announced, web_page.StagePage):
    """One Chromium with one tab on a local server over out/web, as the command line asks."""

    def __init__(self, args, scripts=()):
        self.args, self.engine = args, args.renderer
        super().__init__(args.web, args.chromium, os.path.join(args.out, "chromium.log"), cdp.RENDERERS[args.renderer],
                         time.monotonic() + args.timeout, scripts)


class FirefoxPage(Announced, web_page.FirefoxStagePage):
    """One Firefox on its own Xvfb display (WebGL 2 on Mesa llvmpipe) on a local server over out/web."""

    def __init__(self, args):
        self.args, self.engine = args, "Firefox, llvmpipe"
        super().__init__(args.web, args.firefox, os.path.join(args.out, "firefox.log"), time.monotonic() + args.timeout)


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
    if first is None:  # no record of the page's states (Firefox): when the wait saw it, in the page's time
        first = page.evaluate("performance.now()")
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


def judge_each(cases, judge, noun):
    """judge(case) for each (label, case) in turn in the one browser: every case is judged, then the
    failures are reported together."""
    failures = []
    for label, case in cases:
        try:
            judge(case)
        except Failure as failure:
            print(f"FAILED: {label}: {failure}", flush=True)
            failures.append(f"{label}: {failure}")
    if failures:
        raise Failure(f"{len(failures)} of {len(cases)} {noun} failed:\n  " + "\n  ".join(failures))


def run_goldens(args, page):
    """Each --case in turn in the one browser."""
    cases = []
    for page_and_query, golden, rejects in args.case:
        stage, _, query = page_and_query.partition("?")
        case = argparse.Namespace(**vars(args))
        case.stage, case.golden, case.query = stage, golden, query
        case.name = f"{stage}-{re.sub('[^a-z0-9]+', '-', query.lower())}" if query else None
        case.reject = [r for r in rejects.split(",") if r and r != "-"]
        cases.append((page_and_query, case))
    judge_each(cases, lambda case: run_golden(case, page), "pages")


def run_live(args, page):
    page_folder(args, args.stage)
    page.open(args.stage, GOLDEN_QUERY)
    state, _ = rendered(page, args.stage)
    before = os.path.join(args.out, f"{args.stage}-live-before.png")
    page.capture(before)
    judge(args, before, args.golden, [])
    name, _, value = args.set.partition("=")
    # The controls are made from Module.t10Options(): every entry a setting's own name, each once.
    names = page.evaluate("Module.t10Options().options.map(o => o.name)") or []
    odd = sorted({n for n in names if not re.fullmatch(r"[a-z][a-z0-9-]*", n) or names.count(n) > 1})
    if odd or name not in names:
        raise Failure(f"Module.t10Options() lists {len(names)} options; not setting names or repeated: {odd}; "
                      f"{name!r} {'listed' if name in names else 'missing'}")
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


def run_compares(args, page):
    """Each --verdict in turn in the one browser."""
    cases = []
    for stage, expect in args.verdict:
        case = argparse.Namespace(**vars(args))
        case.stage, case.expect = stage, expect
        cases.append((stage, case))
    judge_each(cases, lambda case: run_compare(case, page), "compare pages")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("command", choices=["golden", "goldens", "live", "nofloat", "compare", "compares"])
    ap.add_argument("--web", required=True, help="the built pages (out/web)")
    ap.add_argument("--out", required=True, help="folder for frames, screenshots and the browser's log")
    ap.add_argument("--stage", help="the stage's page (every command but goldens)")
    ap.add_argument("--case", nargs=3, action="append", default=[], metavar=("STAGE", "GOLDEN", "REJECTS"),
                    help="goldens: STAGE's frame matches GOLDEN and not each of REJECTS (comma-separated, - for none); "
                         "STAGE?QUERY loads it with the query's options")
    ap.add_argument("--name", help="file name for the frame (default: the stage)")
    ap.add_argument("--query", default="", help="more query parameters (the stage's options)")
    ap.add_argument("--golden", help="the golden the frame must match (a stage name)")
    ap.add_argument("--reject", action="append", default=[], help="a golden the frame must not match")
    ap.add_argument("--set", help="NAME=VALUE for Module.t10Set (live)")
    ap.add_argument("--then", help="the golden after --set (live)")
    ap.add_argument("--expect", choices=["pass", "fail"], help="the compare page's verdict (compare)")
    ap.add_argument("--verdict", nargs=2, action="append", default=[], metavar=("STAGE", "VERDICT"),
                    help="compares: STAGE's ?compare=1 page must give VERDICT (pass or fail)")
    ap.add_argument("--goldens", default=os.path.join(HERE, "..", "golden"))
    ap.add_argument("--tolerance", default=os.path.join(HERE, "..", "golden", "web.tolerance"))
    ap.add_argument("--imgcompare", help="the project's imgcompare program")
    ap.add_argument("--browser", choices=["chromium", "firefox"], default="chromium",
                    help="firefox: Firefox ESR under Xvfb over Marionette (golden and goldens only)")
    ap.add_argument("--chromium", default="chromium")
    ap.add_argument("--firefox", default="firefox-esr")
    ap.add_argument("--renderer", choices=sorted(cdp.RENDERERS), default="llvmpipe", help="Chromium's WebGL")
    ap.add_argument("--timeout", type=float, default=120, help="seconds for the whole test")
    args = ap.parse_args()
    if args.command in ("golden", "live") and not (args.golden and args.imgcompare):
        ap.error(f"{args.command} needs --golden and --imgcompare")
    if args.command == "goldens" and not (args.case and args.imgcompare):
        ap.error("goldens needs --case STAGE GOLDEN REJECTS and --imgcompare")
    if args.command == "compares" and not (args.verdict and all(v in ("pass", "fail") for _, v in args.verdict)):
        ap.error("compares needs --verdict STAGE pass|fail")
    if args.command not in ("goldens", "compares") and not args.stage:
        ap.error(f"{args.command} needs --stage")
    if args.command == "live" and not (args.set and args.then and "=" in args.set):
        ap.error("live needs --set NAME=VALUE and --then GOLDEN")
    if args.command == "compare" and not args.expect:
        ap.error("compare needs --expect pass|fail")
    if args.browser == "firefox" and args.command not in ("golden", "goldens"):
        ap.error("--browser firefox runs golden and goldens only")
    needed = [args.chromium] if args.browser == "chromium" else [args.firefox, "Xvfb"]
    missing = [program for program in needed if not shutil.which(program)]
    if missing:
        print(f"SKIP: {', '.join(missing)}: not found (apt-get install "
              f"{'chromium' if args.browser == 'chromium' else 'firefox-esr xvfb'})", file=sys.stderr)
        return 77
    os.makedirs(args.out, exist_ok=True)
    listed = [case[0].partition("?")[0] for case in args.case] + [stage for stage, _ in args.verdict]
    for stage in [args.stage] if args.stage else listed:
        page_folder(args, stage)
    if args.browser == "firefox":
        page = FirefoxPage(args)
    else:
        page = Page(args, scripts=(NO_FLOAT_TARGETS,) if args.command == "nofloat" else ())
    try:
        {"golden": run_golden, "goldens": run_goldens, "live": run_live, "nofloat": run_nofloat,
         "compare": run_compare, "compares": run_compares}[args.command](args, page)
    finally:
        page.close()
    print("ok")
    return 0


if __name__ == "__main__":
    cdp.run_main(main)
