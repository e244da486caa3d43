#!/usr/bin/env python3
"""A screenshot of noVNC's page once it shows the desktop: headless Chromium driven through the
repository's DevTools client (web/cdp.py), so that the shot waits in real time for noVNC to connect
and draw, which Chromium's --screenshot cannot (it shoots at the load event, before the WebSocket has
delivered a frame).

usage: novnc_screenshot.py URL OUT.png [WIDTHxHEIGHT] [--wait S] [--settle S]
Opens URL (a page on 127.0.0.1: cdp's Chromium resolves no other host), waits up to --wait seconds
(60) for noVNC's "connected" state (the class noVNC_connected on the page's root element), then
--settle seconds (3) for the desktop's frames, and writes the viewport as OUT.png; Chromium's own
messages go to OUT-chromium.log. Prints the page's title (noVNC shows the desktop's name there).
Exit 1 when Chromium fails or noVNC never connects, 2 on bad usage. Needs the folder holding web/ on
PYTHONPATH (tools/; inside.sh: the check's folder, where devcontainer_check.sh copies web/).
"""
import argparse
import os
import sys
import time

from web import cdp

CONNECTED = "document.documentElement.classList.contains('noVNC_connected')"


def size(text):
    try:
        width, height = (int(v) for v in text.split("x"))
    except ValueError:
        width = height = 0
    if width <= 0 or height <= 0:
        raise argparse.ArgumentTypeError(f"{text!r} is not WIDTHxHEIGHT")
    return width, height


def shoot(url, out, viewport, wait, settle):
    """Returns the exit status; prints what the page showed."""
    chromium = cdp.find_chromium()
    if not chromium:
        raise cdp.Failure("no chromium found (Debian package chromium)")
    log = os.path.splitext(out)[0] + "-chromium.log"
    with cdp.browsing(None, chromium, log, time.monotonic() + wait + settle + 60, window=viewport) as (browser, _):
        _, session = cdp.open_tab(browser, ("Page", "Runtime"), viewport)
        browser.send("Page.navigate", {"url": url}, session)
        last_error = ""

        def connected():
            nonlocal last_error
            try:
                return bool(cdp.evaluate(browser, session, CONNECTED))
            except cdp.Failure as error:  # between two documents (the root redirects to vnc.html)
                last_error = f" (last: {error})"
                return False

        end = time.monotonic() + wait
        while not connected():
            if time.monotonic() > end:
                title = cdp.evaluate(browser, session, "document.title")
                print(f"noVNC did not connect within {wait:g} s{last_error}; the page's title: {title!r}")
                return 1
            time.sleep(0.5)
        time.sleep(settle)
        title = cdp.evaluate(browser, session, "document.title")
        cdp.screenshot(browser, session, out)
        print(f"connected; the page's title: {title!r}")
        return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("url")
    parser.add_argument("out", help="the screenshot, a PNG")
    parser.add_argument("size", nargs="?", type=size, default=(1280, 800), help="the viewport, WIDTHxHEIGHT (1280x800)")
    parser.add_argument("--wait", type=float, default=60, help="seconds to wait for noVNC to connect (60)")
    parser.add_argument("--settle", type=float, default=3, help="seconds for the desktop's frames after that (3)")
    args = parser.parse_args()
    try:
        return shoot(args.url, args.out, args.size, args.wait, args.settle)
    except (OSError, cdp.Failure) as error:
        print(f"novnc_screenshot: {error}")
        return 1


if __name__ == "__main__":
    sys.exit(main())
