#!/usr/bin/env python3
"""The site's live embeds in Firefox ESR (under its own Xvfb: headless Firefox has no WebGL here).

Loads the built tutorial page in one Firefox (tools/web/marionette.py, Marionette; the pages from a
server on 127.0.0.1), starts its embeds one after the other as a reader clicks them, and checks that
every stage of --stages whose web page was built (WEB/<stage>/index.html) has an embed, that the
embed and the stage's page inside it reach "rendered", and that its canvas is not blank (more than 1%
of the pixels above 8 of 255: the scene is a dim room, not black). Then, in a second Firefox with
WebGL switched off (webgl.disabled), every embed must say that the browser has no WebGL2, keep its
still picture and offer no button. Screenshots: one per running embed (live-firefox-<stage>.png) and
one without WebGL (live-firefox-no-webgl.png).

It can fail: a page whose embeds never start, draw black or break fails the first part; the second
part fails if the site hid a picture or offered a dead button without WebGL (and it runs the same
checks in the other direction: with WebGL, "unavailable" fails the first part).
The frames' agreement with the goldens is tests/web's (the stage pages in Firefox); this test is the
site's embedding: iframes, the site's script, the sizes it asks for. Comparable to site/tests/
live_test.py (Chromium), which also drives the controls; here only the start.

Without any built web stage, or without Firefox or Xvfb, it prints SKIPPED and why and exits 77.
"""

import argparse
import json
import os
import shutil
import sys
import time

sys.dont_write_bytecode = True
from web import cdp, marionette  # noqa: E402  (tools/ on PYTHONPATH)
from web.cdp import Failure  # noqa: E402
from live_embeds import LOAD_PICTURES, no_webgl_problems  # noqa: E402  (beside this script)

SKIP = 77

# Each embed: its stage, its state (live.js: idle, loading, rendered, error, unavailable), its note, its
# page's state and frames, whether its still picture shows and its start button is offered.
STATE = r"""JSON.stringify([...document.querySelectorAll('.live[data-src]')].map(live => {
  const frame = live.querySelector('iframe.live-frame');
  let body = null;
  try { body = frame && frame.contentDocument && frame.contentDocument.body; } catch (e) {}
  const img = live.querySelector('figure.render img');
  return {stage: live.dataset.stage || '', state: live.dataset.state || '',
    note: (live.querySelector('.live-note') || {}).textContent || '',
    pageState: body ? body.dataset.t10 || '' : null, frames: body ? Number(body.dataset.t10Frames || 0) : 0,
    error: body && body.ownerDocument.getElementById('t10-error') ? body.ownerDocument.getElementById('t10-error').textContent : '',
    imageShown: !!img && img.getBoundingClientRect().height > 0 && img.complete && img.naturalWidth > 0,
    button: !!live.querySelector('.live-start:not([hidden])')};
}))"""

# The share of the embed's canvas pixels above 8/255 in any of R, G, B (the page keeps its drawing buffer).
LIT = r"""((stage) => {
  const doc = document.querySelector(`.live[data-stage="${stage}"] iframe.live-frame`).contentDocument;
  const c = doc.getElementById('canvas');
  const t = document.createElement('canvas');
  t.width = c.width; t.height = c.height;
  const ctx = t.getContext('2d');
  ctx.drawImage(c, 0, 0);
  const data = ctx.getImageData(0, 0, t.width, t.height).data;
  let lit = 0;
  for (let i = 0; i < data.length; i += 4) if (Math.max(data[i], data[i + 1], data[i + 2]) > 8) lit++;
  return JSON.stringify({w: t.width, h: t.height, lit: lit / (data.length / 4)});
})"""


def embeds(browser):
    return json.loads(browser.evaluate(STATE))


def wait_embeds(browser, done, timeout, what):
    return cdp.wait_until(lambda: embeds(browser), done, timeout, what,
                          lambda current: "; the embeds: " + "; ".join(
                              f"{e['stage']}: {e['state']} (page {e['pageState']}) {e['note']} {e['error']}".strip()
                              for e in current), interval=0.2)


