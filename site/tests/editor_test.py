#!/usr/bin/env python3
"""The shader editor of the tutorial page's Part 1 embed (issue 52), in headless Chromium (WebGL2 on
SwiftShader, or --renderer llvmpipe), driven as a reader drives it (its buttons and its text, through the DOM):

  1. the embed runs, "Edit the shaders" opens the editor, and the work starts where `make student PART=1`
     starts it: PostProcess.frag is Part 0's (web/<stage>/start/), PostProcessInit.frag, new in Part 1,
     is empty (the reference's runs meanwhile);
  2. the reference copied into both files and applied gives frame A;
  3. the luminance-weights mistake (step 3: Rec. 601's 0.299, 0.587, 0.114 in PostProcessInit.frag, the
     grader's test batch's "rec601") applied: the frame differs from A in more than --min-changed of the
     pixels by more than 4 of 255 (the key, and with it every pixel's exposure, moves); with
     Module.t10Check in the page, "Check my work" scores it under 100, puts step 3 first, names
     luminance-weights with its measured value, and the announced status names it too;
  4. fixed: the frame is A again (within 2 of 255 at every pixel: the same shaders draw the same frame);
     with t10Check, the score is 100;
  5. a syntax error on a known line of PostProcess.frag: the error is listed at that line of the
     student's source and marked there in the text, nothing is applied, and the last good program keeps
     drawing (the frame is still A, the page not in error);
  6. a while loop is refused at its line before it reaches the GPU (a shader that could hang the tab:
     Module.t10SetShader refuses it, and the editor lists and marks it there);
  7. the download is a .zip of part1/PostProcess.frag and part1/PostProcessInit.frag with the editor's
     text, and uploading a file through the upload input puts it into the editor;
  8. after a reload the embed's editor opens with the work as it was left (localStorage);
  9. the stage's own page with ?edit=1 opens the same editor with the same kept work, and keys typed in
     its text reach it (W is typed, Backspace takes it away: emscripten's GLFW cancels Backspace for the
     whole window, so without edit_page.js's listener nothing is deleted); Tab indents there as in the
     embed (the text gains four spaces, the focus stays: the page's own Tab listener, which keeps Tab from
     GLFW for the canvas, leaves the editor's Tab to it), and Escape, then Tab, moves on to Apply (no
     keyboard trap);
 10. there, the WebGL context lost (WEBGL_lose_context, as when the browser's GPU watchdog stops a
     shader): the page's status line (role=status) says WebGL stopped and to reload, and the editor's
     Apply is answered at once with that message (Module.t10SetShader refuses it; nothing hangs);
 11. back on the tutorial page, the embed's context lost: the embed's own status line (role=status)
     says so and its button offers "Run it live again" (data-state idle), which runs it again.
With --axe AXE.JS, axe-core (axe_test.py's WCAG 2.1 A and AA rules) runs on the page with the editor open
and its error listed (step 5), at --width in both schemes: 0 violations.
Screenshots of the embed at each step go into --out (editor-*.jpg).

It can fail: each frame comparison is made against a frame the same run measured, so an editor whose
Apply does nothing fails step 3 (A unchanged), one that applies the wrong file or the wrong text fails
step 4, one that applies a file that did not compile (or loses the last good program) fails step 5,
and a page without the editor fails step 1 (no "Edit the shaders" button).

--firefox FIREFOX runs steps 1-11 but 9's keys in Firefox ESR instead, on its own Xvfb display (tools/web/marionette.py;
no keys are typed there and axe is Chromium's), screenshots from the display (editor-firefox-*.png):
make site-live runs it.

Without the web stages in the site it prints SKIPPED and exits 77, unless --need-embeds.
"""

import argparse
import json
import os
import shutil
import sys
import time

sys.dont_write_bytecode = True
from web import cdp, marionette  # noqa: E402  (the DevTools and Marionette clients; tools/ on PYTHONPATH)
from web.cdp import Failure, evaluate, screenshot  # noqa: E402
import axe_test  # noqa: E402  (axe-core in the page, for --axe)
from keyboard_test import press  # noqa: E402  (keys typed through the DevTools protocol)

