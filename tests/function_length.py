#!/usr/bin/env python3
"""Reports the longest C++ functions of the repository and checks a limit on their length.

usage: function_length.py ROOT [--limit N] [--top K]

Scans every .cpp/.hpp under ROOT except stage files (tutorial10_part*/Tutorial10.cpp and
extras/Tutorial10.cpp keep the tutorial's shape), data generators (tools/make_*: tables of
geometry and pixels), third-party code and build trees. The grader is held to the limit too.
A function is a brace block opened outside any other function after a closing parenthesis (with
optional const / noexcept / override / a trailing return type or a constructor's initialiser list);
TEST_CASE bodies count as functions. Its length runs from the first line of its signature to its
closing brace. Comments and string literals are blanked first, so braces in them do not count.

Prints the K longest (default 5) and every function over N lines (default 120) and exits 1 if there
is one, unless it is listed in PENDING below with the issue that splits it.
"""
import argparse
import pathlib
import re
import sys

SKIP_PARTS = {"third_party", ".git", "_site"}
BUILD_TREE = re.compile(r"^build($|-)")  # build/, build-release/, build-asan/ (CMakePresets.json)
SKIP_PREFIXES = ("tools/make_",)
STAGE_FILE = re.compile(r"^(tutorial10_part[^/]*|extras)/Tutorial10\.cpp$")
# Functions over the limit that another open issue splits: "path:name" -> the issue.
PENDING: dict = {}
SIGNATURE_END = re.compile(r"\)\s*(?:const\s*|noexcept\s*|override\s*|final\s*|mutable\s*|->\s*[\w:<>,\s*&]+)*$")
CONSTRUCTOR = re.compile(r"\)\s*:\s*[\w:]+\s*[({]")


def blank(text):
    """The text with comments, string and character literals replaced by spaces (newlines kept)."""
    out = []
    i = 0
    n = len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif text.startswith('R"', i):
            m = re.match(r'R"([^(]*)\(', text[i:])
            end = text.find(")" + m.group(1) + '"', i) if m else -1
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append(" " * (min(j + 1, n) - i))
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def functions(path):
    """(name, first line, last line) of every top-level function body in `path`."""
    code = blank(path.read_text(errors="replace"))
    found = []
    depth = 0
    body_depth = None  # depth of the function body being read
    statement_start = 0
    start_line = 0
    name = ""
    line = 1
    for index, c in enumerate(code):
        if c == "\n":
            line += 1
        elif c == "{":
            if body_depth is None:
                statement = code[statement_start:index]
                if SIGNATURE_END.search(statement) or CONSTRUCTOR.search(statement):
                    head = statement[: statement.find("(")] if "(" in statement else statement
                    words = re.findall(r"[~\w:]+", head)
                    name = words[-1].split("::")[-1] if words else "?"
                    lead = len(statement) - len(statement.lstrip())
                    start_line = line - statement[lead:].count("\n")
                    body_depth = depth
            depth += 1
        elif c == "}":
            depth -= 1
            if body_depth is not None and depth == body_depth:
                found.append((name, start_line, line))
                body_depth = None
            statement_start = index + 1
        if c in ";{" and body_depth is None:
            statement_start = index + 1
        if c == "#" and body_depth is None:
            # A preprocessor line ends a statement too.
            statement_start = code.find("\n", index) + 1 or len(code)
    return found


def scanned_files(root):
    for path in sorted(root.rglob("*")):
        if path.suffix not in (".cpp", ".hpp") or not path.is_file():
            continue
        relative = path.relative_to(root).as_posix()
        parts = path.relative_to(root).parts
        if SKIP_PARTS & set(parts) or any(BUILD_TREE.match(p) for p in parts) or relative.startswith(SKIP_PREFIXES):
            continue
        if STAGE_FILE.match(relative):
            continue
        yield relative, path


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("root")
    parser.add_argument("--limit", type=int, default=120)
    parser.add_argument("--top", type=int, default=5)
    args = parser.parse_args()
    root = pathlib.Path(args.root)
    everything = []
    for relative, path in scanned_files(root):
        for name, first, last in functions(path):
            everything.append((last - first + 1, relative, name, first))
    if not everything:
        print(f"{root}: no functions found")
        return 1
    everything.sort(reverse=True)
    print(f"{len(everything)} functions; the longest:")
    for length, relative, name, first in everything[: args.top]:
        print(f"  {length:4d} lines  {relative}:{first} {name}")
    over = [f for f in everything if f[0] > args.limit]
    failing = 0
    for length, relative, name, first in over:
        pending = PENDING.get(f"{relative}:{name}")
        if pending:
            print(f"{relative}:{first}: {name} is {length} lines, over {args.limit} (pending: {pending})")
        else:
            print(f"{relative}:{first}: {name} is {length} lines, over {args.limit}")
            failing += 1
    print(f"functions over {args.limit} lines: {failing}" + (" (every one pending)" if over and not failing else ""))
    return 1 if failing else 0


if __name__ == "__main__":
    sys.exit(main())
