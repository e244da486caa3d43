#!/usr/bin/env python3
"""Loads a page of the built site in headless Chromium and checks what a reader would see.

The site is served from a local HTTP server on 127.0.0.1 (a free port) and Chromium is driven over
the DevTools protocol through a pipe (tools/web/cdp.py, the repository's one client), so nothing
beyond the Python standard library and Debian's chromium is needed. Chromium resolves every host name except 127.0.0.1 to
"not found", and every request it makes is recorded: the page must not reach for the network.

Checks, in both the light and the dark scheme:
  - every formula rendered: as many KaTeX elements as the HTML has \\( \\) and \\[ \\] formulas, no
    KaTeX error, no raw $$, \\( or \\[ left in the text;
  - every image loaded (complete, natural width > 0; the rendered frames are 1280x720);
  - nothing makes the page wider than the window (--width 400: captions and code captions wrap);
  - the step numbers the reader sees (CSS counters, read back from the layout) run 1..N in order and
    match the step anchors;
  - every code excerpt has code;
  - no request failed or went anywhere but the local server, and no script error was reported;
  - each --section ID (e.g. the students' "Check your work") is on the page, laid out with a height,
    shows `make check PART=`, and, given as ID<OTHER, comes before the element OTHER (near the top);
    the section "check-your-work" also shows `make student PART=` and `make run STAGE=student_part`.
--plain is for pages without formulas, steps, code excerpts or rendered frames (building.html): those
must then be absent or complete, not present.
It writes full-page screenshots (<page>-light.jpg, <page>-dark.jpg) into --out: JPEGs, since a PNG of
the 32000-pixel tall tutorial page costs Chromium 3-4 s to encode, a JPEG about 1 s.
"""

import argparse
import html.parser
import json
import os
import re
import shutil
import sys
import time

sys.dont_write_bytecode = True
from web import cdp  # noqa: E402  (the DevTools client: Browser, the local server, evaluate, screenshots)

Failure = cdp.Failure


# --- The static HTML: how many formulas should be rendered -------------------------------------

class FormulaCounter(html.parser.HTMLParser):
    SKIP = {"pre", "code", "script", "style", "textarea"}

    def __init__(self):
        super().__init__()
        self.depth = 0
        self.text = []

    def handle_starttag(self, tag, attrs):
        if tag in self.SKIP:
            self.depth += 1

    def handle_endtag(self, tag):
        if tag in self.SKIP and self.depth:
            self.depth -= 1

    def handle_data(self, data):
        if not self.depth:
            self.text.append(data)


def expected_formulas(path):
    counter = FormulaCounter()
    with open(path, encoding="utf-8") as f:
        counter.feed(f.read())
    text = "".join(counter.text)
    return len(re.findall(r"\\\(", text)), len(re.findall(r"\\\[", text))


# --- What the page shows -------------------------------------------------------------------------

