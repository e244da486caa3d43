#!/usr/bin/env python3
"""Every page of the built site checked by axe-core (WCAG 2.0 and 2.1, levels A and AA) in headless Chromium.

Each page (every .html of the site but the web stages' own pages under web/) is loaded from 127.0.0.1 at
each --width (800: the one-column layout; 1280: the sidebar beside the text), in the light and then the
dark scheme (set as the sidebar's button sets it), and axe-core (pinned in site/tests/axe/package-lock.json;
make installs it into build/site-axe/) runs its rules tagged wcag2a, wcag2aa, wcag21a and wcag21aa, in
the page and in every frame it holds. The tutorial page with every live embed running is checked the
same way by keyboard_test.py --axe (which has them running already), or here with --with-embeds.

--pairwise (make test) checks each page once per width, the narrow one in the light scheme and the wide
one in the dark, so that every page, width and scheme is checked in half the runs (16 instead of 32,
about 14 s instead of 27 on two cores); the whole matrix, every width in both schemes, runs in make
site-audit, which CI runs (.ci/run).

Passing means 0 violations, and no text whose contrast axe could not decide because of a pseudo-
element's background (the 1280-px sidebar once drew its colour with .layout::before, so axe skipped
the contrast of every word in it: that is reported as a violation here, not let through).

It can fail: on the site as it was before issue 50 (commit 2cee4be, with its five embeds running) it
reports 931 violating nodes over 32 runs (colour contrast 719, scrollable regions a keyboard cannot
reach 196, the theme toggle's name not containing its visible text 16) and 19502 texts whose contrast
axe could not decide for a pseudo-element's background (the sidebar's and the step numbers' circles).
"""

import argparse
import json
import os
import sys
import time

sys.dont_write_bytecode = True
from web import cdp  # noqa: E402  (the DevTools client; tools/ on PYTHONPATH)
from web.cdp import Failure, evaluate  # noqa: E402

TAGS = ["wcag2a", "wcag2aa", "wcag21a", "wcag21aa"]

# axe in the page and in every live embed's page (same origin), then the run; returns the violations
# and the contrast checks axe left undecided because of a pseudo-element, as JSON.
RUN_AXE = r"""
(async (tags) => {
  for (const frame of document.querySelectorAll('iframe')) {
    const doc = frame.contentDocument;
    if (!doc || !doc.head || frame.contentWindow.axe) continue;
    const script = doc.createElement('script');
    script.textContent = window.__axeSource;
    doc.head.appendChild(script);
  }
  const result = await axe.run(document, {runOnly: {type: 'tag', values: tags}, resultTypes: ['violations', 'incomplete'],
                                          iframes: true, frameWaitTime: 20000});
  const brief = (rule) => ({id: rule.id, impact: rule.impact, help: rule.help,
      nodes: rule.nodes.map(n => ({target: n.target.join(' > '), summary: (n.failureSummary || '').split('\n').slice(0, 3).join(' '),
                                   html: n.html.slice(0, 160)}))});
  const pseudo = result.incomplete.filter(r => r.id === 'color-contrast').map(rule => Object.assign(brief(rule), {
      nodes: brief(rule).nodes.filter((n, i) => /pseudo/i.test(JSON.stringify(rule.nodes[i].any.map(a => a.data))))}))
      .filter(r => r.nodes.length);
  return JSON.stringify({violations: result.violations.map(brief), pseudo: pseudo});
})
"""

STATE = r"""
JSON.stringify([...document.querySelectorAll('.live[data-src]')].map(l => ({stage: l.dataset.stage, state: l.dataset.state,
  note: (l.querySelector('.live-note') || {}).textContent || ''})))
"""


def pages_of(site):
    found = []
    for root, dirs, files in os.walk(site):
        rel = os.path.relpath(root, site)
        if rel.split(os.sep)[0] in ("web", "assets"):
            dirs[:] = []
            continue
        found += [os.path.normpath(os.path.join(rel, f)) for f in files if f.endswith(".html")]
    return sorted(found)


def load(browser, session, url, width):
    browser.send("Emulation.setDeviceMetricsOverride", {"width": width, "height": 900, "deviceScaleFactor": 1, "mobile": False}, session)
    browser.send("Page.navigate", {"url": url}, session)
    browser.wait_event("Page.loadEventFired", session, timeout=60)
    cdp.wait_until(lambda: evaluate(browser, session, "document.documentElement.dataset.scrollables || ''"),
                   lambda v: v == "marked", 30, "the page's script did not finish (formulas, scrolling blocks)")


def set_scheme(browser, session, scheme):
    evaluate(browser, session, f"document.documentElement.setAttribute('data-theme', '{scheme}')")


def run_axe(browser, session):
    started = time.monotonic()
    if not evaluate(browser, session, "typeof axe !== 'undefined'"):
        evaluate(browser, session, "(() => { const s = document.createElement('script'); s.textContent = window.__axeSource;"
                                   " document.head.appendChild(s); return typeof axe; })()")
    result = json.loads(evaluate(browser, session, f"{RUN_AXE}({json.dumps(TAGS)})", await_promise=True, timeout=180))
    result["seconds"] = time.monotonic() - started
    return result