SKIP = 77
REC709 = "vec3(0.2126f, 0.7152f, 0.0722f)"
REC601 = "vec3(0.299f, 0.587f, 0.114f)"

# Helpers defined in the site's page: the embed, its editor, its CodeMirror and its frame's pixels.
HELPERS = r"""
(window.__t = {
  live: (s) => document.querySelector(`.live[data-stage="${s}"]`),
  editor: (s) => window.__t.live(s).t10Editor,
  cm: (s) => window.__t.live(s).querySelector('.CodeMirror').CodeMirror,
  file: (s, name) => window.__t.live(s).querySelector(`.t10-editor-file[data-file="${name}"]`),
  button: (s, cls) => window.__t.live(s).querySelector('.' + cls),
  page: (s) => { try { return window.__t.live(s).querySelector('iframe.live-frame').contentDocument.body; } catch (e) { return null; } },
  // The frame as the reader sees it, kept under `key`; returns the share of pixels above 8/255.
  grab: (s, key) => {
    const c = window.__t.live(s).querySelector('iframe.live-frame').contentDocument.getElementById('canvas');
    const t = document.createElement('canvas'); t.width = c.width; t.height = c.height;
    const ctx = t.getContext('2d'); ctx.drawImage(c, 0, 0);
    const d = ctx.getImageData(0, 0, t.width, t.height).data;
    (window.__frames = window.__frames || {})[key] = d;
    let lit = 0; for (let i = 0; i < d.length; i += 4) if (Math.max(d[i], d[i + 1], d[i + 2]) > 8) lit++;
    return JSON.stringify({w: t.width, h: t.height, lit: lit / (d.length / 4)});
  },
  // The share of pixels differing by more than `by` in a channel, and the largest difference.
  diff: (a, b, by) => {
    const x = window.__frames[a], y = window.__frames[b];
    if (!x || !y || x.length !== y.length) return JSON.stringify({share: 1, max: 255, sizes: [x && x.length, y && y.length]});
    let n = 0, max = 0;
    for (let i = 0; i < x.length; i += 4) {
      const m = Math.max(Math.abs(x[i] - y[i]), Math.abs(x[i + 1] - y[i + 1]), Math.abs(x[i + 2] - y[i + 2]));
      if (m > by) n++; if (m > max) max = m;
    }
    return JSON.stringify({share: n / (x.length / 4), max: max});
  },
  state: (s) => {
    const live = window.__t.live(s), page = window.__t.page(s);
    return JSON.stringify({state: live.dataset.state, editor: live.dataset.editor || '',
      pageState: page ? page.dataset.t10 : null, frames: page ? Number(page.dataset.t10Frames || 0) : 0,
      status: (live.querySelector('.t10-editor-status') || {}).textContent || '',
      busy: !!(live.t10Editor && live.t10Editor.busy),
      errors: [...live.querySelectorAll('.t10-editor-error-link')].map(b => ({file: b.dataset.file, line: Number(b.dataset.line), text: b.textContent})),
      marked: [...live.querySelectorAll('.CodeMirror .t10-editor-error-line')].length,
      report: (live.querySelector('.t10-editor-report:not([hidden])') || {}).textContent || '',
      check: !!live.querySelector('.t10-editor-check')});
  },
}, 0)
"""


