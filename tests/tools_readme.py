#!/usr/bin/env python3
"""Checks that tools/README.md describes tools/: every folder once, under its audience, with what runs it.

usage: tools_readme.py TOOLS_DIR MAKEFILE

The README groups its tables under `## <audience>` headings, one of AUDIENCES; a row starts with the
folder's name in backticks, `| \\`name/\\` | what it does | run by |`. A problem is: a folder of
TOOLS_DIR (one that holds a file other than __pycache__/'s) with no row, a row whose folder does not exist, a row listed twice, a row under a heading
that is not an audience (or under none), a last cell that says nothing of what runs the tool (a
`make` target, tests, by hand, imported or included), and a `make NAME` that MAKEFILE has no target
for. Prints each problem with the README's line and exits 1 if there is any; else prints "ok: ...".
"""
import pathlib
import re
import sys

AUDIENCES = ("Students", "Instructors", "The site", "CI proofs", "Content generation", "Developers", "Libraries")
RUN_BY = ("`make ", "tests", "by hand", "imported", "included")
ROW = re.compile(r"^\|\s*`([^`/]+)/`\s*\|")
MAKE = re.compile(r"`make ([A-Za-z0-9_-]+)")
TARGET = re.compile(r"^([A-Za-z0-9][A-Za-z0-9_. -]*?)\s*:(?![=])")


def makefile_targets(makefile):
    targets = set()
    for line in makefile.read_text().splitlines():
        match = TARGET.match(line)
        if match and not re.match(r"^[A-Za-z0-9_]+\s*[:?+]?=", line):
            targets.update(name for name in match.group(1).split() if not name.startswith("."))
    return targets


def holds_files(folder):
    """A folder counts when it holds a file other than Python's caches (a folder renamed in git leaves
    its __pycache__/ behind in a checkout: that is no tool)."""
    return not folder.name.startswith(".") and any(
        f.is_file() and "__pycache__" not in f.parts for f in folder.rglob("*"))


def check(tools, makefile):
    readme = tools / "README.md"
    folders = sorted(p.name for p in tools.iterdir() if p.is_dir() and holds_files(p))
    targets = makefile_targets(makefile)
    problems, rows, heading = [], {}, None
    for number, line in enumerate(readme.read_text().splitlines(), 1):
        if line.startswith("## "):
            heading = line[3:].strip()
            continue
        match = ROW.match(line)
        if not match:
            continue
        name, where = match.group(1), f"{readme}:{number}: `{match.group(1)}/`"
        if name in rows:
            problems.append(f"{where} is listed twice (also line {rows[name]})")
        rows.setdefault(name, number)
        if heading not in AUDIENCES:
            problems.append(f"{where} is under {heading!r}, which is not an audience: {', '.join(AUDIENCES)}")
        if not (tools / name).is_dir():
            problems.append(f"{where} is listed, but there is no folder {tools / name}/")
        run_by = line.rstrip().rstrip("|").rsplit("|", 1)[-1]
        if not any(word in run_by for word in RUN_BY):
            problems.append(f"{where}: its last cell does not say what runs it (a `make` target, tests, by hand, "
                            f"imported or included): {run_by.strip()!r}")
        for target in MAKE.findall(run_by):
            if target not in targets:
                problems.append(f"{where}: `make {target}` is no target of {makefile}")
    for name in folders:
        if name not in rows:
            problems.append(f"{readme}: `{name}/` is not listed: add its row under the audience it serves")
    return problems, len(folders)


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    tools, makefile = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    for path, kind in ((tools / "README.md", "file"), (makefile, "file")):
        if not path.is_file():
            print(f"{path}: no such {kind}", file=sys.stderr)
            return 2
    problems, count = check(tools, makefile)
    for problem in problems:
        print(problem)
    if problems:
        return 1
    print(f"ok: {tools}/README.md lists the {count} folders of {tools}/, each under its audience with what runs it")
    return 0


if __name__ == "__main__":
    sys.exit(main())
