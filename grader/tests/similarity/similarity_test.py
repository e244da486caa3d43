#!/usr/bin/env python3
"""The similarity report on a generated class (issue 51): the planted pairs found, nobody else.

usage: similarity_test.py SOURCE_ROOT ENGINE_DIR OUT_DIR

make_class.py writes 40 Part 3 students into OUT_DIR/class (two copies of the reference, three who
typed the tutorial's defects, honest students with independent edits, a planted host-code pair and a
planted shader pair, disguised differently; one of them with a hostile name, file name and code), and
similarity.py compares them into OUT_DIR/report. Checked: similarity.json has exactly the issue's shape
and is sorted by score; the two planted pairs are flagged and ranked first and no other pair is
flagged; similarity.csv has every pair; every page is strict UTF-8 with only the page's own tags (the
hostile name and code appear escaped, never as markup, and no control character or bidi override
remains). Shown to fail: the same class compared without the template (--no-template, the issue's
trial) flags honest pairs and the reference copies, and the check of the ranking rejects it, which
this test requires. Exit 77 (skipped) where Java or JPlag is not installed (make similarity-deps).
"""
import csv
import html
import html.parser
import json
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
TAGS = {"html", "head", "meta", "title", "style", "body", "h1", "h2", "h3", "p", "a", "table", "tr", "td", "th", "div",
        "pre", "span", "b"}
BAD_CHARACTERS = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\x7f\u202a-\u202e\u2066-\u2069]")


def display(name):
    """A name as similarity.py shows it (undecodable bytes and control characters replaced)."""
    text = os.fsencode(name).decode("utf-8", "replace")
    return "".join(c if c >= " " and c != "\x7f" and not ("\u202a" <= c <= "\u202e" or "\u2066" <= c <= "\u2069")
                   else "\ufffd" for c in text)


def run_similarity(root, engine, folder, report, *extra):
    command = [sys.executable, os.path.join(root, "grader", "similarity", "similarity.py"), "--part", "3", "--report",
               report, "--engine", engine, "--folder", folder, *extra]
    result = subprocess.run(command, capture_output=True, text=True)
    print(result.stdout.strip())
    if result.returncode != 0:
        sys.exit(f"FAIL: similarity.py exited {result.returncode}: {result.stderr.strip()}")
    with open(os.path.join(report, "similarity.json"), encoding="utf-8") as f:
        return json.load(f)


def shape_problems(result):
    problems = []
    if set(result) != {"engine", "version", "template", "pairs"}:
        problems.append(f"similarity.json's keys are {sorted(result)}")
    if result.get("engine") != "JPlag" or result.get("version") != "4.3.0" or not result.get("template"):
        problems.append(f"engine {result.get('engine')} {result.get('version')}, template {result.get('template')}")
    for pair in result["pairs"]:
        if set(pair) != {"a", "b", "score", "matched_tokens", "flagged", "fragments"} or not 0 <= pair["score"] <= 1:
            problems.append(f"a pair not in the issue's shape: {pair}")
        for fragment in pair["fragments"]:
            if set(fragment) != {"a", "b"} or not all(re.search(r":\d+-\d+$", fragment[s]) for s in "ab"):
                problems.append(f"a fragment not file:first-last: {fragment}")
    scores = [p["score"] for p in result["pairs"]]
    if scores != sorted(scores, reverse=True):
        problems.append("pairs not sorted by score")
    return problems


def ranking_problems(result, expected):
    """What is wrong with who is flagged and ranked first."""
    planted = {tuple(sorted(display(n) for n in pair)) for pair in expected["planted"]}
    pairs = result["pairs"]
    first = {(p["a"], p["b"]) for p in pairs[:2]}
    flagged = {(p["a"], p["b"]) for p in pairs if p["flagged"]}
    problems = []
    if first != planted:
        problems.append(f"ranked first: {sorted(first)}, not the planted pairs {sorted(planted)}")
    if flagged != planted:
        problems.append(f"flagged: {sorted(flagged)[:6]} ({len(flagged)}), not only the planted pairs")
    return problems


class Tags(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.tags = set()

    def handle_starttag(self, tag, attrs):
        self.tags.add(tag)
        for name, _ in attrs:
            if name.startswith("on"):
                self.tags.add(f"{tag}[{name}]")


def page_problems(report, hostile):
    problems = []
    pages = [os.path.join(report, "similarity.html")] + sorted(
        os.path.join(report, "similarity", n) for n in os.listdir(os.path.join(report, "similarity")))
    for page in pages:
        with open(page, "rb") as f:
            data = f.read()
        try:
            text = data.decode("utf-8")
        except UnicodeDecodeError as error:
            problems.append(f"{page}: not UTF-8: {error}")
            continue
        if BAD_CHARACTERS.search(text):
            problems.append(f"{page}: a control character or bidi override: {BAD_CHARACTERS.search(text).group()!r}")
        parser = Tags()
        parser.feed(text)
        if parser.tags - TAGS:
            problems.append(f"{page}: markup that is not the page's own: {sorted(parser.tags - TAGS)}")
    first = open(os.path.join(report, "similarity", "pair-0001.html"), encoding="utf-8").read()
    for needle in (html.escape(display(hostile), quote=True), "&lt;/pre&gt;&lt;/span&gt;&lt;script&gt;"):
        if needle not in first:
            problems.append(f"pair-0001.html does not show {needle!r} escaped")
    return problems


def csv_problems(report, result):
    with open(os.path.join(report, "similarity.csv"), encoding="utf-8", newline="") as f:
        rows = list(csv.DictReader(f))
    got = [(r["a"], r["b"], r["flagged"]) for r in rows]
    want = [(p["a"], p["b"], "yes" if p["flagged"] else "no") for p in result["pairs"]]
    return [] if got == want else [f"similarity.csv disagrees with similarity.json: {got[:3]} against {want[:3]}"]


def main():
    if len(sys.argv) != 4:
        print(__doc__)
        return 2
    root, engine, out = sys.argv[1:]
    if shutil.which("java") is None or not os.path.isfile(os.path.join(engine, "lock")):
        print("SKIPPED: Java or JPlag is not installed (make similarity-deps)")
        return 77
    shutil.rmtree(out, ignore_errors=True)
    folder = os.path.join(out, "class")
    subprocess.run([sys.executable, os.path.join(HERE, "make_class.py"), root, folder], check=True)
    with open(os.path.join(folder, "expected.json"), encoding="utf-8") as f:
        expected = json.load(f)
    report = os.path.join(out, "report")
    result = run_similarity(root, engine, folder, report)
    problems = shape_problems(result) + ranking_problems(result, expected) + page_problems(report, expected["hostile"])
    problems += csv_problems(report, result)
    # The check of the ranking must reject a comparison that keeps what the course hands out.
    untemplated = run_similarity(root, engine, folder, os.path.join(out, "report-no-template"), "--no-template")
    rejected = ranking_problems(untemplated, expected)
    if not rejected:
        problems.append("without the template the ranking check passed too: it cannot fail")
    for problem in problems:
        print("FAIL:", problem)
    if problems:
        return 1
    flagged = [(p["a"][:20], p["b"][:20], p["score"]) for p in result["pairs"] if p["flagged"]]
    print(f"ok: {len(expected['students'])} students, {len(result['pairs'])} pairs share anything beyond the template, "
          f"flagged {flagged}; without the template: {rejected[0]}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