def check_running(browser, built, out, timeout):
    """Each built stage's embed, started in turn, renders a frame that is not blank."""
    problems = []
    wait_embeds(browser, lambda c: all(e["state"] for e in c), 30, "the site's script did not set up the embeds")
    for stage in built:
        started = time.monotonic()
        if not browser.evaluate(f"t10Live.start({json.dumps(stage)})"):
            problems.append(f"{stage}: no idle embed to start ({[e for e in embeds(browser) if e['stage'] == stage]})")
            continue
        current = wait_embeds(browser, lambda c: all(e["state"] != "loading" for e in c if e["stage"] == stage),
                              timeout, f"{stage}: the embed did not finish loading")
        e = next(e for e in current if e["stage"] == stage)
        if e["state"] != "rendered" or e["pageState"] != "rendered":
            problems.append(f"{stage}: embed {e['state']}, its page's dataset.t10 is {e['pageState']!r}: "
                            f"{e['note']} {e['error']}".strip())
            continue
        got = json.loads(browser.evaluate(f"{LIT}({json.dumps(stage)})"))
        print(f"{stage}: rendered in {time.monotonic() - started:.1f} s, {got['w']}x{got['h']}, "
              f"{e['frames']} frame(s), {got['lit']:.0%} of the pixels lit", flush=True)
        if got["lit"] <= 0.01:
            problems.append(f"{stage}: the canvas is blank ({got['lit']:.2%} of its pixels above 8/255)")
        browser.display_screenshot(os.path.join(out, f"live-firefox-{stage}.png"), f'.live[data-stage="{stage}"]')
    return problems


def check_no_webgl(args, url_path, out):
    """Without WebGL every embed keeps its picture, says why and offers no button."""
    problems = []
    with marionette.browsing(args.site, args.firefox, os.path.join(out, "firefox-no-webgl.log"),
                             time.monotonic() + 90, (args.width, 900), {"webgl.disabled": True}) as (browser, base):
        browser.navigate(base + url_path)
        wait_embeds(browser, lambda c: all(e["state"] not in ("", "idle") for e in c), 30,
                    "without WebGL the embeds did not notice")
        # The pictures below the first screen load lazily (issue 50's page weight): each is made to load,
        # then looked at, as live_test.py does in Chromium.
        browser.evaluate(LOAD_PICTURES)
        current = embeds(browser)
        problems += no_webgl_problems(current)
        if current:
            first = current[0]["stage"]
            browser.display_screenshot(os.path.join(out, "live-firefox-no-webgl.png"), f'.live[data-stage="{first}"]')
        print(f"without WebGL: {len(current)} embed(s) keep their pictures", flush=True)
    return problems


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--site", required=True, help="the built site")
    ap.add_argument("--web", required=True, help="the web stages (make web: out/web)")
    ap.add_argument("--stages", required=True, help="stage names, comma-separated")
    ap.add_argument("--page", default="tutorial10.html")
    ap.add_argument("--firefox", default="firefox-esr")
    ap.add_argument("--out", required=True, help="folder for screenshots and Firefox's logs")
    ap.add_argument("--timeout", type=float, default=60, help="seconds for each embed to load")
    ap.add_argument("--width", type=int, default=900, help="the window's width (the embeds render at their width)")
    args = ap.parse_args()

    missing = [p for p in (args.firefox, "Xvfb") if not shutil.which(p)]
    if missing:
        print(f"SKIPPED: {', '.join(missing)} not found (apt-get install firefox-esr xvfb)")
        return SKIP
    built = [n for n in args.stages.split(",") if n and os.path.isfile(os.path.join(args.web, n, "index.html"))]
    if not built:
        print(f"SKIPPED: no web stage is built in {args.web} (make web builds them), "
              f"so the site has no live embed to test")
        return SKIP
    if not os.path.isfile(os.path.join(args.site, args.page)):
        raise Failure(f"{args.site}/{args.page} does not exist: build the site first (make site)")
    os.makedirs(args.out, exist_ok=True)
    started = time.monotonic()
    with marionette.browsing(args.site, args.firefox, os.path.join(args.out, "firefox.log"),
                             started + args.timeout * len(built) + 60, (args.width, 900)) as (browser, base):
        browser.navigate(base + args.page)
        problems = check_running(browser, built, args.out, args.timeout)
    problems += check_no_webgl(args, args.page, args.out)
    print(f"finished in {time.monotonic() - started:.1f} s; screenshots in {args.out}", flush=True)
    if problems:
        raise Failure("\n  ".join([f"{len(problems)} problem(s) with the live embeds in Firefox:"] + problems))
    print(f"ok: {len(built)} live embed(s) render in Firefox, and without WebGL the pictures stay")
    return 0


if __name__ == "__main__":
    cdp.run_main(main)