class Run:
    """The page in headless Chromium (tools/web/cdp.py); keys can be typed."""
    keys = True

    def __init__(self, browser, session, stage, out, width, base):
        self.browser, self.session, self.stage, self.out, self.width, self.base = browser, session, stage, out, width, base

    def open(self, path):
        self.browser.send("Page.navigate", {"url": self.base + path}, self.session)
        self.browser.wait_event("Page.loadEventFired", self.session, timeout=60)

    def js(self, expression, await_promise=False, timeout=60):
        return evaluate(self.browser, self.session, expression, await_promise, timeout)

    def call(self, name, *args):
        return self.js(f"window.__t.{name}({', '.join(json.dumps(a) for a in (self.stage,) + args)})")

    def state(self):
        return json.loads(self.call("state"))

    def click(self, cls):
        self.js(f"window.__t.button({json.dumps(self.stage)}, {json.dumps(cls)}).click()")

    def select(self, name):
        self.js(f"window.__t.file({json.dumps(self.stage)}, {json.dumps(name)}).click()")

    def text(self):
        return self.js(f"window.__t.cm({json.dumps(self.stage)}).getValue()")

    def set_text(self, text):
        self.js(f"window.__t.cm({json.dumps(self.stage)}).setValue({json.dumps(text)})")

    def apply(self, timeout=60):
        """Apply pressed; waits until the editor has finished (its status no longer "Compiling")."""
        self.click("t10-editor-apply")
        return cdp.wait_until(self.state, lambda s: not s["busy"] and "Compiling" not in s["status"], timeout,
                              "the editor did not finish applying", lambda s: f": {s}")

    def grab(self, key):
        time.sleep(0.3)  # the frame drawn after the promise resolved is on the canvas by the next task
        return json.loads(self.call("grab", key))

    def diff(self, a, b, by):
        return json.loads(self.js(f"window.__t.diff({json.dumps(a)}, {json.dumps(b)}, {by})"))

    def shot(self, name):
        """The embed (frame, controls and editor) as a JPEG (PNG takes seconds for a tall one): the viewport made as
        tall as the page meanwhile."""
        rect = json.loads(self.js(f"""(() => {{ const q = window.__t.live({json.dumps(self.stage)}).getBoundingClientRect();
            return JSON.stringify({{x: q.left + scrollX, y: q.top + scrollY, width: q.width, height: q.height,
                                    page: document.documentElement.scrollHeight}}); }})()"""))
        page = rect.pop("page")
        self.browser.send("Emulation.setDeviceMetricsOverride", {"width": self.width, "height": page, "deviceScaleFactor": 1,
                                                                 "mobile": False}, self.session)
        try:
            screenshot(self.browser, self.session, os.path.join(self.out, f"editor-{name}.jpg"), clip=rect)
        finally:
            self.browser.send("Emulation.setDeviceMetricsOverride", {"width": self.width, "height": 900, "deviceScaleFactor": 1,
                                                                     "mobile": False}, self.session)

    def shot_page(self, name):
        """The whole page (a stage page: its canvas, status line and editor) as a JPEG."""
        cdp.full_page_screenshot(self.browser, self.session, os.path.join(self.out, f"editor-{name}.jpg"), self.width)

    def check(self, timeout):
        self.click("t10-editor-check")
        return cdp.wait_until(self.state, lambda s: not s["busy"] and ("Checked" in s["status"] or "failed" in s["status"]),
                              timeout, "the check did not finish", lambda s: f": {s['status']}")


def check_axe(run, source):
    """axe_test.py's rules and run, on the embed alone (its frame, controls and editor: the rest of the page
    is axe_test.py's), in the light and the dark scheme; returns the Findings."""
    context = f"document.querySelector('.live[data-stage=\"{run.stage}\"]')"
    script = axe_test.RUN_AXE.replace("axe.run(document,", f"axe.run({context},")
    if script == axe_test.RUN_AXE:
        raise Failure("axe_test.RUN_AXE no longer calls axe.run(document, ...): editor_test.py cannot limit it to the embed")
    run.js("(() => { window.__axeSource = " + json.dumps(source) + "; const s = document.createElement('script');"
           " s.textContent = window.__axeSource; document.head.appendChild(s); return typeof axe; })()")
    findings = axe_test.Findings()
    for scheme in ("light", "dark"):
        axe_test.set_scheme(run.browser, run.session, scheme)
        started = time.monotonic()
        result = json.loads(run.js(f"{script}({json.dumps(axe_test.TAGS)})", await_promise=True, timeout=120))
        result["seconds"] = time.monotonic() - started
        findings.add(f"the editing embed at {run.width} px, {scheme}", result)
    axe_test.set_scheme(run.browser, run.session, "light")
    return findings


