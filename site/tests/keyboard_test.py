#!/usr/bin/env python3
"""The tutorial page's live embeds used from the keyboard alone, in headless Chromium (keys sent through
the DevTools protocol's Input.dispatchKeyEvent, as a keyboard types them).

For every embed on the page, one after the other:
  - Tab from the still picture's link reaches the embed's "Run it live" button; the five buttons have
    five different accessible names (each carries its stage's title);
  - Enter starts it; the focus moves to its status line and, once the first frame is drawn, into the
    frame: the canvas, named (aria-label) and with a visible focus ring (an outline of 2 px or more);
  - the camera keys work while the canvas has the focus: W held for a moment draws new frames and
    changes the picture;
  - Tab leaves the canvas (no keyboard trap, WCAG 2.1.2), Shift+Tab comes back into it, Shift+Tab
    again leaves it backwards, and Escape leaves it too;
  - every control of the embed is reached with Tab, named in words, has a visible focus ring, and is
    operated with a key (Space on a checkbox, ArrowDown on a choice, ArrowRight on a slider): the
    embed draws a new frame and its status line names the option and the value.

With --edit-stage STAGE, that embed's shader editor too (issue 52): Tab from its last control reaches
"Edit the shaders", Enter opens the editor, Tab reaches the first file's button and Enter puts the focus
in the text (named, with a focus ring); Tab there indents (the text changes, the focus stays); Escape,
then Tab, leaves the text forwards to Apply, and Escape, then Shift+Tab, backwards (no keyboard trap);
Enter on Apply compiles the edit and the result is announced (the status line, role=status, says what
was applied). The axe run of --axe then has this editor open.

It can fail: on the site before issue 50 (commit 2cee4be) focus never left a running embed's canvas:
Tab, Shift+Tab and Escape all left document.activeElement on the canvas (emscripten's GLFW cancels
Tab's default on the window), the first embed failed there, and the buttons shared one name.

--axe AXE.JS: then, with every embed running and operated, axe-core (axe_test.py's rules) on the page at
each --axe-widths width in both schemes: 0 violations (the embeds' pages and controls included).

Without any web stage in the site it prints SKIPPED and exits 77, unless --need-embeds.
"""

import argparse
import json
import os
import sys
import time

sys.dont_write_bytecode = True
from web import cdp  # noqa: E402  (the DevTools client; tools/ on PYTHONPATH)
from web.cdp import Failure, evaluate  # noqa: E402
import axe_test  # noqa: E402  (axe-core in the page, for --axe)

SKIP = 77

KEYS = {  # key: (code, windows virtual key code, text typed)
    "Tab": ("Tab", 9, ""), "Enter": ("Enter", 13, "\r"), "Escape": ("Escape", 27, ""), " ": ("Space", 32, " "),
    "ArrowDown": ("ArrowDown", 40, ""), "ArrowRight": ("ArrowRight", 39, ""), "w": ("KeyW", 87, "w"),
    "Backspace": ("Backspace", 8, ""),
}
SHIFT = 8

# Where the focus is: in the site's page, and inside an embed's frame when the frame has it.
FOCUS = r"""
(() => {
  const describe = (e) => !e ? null : {tag: e.tagName.toLowerCase(), id: e.id || '', cls: e.className && e.className.baseVal === undefined ? e.className : '',
      option: e.dataset ? e.dataset.option || '' : '', stage: e.closest && e.closest('.live') ? e.closest('.live').dataset.stage : '',
      label: e.getAttribute('aria-label') || '', outline: (() => { const s = getComputedStyle(e);
        return s.outlineStyle === 'none' ? 0 : parseFloat(s.outlineWidth); })()};
  const top = document.activeElement;
  let inner = null;
  if (top && top.tagName === 'IFRAME') { try { inner = describe(top.contentDocument.activeElement); } catch (e) {} }
  return JSON.stringify({top: describe(top), inner: inner});
})()
"""

