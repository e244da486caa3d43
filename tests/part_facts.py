#!/usr/bin/env python3
"""Checks that every copy of the facts of the tutorial's parts agrees with the grader's description.

usage: part_facts.py ROOT [--replace FILE OLD NEW]...

The facts of Part N (its reference stage, the steps it adds, its golden image) are written in the
grader's part description (grader/part/part.cpp, the source) and, in languages that cannot include
it, in these places, each read here as the text it is:

    tests/stage_tests.cmake           t10_add_stage_tests(STAGE AFTER PREVIOUS STEPS FIRST LAST)
    CMakeLists.txt                    T10_GOLDEN_STAGES: item N is Part N's stage (cmake/T10WebCompare.cmake
                                      takes a student's reference and golden tolerance by that index)
    tests/golden/                     STAGE.png and STAGE.tolerance, Part N's golden
    tools/.../new_student.py          PARTS[N] = (title, "FIRST-LAST"), REFERENCE[N] = STAGE, REFERENCE[0] the start
    tools/.../build_site.py           P1, P2, P3 = the stages
    grader/tests/make_submissions.py  STAGES[N] = STAGE
    grader/platforms/gradescope/setup.sh  case "$T10_PART" in N) stage=STAGE ;; ...

Prints each disagreement with its file and exits 1; prints the count of places that agree and exits 0.
--replace changes OLD (which must occur) into NEW in FILE as read, to show that a disagreement fails.
"""
import ast
import pathlib
import re
import sys

PARTS = (1, 2, 3)


class Source:
    def __init__(self, root, replacements):
        self.root = root
        self.replacements = replacements

    def find(self, pattern):
        """The one file under ROOT matching the glob `pattern` (tools/ may move its folders)."""
        found = sorted(self.root.glob(pattern))
        if len(found) != 1:
            raise SystemExit(f"part_facts.py: {pattern}: expected one file under {self.root}, found {len(found)}")
        return found[0].relative_to(self.root).as_posix()

    def text(self, relative):
        text = (self.root / relative).read_text()
        for file, old, new in self.replacements:
            if file == relative:
                text = text.replace(old, new)
        return text


def python_assignments(text, names):
    """The literal values assigned to `names` at a Python module's top level."""
    values = {}
    for node in ast.parse(text).body:
        if isinstance(node, ast.Assign) and len(node.targets) == 1:
            target = node.targets[0]
            if isinstance(target, ast.Name) and target.id in names:
                values[target.id] = ast.literal_eval(node.value)
            elif isinstance(target, ast.Tuple) and all(isinstance(t, ast.Name) for t in target.elts):
                for name, value in zip((t.id for t in target.elts), ast.literal_eval(node.value)):
                    if name in names:
                        values[name] = value
    return values


def grader_parts(src):
    """{N: (stage, first, last)} from the grader's part description, the source of the facts."""
    path = "grader/part/part.cpp"
    found = {int(n): (stage, int(first), int(last))
             for n, stage, first, last in re.findall(r'describe\((\d), "([^"]+)", (\d+), (\d+),', src.text(path))}
    if sorted(found) != list(PARTS):
        raise SystemExit(f"part_facts.py: {path}: expected describe(N, \"stage\", first, last, ...) for Parts 1-3, found {sorted(found)}")
    return found


def check(src):
    parts = grader_parts(src)
    problems = []
    places = 0

    def expect(where, what, got, wanted):
        if got != wanted:
            problems.append(f"{where}: {what}: {got!r}, where grader/part/part.cpp says {wanted!r}")

    path = "tests/stage_tests.cmake"
    rows = {stage: (after, int(first), int(last)) for stage, after, first, last in
            re.findall(r"^t10_add_stage_tests\((\S+) AFTER (\S+) STEPS (\d+) (\d+)", src.text(path), re.M)}
    start = rows.get(parts[1][0], ("?",))[0]
    for n in PARTS:
        stage, first, last = parts[n]
        after, got_first, got_last = rows.get(stage, (None, None, None))
        expect(path, f"Part {n}'s stage {stage}: its steps", (got_first, got_last), (first, last))
        if n > 1:
            expect(path, f"Part {n}'s stage {stage}: the stage it comes after", after, parts[n - 1][0])
    places += 1

    path = "CMakeLists.txt"
    golden = re.search(r"^set\(T10_GOLDEN_STAGES ([^)]*)\)", src.text(path), re.M)
    golden = golden.group(1).split() if golden else []
    expect(path, "T10_GOLDEN_STAGES", golden, [start] + [parts[n][0] for n in PARTS])
    compare = "cmake/T10WebCompare.cmake"
    if "list(GET T10_GOLDEN_STAGES ${part} reference)" not in src.text(compare):
        problems.append(f"{compare}: no longer takes Part N's reference as item N of T10_GOLDEN_STAGES")
    for n in PARTS:
        for suffix in (".png", ".tolerance"):
            if not (src.root / "tests/golden" / (parts[n][0] + suffix)).is_file():
                problems.append(f"tests/golden/{parts[n][0]}{suffix}: Part {n}'s golden is missing")
    places += 3

    path = src.find("tools/**/new_student.py")
    values = python_assignments(src.text(path), {"PARTS", "REFERENCE"})
    for n in PARTS:
        stage, first, last = parts[n]
        expect(path, f"PARTS[{n}]'s steps", values.get("PARTS", {}).get(n, (None, None))[1], f"{first}-{last}")
        expect(path, f"REFERENCE[{n}]", values.get("REFERENCE", {}).get(n), stage)
    expect(path, "REFERENCE[0] (where Part 1 starts)", values.get("REFERENCE", {}).get(0), start)
    places += 1

    path = src.find("tools/**/build_site.py")
    values = python_assignments(src.text(path), {"P1", "P2", "P3"})
    for n in PARTS:
        expect(path, f"P{n}", values.get(f"P{n}"), parts[n][0])
    places += 1

    path = "grader/tests/make_submissions.py"
    stages = python_assignments(src.text(path), {"STAGES"}).get("STAGES", {})
    expect(path, "STAGES", stages, {n: parts[n][0] for n in PARTS})
    places += 1

    path = "grader/platforms/gradescope/setup.sh"
    case = re.search(r'case "\$T10_PART" in (.*) esac', src.text(path))
    arms = dict(re.findall(r"(\S+)\) stage=(\S+) ;;", case.group(1))) if case else {}
    expect(path, "the case of $T10_PART", arms, {"1": parts[1][0], "2": parts[2][0], "*": parts[3][0]})
    places += 1
    return problems, places


def main():
    args = sys.argv[1:]
    if not args:
        print(__doc__)
        return 2
    root, replacements = pathlib.Path(args[0]), []
    rest = args[1:]
    while rest[:1] == ["--replace"] and len(rest) >= 4:
        replacements.append(tuple(rest[1:4]))
        rest = rest[4:]
    if rest:
        print(__doc__)
        return 2
    src = Source(root, replacements)
    for file, old, new in replacements:
        if old not in (root / file).read_text():
            print(f"part_facts.py: --replace {file}: {old!r} does not occur")
            return 2
    problems, places = check(src)
    for problem in problems:
        print(problem)
    print(f"part facts: {places} places beside grader/part/part.cpp: " +
          ("they agree" if not problems else f"{len(problems)} disagreements"))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
