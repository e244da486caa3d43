"""Step markers in the stage sources.

Code that a step of the tutorial adds is wrapped in

    // [step 13] Create post-process frame buffer
    ...
    // [/step 13]

in C++ and GLSL alike (a stage folder holds nothing else). A step may have several blocks in one
file and across files, and blocks may nest (step 9 inside step 8). This module parses them
strictly: an unmatched or crossed marker is an error that names the file and line, so a typo
cannot silently drop an excerpt. It is the one parser of the markers: the site
(tools/build_site/build_site.py) and the stage-rule check (tests/stage_diff.py) both use it.
"""

import re
import textwrap

OPEN = re.compile(r"^(?P<indent>[ \t]*)(?P<comment>//)[ \t]*\[step (?P<step>\d+)\][ \t]?(?P<title>.*?)[ \t]*$")
CLOSE = re.compile(r"^[ \t]*//[ \t]*\[/step (?P<step>\d+)\][ \t]*$")

# File extensions whose step markers are read, and the highlighter language of each.
LANGUAGES = {
    ".cpp": "cpp", ".cc": "cpp", ".cxx": "cpp", ".hpp": "cpp", ".h": "cpp",
    ".frag": "glsl", ".vert": "glsl", ".geom": "glsl", ".comp": "glsl", ".tesc": "glsl",
    ".tese": "glsl", ".glsl": "glsl",
}


class MarkerError(Exception):
    pass


class Block:
    def __init__(self, step, title, indent, comment, start):
        self.step = step          # step number
        self.title = title        # text after the marker
        self.indent = indent      # indentation of the opening marker
        self.comment = comment    # "//"
        self.start = start        # 0-based index of the opening marker line
        self.end = None           # 0-based index of the closing marker line
        self.children = []

    @property
    def first_line(self):  # 1-based number of the first line inside the block
        return self.start + 2

    @property
    def last_line(self):   # 1-based number of the last line inside the block
        return self.end


def owners(lines, blocks):
    """For each line, the step of the innermost block it is in (marker lines count as inside), or None."""
    owner = [None] * len(lines)
    for block in blocks:  # outermost first, so nested blocks overwrite their lines
        for i in range(block.start, block.end + 1):
            owner[i] = block.step
    return owner


def language_of(path):
    for ext, lang in LANGUAGES.items():
        if path.endswith(ext):
            return lang
    return None


def parse(text, where):
    """Returns (lines, blocks): every block of the file, outermost first, in source order."""
    lines = text.split("\n")
    stack, blocks = [], []
    for i, line in enumerate(lines):
        m = OPEN.match(line)
        if m:
            block = Block(int(m["step"]), m["title"], m["indent"], m["comment"], i)
            if stack:
                stack[-1].children.append(block)
            stack.append(block)
            blocks.append(block)
            continue
        m = CLOSE.match(line)
        if m:
            step = int(m["step"])
            if not stack:
                raise MarkerError(f"{where}:{i + 1}: [/step {step}] closes nothing")
            if stack[-1].step != step:
                raise MarkerError(f"{where}:{i + 1}: [/step {step}] closes [step {stack[-1].step}] "
                                  f"opened on line {stack[-1].start + 1}")
            stack.pop().end = i
    if stack:
        raise MarkerError(f"{where}:{stack[-1].start + 1}: [step {stack[-1].step}] is never closed")
    for block in blocks:
        if block.step < 1:
            raise MarkerError(f"{where}:{block.start + 1}: step numbers start at 1")
    return lines, blocks


_SENTENCE_END = re.compile(r"^(.*?[.!?])(?:\s|$)")
# A comment line this long was wrapped by its author: its sentence goes on in the next line.
_WRAPPED = 90


def _first_sentence(block, lines):
    """The marker's title for a folded '... step N: title' line: where the marker's line was wrapped
    mid-sentence, read on into the comment lines under it, and keep the first sentence, so that the
    folded line never breaks off mid-sentence."""
    title = block.title or ""
    line, i = lines[block.start], block.start + 1
    while title and not _SENTENCE_END.match(title) and len(line.rstrip()) >= _WRAPPED and i < block.end:
        line = lines[i]
        text = line.strip()
        if not text.startswith(block.comment) or "[step" in text or "[/step" in text:
            break
        title += " " + text[len(block.comment):].strip()
        i += 1
    m = _SENTENCE_END.match(title)
    return m.group(1) if m else title


def _render(block, lines, out):
    if block.title:
        out.append(f"{block.indent}{block.comment} {block.title}")
    i = block.start + 1
    children = {child.start: child for child in block.children}
    while i < block.end:
        child = children.get(i)
        if child is None:
            out.append(lines[i])
            i += 1
        elif child.step == block.step:
            _render(child, lines, out)
            i = child.end + 1
        else:
            # Another step's code inside this one: the page shows it at that step.
            title = _first_sentence(child, lines)
            note = f": {title}" if title else ""
            out.append(f"{child.indent}{child.comment} ... step {child.step}{note}")
            i = child.end + 1


def code_of(block, lines):
    """The block's code as the page shows it: the marker's title kept as an ordinary comment,
    nested blocks of other steps folded into a one-line '... step N' comment, dedented."""
    out = []
    _render(block, lines, out)
    code = textwrap.dedent("\n".join(line.rstrip() for line in out))
    return code.strip("\n")
