#!/usr/bin/env python3
"""The page's workbench, timed (issue 52, item 5): a benchmark that prints, not a timed test.

usage: bench_workbench.py --web OUT_WEB [--stage S ...] [--size 640x360] [--renderer R] [--runs N]
                          [--baseline OTHER_OUT_WEB]

For each stage page (default Parts 1-3) at the embed's size (the site's live embeds render at their
width in device pixels, 640x360 for the usual column), in headless Chromium:
  edit-to-redraw: Module.t10SetShader(PostProcess.frag, an edited source) until the promise settles,
                  which is when the frame is redrawn (two white points the page has not seen a run);
  check:          Module.t10Check() until its promise settles (t10-grade's camera cases rendered, read
                  back and checked, the page's own frame drawn again), on the reference's shaders and
                  with a mistake fitted (the white point 1.0);
the median of --runs of each, the edits both one after another (as while typing) and each pair after a check. Then each page's download (index.html, .js, .wasm, .data) gzip-compressed
as a server would send it (gzip -6), and with --baseline the same for another build of the pages (the
build before the workbench) and the growth, which issue 52 bounds at 1 MB per page.
"""
import argparse
import gzip
import json
import os
import statistics
import sys

sys.dont_write_bytecode = True
import web_test  # noqa: E402  (beside this file)
from web import cdp  # noqa: E402

EDIT = "PostProcess.frag"
WHITE = ("fYwhite = 0.22f", "fYwhite = 1.0f")

# Two edits, each a white point the page has not compiled before (a renderer may keep the machine code
# of a source it has seen: toggling between two sources would time its cache, not an edit).
TIME_EDIT = """(async () => {
  const source = Module.t10Shaders().find(s => s.file === %(file)s).source;
  const times = [];
  let ok = true;
  for (const value of %(values)s) {
    const t0 = performance.now();
    const a = await Module.t10SetShader(%(file)s, source.replace(%(old)s, 'fYwhite = ' + value + 'f'));
    times.push(performance.now() - t0);
    ok = ok && a.ok;
  }
  ok = ok && (await Module.t10SetShader(%(file)s, source)).ok;
  return {ok: ok, ms: times};
})()"""

TIME_CHECK = """(async () => {
  const t0 = performance.now();
  const r = await Module.t10Check();
  return {ms: performance.now() - t0, score: r.score, error: r.error || ''};
})()"""


def gzip_size(folder, stage):
    total = 0
    for name in ("index.html", f"{stage}.js", f"{stage}.wasm", f"{stage}.data"):
        path = os.path.join(folder, stage, name)
        if os.path.isfile(path):
            with open(path, "rb") as f:
                total += len(gzip.compress(f.read(), 6))
    return total


def time_stage(page, args, stage):
    page.open(stage, f"size={args.size}&camera=default&frames=1")
    web_test.rendered(page, stage)
    edits, alone, checks, mistaken, scores = [], [], [], [], set()
    fresh = iter(range(1, 10000))

    def expression():
        values = [f"{0.22 + next(fresh) * 1e-4:.4f}" for _ in range(2)]
        return TIME_EDIT % {"file": json.dumps(EDIT), "old": json.dumps(WHITE[0]), "values": json.dumps(values)}
    for _ in range(args.runs):  # edits one after another, as while typing
        result = page.evaluate(expression(), await_promise=True)
        if not result["ok"]:
            raise cdp.Failure(f"{stage}: the edit was refused")
        alone.extend(result["ms"])
    for _ in range(args.runs):  # an edit after a check (the check rebuilds the stage at its cases' sizes)
        result = page.evaluate(expression(), await_promise=True)
        if not result["ok"]:
            raise cdp.Failure(f"{stage}: the edit was refused")
        edits.extend(result["ms"])
        result = page.evaluate(TIME_CHECK, await_promise=True)
        if result["error"]:
            raise cdp.Failure(f"{stage}: the check answered {result}")
        checks.append(result["ms"])
        scores.add(result["score"])
    source = page.evaluate(f"Module.t10Shaders().find(s => s.file === {json.dumps(EDIT)}).source")
    page.evaluate(f"Module.t10SetShader({json.dumps(EDIT)}, {json.dumps(source.replace(*WHITE))})", await_promise=True)
    for _ in range(args.runs):
        mistaken.append(page.evaluate(TIME_CHECK, await_promise=True)["ms"])
    page.evaluate(f"Module.t10SetShader({json.dumps(EDIT)}, {json.dumps(source)})", await_promise=True)
    print(f"{stage} at {args.size} ({args.renderer}): edit-to-redraw median {statistics.median(alone):.0f} ms "
          f"(max {max(alone):.0f}, {len(alone)} edits in a row), after a check {statistics.median(edits):.0f} ms "
          f"(max {max(edits):.0f}, {len(edits)} edits); check median {statistics.median(checks):.0f} ms "
          f"(max {max(checks):.0f}), with a mistake fitted {statistics.median(mistaken):.0f} ms; the reference "
          f"scores {sorted(scores)}", flush=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--web", required=True)
    ap.add_argument("--stage", action="append", default=[])
    ap.add_argument("--size", default="640x360")
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--renderer", choices=sorted(cdp.RENDERERS), default="llvmpipe")
    ap.add_argument("--chromium", default="chromium")
    ap.add_argument("--baseline", help="another build of the pages, for the download's growth")
    ap.add_argument("--timeout", type=float, default=600)
    args = ap.parse_args()
    args.stage = args.stage or list(web_test_stages())
    args.out = os.path.join(args.web, "..", "bench-workbench")
    os.makedirs(args.out, exist_ok=True)
    page = web_test.Page(args)
    try:
        for stage in args.stage:
            time_stage(page, args, stage)
    finally:
        page.close()
    for stage in args.stage:
        now = gzip_size(args.web, stage)
        line = f"{stage}: download {now / 1e6:.2f} MB gzip"
        if args.baseline:
            before = gzip_size(args.baseline, stage)
            line += f", {before / 1e6:.2f} MB before: grows by {(now - before) / 1e6:.3f} MB (bound 1 MB)"
        print(line)
    return 0


def web_test_stages():
    return ("tutorial10_part1_tonemap", "tutorial10_part2_bloom", "tutorial10_part3_gaussian")


if __name__ == "__main__":
    cdp.run_main(main)
