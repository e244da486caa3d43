#!/usr/bin/env python3
"""Proves that the browser check can fail: breaks a copy of the built site in six ways and runs the
same checks on it (light scheme only); succeeds only if every breakage is reported.

  - one rendered frame deleted                      -> "image not loaded"
  - KaTeX's auto-render script deleted              -> "KaTeX did not run"
  - the step counter reset by every list            -> "numbers shown in front of the steps"
  - a script from a CDN added to the page           -> "request outside the local server"
  - the code of one excerpt emptied                 -> "empty excerpt"
  - the "Check your work" heading renamed           -> "section #check-your-work missing"
"""

import argparse
import os
import re
import shutil
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import browser_test  # noqa: E402

EXPECTED = ["image not loaded", "KaTeX did not run", "numbers shown in front of the steps",
            "request outside the local server", "empty excerpt", "section #check-your-work missing"]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--site", required=True)
    ap.add_argument("--page", default="tutorial10.html")
    ap.add_argument("--chromium", default="chromium")
    ap.add_argument("--scratch", required=True, help="scratch folder in the build tree (emptied first)")
    ap.add_argument("--steps", type=int, default=40)
    ap.add_argument("--timeout", type=float, default=80)
    args = ap.parse_args()

    if os.path.isdir(args.scratch):
        shutil.rmtree(args.scratch)
    broken = os.path.join(args.scratch, "site")
    shutil.copytree(args.site, broken, ignore=shutil.ignore_patterns("CMakeFiles", "*.cmake"))
    page = os.path.join(broken, args.page)
    with open(page, encoding="utf-8") as f:
        text = f.read()
    images = re.findall(r'<img src="(assets/images/[^"]+)"', text)
    if not images:
        raise browser_test.Failure(f"{args.page} has no rendered images to break")
    os.remove(os.path.join(broken, images[0]))
    os.remove(os.path.join(broken, "assets", "katex", "contrib", "auto-render.js"))
    css = os.path.join(broken, "assets", "css", "site.css")
    with open(css, "a", encoding="utf-8") as f:
        f.write("\n.steps > ol { counter-reset: step; }\n")
    text = text.replace("</head>", '<script src="https://cdn.jsdelivr.net/npm/katex/dist/katex.min.js"></script>\n</head>', 1)
    text, emptied = re.subn(r'(<figure class="excerpt".*?<code[^>]*>).*?(</code>)', r"\1\2", text, count=1, flags=re.S)
    if not emptied:
        raise browser_test.Failure(f"{args.page} has no excerpt to empty")
    text, renamed = re.subn(r'id="check-your-work"', 'id="renamed-section"', text)
    if not renamed:
        raise browser_test.Failure(f"{args.page} has no #check-your-work section to break")
    with open(page, "w", encoding="utf-8") as f:
        f.write(text)

    problems = browser_test.run(broken, args.page, args.chromium, os.path.join(args.scratch, "out"),
                                args.steps, timeout=args.timeout, schemes=("light",),
                                sections=("check-your-work<part-1-tone-mapping",))
    print("\n".join(p[:200] for p in problems))
    missed = [e for e in EXPECTED if not any(e in p for p in problems)]
    if missed:
        raise browser_test.Failure("the browser check did not report: " + ", ".join(missed))
    print(f"ok: all {len(EXPECTED)} breakages were reported")
    shutil.rmtree(args.scratch, ignore_errors=True)


if __name__ == "__main__":
    browser_test.cdp.run_main(main)
