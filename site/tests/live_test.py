#!/usr/bin/env python3
"""The site's live embeds (issue 36) in headless Chromium with WebGL2 (ANGLE on SwiftShader).

Loads the built tutorial page, served from 127.0.0.1, starts its embeds one by one, and checks:
  - every stage of --stages whose web page was built (WEB/<stage>/index.html) has an embed on the page,
    and its copy is in the built site (SITE/web/<stage>/);
  - inside each embed the stage's page reaches dataset.t10 == "rendered" and its canvas is not blank
    (more than 1% of its pixels above 8 of 255: the scene is a dim room, not black);
  - the embed of --controls-stage has a control for every option its page lists in Module.t10Options()
    (the site holds no second copy), among them --need (the exercises' settings and the view), and the
    controls change the frame: each --change NAME=VALUE, set through its control, gives a frame that
    differs from the default one in more than --min-changed of the pixels by more than 4 of 255, and
    putting the control back gives the default frame again (within 2 of 255 at every pixel: the same
    settings draw the same frame, so a difference comes from the setting);
  - with WebGL switched off (--disable-3d-apis) every embed says the browser has no WebGL2 and keeps
    its still picture, and no embed starts.
Writes screenshots: the table of download sizes and first-frame times (live-costs.png), each embed
running (live-<stage>.png),
the exercises' embed after each change (live-<stage>-<name>-<value>.png) and the page without WebGL
(live-no-webgl.png).

Without any built web stage (make web not run on this machine) it prints SKIPPED and why and exits
77 (never 0). `make site-live` runs it (the CMake target site-live; not part of make test: two minutes
on two cores). Comparisons with the goldens are the web tests' (tests/web/), not this test's.
"""

import argparse
import json
import os
import re
import sys
import time

sys.dont_write_bytecode = True
from web import cdp  # noqa: E402  (the DevTools client; tools/ on PYTHONPATH)
from web.cdp import Failure, evaluate, screenshot  # noqa: E402
from live_embeds import LOAD_PICTURES, no_webgl_problems  # noqa: E402  (beside this script)

# WebGL2 as Chromium draws it without a usable GPU: ANGLE on SwiftShader, its own software renderer (no
# EXT_texture_norm16: the pages emulate GL_R16). The goldens' rasteriser, llvmpipe, is the web tests'.
WEBGL_ARGS = cdp.RENDERERS["swiftshader"]

SKIP = 77

STATE = r"""
(() => JSON.stringify([...document.querySelectorAll('.live')].map(live => {
  const frame = live.querySelector('iframe.live-frame');
  let page = null;
  try { page = frame && frame.contentDocument && frame.contentDocument.body; } catch (e) {}
  const img = live.querySelector('figure.render img');
  return {stage: live.dataset.stage || '', src: live.dataset.src || '', state: live.dataset.state || '',
    note: (live.querySelector('.live-note') || {}).textContent || '',
    pageState: page ? page.dataset.t10 || '' : null, frames: page ? Number(page.dataset.t10Frames || 0) : 0,
    error: page && page.ownerDocument.getElementById('t10-error') ? page.ownerDocument.getElementById('t10-error').textContent : '',
    controls: [...live.querySelectorAll('.live-controls [data-option]:not(label)')].map(c => c.dataset.option),
    status: (live.querySelector('.live-control-status') || {}).textContent || '',
    statusError: !!live.querySelector('.live-control-error'),
    imageShown: !!img && img.getBoundingClientRect().height > 0 && img.complete && img.naturalWidth > 0,
    button: !!live.querySelector('.live-start:not([hidden])')};
})))()
"""

# The canvas of one embed's page, drawn into a 2D canvas and kept under `key` in the site page; returns
# its size and the share of pixels above 8/255 (the numbers are computed in the page: a frame is a
# million values).
PIXELS = r"""
((stage, key) => {
  const live = document.querySelector(`.live[data-stage="${stage}"]`);
  const doc = live.querySelector('iframe.live-frame').contentDocument;
  const c = doc.getElementById('canvas');
  const t = document.createElement('canvas');
  t.width = c.width; t.height = c.height;
  const ctx = t.getContext('2d');
  ctx.drawImage(c, 0, 0);
  const data = ctx.getImageData(0, 0, t.width, t.height).data;
  (window.__t10Frames = window.__t10Frames || {})[key] = data;
  let lit = 0;
  for (let i = 0; i < data.length; i += 4) if (Math.max(data[i], data[i + 1], data[i + 2]) > 8) lit++;
  return JSON.stringify({w: t.width, h: t.height, lit: lit / (data.length / 4)});
})
"""