PAGE_STATE = r"""
(() => {
  const content = document.querySelector('.content');
  const r = {};
  r.math = document.documentElement.dataset.math || '';
  r.katex = document.querySelectorAll('.content .katex').length;
  r.katexDisplay = document.querySelectorAll('.content .katex-display').length;
  r.katexErrors = [...document.querySelectorAll('.katex-error')].map(e => e.textContent.slice(0, 80));
  const raw = [];
  const walker = document.createTreeWalker(content, NodeFilter.SHOW_TEXT, {
    acceptNode: n => n.parentElement.closest('pre, code, script, style, .katex')
      ? NodeFilter.FILTER_REJECT : NodeFilter.FILTER_ACCEPT });
  for (let n; (n = walker.nextNode());)
    if (/\$\$|\\\(|\\\)|\\\[|\\\]/.test(n.nodeValue)) raw.push(n.nodeValue.trim().slice(0, 80));
  r.rawMath = raw;
  r.images = [...document.images].map(i => ({src: i.getAttribute('src'), complete: i.complete,
    w: i.naturalWidth, h: i.naturalHeight, render: !!i.closest('figure.render:not(.derived)')}));
  r.items = [...document.querySelectorAll('.steps > ol:not(#markdown-toc) > li')].map(li => li.id);
  r.excerpts = [...document.querySelectorAll('.content figure.excerpt')].map(f => ({
    step: f.dataset.step, stage: f.dataset.stage, file: f.dataset.file,
    blocks: f.querySelectorAll('pre').length,
    folded: !!f.closest('details:not([open])'),
    empty: [...f.querySelectorAll('pre')].filter(p => p.textContent.trim().length === 0).length,
    chars: [...f.querySelectorAll('pre')].reduce((s, p) => s + p.textContent.trim().length, 0)}));
  r.missing = [...document.querySelectorAll('.excerpt-missing')].map(p => p.dataset.step);
  r.background = getComputedStyle(document.body).backgroundColor;
  r.height = document.documentElement.scrollHeight;
  r.scrollWidth = document.documentElement.scrollWidth;
  r.innerWidth = window.innerWidth;
  // What sticks out past the right edge, outside the boxes that scroll on their own (code, diffs, formulas).
  r.wide = [...document.querySelectorAll('body *')].filter(e => e.getBoundingClientRect().right > innerWidth + 1
      && !e.closest('pre, .diff, .katex-display, .katex-mathml, .table-wrap, table'))
    .slice(0, 5).map(e => e.tagName.toLowerCase() + (e.className ? '.' + String(e.className).split(' ')[0] : '')
      + ': ' + (e.textContent || '').trim().slice(0, 50));
  return JSON.stringify(r);
})()
"""


def rendered_step_numbers(browser, session):
    """The numbers the reader sees in front of each step: the CSS counters of the ::before boxes,
    read back from Chromium's layout tree (generated content is laid out as text)."""
    snap = browser.send("DOMSnapshot.captureSnapshot", {"computedStyles": [], "includeDOMRects": False},
                        session, timeout=60)
    strings = snap["strings"]
    doc = snap["documents"][0]
    nodes, layout = doc["nodes"], doc["layout"]
    parent = nodes["parentIndex"]
    names = nodes["nodeName"]
    attributes = nodes["attributes"]
    pseudo = {i: strings[t] for i, t in zip(nodes["pseudoType"]["index"], nodes["pseudoType"]["value"])}

    def attr(i, name):
        a = attributes[i]
        for k, v in zip(a[::2], a[1::2]):
            if strings[k] == name:
                return strings[v]
        return None

    # Text of the layout objects that belong to a ::before pseudo-element of a step <li>.
    found = []
    for node, text in zip(layout["nodeIndex"], layout["text"]):
        if text < 0:
            continue
        i = node
        while i >= 0 and pseudo.get(i) != "before":
            i = parent[i]
        if i < 0:
            continue
        li = parent[i]
        if strings[names[li]].lower() != "li":
            continue
        ol = parent[li]
        if "markdown-toc" == attr(ol, "id"):
            continue
        found.append((attr(li, "id"), strings[text].strip()))
    return found


SECTION_STATE = r"""
((id, before) => {
  const e = document.getElementById(id);
  if (!e) return JSON.stringify(null);
  // A heading's section runs to the next heading of its level or higher; another element is itself.
  let text = e.textContent;
  if (/^H[1-6]$/.test(e.tagName)) {
    for (let n = e.nextElementSibling; n && !(/^H[1-6]$/.test(n.tagName) && n.tagName <= e.tagName);
         n = n.nextElementSibling)
      text += '\n' + n.textContent;
  }
  const other = before ? document.getElementById(before) : null;
  return JSON.stringify({height: e.getBoundingClientRect().height, top: e.getBoundingClientRect().top,
    text: text, beforeTop: other ? other.getBoundingClientRect().top : null, beforeFound: !!other});
})
"""

# What each section must show; "check-your-work" carries the three commands.
SECTION_TEXT = {"check-your-work": ["make student PART=", "make check PART=", "make run STAGE=student_part"]}


