#!/usr/bin/env python3
"""Lighthouse on a page of the built site (make site-audit): its mobile preset (a mid-range phone on a
throttled connection, simulated), accessibility and performance.

The site is served from 127.0.0.1 (tools/web/cdp.py's server) and Lighthouse (pinned in
site/tests/lighthouse/package-lock.json; make site-audit installs it into build/site-lighthouse/) drives
Debian's Chromium headless. Asserts the accessibility score is at least --min-accessibility (100: every
audit passes; the failing audits are listed otherwise); prints the performance score, the largest
contentful paint and the bytes the page loads as a benchmark, with no limit (simulated timings depend
on the machine). The whole report goes to OUT/lighthouse.json.

It can fail: on the site before issue 50 (commit 2cee4be) it reports accessibility 96 (colour contrast)
and fails; performance 46, largest contentful paint 46.3 s, 19.33 MiB.
"""

import argparse
import json
import os
import subprocess
import sys
import time

sys.dont_write_bytecode = True
from web import cdp  # noqa: E402  (the DevTools client's local server; tools/ on PYTHONPATH)
from web.cdp import Failure  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--site", required=True, help="the built site")
    ap.add_argument("--page", default="tutorial10.html")
    ap.add_argument("--lighthouse", required=True, help="Lighthouse's command (build/site-lighthouse/node_modules/.bin/lighthouse)")
    ap.add_argument("--chromium", default="chromium")
    ap.add_argument("--out", required=True, help="folder for the report")
    ap.add_argument("--min-accessibility", type=int, default=100)
    ap.add_argument("--timeout", type=float, default=300)
    args = ap.parse_args()
    if not os.path.isfile(args.lighthouse):
        raise Failure(f"{args.lighthouse} does not exist: make site-audit installs Lighthouse there "
                      f"(npm ci, site/tests/lighthouse/package-lock.json)")
    if not os.path.isfile(os.path.join(args.site, args.page)):
        raise Failure(f"{args.site}/{args.page} does not exist: build the site first (make site)")
    os.makedirs(args.out, exist_ok=True)
    report = os.path.join(args.out, "lighthouse.json")
    server = cdp.start_server(args.site)
    url = f"http://127.0.0.1:{server.server_address[1]}/{args.page}"
    started = time.monotonic()
    try:
        result = subprocess.run(
            [args.lighthouse, url, "--only-categories=accessibility,performance", "--output=json",
             f"--output-path={report}", "--quiet",
             "--chrome-flags=--headless=new --no-sandbox --disable-gpu --host-resolver-rules=MAP * ~NOTFOUND , EXCLUDE 127.0.0.1"],
            env=dict(os.environ, CHROME_PATH=args.chromium), stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
            text=True, timeout=args.timeout)
    except subprocess.TimeoutExpired:
        raise Failure(f"lighthouse did not finish within {args.timeout:.0f} s")
    finally:
        server.shutdown()
        server.server_close()
    if result.returncode != 0 or not os.path.isfile(report):
        raise Failure(f"lighthouse exited with {result.returncode}:\n{result.stdout[-3000:]}")
    with open(report, encoding="utf-8") as f:
        data = json.load(f)
    if data.get("runtimeError"):
        raise Failure(f"lighthouse: {data['runtimeError']}")
    categories, audits = data["categories"], data["audits"]
    accessibility = round(100 * (categories["accessibility"]["score"] or 0))
    performance = round(100 * (categories["performance"]["score"] or 0))
    lcp = audits["largest-contentful-paint"]["numericValue"] / 1000
    weight = audits["total-byte-weight"]["numericValue"] / (1024 * 1024)
    print(f"lighthouse {data['lighthouseVersion']} ({data['configSettings']['formFactor']}, {args.page}): "
          f"accessibility {accessibility}, performance {performance}, largest contentful paint {lcp:.1f} s "
          f"(simulated), {weight:.2f} MiB loaded; {time.monotonic() - started:.0f} s; report {report}")
    if accessibility < args.min_accessibility:
        failing = [f"{a['id']}: {a['title']}" for ref in categories["accessibility"]["auditRefs"]
                   for a in [audits[ref["id"]]] if ref["weight"] > 0 and a["score"] is not None and a["score"] < 1]
        raise Failure(f"accessibility {accessibility} < {args.min_accessibility}; failing audits:\n  " + "\n  ".join(failing))
    return 0


if __name__ == "__main__":
    cdp.run_main(main)