# The share of pixels where any of R, G, B differs by more than `threshold` (of 255) between two kept frames.
DIFFER = r"""
((a, b, threshold) => {
  const x = window.__t10Frames[a], y = window.__t10Frames[b];
  if (x.length !== y.length) return 1;
  let n = 0;
  for (let i = 0; i < x.length; i += 4)
    if (Math.max(Math.abs(x[i] - y[i]), Math.abs(x[i + 1] - y[i + 1]), Math.abs(x[i + 2] - y[i + 2])) > threshold) n++;
  return n / (x.length / 4);
})
"""

# The page's own list (Module.t10Options()) and the site's reading of it (what the controls were made from).
OPTIONS = r"""
((stage) => {
  const live = document.querySelector(`.live[data-stage="${stage}"]`);
  const list = live.querySelector('iframe.live-frame').contentWindow.Module.t10Options();
  return JSON.stringify({raw: typeof list === 'string' ? JSON.parse(list) : list, read: t10Live.options(stage)});
})
"""

# Sets a control the way a reader does (the input's value, then the events a browser fires).
SET_CONTROL = r"""
((stage, name, value) => {
  const live = document.querySelector(`.live[data-stage="${stage}"]`);
  const input = live.querySelector(`.live-controls [data-option="${name}"]:not(label)`);
  if (!input) return 'no control for ' + name;
  if (input.type === 'checkbox') input.checked = value === '1' || value === 'true';
  else input.value = value;
  input.dispatchEvent(new Event('input'));
  input.dispatchEvent(new Event('change'));
  return '';
})
"""


def states(browser, session):
    return json.loads(evaluate(browser, session, STATE))


def wait_until(browser, session, done, timeout, what):
    """Waits until done(the embeds' states); the failure lists each embed's."""
    return cdp.wait_until(lambda: states(browser, session), done, timeout, what,
                          lambda current: "; the embeds: " + "; ".join(
                              f"{s['stage']}: {s['state']} (page {s['pageState']}) {s['note']} {s['error']}".strip()
                              for s in current), interval=0.2)


def pixels(browser, session, stage, key):
    """Keeps the embed's frame under key; returns (width, height, share of lit pixels)."""
    got = json.loads(evaluate(browser, session, f"{PIXELS}({json.dumps(stage)}, {json.dumps(key)})"))
    return got["w"], got["h"], got["lit"]


def differing_share(browser, session, a, b, threshold):
    return float(evaluate(browser, session, f"{DIFFER}({json.dumps(a)}, {json.dumps(b)}, {threshold})"))


def element_clip(browser, session, selector):
    box = json.loads(evaluate(browser, session, f"""(() => {{ const e = document.querySelector({json.dumps(selector)});
        e.scrollIntoView(); const r = e.getBoundingClientRect();
        return JSON.stringify({{x: r.left + scrollX, y: r.top + scrollY, width: r.width, height: r.height}}); }})()"""))
    return box


def open_page(browser, url, width):
    """A tab `width` wide showing `url`, once loaded; returns its session."""
    _, session = cdp.open_tab(browser, size=(width, 900))
    browser.send("Page.navigate", {"url": url}, session)
    browser.wait_event("Page.loadEventFired", session, timeout=60)
    return session


def check_running(browser, session, expected, site, out, timeout):
    """Every expected stage has an embed, reaches "rendered" and draws a frame that is not blank. The
    embeds are started one after the other, as a reader clicks them (five at once would share two
    cores)."""
    problems = []
    for stage in expected:
        if evaluate(browser, session, f"t10Live.start({json.dumps(stage)})"):
            wait_until(browser, session, lambda c: all(s["state"] != "loading" for s in c if s["stage"] == stage),
                       timeout, f"{stage}: the embed did not finish loading")
    current = states(browser, session)
    shown = {s["stage"]: s for s in current if s["src"]}
    for stage in expected:
        if not os.path.isfile(os.path.join(site, "web", stage, "index.html")):
            problems.append(f"{stage}: its web page was built but is not in the site ({site}/web/{stage}/): "
                            f"build the site again (make site)")
        s = shown.get(stage)
        if not s:
            problems.append(f"{stage}: no live embed on the page")
            continue
        if s["state"] != "rendered" or s["pageState"] != "rendered":
            problems.append(f"{stage}: embed {s['state']}, its page's dataset.t10 is {s['pageState']!r}: "
                            f"{s['note']} {s['error']}".strip())
            continue
        w, h, lit = pixels(browser, session, stage, stage)
        print(f"{stage}: rendered, {w}x{h}, {s['frames']} frame(s), {lit:.0%} of the pixels lit", flush=True)
        if lit <= 0.01:
            problems.append(f"{stage}: the canvas is blank ({lit:.2%} of its pixels above 8/255)")
        screenshot(browser, session, os.path.join(out, f"live-{stage}.png"),
                   element_clip(browser, session, f'.live[data-stage="{stage}"]'))
    return problems, shown