def check_sections(browser, session, sections, label):
    problems = []
    for spec in sections:
        sid, _, before = spec.partition("<")
        state = json.loads(cdp.evaluate(browser, session, f"{SECTION_STATE}({json.dumps(sid)}, {json.dumps(before)})"))
        if state is None:
            problems.append(f"[{label}] section #{sid} missing")
            continue
        if state["height"] <= 0:
            problems.append(f"[{label}] section #{sid} is not laid out (height {state['height']})")
        for needed in SECTION_TEXT.get(sid, ["make check PART="]):
            if needed not in state["text"]:
                problems.append(f"[{label}] section #{sid} does not show '{needed}'")
        if before and not state["beforeFound"]:
            problems.append(f"[{label}] section #{sid}: #{before} missing, so its place cannot be checked")
        elif before and state["top"] >= state["beforeTop"]:
            problems.append(f"[{label}] section #{sid} comes after #{before}, not before it")
    return problems


def check(state, page_html, expected_steps, allow_missing_from, label, plain=False):
    problems = []
    inline, display = expected_formulas(page_html)
    if state["math"] != "done":
        problems.append(f"KaTeX did not run (data-math={state['math']!r})")
    if state["katex"] != inline + display or state["katexDisplay"] != display:
        problems.append(f"{state['katex']} formulas rendered ({state['katexDisplay']} displayed), "
                        f"the HTML has {inline + display} ({display} displayed)")
    if inline + display == 0 and not plain:
        problems.append("the page has no formulas at all")
    if state["katexErrors"]:
        problems.append(f"KaTeX errors: {state['katexErrors']}")
    if state["rawMath"]:
        problems.append(f"raw math left in the text: {state['rawMath'][:5]}")
    if not state["images"] and not plain:
        problems.append("no images")
    for img in state["images"]:
        if not img["complete"] or img["w"] <= 0:
            problems.append(f"image not loaded: {img['src']}")
        elif img["render"] and (img["w"], img["h"]) != (1280, 720):
            problems.append(f"rendered frame {img['src']} is {img['w']}x{img['h']}, not 1280x720")
    if state["scrollWidth"] > state["innerWidth"] + 1:
        problems.append(f"the page is {state['scrollWidth']} px wide in a {state['innerWidth']} px window, so it "
                        f"pans sideways; sticking out: {state['wide']}")
    wanted = [f"step-{n}" for n in range(1, expected_steps + 1)]
    if state["items"] != wanted:
        problems.append(f"step anchors are {state['items']}, expected step-1 .. step-{expected_steps} in order")
    if not state["excerpts"] and not plain:
        problems.append("no code excerpts")
    for ex in state["excerpts"]:
        if ex["blocks"] == 0 or ex["empty"] or ex["chars"] == 0:
            problems.append(f"empty excerpt: step {ex['step']} {ex['stage']}/{ex['file']}")
    for step in state["missing"]:
        if int(step) < allow_missing_from:
            problems.append(f"step {step} shows the 'no code yet' placeholder")
    return [f"[{label}] {p}" for p in problems]


def event_problems(events, base, label):
    """What the page's events tell: a request beyond the local server (at `base`), a failed one, a script
    or console error."""
    problems = []
    for event in events:
        method, params = event.get("method"), event.get("params", {})
        if method == "Network.requestWillBeSent":
            url = params["request"]["url"]
            if not (url.startswith(base) or url.startswith(("data:", "about:", "blob:"))):
                problems.append(f"[{label}] request outside the local server: {url}")
        elif method == "Network.responseReceived" and params["response"]["status"] >= 400:
            problems.append(f"[{label}] HTTP {params['response']['status']}: {params['response']['url']}")
        elif method == "Network.loadingFailed":
            problems.append(f"[{label}] request failed: {params.get('errorText')}")
        elif method == "Runtime.exceptionThrown":
            problems.append(f"[{label}] script error: {params['exceptionDetails'].get('text')}")
        elif method == "Log.entryAdded" and params["entry"]["level"] == "error":
            problems.append(f"[{label}] console error: {params['entry'].get('text')}")
    return problems


