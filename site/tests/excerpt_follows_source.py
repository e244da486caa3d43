#!/usr/bin/env python3
"""Proves that the tutorial page's code comes from the stage sources, not from a copy.

Copies one stage folder into a scratch folder, changes one line inside a step marker there, builds
the site again from that copy (reusing the images and --help texts of the normal build, so no GPU work
is repeated), and asserts that:
  - the built tutorial page differs from the normal build's page;
  - the changed line appears on the new page, inside that step's excerpt, and not on the old page;
  - a line changed *outside* every step marker of that file does not appear in any excerpt;
  - the real sources were not touched.
"""

import argparse
import hashlib
import html
import os
import re
import secrets
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
BUILD_SITE = os.path.join(HERE, "..", "..", "tools", "build_site", "build_site.py")


class Failure(Exception):
    pass


def tree_hash(folder):
    digest = hashlib.sha256()
    for root, dirs, files in os.walk(folder):
        dirs.sort()
        for name in sorted(files):
            path = os.path.join(root, name)
            digest.update(os.path.relpath(path, folder).encode())
            with open(path, "rb") as f:
                digest.update(f.read())
    return digest.hexdigest()


def excerpt_html(page, stage, file, step):
    """The HTML of the excerpt figures of one step of one file (an excerpt is a <figure> whose
    closing tag stands on a line of its own; the highlighted code inside never starts a line with '<')."""
    opening = f'<figure class="excerpt" data-step="{step}" data-stage="{stage}" data-file="{file}">'
    out, start = [], page.find(opening)
    while start >= 0:
        end = page.find("\n</figure>", start)
        out.append(page[start:end if end >= 0 else len(page)])
        start = page.find(opening, start + 1)
    return "".join(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--source-root", required=True)
    ap.add_argument("--built-work", required=True, help="the normal build's work folder (build/site-src)")
    ap.add_argument("--built-site", required=True, help="the normal build's site (build/site)")
    ap.add_argument("--scratch", required=True, help="scratch folder in the build tree (emptied first)")
    ap.add_argument("--stages", required=True)
    ap.add_argument("--katex", default="/usr/share/javascript/katex")
    ap.add_argument("--jekyll", default="jekyll")
    ap.add_argument("--stage", default="tutorial10_part1_tonemap")
    ap.add_argument("--file", default="Tutorial10.cpp")
    ap.add_argument("--step", type=int, default=13)
    ap.add_argument("--page", default="tutorial10.html")
    args = ap.parse_args()

    real = os.path.join(args.source_root, args.stage)
    before = tree_hash(real)
    old_page_path = os.path.join(args.built_site, args.page)
    if not os.path.isfile(old_page_path):
        raise Failure(f"{old_page_path} does not exist: the site must be built first")
    with open(old_page_path, encoding="utf-8") as f:
        old_page = f.read()
    if not excerpt_html(old_page, args.stage, args.file, args.step).strip():
        raise Failure(f"{args.page} has no excerpt of step {args.step} from {args.stage}/{args.file}")

    if os.path.isdir(args.scratch):
        shutil.rmtree(args.scratch)
    copy = os.path.join(args.scratch, "src", args.stage)
    shutil.copytree(real, copy)

    # Change the first code line inside the step's block, and one line outside every block.
    token_in, token_out = f"t10sitetest{secrets.token_hex(4)}", f"t10sitetestoutside{secrets.token_hex(4)}"
    path = os.path.join(copy, args.file)
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    opening = re.compile(r"^\s*(//|#)\s*\[step %d\]" % args.step)
    marker = re.compile(r"^\s*(//|#)\s*\[/?step \d+\]")
    start = next((i for i, l in enumerate(lines) if opening.match(l)), None)
    if start is None:
        raise Failure(f"{args.stage}/{args.file} has no [step {args.step}] marker")
    target = next(i for i in range(start + 1, len(lines)) if lines[i].strip() and not marker.match(lines[i]))
    changed_from = lines[target]
    lines[target] = lines[target] + f" // {token_in}"
    depth, outside = 0, None
    for i, l in enumerate(lines):  # a line at depth 0 that is code: outside every marker
        if marker.match(l):
            depth += -1 if "[/step" in l else 1
        elif depth == 0 and l.strip().endswith(";") and i > start:
            outside = i
            break
    if outside is None:
        raise Failure(f"{args.stage}/{args.file}: no code line outside the step markers to change")
    lines[outside] = lines[outside] + f" // {token_out}"
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(lines))
    print(f"changed {args.stage}/{args.file}:{target + 1} (inside step {args.step}): {changed_from.strip()}")
    print(f"changed {args.stage}/{args.file}:{outside + 1} (outside every step marker)")

    work, dest = os.path.join(args.scratch, "site-src"), os.path.join(args.scratch, "site")
    cmd = [sys.executable, BUILD_SITE, "--source-root", args.source_root, "--work", work, "--dest", dest,
           "--stages", args.stages, "--stage-dir", f"{args.stage}={copy}", "--reuse", args.built_work,
           "--katex", args.katex, "--jekyll", args.jekyll]
    result = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=240)
    print(result.stdout.rstrip())
    if result.returncode != 0:
        raise Failure("the site did not build from the changed copy")

    with open(os.path.join(dest, args.page), encoding="utf-8") as f:
        new_page = f.read()
    problems = []
    if new_page == old_page:
        problems.append(f"{args.page} is identical although the source under [step {args.step}] changed")
    new_excerpt = excerpt_html(new_page, args.stage, args.file, args.step)
    if token_in not in new_excerpt:
        problems.append(f"the changed line is not in the step {args.step} excerpt of the new page")
    if token_in in old_page:
        problems.append("the change is on the old page too (the test is broken)")
    if token_out in new_page:
        problems.append("a line outside every step marker appeared on the tutorial page")
    if tree_hash(real) != before:
        problems.append(f"the real sources in {real} changed")
    if problems:
        raise Failure("\n  ".join(problems))
    print(f"ok: the changed line shows up in step {args.step}'s excerpt ({html.escape(token_in)}), "
          "the line outside the markers does not, and the real sources are untouched")
    shutil.rmtree(args.scratch, ignore_errors=True)


if __name__ == "__main__":
    try:
        main()
    except Failure as e:
        print(f"FAIL: {e}", file=sys.stderr)
        sys.exit(1)