def check_controls(browser, session, stage, need, changes, tries, min_changed, out, timeout):
    """The controls are the page's option list, and each change changes the frame and comes back."""
    problems = []
    got = json.loads(evaluate(browser, session, f"{OPTIONS}({json.dumps(stage)})"))
    names = [re.sub(r"\{[^}]*\}$", "", o["name"]) for o in got["raw"].get("options", [])]
    listed = got["read"]
    state = next(s for s in states(browser, session) if s["stage"] == stage)
    controllable = [o["name"] for o in listed if o["type"] in ("flag", "choice") or
                    (o["type"] in ("int", "float") and o.get("min") is not None)]
    if state["controls"] != controllable:
        problems.append(f"{stage}: controls {state['controls']}, but the page's t10Options() gives {controllable}")
    for name in need:
        if name not in names:
            problems.append(f"{stage}: t10Options() lists no '{name}' ({names}), so the page has no control for it")
        elif name not in state["controls"]:
            problems.append(f"{stage}: no control for '{name}' ({[o for o in listed if o['name'] == name]})")
    defaults = {o["name"]: o["value"] for o in listed}
    pixels(browser, session, stage, "default")

    def set_and_wait(name, value, key):
        before = next(s for s in states(browser, session) if s["stage"] == stage)["frames"]
        error = evaluate(browser, session, f"{SET_CONTROL}({json.dumps(stage)}, {json.dumps(name)}, {json.dumps(value)})")
        if error:
            raise Failure(f"{stage}: {error}")
        s = wait_until(browser, session, lambda c: any(x["stage"] == stage and (x["statusError"] or x["state"] == "error" or
                                                       x["frames"] > before and x["state"] == "rendered") for x in c),
                       timeout, f"{stage}: no new frame after --{name} {value}")
        s = next(x for x in s if x["stage"] == stage)
        if s["statusError"]:
            raise Failure(f"{stage}: --{name} {value} through its control: the page answers {s['status']!r}")
        if s["state"] != "rendered":
            raise Failure(f"{stage}: --{name} {value}: {s['note']} {s['error']}")
        pixels(browser, session, stage, key)

    choices = {o["name"]: o.get("choices") for o in listed}
    for change in tries + changes:
        name, value = change.split("=", 1)
        if choices.get(name) and value not in choices[name]:
            problems.append(f"{stage}: --{name} {value} is not among the page's choices {choices[name]}")
    if problems:
        return problems
    for change in tries:
        name, value = change.split("=", 1)
        if name in defaults:
            set_and_wait(name, value, "tried")
            print(f"{stage}: --{name} {value}: drawn", flush=True)
            set_and_wait(name, defaults[name], "back")
    for change in changes:
        name, value = change.split("=", 1)
        if name not in defaults:
            continue  # reported above when needed
        set_and_wait(name, value, "changed")
        share = differing_share(browser, session, "default", "changed", 4)
        print(f"{stage}: --{name} {value}: {share:.2%} of the pixels differ from the default frame by more than 4/255", flush=True)
        screenshot(browser, session, os.path.join(out, f"live-{stage}-{name}-{value}.png"),
                   element_clip(browser, session, f'.live[data-stage="{stage}"]'))
        if share <= min_changed:
            problems.append(f"{stage}: --{name} {value} through its control changes only {share:.2%} of the "
                            f"pixels (more than {min_changed:.2%} expected)")
        set_and_wait(name, defaults[name], "back")
        residue = differing_share(browser, session, "default", "back", 2)
        if residue > 0:
            problems.append(f"{stage}: --{name} back to {defaults[name]} does not give the default frame again "
                            f"({residue:.2%} of the pixels differ by more than 2/255)")
    return problems