class FirefoxRun(Run):
    """The page in Firefox ESR on its own Xvfb display (tools/web/marionette.py): the same steps but the
    keys typed and axe (Chromium's), screenshots from the display."""
    keys = False

    def __init__(self, browser, stage, out, width, base):
        super().__init__(browser, None, stage, out, width, base)

    def open(self, path):
        self.browser.navigate(self.base + path)

    def js(self, expression, await_promise=False, timeout=60):
        return self.browser.evaluate(expression, timeout)

    def shot_page(self, name):
        """The top of the page (a stage page: its canvas and status line), as the display shows it."""
        self.browser.display_screenshot(os.path.join(self.out, f"editor-firefox-{name}.png"), "body")

    def shot(self, name):
        """The display shows a window's height: the frame, then the editor's panel from its top."""
        self.browser.display_screenshot(os.path.join(self.out, f"editor-firefox-{name}.png"), f'.live[data-stage="{self.stage}"]')
        self.browser.display_screenshot(os.path.join(self.out, f"editor-firefox-{name}-editor.png"),
                                        f'.live[data-stage="{self.stage}"] .live-editor-panel')


def open_editor(run, timeout):
    run.js(HELPERS)
    if not run.js(f"window.t10Live.start({json.dumps(run.stage)})"):
        raise Failure(f"{run.stage}: the embed could not be started (not idle: {run.state()})")
    cdp.wait_until(run.state, lambda s: s["state"] not in ("idle", "loading"), timeout, f"{run.stage}: the embed did not run",
                   lambda s: f": {s}")
    if run.state()["state"] != "rendered":
        raise Failure(f"{run.stage}: the embed did not render: {run.state()}")
    if run.js(f"!!window.__t.button({json.dumps(run.stage)}, 'live-edit') && !window.__t.live({json.dumps(run.stage)}).querySelector('.live-editor').hidden") is not True:
        raise Failure(f"{run.stage}: the running embed offers no \"Edit the shaders\" button")
    run.click("live-edit")
    return cdp.wait_until(run.state, lambda s: s["editor"] in ("ready", "error"), 60, f"{run.stage}: the editor did not open",
                          lambda s: f": {s}")


