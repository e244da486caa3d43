#!/usr/bin/env python3
"""Opens a page of a folder in headless Chromium and prints, as JSON, the value of a JavaScript
expression once it is neither null nor undefined.

usage: PYTHONPATH=tools python3 -m web.page_value --root DIR --page PATH --value EXPR
           [--renderer swiftshader|llvmpipe] [--timeout S] [--chromium PROGRAM] [--log FILE]
Serves DIR on 127.0.0.1 (a free port; cdp.py), opens PATH below it with WebGL 2 drawn by --renderer
(cdp.RENDERERS; default swiftshader), and polls EXPR until it has a value (at most --timeout seconds,
default 120). Exit 0 with the value on stdout; 1 when the page never gives one or Chromium fails (the
reason, with the page's script errors, on stderr); 2 on bad usage. Chromium's own messages go to
--log (default: a file in a scratch folder, removed afterwards).

The GLSL ES translations' browser test (tests/unit/test_glsl_es_browser.cpp) runs its page this way.
"""
import argparse
import json
import os
import sys
import tempfile
import time

sys.dont_write_bytecode = True
from web import cdp  # noqa: E402  (the DevTools client)


def script_errors(browser):
    """The page's uncaught exceptions so far, for a failure message."""
    found = [event["params"]["exceptionDetails"] for event in browser.drain()
             if event.get("method") == "Runtime.exceptionThrown"]
    return "".join(f"\n  script error: {d.get('exception', {}).get('description') or d.get('text')}" for d in found[:5])


def page_value(root, page, expression, renderer, timeout, chromium, log):
    gpu_args = tuple(dict.fromkeys(cdp.RENDERERS[renderer] + ("--ignore-gpu-blocklist",)))
    with cdp.browsing(root, chromium, log, time.monotonic() + timeout + 30, gpu_args) as (browser, base):
        _, session = cdp.open_tab(browser)
        browser.send("Page.navigate", {"url": base + page}, session)
        last_error = ""

        def read():
            nonlocal last_error
            try:
                return cdp.evaluate(browser, session, expression)
            except cdp.Failure as error:  # between about:blank and the page, or the page's own error
                last_error = f"; last: {error}"
                return None

        try:
            return cdp.wait_until(read, lambda v: v is not None, timeout, f"{page}: no value of {expression}",
                                  lambda v: last_error)
        except cdp.Failure as failure:
            raise cdp.Failure(f"{failure}{script_errors(browser)}") from None


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--root", required=True, help="the folder to serve")
    parser.add_argument("--page", required=True, help="the page's path below --root")
    parser.add_argument("--value", required=True, help="the JavaScript expression whose value is printed")
    parser.add_argument("--renderer", choices=sorted(cdp.RENDERERS), default="swiftshader")
    parser.add_argument("--timeout", type=float, default=120)
    parser.add_argument("--chromium", help="the browser program (default: chromium on PATH)")
    parser.add_argument("--log", help="Chromium's messages")
    args = parser.parse_args()
    if not os.path.isfile(os.path.join(args.root, args.page.split("?")[0])):
        parser.error(f"{os.path.join(args.root, args.page)}: no such file")
    chromium = args.chromium or cdp.find_chromium()
    if not chromium:
        print("page_value: no chromium found (Debian package chromium)", file=sys.stderr)
        return 1
    with tempfile.TemporaryDirectory(prefix="t10-page-value-") as scratch:
        value = page_value(args.root, args.page, args.value, args.renderer, args.timeout, chromium,
                           args.log or os.path.join(scratch, "chromium.log"))
    print(json.dumps(value))
    return 0


if __name__ == "__main__":
    cdp.run_main(main, prefix="page_value: ")