def run(site, page, chromium, out, steps, allow_missing_from=37, width=1280, timeout=100,
        schemes=("light", "dark"), plain=False, sections=()):
    """Loads the page in each scheme; returns the list of problems found (empty: all good)."""
    started = time.monotonic()
    page_html = os.path.join(site, page)
    if not os.path.isfile(page_html):
        raise Failure(f"{page_html} does not exist: build the site first (make site)")
    if not shutil.which(chromium):
        raise Failure(f"{chromium}: not found (apt-get install chromium)")
    os.makedirs(out, exist_ok=True)
    stem = os.path.splitext(os.path.basename(page))[0]
    problems = []
    light_background = None
    with cdp.browsing(site, chromium, os.path.join(out, "chromium.log"), started + timeout) as (browser, base):
        _, session = cdp.open_tab(browser, ("Page", "Network", "Runtime", "Log"), (width, 900))
        for scheme in schemes:
            browser.send("Emulation.setEmulatedMedia",
                         {"features": [{"name": "prefers-color-scheme", "value": scheme}]}, session)
            browser.drain()
            browser.send("Page.navigate", {"url": base + page}, session)
            browser.wait_event("Page.loadEventFired", session, timeout=60)
            cdp.evaluate(browser, session, "document.fonts.ready.then(() => true)", await_promise=True)
            state = json.loads(cdp.evaluate(browser, session, PAGE_STATE))
            problems += check(state, page_html, steps, allow_missing_from, scheme, plain)
            problems += check_sections(browser, session, sections, scheme)

            numbers = rendered_step_numbers(browser, session)
            shown = [(anchor, text.rstrip(".")) for anchor, text in numbers]
            wanted = [(f"step-{n}", str(n)) for n in range(1, steps + 1)]
            if shown != wanted:
                problems.append(f"[{scheme}] the numbers shown in front of the steps are "
                                f"{[t for _, t in shown]} (anchors {[a for a, _ in shown]}), "
                                f"expected 1..{steps} on step-1..step-{steps}")
            if scheme == "light":
                light_background = state["background"]
            elif state["background"] == light_background:
                problems.append(f"[{scheme}] the page background stays {state['background']} in the dark scheme")

            shot = os.path.join(out, f"{stem}-{scheme}.jpg")
            height = cdp.full_page_screenshot(browser, session, shot, width)
            print(f"{scheme}: {state['katex']} formulas, {len(state['images'])} images, "
                  f"{len(state['excerpts'])} excerpts, steps "
                  f"{shown[0][1] if shown else '-'}..{shown[-1][1] if shown else '-'}; "
                  f"screenshot {shot} ({width}x{height})", flush=True)
            # Everything the page asked for came from the local server, and nothing failed.
            problems += event_problems(browser.drain(), base, scheme)
    print(f"finished in {time.monotonic() - started:.1f} s", flush=True)
    return problems


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--site", required=True, help="the built site")
    ap.add_argument("--page", default="tutorial10.html")
    ap.add_argument("--chromium", default="chromium")
    ap.add_argument("--out", required=True, help="folder for the screenshots and Chromium's log")
    ap.add_argument("--steps", type=int, default=40, help="the page must number its steps 1..STEPS")
    ap.add_argument("--allow-missing-from", type=int, default=37,
                    help="steps from this one on may show the 'code not in the repository yet' note")
    ap.add_argument("--width", type=int, default=1280)
    ap.add_argument("--timeout", type=float, default=100, help="seconds for the whole test")
    ap.add_argument("--plain", action="store_true", help="a page without formulas, steps, excerpts or frames")
    ap.add_argument("--section", action="append", default=[], metavar="ID[<OTHER]",
                    help="an element that must be shown (before #OTHER when given)")
    args = ap.parse_args()
    problems = run(args.site, args.page, args.chromium, args.out, args.steps, args.allow_missing_from,
                   args.width, args.timeout, plain=args.plain, sections=args.section)
    if problems:
        raise Failure("\n  ".join([f"{len(problems)} problem(s) on {args.page}:"] + problems))
    print(f"ok: {args.page} renders completely in both schemes")


if __name__ == "__main__":
    cdp.run_main(main)