EMBED = r"""
((stage) => {
  const live = document.querySelector(`.live[data-stage="${stage}"]`);
  const frame = live.querySelector('iframe.live-frame');
  let page = null;
  try { page = frame && frame.contentDocument.body; } catch (e) {}
  return JSON.stringify({state: live.dataset.state, frames: page ? Number(page.dataset.t10Frames || 0) : 0,
    status: (live.querySelector('.live-control-status') || {}).textContent || '',
    statusError: !!live.querySelector('.live-control-error'),
    controls: [...live.querySelectorAll('.live-controls [data-option]')].map(c => ({option: c.dataset.option, type: c.type || c.tagName,
        name: c.labels && c.labels[0] ? c.labels[0].textContent : '', value: c.type === 'checkbox' ? String(c.checked) : c.value}))});
})
"""

# The embed's canvas drawn into a 2D canvas: a digest of its pixels (to see that the camera moved).
DIGEST = r"""
((stage) => {
  const c = document.querySelector(`.live[data-stage="${stage}"] iframe.live-frame`).contentDocument.getElementById('canvas');
  const t = document.createElement('canvas'); t.width = c.width; t.height = c.height;
  const ctx = t.getContext('2d'); ctx.drawImage(c, 0, 0);
  const d = ctx.getImageData(0, 0, t.width, t.height).data;
  let h = 0; for (let i = 0; i < d.length; i += 40) h = (h * 31 + d[i]) >>> 0;
  return h;
})
"""


def press(browser, session, key, modifiers=0, hold=None):
    """The key pressed and released; hold: a function called between the two (the key held meanwhile)."""
    code, vk, text = KEYS[key]
    down = {"type": "keyDown" if text else "rawKeyDown", "key": key if key != " " else " ", "code": code,
            "windowsVirtualKeyCode": vk, "nativeVirtualKeyCode": vk, "modifiers": modifiers}
    if text:
        down["text"] = text
    browser.send("Input.dispatchKeyEvent", down, session)
    try:
        if hold:
            hold()
    finally:
            browser.send("Input.dispatchKeyEvent", {"type": "keyUp", "key": key, "code": code, "windowsVirtualKeyCode": vk,
                                                "nativeVirtualKeyCode": vk, "modifiers": modifiers}, session)


def focus(browser, session):
    return json.loads(evaluate(browser, session, FOCUS))


def embed(browser, session, stage):
    return json.loads(evaluate(browser, session, f"{EMBED}({json.dumps(stage)})"))


def on_canvas(f, stage):
    return bool(f["top"] and f["top"]["tag"] == "iframe" and f["top"]["stage"] == stage and f["inner"]
                and f["inner"]["id"] == "canvas")


def where(f):
    t, i = f["top"] or {}, f["inner"]
    return f"{t.get('tag')}#{t.get('id')}.{t.get('cls')}" + (f" > {i['tag']}#{i['id']}" if i else "")


def settle(browser, session, check, what, timeout=5):
    return cdp.wait_until(lambda: focus(browser, session), check, timeout, what, lambda f: f": the focus is on {where(f)}",
                          interval=0.05)