def steps(run, args, start_text, started, expect):
    """Steps 1-11 of the docstring in one browser (the keys of 9 where run.keys: Chromium's)."""
    # 1. Open: the starting point of make student PART=1.
    s = open_editor(run, 120)
    if s["editor"] != "ready":
        raise Failure(f"the editor did not start: {s['status']}")
    has_check = s["check"]
    run.select("PostProcess.frag")
    expect(run.text() == start_text, "PostProcess.frag does not start as Part 0's (start/PostProcess.frag)")
    run.select("PostProcessInit.frag")
    expect(run.text() == "", "PostProcessInit.frag (new in Part 1) does not start empty")
    run.shot("1-start")
    print(f"1. editor open from Part 0's shaders after {time.monotonic() - started:.1f} s: {s['status']}", flush=True)

    # 2. The reference in both files: frame A.
    for name in ("PostProcess.frag", "PostProcessInit.frag"):
        run.select(name)
        run.click("t10-editor-copy-reference")
    s = run.apply()
    expect(not s["errors"] and "Applied" in s["status"], f"the reference did not apply: {s}")
    frame = run.grab("A")
    expect(frame["lit"] > 0.01, f"frame A is blank: {frame}")
    reference_init = run.text()
    expect(REC709 in reference_init, f"the reference's PostProcessInit.frag has no {REC709}")
    print(f"2. reference applied: {s['status']} ({frame['w']}x{frame['h']})", flush=True)

    # 3. The luminance-weights mistake.
    run.set_text(reference_init.replace(REC709, REC601))
    s = run.apply()
    expect(not s["errors"] and "PostProcessInit.frag" in s["status"], f"the mistake did not apply: {s}")
    run.grab("B")
    d = run.diff("A", "B", 4)
    expect(d["share"] > args.min_changed, f"the luminance-weights mistake changed {d['share']:.1%} of the pixels "
           f"(at most {d['max']}/255), not more than {args.min_changed:.0%}")
    print(f"3. Rec. 601 weights: {d['share']:.1%} of the pixels changed (up to {d['max']}/255)", flush=True)
    if has_check:
        s = run.check(120)
        expect("luminance-weights" in s["report"] or "luminance weights" in s["report"],
               f"the check does not name the luminance-weights mistake: {s['report'][:400]}")
        expect("0.299" in s["report"], f"the check does not report the measured weights (0.299, 0.587, 0.114): {s['report'][:400]}")
        expect("Fix first: step 3" in s["report"] and "Score: 100" not in s["report"],
               f"the check does not put step 3 first, or scores the mistake 100: {s['report'][:300]}")
        expect("luminance-weights" in s["status"], f"the announced result does not name the mistake: {s['status']!r}")
        print(f"   check: {s['status']}", flush=True)
    run.shot("3-mistake")

    # 4. Fixed: frame A again.
    run.set_text(reference_init)
    s = run.apply()
    run.grab("C")
    d = run.diff("A", "C", 2)
    expect(d["share"] == 0, f"fixed, the frame differs from A in {d['share']:.2%} of the pixels (up to {d['max']}/255)")
    if has_check:
        s = run.check(120)
        expect("Score: 100" in s["report"], f"fixed, the check does not score 100: {s['report'][:300]}")
        print(f"   check: {s['status']}", flush=True)
    print(f"4. fixed: the frame is A again (largest difference {d['max']}/255)", flush=True)
    run.shot("4-fixed")

    # 5. A syntax error on a known line of PostProcess.frag.
    run.select("PostProcess.frag")
    lines = run.text().split("\n")
    broken_line = min(len(lines), 12)
    lines.insert(broken_line - 1, "    float fBroken = ;")
    run.set_text("\n".join(lines))
    s = run.apply()
    errors = [e for e in s["errors"] if e["file"] == "PostProcess.frag"]
    expect(errors and errors[0]["line"] == broken_line,
           f"the syntax error on line {broken_line} is listed as {s['errors']}")
    expect(s["marked"] >= 1, "the error's line is not marked in the text")
    expect(s["pageState"] != "error", f"the page went into error on a syntax error: {s}")
    run.grab("D")
    d = run.diff("A", "D", 2)
    expect(d["share"] == 0, f"after the syntax error the frame is not the last good one ({d['share']:.2%} differ)")
    print(f"5. syntax error: {s['errors'][:1]}; the last good frame stays", flush=True)
    run.shot("5-error")
    broken_text = run.text()
    if args.axe and run.keys:
        findings = check_axe(run, axe_test.read_axe(args.axe))
        findings.write(args.out, "axe")
        expect(not findings.total, str(findings.failure()))
        print(f"   axe-core on the editing embed: {findings.runs} runs, {findings.total} violating node(s)", flush=True)

    # 6. A loop the page cannot bound is refused at its line.
    run.select("PostProcessInit.frag")
    init = run.text().split("\n")
    init.insert(len(init) - 2, "    while (true) { }")
    run.set_text("\n".join(init))
    s = run.apply()
    loop = [e for e in s["errors"] if e["file"] == "PostProcessInit.frag"]
    expect(loop and loop[0]["line"] == len(init) - 2 and "while" in loop[0]["text"],
           f"the while loop on line {len(init) - 2} is not refused there: {s['errors']}")
    expect(s["marked"] >= 1, "the refused loop's line is not marked in the text")
    run.shot("6-loop")
    run.set_text(reference_init)
    print(f"6. loop refused: {loop[:1]}", flush=True)

    # 7. Download and upload.
    files = json.loads(run.js(r"""(async () => {
        let blob = null; const keep = URL.createObjectURL;
        URL.createObjectURL = (b) => { blob = b; return keep.call(URL, b); };
        try { window.__t.button(%s, 't10-editor-download').click(); } finally { URL.createObjectURL = keep; }
        return JSON.stringify(await T10Editor.readZip(await blob.arrayBuffer()));
    })()""" % json.dumps(args.stage), await_promise=True))
    names = sorted(f["name"] for f in files)
    expect(names == ["part1/PostProcess.frag", "part1/PostProcessInit.frag"], f"the download holds {names}")
    expect(any(f["name"] == "part1/PostProcess.frag" and f["text"] == broken_text for f in files),
           "the download's PostProcess.frag is not the editor's text")
    uploaded = "// uploaded\n" + start_text
    run.js(r"""(() => { const input = window.__t.live(%s).querySelector('.t10-editor-actions input[type=file]');
        const t = new DataTransfer(); t.items.add(new File([%s], 'PostProcess.frag')); input.files = t.files;
        input.dispatchEvent(new Event('change')); })()""" % (json.dumps(args.stage), json.dumps(uploaded)))
    s = cdp.wait_until(run.state, lambda s: not s["busy"] and "uploaded" in s["status"], 60, "the upload was not applied",
                       lambda s: f": {s['status']}")
    run.select("PostProcess.frag")
    expect(run.text() == uploaded, "the uploaded PostProcess.frag is not in the editor")
    run.set_text(broken_text)
    run.js(f"window.__t.editor({json.dumps(args.stage)}).save()")
    print(f"7. download: {names}; upload: {s['status']}", flush=True)

    # 8. Reload: the work is still there.
    run.open(args.page)
    s = open_editor(run, 120)
    run.select("PostProcess.frag")
    expect(run.text() == broken_text, "after a reload PostProcess.frag is not the work left there")
    run.select("PostProcessInit.frag")
    expect(run.text() == reference_init, "after a reload PostProcessInit.frag is not the work left there")
    errors = [e for e in s["errors"] if e["file"] == "PostProcess.frag"]
    expect(errors and errors[0]["line"] == broken_line, f"after a reload the kept syntax error is not listed: {s['errors']}")
    run.shot("8-reloaded")
    print(f"8. reloaded: the work is kept ({s['status']})", flush=True)

    # 9. The stage's own page with ?edit=1 (its keys where run.keys: Chromium's).
    run.open(f"web/{args.stage}/index.html?edit=1&size=640x360")
    status = "document.querySelector('.t10-editor-status') ? document.querySelector('.t10-editor-status').textContent : ''"
    cm = "document.querySelector('.CodeMirror').CodeMirror"
    text = cdp.wait_until(lambda: run.js(status), lambda v: v and "Loading" not in v and "Compiling" not in v, 60,
                          "the stage page's editor did not open", lambda v: f": {v!r}")
    expect(run.js(f"{cm}.getValue()") == broken_text, "the stage page's editor does not open with the kept work")
    if run.keys:
        stage_page_keys(run, cm, broken_text, expect)
    print(f"9. the stage page with ?edit=1: {text}" + ("; typing, Tab (indents) and Escape-Tab (leaves) work" if run.keys else ""),
          flush=True)

    # 10. The stage page's WebGL context lost: said, and the editor's Apply refused at once.
    run.js(f"{cm}.setValue({cm}.getValue() + '\\n')")
    lose = "document.getElementById('canvas').getContext('webgl2').getExtension('WEBGL_lose_context').loseContext()"
    run.js(lose)
    page_status = "document.getElementById('t10-status').getAttribute('role') + ': ' + document.getElementById('t10-status').textContent"
    said = cdp.wait_until(lambda: run.js(page_status), lambda v: "WebGL stopped" in v, 20,
                          "the stage page did not say its WebGL context was lost", lambda v: f": {v!r}")
    expect(said.startswith("status: ") and "reload" in said, f"the lost context's status line: {said!r}")
    run.js("document.querySelector('.t10-editor-apply').click()")
    # Said in the editor's status line, not marked at a line of the student's file (it is no line's fault).
    editor_status = "document.querySelector('#t10-editor .t10-editor-status').textContent"
    errors = cdp.wait_until(lambda: run.js(editor_status), lambda v: "WebGL stopped" in v, 20,
                            "the editor's Apply after the context was lost was not refused with its message",
                            lambda v: f": the editor's status says {v!r}")
    marked = run.js("document.querySelectorAll('#t10-editor .t10-editor-error-link, #t10-editor .t10-editor-error-line').length")
    expect(marked == 0, f"the lost context marked {marked} line(s) of the student's file as errors")
    run.shot_page("10-context-lost")
    print(f"10. the context lost: {said[:90]}...; Apply answered: {errors[:80]}...", flush=True)

    # 11. The embed's context lost: its own status line says so and offers to run it again.
    run.open(args.page)
    run.js(HELPERS)
    run.js(f"window.t10Live.start({json.dumps(args.stage)})")
    cdp.wait_until(run.state, lambda s: s["state"] == "rendered", 120, "the embed did not run again", lambda s: f": {s}")
    frame = f"window.__t.live({json.dumps(args.stage)}).querySelector('iframe.live-frame').contentDocument"
    run.js(f"{frame}.getElementById('canvas').getContext('webgl2').getExtension('WEBGL_lose_context').loseContext()")
    embed = f"JSON.stringify({{state: window.__t.live({json.dumps(args.stage)}).dataset.state, " \
            f"note: window.__t.live({json.dumps(args.stage)}).querySelector('.live-note').textContent, " \
            f"role: window.__t.live({json.dumps(args.stage)}).querySelector('.live-note').getAttribute('role'), " \
            f"button: window.__t.button({json.dumps(args.stage)}, 'live-start').hidden ? '' : " \
            f"window.__t.button({json.dumps(args.stage)}, 'live-start').textContent}})"
    e = cdp.wait_until(lambda: json.loads(run.js(embed)), lambda v: v["state"] != "rendered", 20,
                       "the embed did not notice its lost context", lambda v: f": {v}")
    expect(e["state"] == "idle" and e["role"] == "status" and "WebGL stopped" in e["note"] and "Run it live again" in e["button"],
           f"the embed after its context was lost: {e}")
    run.click("live-start")
    cdp.wait_until(run.state, lambda s: s["state"] == "rendered", 120, "\"Run it live again\" did not run the embed again",
                   lambda s: f": {s}")
    print(f"11. the embed's context lost: {e['note'][:90]}...; run again: rendered", flush=True)