def check_no_webgl(chromium, site, page, out, timeout, width):
    """Without WebGL every embed keeps its picture and says why; nothing starts."""
    problems = []
    with cdp.browsing(site, chromium, os.path.join(out, "chromium-no-webgl.log"), time.monotonic() + timeout,
                      gpu_args=("--disable-gpu", "--disable-3d-apis")) as (browser, base):
        session = open_page(browser, base + page, width)
        wait_until(browser, session, lambda c: all(s["state"] != "idle" or not s["src"] for s in c),
                   timeout / 2, "the embeds did not notice the missing WebGL")
        # The pictures below the first screen load lazily: each is made to load, then looked at.
        evaluate(browser, session, LOAD_PICTURES, await_promise=True)
        current = states(browser, session)
        problems += no_webgl_problems([s for s in current if s["src"]])
        first = next((s["stage"] for s in current if s["src"]), None)
        if first:
            screenshot(browser, session, os.path.join(out, "live-no-webgl.png"),
                       element_clip(browser, session, f'.live[data-stage="{first}"]'))
    return problems


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--site", required=True, help="the built site")
    ap.add_argument("--web", required=True, help="the web stages (make web: out/web)")
    ap.add_argument("--stages", required=True, help="stage names, comma-separated")
    ap.add_argument("--page", default="tutorial10.html")
    ap.add_argument("--chromium", default="chromium")
    ap.add_argument("--out", required=True, help="folder for screenshots and Chromium's logs")
    ap.add_argument("--controls-stage", default="extras")
    ap.add_argument("--need", action="append", default=[], help="an option the controls stage must offer")
    ap.add_argument("--change", action="append", default=[], metavar="NAME=VALUE")
    ap.add_argument("--try", dest="tries", action="append", default=[], metavar="NAME=VALUE",
                    help="a setting that must draw a frame through its control (no difference needed: r16f)")
    ap.add_argument("--min-changed", type=float, default=0.002, help="share of pixels a change must alter")
    ap.add_argument("--timeout", type=float, default=240)
    ap.add_argument("--width", type=int, default=1280,
                    help="the window's width: the embeds render at their width (a narrower window draws fewer pixels)")
    args = ap.parse_args()

    names = [n for n in args.stages.split(",") if n]
    built = [n for n in names if os.path.isfile(os.path.join(args.web, n, "index.html"))]
    if not built:
        print(f"SKIPPED: no web stage is built in {args.web} (make web builds them; this machine has not), "
              f"so the site has no live embed to test")
        return SKIP
    if not os.path.isfile(os.path.join(args.site, args.page)):
        raise Failure(f"{args.site}/{args.page} does not exist: build the site first (make site)")
    os.makedirs(args.out, exist_ok=True)
    started = time.monotonic()
    problems = []
    with cdp.browsing(args.site, args.chromium, os.path.join(args.out, "chromium.log"), started + args.timeout,
                      gpu_args=WEBGL_ARGS) as (browser, base):
        session = open_page(browser, base + args.page, args.width)
        found, shown = check_running(browser, session, built, args.site, args.out, 90)
        problems += found
        if evaluate(browser, session, "!!document.getElementById('live-costs')"):
            screenshot(browser, session, os.path.join(args.out, "live-costs.png"), element_clip(browser, session, "#live-costs"))
        else:
            problems.append("the page does not state the web stages' download sizes (#live-costs)")
        if args.controls_stage in built and shown.get(args.controls_stage, {}).get("state") == "rendered":
            problems += check_controls(browser, session, args.controls_stage, args.need, args.change,
                                       args.tries, args.min_changed, args.out, 60)
        elif args.controls_stage in names and args.controls_stage not in built:
            problems.append(f"{args.controls_stage}: not built in {args.web}, so its controls are untested")
    problems += check_no_webgl(args.chromium, args.site, args.page, args.out, 60, args.width)
    print(f"finished in {time.monotonic() - started:.1f} s; screenshots in {args.out}", flush=True)
    if problems:
        raise Failure("\n  ".join([f"{len(problems)} problem(s) with the live embeds:"] + problems))
    print(f"ok: {len(built)} live embed(s) render, the controls change the frame, and without WebGL the pictures stay")
    return 0


if __name__ == "__main__":
    cdp.run_main(main)