def check_embed(browser, session, stage, timeout, need_controls, leave):
    """One embed from the keyboard; returns its problems (the first that stops the rest ends the list)."""
    problems = []
    evaluate(browser, session, f"""(() => {{ const a = document.querySelector('.live[data-stage="{stage}"] figure.render a');
        a.focus(); a.scrollIntoView(); }})()""")
    press(browser, session, "Tab")
    f = focus(browser, session)
    if not (f["top"] and "live-start" in (f["top"]["cls"] or "") and f["top"]["stage"] == stage):
        return [f"{stage}: Tab from the picture reaches {where(f)}, not the embed's start button"]
    press(browser, session, "Enter")
    f = focus(browser, session)
    if not (f["top"] and "live-note" in (f["top"]["cls"] or "")):
        problems.append(f"{stage}: after Enter on the start button the focus is on {where(f)}, not the status line")
    cdp.wait_until(lambda: embed(browser, session, stage), lambda e: e["state"] != "loading" and e["state"] != "idle",
                   timeout, f"{stage}: the embed did not start")
    if embed(browser, session, stage)["state"] != "rendered":
        return problems + [f"{stage}: the embed did not render: {embed(browser, session, stage)}"]
    try:
        f = settle(browser, session, lambda f: on_canvas(f, stage), f"{stage}: the focus did not move into the running frame")
    except Failure as e:
        problems.append(str(e))  # reported; the canvas is focused by script so that the rest is checked
        evaluate(browser, session, f"""document.querySelector('.live[data-stage="{stage}"] iframe.live-frame')
                                       .contentDocument.getElementById('canvas').focus()""")
        f = focus(browser, session)
        if not on_canvas(f, stage):
            return problems + [f"{stage}: the canvas cannot be focused (the focus is on {where(f)})"]
    if not f["inner"]["label"]:
        problems.append(f"{stage}: the canvas has no name (aria-label)")
    if f["inner"]["outline"] < 2:
        problems.append(f"{stage}: the focused canvas shows no focus ring (outline {f['inner']['outline']} px)")

    # The camera keys, with the canvas focused.
    before = embed(browser, session, stage)["frames"]
    digest = evaluate(browser, session, f"{DIGEST}({json.dumps(stage)})")
    try:
        # Held until a frame is drawn (as a reader holds it until the view moves: a loaded machine may
        # draw no frame in a short press), then a moment longer.
        press(browser, session, "w", hold=lambda: (cdp.wait_until(
            lambda: embed(browser, session, stage)["frames"], lambda n: n > before, 20,
            f"{stage}: W held on the canvas drew no new frame"), time.sleep(0.2)))
        time.sleep(0.3)
        if evaluate(browser, session, f"{DIGEST}({json.dumps(stage)})") == digest:
            problems.append(f"{stage}: W held on the canvas drew frames, but the picture did not change")
    except Failure as e:
        problems.append(str(e))

    # Out and back in, both ways, and Escape.
    press(browser, session, "Tab")
    try:
        after_tab = settle(browser, session, lambda f: not on_canvas(f, stage), f"{stage}: Tab does not leave the canvas")
    except Failure as e:
        return problems + [f"{e} (a keyboard trap)"]
    press(browser, session, "Tab", SHIFT)
    try:
        settle(browser, session, lambda f: on_canvas(f, stage), f"{stage}: Shift+Tab from {where(after_tab)} does not come back to the canvas")
        press(browser, session, "Tab", SHIFT)
        settle(browser, session, lambda f: not on_canvas(f, stage), f"{stage}: Shift+Tab does not leave the canvas")
        press(browser, session, "Tab")
        settle(browser, session, lambda f: on_canvas(f, stage), f"{stage}: Tab does not come back to the canvas")
        press(browser, session, "Escape")
        settle(browser, session, lambda f: not on_canvas(f, stage), f"{stage}: Escape does not leave the canvas")
    except Failure as e:
        return problems + [str(e)]
    return problems + check_controls(browser, session, stage, need_controls, leave)


# The focus in an embed's shader editor: the focused element's classes, whether it is CodeMirror's text
# (and then its name and the editor's focus ring), the text of the file shown and the status line.
EDITOR_FOCUS = r"""
((stage) => {
  const live = document.querySelector(`.live[data-stage="${stage}"]`);
  const e = document.activeElement, cm = e && e.closest ? e.closest('.CodeMirror') : null;
  const wrapper = live.querySelector('.CodeMirror');
  const ring = (n) => { if (!n) return 0; const s = getComputedStyle(n); return s.outlineStyle === 'none' ? 0 : parseFloat(s.outlineWidth); };
  return JSON.stringify({cls: e ? String(e.className || '') : '', inText: !!cm && live.contains(cm), label: e ? e.getAttribute('aria-label') || '' : '',
    ring: cm ? ring(cm) : ring(e), editor: live.dataset.editor || '', text: wrapper ? wrapper.CodeMirror.getValue() : '',
    status: (live.querySelector('.t10-editor-status') || {}).textContent || '',
    statusRole: (live.querySelector('.t10-editor-status') || {getAttribute: () => ''}).getAttribute('role')});
})
"""


