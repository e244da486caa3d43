#!/usr/bin/env python3
"""Lighthouse on a page of the built site (make site-audit): its mobile preset (a mid-range phone on a
throttled connection, simulated), accessibility and performance.

The site is served from 127.0.0.1 (tools/web/cdp.py's server) and Lighthouse (pinned in
site/tests/lighthouse/package-lock.json; make site-audit installs it into build/site-lighthouse/) drives
Debian's Chromium headless. Asserts the accessibility score is at least --min-accessibility (100: every
audit passes; the failing audits are listed otherwise); prints the performance score, the largest
contentful paint and the bytes the page loads as a benchmark, with no limit (simulated timings depend
on the machine, and vary from run to run: --runs, default 3, and their median). Each run's report goes
to OUT/lighthouse-N.json. The site is served gzip-compressed, as a publishing host serves it.

It can fail: on the site before issue 50 (commit 2cee4be) it reports accessibility 96 (colour contrast)
and fails; performance 46, largest contentful paint 46.3 s, 19.33 MiB.
"""

import argparse
import json
import os
import statistics
import subprocess
import sys
import time

sys.dont_write_bytecode = True
from web import cdp  # noqa: E402  (the DevTools client's local server; tools/ on PYTHONPATH)
from web.cdp import Failure  # noqa: E402


def audit(args, url, report):
    """One Lighthouse run into `report`; its parsed JSON."""
    try:
        result = subprocess.run(
            [args.lighthouse, url, "--only-categories=accessibility,performance", "--output=json",
             f"--output-path={report}", "--quiet",
             "--chrome-flags=--headless=new --no-sandbox --disable-gpu --host-resolver-rules=MAP * ~NOTFOUND , EXCLUDE 127.0.0.1"],
            env=dict(os.environ, CHROME_PATH=args.chromium), stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
            text=True, timeout=args.timeout)
    except subprocess.TimeoutExpired:
        raise Failure(f"lighthouse did not finish within {args.timeout:.0f} s")
    if result.returncode != 0 or not os.path.isfile(report):
        raise Failure(f"lighthouse exited with {result.returncode}:\n{result.stdout[-3000:]}")
    with open(report, encoding="utf-8") as f:
        data = json.load(f)
    if data.get("runtimeError"):
        raise Failure(f"lighthouse: {data['runtimeError']}")
    return data


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--site", required=True, help="the built site")
    ap.add_argument("--page", default="tutorial10.html")
    ap.add_argument("--lighthouse", required=True, help="Lighthouse's command (build/site-lighthouse/node_modules/.bin/lighthouse)")
    ap.add_argument("--chromium", default="chromium")
    ap.add_argument("--out", required=True, help="folder for the reports")
    ap.add_argument("--min-accessibility", type=int, default=100)
    ap.add_argument("--runs", type=int, default=3,
                    help="runs (each must meet --min-accessibility; the performance printed is their median)")
    ap.add_argument("--timeout", type=float, default=300, help="seconds for each run")
    args = ap.parse_args()
    if not os.path.isfile(args.lighthouse):
        raise Failure(f"{args.lighthouse} does not exist: make site-audit installs Lighthouse there "
                      f"(npm ci, site/tests/lighthouse/package-lock.json)")
    if not os.path.isfile(os.path.join(args.site, args.page)):
        raise Failure(f"{args.site}/{args.page} does not exist: build the site first (make site)")
    if not 1 <= args.runs <= 20:
        raise Failure(f"--runs {args.runs}: between 1 and 20")
    os.makedirs(args.out, exist_ok=True)
    # Served as a publishing host serves it: text gzip-compressed (cdp.GzipHandler). Uncompressed, the
    # page's 190 KiB of HTML alone took a second of the simulated phone's connection.
    server = cdp.start_server(args.site, compress=True)
    url = f"http://127.0.0.1:{server.server_address[1]}/{args.page}"
    runs = []
    try:
        for run in range(1, args.runs + 1):
            started = time.monotonic()
            report = os.path.join(args.out, f"lighthouse-{run}.json")
            data = audit(args, url, report)
            categories, audits = data["categories"], data["audits"]
            accessibility = round(100 * (categories["accessibility"]["score"] or 0))
            performance = round(100 * (categories["performance"]["score"] or 0))
            figures = {key: audits[key]["numericValue"] for key in
                       ("first-contentful-paint", "largest-contentful-paint", "total-blocking-time", "total-byte-weight")}
            print(f"lighthouse {data['lighthouseVersion']} ({data['configSettings']['formFactor']}, {args.page}) run {run}: "
                  f"accessibility {accessibility}, performance {performance}, first contentful paint "
                  f"{figures['first-contentful-paint'] / 1000:.1f} s, largest contentful paint "
                  f"{figures['largest-contentful-paint'] / 1000:.1f} s, total blocking time "
                  f"{figures['total-blocking-time']:.0f} ms (simulated), {figures['total-byte-weight'] / 1024:.0f} KiB loaded "
                  f"(gzip); {time.monotonic() - started:.0f} s; report {report}", flush=True)
            if accessibility < args.min_accessibility:
                failing = [f"{a['id']}: {a['title']}" for ref in categories["accessibility"]["auditRefs"]
                           for a in [audits[ref["id"]]] if ref["weight"] > 0 and a["score"] is not None and a["score"] < 1]
                raise Failure(f"accessibility {accessibility} < {args.min_accessibility}; failing audits:\n  " + "\n  ".join(failing))
            runs.append(performance)
    finally:
        server.shutdown()
        server.server_close()
    with open("/proc/loadavg") as f:
        load = f.read().split()[0]
    print(f"lighthouse: performance median {statistics.median(runs):.0f} of {args.runs} runs ({', '.join(map(str, runs))}); "
          f"simulated timings scale with the machine's load (1-minute load average now {load})")
    return 0


if __name__ == "__main__":
    cdp.run_main(main)
