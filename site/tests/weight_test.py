#!/usr/bin/env python3
"""What a page of the built site costs a reader to open, measured in headless Chromium: the sum of every
response it loads (Network.loadingFinished's encodedDataLength: bytes on the wire, headers included; the
test's server does not compress, so a server that does sends less), from the navigation until the
network has been quiet for a second, before any live embed starts. Fails above --limit-mib.

Measured at each --window WxH (1280x900: a laptop; 412x915: a phone, as Lighthouse's mobile preset);
the figures below the first screen load lazily, so it also prints, without a limit, what the page
weighs once every picture has been scrolled to.

It can fail: the tutorial page before issue 50 (commit 2cee4be: 20 PNG figures at 1280x720, none lazy)
loads 19.33 MiB at 1280x900 and at 412x915, the home page 7.06 MiB (five frames), over the 3 MiB limit.
"""

import argparse
import os
import sys
import time

sys.dont_write_bytecode = True
from web import cdp  # noqa: E402  (the DevTools client; tools/ on PYTHONPATH)
from web.cdp import Failure, evaluate  # noqa: E402

MIB = 1024 * 1024


def collect(browser, session, sizes, urls, quiet=1.0, timeout=60):
    """Adds each finished response's size to sizes (by request id) until no request has started or
    finished for `quiet` seconds."""
    last = time.monotonic()
    end = last + timeout
    pending = set()
    while time.monotonic() < end:
        events = browser.drain()
        for e in events:
            if e.get("sessionId") != session:
                continue
            method, params = e.get("method"), e.get("params", {})
            if method == "Network.requestWillBeSent":
                pending.add(params["requestId"])
                urls[params["requestId"]] = params["request"]["url"]
                last = time.monotonic()
            elif method == "Network.loadingFinished":
                sizes[params["requestId"]] = params["encodedDataLength"]
                pending.discard(params["requestId"])
                last = time.monotonic()
            elif method == "Network.loadingFailed":
                pending.discard(params["requestId"])
                last = time.monotonic()
        if not pending and time.monotonic() - last > quiet:
            return
        time.sleep(0.05)
    raise Failure(f"the page was still loading after {timeout} s: {sorted(urls[r] for r in pending)}")


def measure(browser, url, width, height):
    """(bytes before any scrolling, the largest responses, bytes with every lazy picture loaded)."""
    _, session = cdp.open_tab(browser, domains=("Page", "Runtime", "Network"))
    browser.send("Network.setCacheDisabled", {"cacheDisabled": True}, session)
    browser.send("Emulation.setDeviceMetricsOverride", {"width": width, "height": height, "deviceScaleFactor": 1,
                                                        "mobile": width < 600}, session)
    sizes, urls = {}, {}
    browser.drain()
    browser.send("Page.navigate", {"url": url}, session)
    browser.wait_event("Page.loadEventFired", session, timeout=60)
    collect(browser, session, sizes, urls)
    # Only an embed has a state: a site built without web stages keeps its .live boxes stateless (the
    # still picture alone), and those never start (counting them failed CI's test-asan, built so).
    started = evaluate(browser, session, "[...document.querySelectorAll('.live[data-state]')].filter(l => "
                                         "l.dataset.state !== 'idle' && l.dataset.state !== 'unavailable').length")
    if started:
        raise Failure(f"{url}: {started} embed(s) started on their own; the weight is measured before any starts")
    first = sum(sizes.values())
    biggest = sorted(((sizes[r], urls[r].rsplit("/", 1)[-1]) for r in sizes), reverse=True)[:4]
    # Every picture in view once: the page scrolled to each image in turn.
    evaluate(browser, session, "(async () => { for (const i of document.querySelectorAll('img')) { i.scrollIntoView(); "
                               "await new Promise(r => setTimeout(r, 20)); } })()", await_promise=True)
    collect(browser, session, sizes, urls)
    return first, biggest, sum(sizes.values())


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--site", required=True, help="the built site")
    ap.add_argument("--page", action="append", default=[], help="a page to weigh (default tutorial10.html)")
    ap.add_argument("--chromium", default="chromium")
    ap.add_argument("--out", required=True, help="folder for Chromium's log")
    ap.add_argument("--window", action="append", default=[], metavar="WxH")
    ap.add_argument("--limit-mib", type=float, default=3.0)
    ap.add_argument("--timeout", type=float, default=120)
    args = ap.parse_args()
    pages = args.page or ["tutorial10.html"]
    for page in pages:
        if not os.path.isfile(os.path.join(args.site, page)):
            raise Failure(f"{args.site}/{page} does not exist: build the site first (make site)")
    os.makedirs(args.out, exist_ok=True)
    problems = []
    with cdp.browsing(args.site, args.chromium, os.path.join(args.out, "chromium.log"),
                      time.monotonic() + args.timeout) as (browser, base):
        for page, window in [(p, w) for p in pages for w in args.window or ["1280x900"]]:
            width, height = (int(v) for v in window.split("x"))
            first, biggest, everything = measure(browser, base + page, width, height)
            print(f"{page} at {window}: {first / MIB:.2f} MiB loaded before any embed starts (limit "
                  f"{args.limit_mib} MiB; largest: {', '.join(f'{n} {b / 1024:.0f} KiB' for b, n in biggest)}); "
                  f"{everything / MIB:.2f} MiB with every picture scrolled to", flush=True)
            if first > args.limit_mib * MIB:
                problems.append(f"{page} at {window} loads {first / MIB:.2f} MiB before any embed starts, "
                                f"over {args.limit_mib} MiB")
    if problems:
        raise Failure("; ".join(problems))
    return 0


if __name__ == "__main__":
    cdp.run_main(main)