def check_editor(browser, session, stage):
    """The embed's shader editor from the keyboard (the focus is on its last control, or its canvas)."""
    def at():
        return json.loads(evaluate(browser, session, f"{EDITOR_FOCUS}({json.dumps(stage)})"))

    def expect_focus(check, what):
        return cdp.wait_until(at, check, 5, f"{stage}: {what}", lambda f: f": the focus is on {f['cls']!r}", interval=0.05)

    try:
        press(browser, session, "Tab")
        expect_focus(lambda f: "live-edit" in f["cls"], "Tab after the controls does not reach \"Edit the shaders\"")
        press(browser, session, "Enter")
        cdp.wait_until(at, lambda f: f["editor"] in ("ready", "error"), 60, f"{stage}: Enter did not open the editor",
                       lambda f: f": {f['status']}")
        if at()["editor"] != "ready":
            return [f"{stage}: the editor did not start: {at()['status']}"]
        press(browser, session, "Tab")
        expect_focus(lambda f: "t10-editor-file" in f["cls"], "Tab from \"Edit the shaders\" does not reach a file's button")
        press(browser, session, "Enter")
        f = expect_focus(lambda f: f["inText"], "Enter on a file's button does not put the focus in its text")
        problems = []
        if not f["label"]:
            problems.append(f"{stage}: the editor's text has no name (aria-label)")
        if f["ring"] < 2:
            problems.append(f"{stage}: the focused editor shows no focus ring (outline {f['ring']} px)")
        before = f["text"]
        press(browser, session, "Tab")
        f = expect_focus(lambda f: f["inText"] and f["text"] != before, "Tab in the text does not indent (or leaves it)")
        press(browser, session, "Escape")
        press(browser, session, "Tab")
        expect_focus(lambda f: "t10-editor-apply" in f["cls"], "Escape, then Tab, does not leave the text for Apply (a keyboard trap)")
        press(browser, session, "Tab", SHIFT)
        expect_focus(lambda f: f["inText"], "Shift+Tab from Apply does not come back to the text")
        press(browser, session, "Escape")
        press(browser, session, "Tab", SHIFT)
        expect_focus(lambda f: not f["inText"], "Escape, then Shift+Tab, does not leave the text backwards (a keyboard trap)")
        press(browser, session, "Tab")
        expect_focus(lambda f: f["inText"], "Tab does not come back to the text")
        press(browser, session, "Escape")
        press(browser, session, "Tab")
        expect_focus(lambda f: "t10-editor-apply" in f["cls"], "Escape, then Tab, does not reach Apply")
        press(browser, session, "Enter")
        f = cdp.wait_until(at, lambda f: "Applied" in f["status"] or "error" in f["status"], 60,
                           f"{stage}: Enter on Apply announced no result", lambda f: f": {f['status']!r}")
        if f["statusRole"] != "status" or "Applied" not in f["status"]:
            problems.append(f"{stage}: Apply's result {f['status']!r} (role {f['statusRole']!r}) is not an announced application")
        else:
            print(f"{stage}: editor from the keyboard: {f['status']}", flush=True)
        return problems
    except Failure as e:
        return [str(e)]


