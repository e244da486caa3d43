#!/usr/bin/env python3
"""t10-grade --similarity on a small class: the class index lists the pair to review and links its page.

usage: grade_similarity_test.py SOURCE_ROOT T10_GRADE OUT_DIR

Three Part 3 submissions of Gauss.frag alone, graded with --fill-from-reference none (each stops at
missing-files, so nothing is built: the test is about the comparison after grading): two hand in the
same distinctive shader (make_class.py's planted one, disguised differently), one the reference's.
Checked: exit 0, similarity.json beside index.html with the planted pair flagged, and index.html's
"Pairs to review" linking that pair's page, which exists. Shown to fail by the third submission: it is
not listed. Then t10-grade --similarity without Java on PATH must stop before grading (exit 2) naming
what to install. Exit 77 (skipped) where Java or JPlag is not installed.
"""
import json
import os
import random
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_class  # noqa: E402


def main():
    if len(sys.argv) != 4:
        print(__doc__)
        return 2
    root, grade, out = sys.argv[1:]
    problems = []
    shutil.rmtree(out, ignore_errors=True)
    reference = make_class.read_reference(root)
    rng = random.Random(5)
    shaders = {"pair_one": make_class.disguise(dict(reference, **{"Gauss.frag": make_class.SHADER_SOLUTION}), rng),
               "pair_two": make_class.disguise(dict(reference, **{"Gauss.frag": make_class.SHADER_SOLUTION}), rng),
               "reference": reference}
    folders = []
    for name, files in shaders.items():
        make_class.write(os.path.join(out, "class"), name, {"Gauss.frag": files["Gauss.frag"]})
        folders.append(os.path.join(out, "class", name))
    # Without Java on PATH: refused before any grading, naming make similarity-deps.
    refused = subprocess.run([grade, "--part", "3", "--similarity", "--report", os.path.join(out, "refused"), *folders],
                             capture_output=True, text=True, env=dict(os.environ, PATH="/nonexistent"))
    if refused.returncode != 2 or "make similarity-deps" not in refused.stderr:
        problems.append(f"without Java: exit {refused.returncode}, {refused.stderr.strip()[:200]!r}")
    if os.path.exists(os.path.join(out, "refused")):
        problems.append("without Java the grader still wrote a report")
    # JPlag's jars where this build's t10-grade looks for them (build/jplag/, as the generated class's test).
    engine = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(grade))), "jplag")
    jars = subprocess.run([sys.executable, os.path.join(root, "grader", "similarity", "fetch_engine.py"),
                           os.path.join(root, "grader", "similarity", "jplag.lock"), engine, "--check"],
                          capture_output=True, text=True)
    if shutil.which("java") is None or jars.returncode != 0 or problems:
        for problem in problems:
            print("FAIL:", problem)
        if not problems:
            print("SKIP: " + ("java is not installed" if shutil.which("java") is None else
                              f"JPlag's jars are not in {engine} (make similarity-deps)"))
        return 1 if problems else 77
    report = os.path.join(out, "report")
    result = subprocess.run([grade, "--part", "3", "--fill-from-reference", "none", "--jobs", "2", "--similarity",
                             "--report", report, *folders], capture_output=True, text=True)
    print(result.stdout.strip())
    if result.returncode != 0:
        print(f"FAIL: t10-grade --similarity exited {result.returncode}: {result.stderr.strip()}")
        return 1
    with open(os.path.join(report, "similarity.json"), encoding="utf-8") as f:
        pairs = json.load(f)["pairs"]
    flagged = [(p["a"], p["b"]) for p in pairs if p["flagged"]]
    if flagged != [("pair_one", "pair_two")]:
        problems.append(f"flagged {flagged}, not the planted pair")
    index = open(os.path.join(report, "index.html"), encoding="utf-8").read()
    section = index[index.find("<h2>Pairs to review</h2>"):]
    if not section or "similarity/pair-0001.html" not in section or "pair_one" not in section:
        problems.append("index.html does not list the pair to review with its page")
    if "<td class=\"l\">reference</td>" in section:
        problems.append("index.html lists the reference's submission among the pairs to review")
    if not os.path.isfile(os.path.join(report, "similarity", "pair-0001.html")):
        problems.append("the pair's page is missing")
    for problem in problems:
        print("FAIL:", problem)
    if not problems:
        print("ok: t10-grade --similarity listed pair_one and pair_two in index.html with their page; without Java "
              "it stopped: " + refused.stderr.strip().splitlines()[0])
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
