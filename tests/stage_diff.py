#!/usr/bin/env python3
"""Checks the stage rule: the difference between two consecutive stage folders is exactly the steps
of one part of the tutorial.

usage: stage_diff.py OLD_DIR NEW_DIR FIRST_STEP LAST_STEP

Passes when
- the folders hold only host code (.cpp) and shaders (.vert .frag .geom .comp .tesc .tese),
- no file of the old stage disappears,
- every line the new stage adds is blank, braces only, part of the file's header comment, a `#version` line,
  inside a `[step N]` ... `[/step N]` block with FIRST_STEP <= N <= LAST_STEP, or the same text as a
  line the old stage had there and the new one removed (code re-indented or moved by a step that
  wraps it, which adds nothing),
- lines of the old stage are only removed where such a step block replaces them, where they move,
  or where they belonged to an earlier step's block (a later step, such as an exercise, may change
  the code of an earlier one; code outside every step may not change at all).
Prints every offending line with its file and line number, and exits 1 if there is any.
"""
import collections
import difflib
import pathlib
import sys

# The one step-marker parser, shared with the site (tools/ on PYTHONPATH).
from markers import markers

ALLOWED = {".cpp", ".vert", ".frag", ".geom", ".comp", ".tesc", ".tese"}


def header_length(lines):
    """Number of leading comment lines (the file's header comment)."""
    count = 0
    for line in lines:
        if line.lstrip().startswith("//"):
            count += 1
        else:
            break
    return count


def step_of_each_line(lines, path, problems):
    """For each line, the innermost step block it is in (marker lines count as inside), or None.
    A malformed marker is a problem, and then no line counts as inside a step."""
    try:
        _, blocks = markers.parse("\n".join(lines), str(path))
    except markers.MarkerError as error:
        problems.append(str(error))
        return [None] * len(lines)
    return markers.owners(lines, blocks)


def main():
    if len(sys.argv) != 5:
        print(__doc__)
        return 2
    old_dir, new_dir = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    first, last = int(sys.argv[3]), int(sys.argv[4])
    problems = []
    old_files = {p.name for p in old_dir.iterdir() if p.is_file()}
    new_files = {p.name for p in new_dir.iterdir() if p.is_file()}
    for name in sorted(old_files | new_files):
        if pathlib.Path(name).suffix not in ALLOWED:
            problems.append(f"{name}: only host code and shaders belong in a stage folder")
            continue
        if name not in new_files:
            problems.append(f"{name}: removed by {new_dir.name}; a stage only adds steps")
            continue
        new_lines = (new_dir / name).read_text().splitlines()
        old_lines = (old_dir / name).read_text().splitlines() if name in old_files else []
        owner = step_of_each_line(new_lines, new_dir / name, problems)
        old_owner = step_of_each_line(old_lines, old_dir / name, []) if old_lines else []
        header = header_length(new_lines)

        def allowed(index):
            line = new_lines[index]
            step = owner[index]
            # A line of braces only does nothing by itself; the `if` or loop that needs it is checked.
            return (not line.strip() or index < header or line.startswith("#version")
                    or set(line.strip()) <= set("{};")
                    or (step is not None and first <= step <= last))

        matcher = difflib.SequenceMatcher(a=old_lines, b=new_lines, autojunk=False)
        opcodes = [op for op in matcher.get_opcodes() if op[0] != "equal"]
        # Lines removed anywhere in the file, by content: an added line with the same text is a move.
        moved = collections.Counter(old_lines[i].strip() for _, a0, a1, _, _ in opcodes for i in range(a0, a1)
                                    if old_lines[i].strip())
        # Lines added anywhere in the file, by content: a removed line with the same text is a move.
        added_text = collections.Counter(new_lines[i].strip() for _, _, _, b0, b1 in opcodes for i in range(b0, b1)
                                         if new_lines[i].strip())
        for tag, a0, a1, b0, b1 in opcodes:
            added = range(b0, b1)
            for index in added:
                text = new_lines[index].strip()
                if not allowed(index) and moved[text] > 0:
                    moved[text] -= 1
                    continue
                if not allowed(index):
                    problems.append(f"{new_dir.name}/{name}:{index + 1}: not part of steps {first}-{last}: "
                                    f"{new_lines[index].strip()}")
            header_change = a1 <= header_length(old_lines) and b1 <= header
            replaced_by_step = any(owner[i] is not None and first <= owner[i] <= last for i in added)
            if header_change or replaced_by_step:
                continue
            for index in range(a0, a1):
                text = old_lines[index].strip()
                if not text or old_owner[index] is not None:
                    continue
                if added_text[text] > 0:
                    added_text[text] -= 1
                    continue
                problems.append(f"{old_dir.name}/{name}:{index + 1}: line removed without a step replacing it: {text}")
    for problem in problems:
        print(problem)
    print(f"{old_dir.name} -> {new_dir.name}: " + ("only steps %d-%d" % (first, last) if not problems
                                                   else f"{len(problems)} lines outside steps {first}-{last}"))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