def check_controls(browser, session, stage, need_controls, leave):
    """Each control: reached by Tab from the canvas onwards, named in words, focus ring, operated by a key."""
    problems = []
    controls = embed(browser, session, stage)["controls"]
    if stage in need_controls and not controls:
        return [f"{stage}: the running embed offers no control"]
    evaluate(browser, session, f"""document.querySelector('.live[data-stage="{stage}"] iframe.live-frame')
                                   .contentDocument.getElementById('canvas').focus()""")
    for control in controls:
        press(browser, session, "Tab")
        f = focus(browser, session)
        if not f["top"] or f["top"]["option"] != control["option"]:
            problems.append(f"{stage}: Tab reaches {where(f)}, not the control --{control['option']}")
            break
        if not control["name"] or control["name"].startswith("-"):
            problems.append(f"{stage}: the control --{control['option']} is named {control['name']!r}, not in words")
        if f["top"]["outline"] < 2:
            problems.append(f"{stage}: the focused control --{control['option']} shows no focus ring")
        if control["option"] in leave:
            print(f"{stage}: --{control['option']} ({control['name']}) reached, not operated (--leave)", flush=True)
            continue
        before = embed(browser, session, stage)["frames"]
        key = {"checkbox": " ", "range": "ArrowRight"}.get(control["type"], "ArrowDown")
        press(browser, session, key)
        try:
            state = cdp.wait_until(lambda: embed(browser, session, stage), lambda e: e["statusError"] or
                                   (e["frames"] > before and e["state"] == "rendered"), 30,
                                   f"{stage}: {key} on --{control['option']} drew no new frame")
        except Failure as e:
            problems.append(str(e))
            continue
        now = next(c for c in state["controls"] if c["option"] == control["option"])
        if state["statusError"] or now["value"] == control["value"] or f"--{control['option']}" not in state["status"]:
            problems.append(f"{stage}: {key} on --{control['option']}: value {control['value']} -> {now['value']}, "
                            f"status {state['status']!r}")
        else:
            print(f"{stage}: {key} on --{control['option']} ({control['name']}): {state['status']}", flush=True)
    return problems


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--site", required=True, help="the built site")
    ap.add_argument("--page", default="tutorial10.html")
    ap.add_argument("--chromium", default="chromium")
    ap.add_argument("--out", required=True, help="folder for Chromium's log")
    ap.add_argument("--need-embeds", action="store_true", help="fail (not skip) when the site has no web stage")
    ap.add_argument("--controls-stage", action="append", default=[], help="a stage whose embed must offer controls")
    ap.add_argument("--leave", action="append", default=[], metavar="OPTION",
                    help="a control reached and named but not operated (a value of it stops the embed)")
    ap.add_argument("--edit-stage", action="append", default=[], help="a stage whose embed's shader editor is used too")
    ap.add_argument("--width", type=int, default=800,
                    help="the window's width while the embeds run (they draw at their width: 800 draws half the pixels of 1280)")
    ap.add_argument("--axe", help="axe.min.js: check the page with its embeds running too")
    ap.add_argument("--axe-widths", default="800,1280")
    ap.add_argument("--timeout", type=float, default=300)
    args = ap.parse_args()
    if not os.path.isfile(os.path.join(args.site, args.page)):
        raise Failure(f"{args.site}/{args.page} does not exist: build the site first (make site)")
    if not os.path.isdir(os.path.join(args.site, "web")):
        if args.need_embeds:
            raise Failure(f"{args.site}/web/ does not exist: the site was built without the web stages")
        print(f"SKIPPED: {args.site} has no web stages (make web, then make site), so no embed to use")
        return SKIP
    os.makedirs(args.out, exist_ok=True)
    started = time.monotonic()
    problems = []
    with cdp.browsing(args.site, args.chromium, os.path.join(args.out, "chromium.log"), started + args.timeout,
                      gpu_args=cdp.RENDERERS["swiftshader"]) as (browser, base):
        _, session = cdp.open_tab(browser, size=(args.width, 900))
        if args.axe:
            axe_test.set_axe_source(browser, session, axe_test.read_axe(args.axe))
        browser.send("Page.navigate", {"url": base + args.page}, session)
        browser.wait_event("Page.loadEventFired", session, timeout=60)
        stages = json.loads(evaluate(browser, session, "JSON.stringify([...document.querySelectorAll('.live[data-src]')].map(l => l.dataset.stage))"))
        names = json.loads(evaluate(browser, session, "JSON.stringify([...document.querySelectorAll('.live-start')].map(b => b.textContent.trim()))"))
        if len(set(names)) != len(names):
            problems.append(f"the start buttons share names: {names}")
        if not stages:
            raise Failure(f"{args.page} has no live embed")
        for stage in stages:
            found = check_embed(browser, session, stage, 120, args.controls_stage, args.leave)
            if stage in args.edit_stage and not found:
                found = check_editor(browser, session, stage)
            problems += found
            print(f"{stage}: {'ok' if not found else str(len(found)) + ' problem(s)'}", flush=True)
        if args.axe:
            findings = axe_test.Findings()
            axe_test.check_loaded(browser, session, [int(w) for w in args.axe_widths.split(",")],
                                  f"{args.page} with its embeds running", findings)
            findings.write(args.out, "axe")
            print(f"axe-core: {findings.runs} runs with the embeds running: {findings.total} violating node(s)")
            if findings.total:
                problems.append(str(findings.failure()))
    print(f"keyboard: {len(stages)} embeds in {time.monotonic() - started:.1f} s")
    if problems:
        raise Failure("\n  ".join([f"{len(problems)} problem(s) using the embeds from the keyboard:"] + problems))
    print(f"ok: every embed is started, left, re-entered and operated from the keyboard")
    return 0


if __name__ == "__main__":
    cdp.run_main(main)