class Findings:
    """What the axe runs found: a line per violating rule, every node (for axe-nodes.json), the count."""

    def __init__(self):
        self.lines, self.details, self.total, self.runs = [], {}, 0, 0

    def add(self, where, result):
        self.details[where] = result
        self.runs += 1
        print(f"{where}: {result['seconds']:.1f} s", flush=True)
        for rule in result["violations"] + [dict(r, id="color-contrast undecided: a pseudo-element's background")
                                            for r in result["pseudo"]]:
            self.total += len(rule["nodes"])
            first = rule["nodes"][0] if rule["nodes"] else {}
            self.lines.append(f"{where}: {rule['id']} ({rule.get('impact')}), {len(rule['nodes'])} node(s): {rule['help']}; "
                              f"first: {first.get('target')} {first.get('html', '')!r} {first.get('summary', '')}")

    def write(self, out, name):
        with open(os.path.join(out, f"{name}-report.txt"), "w") as f:
            f.write("\n".join(self.lines) + "\n")
        with open(os.path.join(out, f"{name}-nodes.json"), "w") as f:
            json.dump(self.details, f, indent=1)

    def failure(self):
        return Failure(f"{self.total} violating node(s) (WCAG 2.0/2.1 A and AA, axe-core):\n  " + "\n  ".join(self.lines))


def set_axe_source(browser, session, source):
    """axe's source, kept in every page the tab loads (run_axe injects it into the page and its frames)."""
    browser.send("Page.addScriptToEvaluateOnNewDocument", {"source": "window.__axeSource = " + json.dumps(source) + ";"}, session)


def read_axe(path):
    if not os.path.isfile(path):
        raise Failure(f"{path} does not exist: make installs axe-core there (npm ci, site/tests/axe/package-lock.json); "
                      f"run make test, or make site-deps")
    with open(path, encoding="utf-8") as f:
        return f.read()


def check_loaded(browser, session, widths, label, findings, schemes=("light", "dark")):
    """axe on the page as it is now, at each width (widest first) and in each of `schemes`."""
    for width in sorted(widths, reverse=True):
        browser.send("Emulation.setDeviceMetricsOverride",
                     {"width": width, "height": 900, "deviceScaleFactor": 1, "mobile": False}, session)
        time.sleep(0.3)  # the resize event, on which site.js marks the blocks that now scroll
        for scheme in schemes:
            set_scheme(browser, session, scheme)
            findings.add(f"{label} at {width} px, {scheme}", run_axe(browser, session))


def start_embeds(browser, session, timeout):
    """Starts every embed of the page, one after the other as a reader clicks them (two cores); returns
    their stages once all are running."""
    stages = [s["stage"] for s in json.loads(evaluate(browser, session, STATE))]
    for stage in stages:
        evaluate(browser, session, f"t10Live.start({json.dumps(stage)})")
        cdp.wait_until(lambda: json.loads(evaluate(browser, session, STATE)),
                       lambda c: all(s["state"] != "loading" for s in c if s["stage"] == stage), timeout,
                       f"{stage}: the embed did not finish loading", lambda c: f": {c}", interval=0.2)
    current = json.loads(evaluate(browser, session, STATE))
    broken = [f"{s['stage']}: {s['state']} {s['note']}" for s in current if s["state"] != "rendered"]
    if broken:
        raise Failure("embeds that did not run: " + "; ".join(broken))
    return stages


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--site", required=True, help="the built site")
    ap.add_argument("--axe", required=True, help="axe.min.js (build/site-axe/node_modules/axe-core/axe.min.js)")
    ap.add_argument("--chromium", default="chromium")
    ap.add_argument("--out", required=True, help="folder for Chromium's log and the report")
    ap.add_argument("--widths", default="800,1280")
    ap.add_argument("--pairwise", action="store_true",
                    help="each width in one scheme (the narrowest light, the next dark, ...), not in both")
    ap.add_argument("--tutorial", default="tutorial10.html", help="the page whose embeds run")
    ap.add_argument("--with-embeds", action="store_true",
                    help="also the tutorial with every embed running (make test does this in keyboard_test.py --axe)")
    ap.add_argument("--timeout", type=float, default=400)
    args = ap.parse_args()
    source = read_axe(args.axe)
    widths = [int(w) for w in args.widths.split(",")]
    pages = pages_of(args.site)
    if args.tutorial not in pages:
        raise Failure(f"{args.site}/{args.tutorial} does not exist: build the site first (make site)")
    os.makedirs(args.out, exist_ok=True)
    started = time.monotonic()
    findings = Findings()
    with cdp.browsing(args.site, args.chromium, os.path.join(args.out, "chromium.log"), started + args.timeout,
                      gpu_args=cdp.RENDERERS["swiftshader"]) as (browser, base):
        _, session = cdp.open_tab(browser)
        set_axe_source(browser, session, source)
        for page in pages:
            # Each page once per width, then its scheme switched as its toggle button does (a reload for
            # the dark one would cost a second a page and check nothing more).
            for i, width in enumerate(sorted(widths)):
                load(browser, session, base + page, width)
                schemes = (("light", "dark")[i % 2],) if args.pairwise else ("light", "dark")
                check_loaded(browser, session, [width], page, findings, schemes)
        if args.with_embeds:
            load(browser, session, base + args.tutorial, max(widths))
            stages = start_embeds(browser, session, 120)
            check_loaded(browser, session, widths, f"{args.tutorial} with {len(stages)} embeds running", findings)
    findings.write(args.out, "axe")
    print(f"axe-core: {findings.runs} runs over {len(pages)} pages ({', '.join(pages)}) at {args.widths} px, {'one scheme each' if args.pairwise else 'light and dark'}"
          f"{', the tutorial with its embeds running' if args.with_embeds else ''}: {findings.total} violating node(s) "
          f"in {time.monotonic() - started:.1f} s")
    if findings.total:
        raise findings.failure()
    return 0


if __name__ == "__main__":
    cdp.run_main(main)
