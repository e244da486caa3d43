#!/usr/bin/env python3
"""Checks the stage rule: the difference between two consecutive stage folders is exactly the steps
of one part of the tutorial.

usage: stage_diff.py OLD_DIR NEW_DIR FIRST_STEP LAST_STEP

Passes when
- the folders hold only host code (.cpp) and shaders (.vert .frag .geom .comp .tesc .tese),
- no file of the old stage disappears,
- every line the new stage adds is blank, part of the file's header comment, a `#version` line, or
  inside a `[step N]` ... `[/step N]` block with FIRST_STEP <= N <= LAST_STEP,
- lines of the old stage are only removed where such a step block replaces them.
Prints every offending line with its file and line number, and exits 1 if there is any.
"""
import difflib
import pathlib
import re
import sys

ALLOWED = {".cpp", ".vert", ".frag", ".geom", ".comp", ".tesc", ".tese"}
MARKER = re.compile(r"^\s*//\s*\[(/?)step (\d+)\]")


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
    """For each line, the innermost step block it is in (marker lines count as inside), or None."""
    stack, owner = [], []
    for number, line in enumerate(lines, 1):
        match = MARKER.match(line)
        if match and not match.group(1):
            stack.append(int(match.group(2)))
            owner.append(stack[-1])
            continue
        if match:
            step = int(match.group(2))
            if not stack or stack[-1] != step:
                problems.append(f"{path}:{number}: [/step {step}] does not close the open block {stack[-1:] or 'none'}")
            else:
                owner.append(stack.pop())
                continue
        owner.append(stack[-1] if stack else None)
    if stack:
        problems.append(f"{path}: [step {stack[-1]}] is never closed")
    return owner


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
        header = header_length(new_lines)

        def allowed(index):
            line = new_lines[index]
            step = owner[index]
            return (not line.strip() or index < header or line.startswith("#version")
                    or (step is not None and first <= step <= last))

        matcher = difflib.SequenceMatcher(a=old_lines, b=new_lines, autojunk=False)
        for tag, a0, a1, b0, b1 in matcher.get_opcodes():
            if tag == "equal":
                continue
            added = range(b0, b1)
            for index in added:
                if not allowed(index):
                    problems.append(f"{new_dir.name}/{name}:{index + 1}: not part of steps {first}-{last}: "
                                    f"{new_lines[index].strip()}")
            removed = [line for line in old_lines[a0:a1] if line.strip()]
            header_change = a1 <= header_length(old_lines) and b1 <= header
            replaced_by_step = any(owner[i] is not None and first <= owner[i] <= last for i in added)
            if removed and not header_change and not replaced_by_step:
                for line in removed:
                    problems.append(f"{old_dir.name}/{name}: line removed without a step replacing it: {line.strip()}")
    for problem in problems:
        print(problem)
    print(f"{old_dir.name} -> {new_dir.name}: " + ("only steps %d-%d" % (first, last) if not problems
                                                   else f"{len(problems)} lines outside steps {first}-{last}"))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