def stage_page_keys(run, cm, broken_text, expect):
    """Step 9's keys on the stage page's editor: typing, Backspace, Tab and Escape-Tab."""
    run.js(f"{cm}.focus(); {cm}.setCursor({{line: 0, ch: 0}})")
    press(run.browser, run.session, "w")
    typed = run.js(f"{cm}.getValue()")
    press(run.browser, run.session, "Backspace")
    erased = run.js(f"{cm}.getValue()")
    expect(typed == "w" + broken_text and erased == broken_text,
           f"typing in the stage page's editor: W gave {typed[:12]!r}, Backspace {erased[:12]!r}")
    in_text = "!!document.activeElement.closest('.CodeMirror')"
    press(run.browser, run.session, "Tab")
    indented = run.js(f"{cm}.getValue()")
    expect(indented == "    " + broken_text and run.js(in_text) is True,
           f"Tab in the stage page's text gave {indented[:12]!r} with the focus on "
           f"{run.js('document.activeElement.className')!r}: it must indent and stay")
    press(run.browser, run.session, "Escape")
    press(run.browser, run.session, "Tab")
    focused = run.js("document.activeElement.className")
    expect("t10-editor-apply" in focused, f"Escape, then Tab, from the stage page's text reaches {focused!r}, not Apply")
    run.js(f"{cm}.undo()")
    expect(run.js(f"{cm}.getValue()") == broken_text, "Ctrl+Z's undo did not take the indent back")
    help_text = run.js("(document.querySelector('.t10-editor-intro') || {}).textContent || ''")
    expect("Escape, then Tab" in help_text, f"the stage page's editor's help says {help_text!r}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--site", required=True)
    ap.add_argument("--page", default="tutorial10.html")
    ap.add_argument("--stage", default="tutorial10_part1_tonemap")
    ap.add_argument("--chromium", default="chromium")
    ap.add_argument("--renderer", choices=sorted(cdp.RENDERERS), default="swiftshader",
                    help="Chromium's WebGL (make test: llvmpipe, the cheaper one to draw with here)")
    ap.add_argument("--firefox", help="run in this Firefox ESR (under its own Xvfb) instead: steps 1-11 but the keys of 9, without axe")
    ap.add_argument("--out", required=True)
    ap.add_argument("--need-embeds", action="store_true", help="fail (not skip) when the site has no web stage")
    ap.add_argument("--axe", help="axe.min.js: check the page with the editor open too")
    ap.add_argument("--min-changed", type=float, default=0.2,
                    help="the share of pixels the mistake must change (Rec. 601 weights move the key by about "
                         "a tenth, which changes most lit pixels by more than 4 of 255)")
    ap.add_argument("--width", type=int, default=800, help="the window's width (the embed draws at its width)")
    ap.add_argument("--timeout", type=float, default=200)
    args = ap.parse_args()
    if not os.path.isfile(os.path.join(args.site, args.page)):
        raise Failure(f"{args.site}/{args.page} does not exist: build the site first (make site)")
    if not os.path.isfile(os.path.join(args.site, "web", args.stage, "index.html")):
        if args.need_embeds:
            raise Failure(f"{args.site}/web/{args.stage}/ does not exist: the site was built without the web stages")
        print(f"SKIPPED: {args.site} has no web stage {args.stage} (make web, then make site)")
        return SKIP
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.site, "web", args.stage, "start", "PostProcess.frag"), encoding="utf-8") as f:
        start_text = f.read()
    started = time.monotonic()
    problems = []

    def expect(condition, message):
        if not condition:
            problems.append(message)
        return condition

    if args.firefox:
        if not shutil.which(args.firefox) or not shutil.which("Xvfb"):
            print(f"SKIPPED: {args.firefox} or Xvfb not found (apt-get install firefox-esr xvfb)")
            return SKIP
        with marionette.browsing(args.site, args.firefox, os.path.join(args.out, "firefox.log"), started + args.timeout,
                                 (args.width, 900)) as (browser, base):
            run = FirefoxRun(browser, args.stage, args.out, args.width, base)
            run.open(args.page)
            steps(run, args, start_text, started, expect)
        return finish(problems, started, "Firefox")
    with cdp.browsing(args.site, args.chromium, os.path.join(args.out, "chromium.log"), started + args.timeout,
                      gpu_args=cdp.RENDERERS[args.renderer]) as (browser, base):
        _, session = cdp.open_tab(browser, size=(args.width, 900))
        run = Run(browser, session, args.stage, args.out, args.width, base)
        run.open(args.page)
        steps(run, args, start_text, started, expect)

    return finish(problems, started, "Chromium")


def finish(problems, started, engine):
    print(f"editor ({engine}): {time.monotonic() - started:.1f} s")
    if problems:
        raise Failure("\n  ".join([f"{len(problems)} problem(s) with the embed's shader editor in {engine}:"] + problems))
    print(f"ok ({engine}): the Part 1 embed's editor starts from Part 0, applies, shows errors at their lines and keeps the work")
    return 0


if __name__ == "__main__":
    cdp.run_main(main)
