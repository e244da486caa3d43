#!/usr/bin/env python3
"""A nested step's code folds into one '... step N: title' line that ends a sentence: a marker title
wrapped mid-sentence is read on into the next comment line, and a short title is kept as it is.
Exit 0 when both hold, 1 (naming the line) when not."""
import sys

sys.dont_write_bytecode = True
from markers import markers  # noqa: E402  (tools/ on PYTHONPATH)

SOURCE = """\
// [step 1] Outer
int a;
    // [step 2] Map [log(epsilon), log(Yw)] to [0, 1]. Anything brighter than Yw saturates to 1 in
    // GL_R16, so very bright scenes get a lower key.
    int b;
    // [/step 2]
    // [step 3] A short title
    // Get coordinates
    int c;
    // [/step 3]
    // [step 4] Output bloom values: the threshold is a multiple of the white point, so it acts on
    // approximate brightness before the tone map has run
    int d;
    // [/step 4]
// [/step 1]
"""
EXPECTED = [
    "// ... step 2: Map [log(epsilon), log(Yw)] to [0, 1].",
    "// ... step 3: A short title",
    "// ... step 4: Output bloom values: the threshold is a multiple of the white point, so it acts on "
    "approximate brightness before the tone map has run",
]

lines, blocks = markers.parse(SOURCE, "fixture.frag")
folded = [l.strip() for l in markers.code_of(blocks[0], lines).splitlines() if "... step" in l]
if folded != EXPECTED:
    print("folded lines:\n  " + "\n  ".join(folded) + "\nexpected:\n  " + "\n  ".join(EXPECTED))
    sys.exit(1)
print("ok: " + str(len(folded)) + " folded lines end a sentence or keep a short title")
