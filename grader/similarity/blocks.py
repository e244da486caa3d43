"""The top-level blocks of a C++ or GLSL file: JPlag reads each as a file of its own.

JPlag's C/C++ scanner sees structure only (declarations, assignments, blocks, control flow; not calls
nor names), so a function or a global declaration is often shorter than its minimum match of 12
tokens. JPlag removes template code in runs of at least that length: when a student moves the
reference's functions around, the runs across the seams are no run of the template and stay, and two
students who happened to move the same blocks then share them (a trial class: 37 shared tokens between
two honest students, more than one planted pair). With each top-level block (a function, a
declaration, a preprocessor line, with the comments above it) a file of its own, no match crosses a
block, so moving blocks is neither a disguise nor a coincidence, and every fragment lies within one
block of the student's file (its lines are the block's lines plus the block's offset).
"""
import re

COMMENT = re.compile(r"//[^\n]*|/\*.*?\*/", re.S)


def blocks(lines):
    """[(first line index, last line index)] of the top-level blocks of `lines` (a list of str)."""
    found, start, depth, in_comment = [], None, 0, False
    for i, line in enumerate(lines):
        code = line
        if in_comment:
            end = code.find("*/")
            if end < 0:
                continue
            code, in_comment = code[end + 2:], False
        code = COMMENT.sub("", code)
        if "/*" in code:
            code, in_comment = code[: code.index("/*")], True
        stripped = code.strip()
        if start is None:
            if not line.strip():
                continue
            start = i
        depth = max(0, depth + stripped.count("{") - stripped.count("}"))
        ends = stripped.startswith("#") or stripped.endswith((";", "}"))
        if depth == 0 and ends:
            found.append((start, i))
            start = None
    if start is not None:
        found.append((start, len(lines) - 1))
    return found
