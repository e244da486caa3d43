#!/usr/bin/env python3
"""Writes a generated Part 3 class for the similarity tests (issue 51), from the current reference.

usage: make_class.py SOURCE_ROOT OUT_DIR [--honest N] [--seed S] [--names PREFIX]

OUT_DIR/<student>/ holds Tutorial10.cpp and the part's shaders of each student:
- ref_copy_1, ref_copy_2: the reference exactly;
- typist_1..3: the tutorial typed as printed (its defects: ceil levels, no unit 16 before the key's
  mipmaps, step 9's fYwhite order and 0 / 0), with their own edits;
- honest_NN (N of them): the reference with independent edits: identifiers renamed, comments removed or
  reworded, top-level blocks reordered, indentation and braces reformatted; a third of them add a small
  helper of their own (random statements);
- host_a / host_b: both hand in one distinctive blur loop in Tutorial10.cpp, each disguised differently;
  host_b has a hostile name and hostile bytes in its shared code (the pages must escape them);
- shader_a / shader_b: both hand in one distinctive Gauss.frag, disguised differently.
OUT_DIR/expected.json names the planted pairs and the rest. Deterministic for a seed.
"""
import json
import os
import random
import re
import sys

PART3 = "tutorial10_part3_gaussian"
FILES = ["Tutorial10.cpp", "Gauss.frag", "PostProcess.frag", "PostProcessInit.frag"]
HOSTILE_NAME = "host_b <img src=x onerror=alert(1)> &amp; \"q\" 'é' \udcfe\u202e"
# Identifiers students rename (whole words), per file.
RENAMABLE = {
    "Tutorial10.cpp": ["g_uiPostProcInitProgram", "g_uiGaussProgram", "g_uiFBOPostProc", "g_uiLuminanceKey", "g_uiBloom",
                       "g_uiFBOBlur", "g_uiFBOBloom", "g_uiBlur", "iLevels", "v2InverseRes", "uiSubRoutines", "iBlurPasses",
                       "uiDrawBuffers", "g_uiInverseResUBO", "g_uiPostProcProgram"],
    "Gauss.frag": ["fGaussSigma", "v2Du1", "v2Du2", "v3Filtered", "v2UV", "SampleOffsetUniform"],
    "PostProcess.frag": ["fYa", "fDg", "fYr", "fYNew", "v3Bloom", "fVal", "v2UV", "v3RetColour"],
    "PostProcessInit.frag": ["v3AccumColour", "fYoutTemp", "v2UV", "fY"],
}
WORDS = ["now", "then", "compute", "the", "value", "pass", "texture", "bind", "here", "result", "my", "blur", "step",
         "draw", "setup", "todo", "check", "ok", "fix", "later"]

HOST_SOLUTION = """    // Blur: five rounds, each a horizontal then a vertical pass
    int iRound = 0;
    float fHalfW = (float)(g_iWindowWidth / 2);
    float fHalfH = (float)(g_iWindowHeight / 2);
    glViewport(0, 0, (int)fHalfW, (int)fHalfH);
    vec2 v2InverseRes = 1.0f / vec2(fHalfW, fHalfH);
    glBindBuffer(GL_UNIFORM_BUFFER, g_uiInverseResUBO);
    glBufferData(GL_UNIFORM_BUFFER, sizeof(vec2), &v2InverseRes, GL_STATIC_DRAW);
    glUseProgram(g_uiGaussProgram);
    GLuint uiSubRoutines[2] = {0, 1};
    while (iRound < 5) {
        for (int iDir = 0; iDir < 2; ++iDir) {
            const bool bHoriz = (iDir == 0);
            GLuint uiTarget = bHoriz ? g_uiFBOBlur : g_uiFBOBloom;
            glBindFramebuffer(GL_DRAW_FRAMEBUFFER, uiTarget);
            glUniformSubroutinesuiv(GL_FRAGMENT_SHADER, 1, &uiSubRoutines[iDir]);
            if (!bHoriz) {
                glBindTexture(GL_TEXTURE_2D, g_uiBlur);
            } else {
                int iUnused = 0;
            }
            glClear(GL_COLOR_BUFFER_BIT);
            glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, 0);
        }
        glBindTexture(GL_TEXTURE_2D, g_uiBloom);
        if (iRound == 0) {
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 1);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 1);
        }
        iRound = iRound + 1;
    }
"""
# Markup, a NUL, an escape sequence, bytes that are not UTF-8 (written through surrogateescape) and a
# right-to-left override.
HOSTILE_COMMENT = "// </pre></span><script>alert('x')</script> \x00 \x1b[31m \udcff\udcfe \u202e"

SHADER_SOLUTION = """#version 430 core
layout(binding = 7) uniform InvResolution {
    vec2 v2InvResolution;
};
layout(binding = 17) uniform sampler2D s2InputTexture;

out vec3 v3ColourOut;

const float fGaussSigma = 2.5f;
const float fTapOffsets[5] = float[5](-1.282f, -0.524f, 0.0f, 0.524f, 1.282f);

subroutine vec2 SampleOffset(out vec2);
layout(location = 0) subroutine uniform SampleOffset SampleOffsetUniform;

layout(index = 0) subroutine(SampleOffset) vec2 horizSampleOffset(out vec2 v2Du1)
{
    v2Du1 = vec2(v2InvResolution.x * fGaussSigma, 0.0f);
    return v2Du1;
}

layout(index = 1) subroutine(SampleOffset) vec2 vertSampleOffset(out vec2 v2Du1)
{
    v2Du1 = vec2(0.0f, v2InvResolution.y * fGaussSigma);
    return v2Du1;
}

void main() {
    vec2 v2UV = gl_FragCoord.xy * v2InvResolution;
    vec2 v2Axis;
    vec2 v2Unused = SampleOffsetUniform(v2Axis);
    vec3 v3Sum = vec3(0.0f);
    float fCount = 0.0f;
    for (int i = 0; i < 5; i++) {
        float fWeight = 1.0f;
        if (fTapOffsets[i] == 0.0f) {
            fWeight = 1.0f;
        } else {
            fWeight = 1.0f;
        }
        vec3 v3Tap = texture(s2InputTexture, v2UV + v2Axis * fTapOffsets[i]).rgb;
        v3Sum = v3Sum + v3Tap * fWeight;
        fCount = fCount + fWeight;
    }
    float fInv = 1.0f / fCount;
    int iCheck = 0;
    while (iCheck < 1) {
        iCheck = iCheck + 1;
    }
    v3ColourOut = v3Sum * fInv;
}
"""


def read_reference(root):
    return {name: open(os.path.join(root, PART3, name), encoding="utf-8").read() for name in FILES}


def as_typist(files):
    """The tutorial's defects, as a student who typed the snippets exactly has them."""
    host = files["Tutorial10.cpp"]
    host = re.sub(r"int iLevels = \(int\)floorf\(log2f\(\(float\)max\(g_iWindowWidth, g_iWindowHeight\)\)\) \+ 1;",
                  "int iLevels = (int)ceilf(log2f((float)max(g_iWindowWidth, g_iWindowHeight)));", host)
    host = host.replace("    glActiveTexture(GL_TEXTURE16);\n    glBindTexture(GL_TEXTURE_2D, g_uiLuminanceKey);\n    glGenerateMipmap",
                        "    glBindTexture(GL_TEXTURE_2D, g_uiLuminanceKey);\n    glGenerateMipmap")
    shader = files["PostProcess.frag"]
    shader = shader.replace("    const float fYwhite = 0.22f;\n\n    // Perform range", "    // Perform range")
    shader = shader.replace("    // Calculate new luminance\n", "    // Calculate new luminance\n    const float fYwhite = 0.22f;\n")
    shader = re.sub(r"return \(fY > 0\.0f\) \? v3RetColour \* \(fYNew / fY\) : vec3\(0\.0f\);",
                    "return v3RetColour * (fYNew / fY);", shader)
    typed = dict(files, **{"Tutorial10.cpp": host, "PostProcess.frag": shader})
    changed = [name for name in ("Tutorial10.cpp", "PostProcess.frag") if typed[name] != files[name]]
    if len(changed) != 2 or "ceilf" not in host or "(fY > 0.0f)" in shader:
        sys.exit("make_class: the reference no longer has the lines the tutorial's defects replace")
    return typed


def rename(text, names, rng, style):
    for name in names:
        if rng.random() < 0.6:
            new = {0: name + "_" + rng.choice(WORDS), 1: "m" + name[0].upper() + name[1:], 2: name.replace("g_ui", "gl_")}[style]
            if new == name:
                new = name + "X"
            text = re.sub(r"\b" + re.escape(name) + r"\b", new, text)
    return text


def comments(text, rng):
    mode = rng.randrange(3)
    if mode == 0:  # removed
        return re.sub(r"[ \t]*//[^\n]*", "", text)
    if mode == 1:  # reworded
        return re.sub(r"//[^\n]*", lambda m: "// " + " ".join(rng.choice(WORDS) for _ in range(rng.randint(2, 6))), text)
    return text


def blocks(text):
    """Top-level chunks: split at blank lines outside braces."""
    chunks, current, depth = [], [], 0
    for line in text.split("\n"):
        if not line.strip() and depth == 0 and current:
            chunks.append("\n".join(current))
            current = []
            continue
        current.append(line)
        code = line.split("//")[0]
        depth += code.count("{") - code.count("}")
    if current:
        chunks.append("\n".join(current))
    return chunks


def reorder(text, rng):
    chunks = blocks(text)
    if len(chunks) < 4:
        return text
    head, body = chunks[:2], chunks[2:]
    rng.shuffle(body)
    return "\n\n".join(head + body) + "\n"


def reformat(text, rng):
    indent = rng.choice(["  ", "\t", "    ", "   "])
    text = re.sub(r"^((?:    )+)", lambda m: indent * (len(m.group(1)) // 4), text, flags=re.M)
    if rng.random() < 0.5:  # K&R braces for functions
        text = re.sub(r"\)\n\{", ") {", text)
    if rng.random() < 0.5:
        text = re.sub(r"\n\s*\n", "\n", text)
    if rng.random() < 0.5:
        text = text.replace(", ", ",").replace(" = ", "=")
    return text


def statement(rng, depth):
    """One random statement of a student's own code: a declaration, an assignment or a control structure
    (nested up to depth), in the scanner's varied tokens (types, keywords, ?:, blocks)."""
    var = rng.choice("bcdefgh") + str(rng.randrange(99))
    kind = rng.randrange(12 if depth else 8)
    simple = [f"int {var} = a;", f"float {var} = 1.0f;", f"double {var} = 2.0;", f"unsigned {var} = 3u;",
              f"const long {var} = a * 2;", "r = (a > 2) ? r : a;", "r = r + (int)sizeof(float);", f"char {var} = 'x';"]
    if kind < 8:
        return "    " + simple[kind]
    body = " ".join(statement(rng, depth - 1).strip() for _ in range(rng.randint(1, 3)))
    return "    " + [f"if (a > {rng.randrange(9)}) {{ {body} }}", f"if (r < a) {{ {body} }} else {{ r = 0; }}",
                     f"for (int i = 0; i < a; ++i) {{ {body} }}", f"while (r > {rng.randrange(90) + 9}) {{ {body} break; }}"][kind - 8]


def helper(rng, index):
    """A small function of the student's own: random statements."""
    lines = [f"int helper{index}(int a)", "{", "    int r = 0;"]
    lines += [statement(rng, 2) for _ in range(rng.randint(5, 10))]
    lines += ["    return r;", "}", ""]
    return "\n".join(lines)


def disguise(files, rng, own_helper=None):
    style = rng.randrange(3)
    out = {}
    for name, text in files.items():
        text = rename(text, RENAMABLE[name], rng, style)
        text = comments(text, rng)
        if rng.random() < 0.7:
            text = reorder(text, rng)
        text = reformat(text, rng)
        out[name] = text
    if own_helper:
        out["Tutorial10.cpp"] += "\n" + own_helper + "\n"
    return out


def with_host_solution(files):
    host = files["Tutorial10.cpp"]
    start = host.index("    // [step 32]")
    end = host.index("    // [/step 34]\n") + len("    // [/step 34]\n")
    return dict(files, **{"Tutorial10.cpp": host[:start] + HOST_SOLUTION + host[end:]})


def write(out, name, files, extra=None):
    folder = os.path.join(out, name)
    os.makedirs(folder, exist_ok=True)
    for file, text in list(files.items()) + list((extra or {}).items()):
        with open(os.path.join(folder, file), "wb") as f:
            f.write(text.encode("utf-8", "surrogateescape") if isinstance(text, str) else text)


def main(argv):
    if len(argv) < 2:
        print(__doc__)
        return 2
    root, out = argv[0], argv[1]
    honest = int(argv[argv.index("--honest") + 1]) if "--honest" in argv else 31
    seed = int(argv[argv.index("--seed") + 1]) if "--seed" in argv else 51
    prefix = argv[argv.index("--names") + 1] if "--names" in argv else ""
    rng = random.Random(seed)
    reference = read_reference(root)
    students = {}
    for i in (1, 2):
        students[f"ref_copy_{i}"] = (dict(reference), None)
    for i in range(1, 4):
        students[f"typist_{i}"] = (disguise(as_typist(reference), rng), None)
    for i in range(1, honest + 1):
        own = helper(rng, i) if i % 3 == 0 else None
        students[f"{prefix}honest_{i:03d}"] = (disguise(reference, rng, own), None)
    host = with_host_solution(reference)
    students["host_a"] = (disguise(host, rng), None)
    hostile = disguise(host, rng)
    # Inside the shared code, after the disguise (which may drop or reword comments and spaces).
    marked = re.sub(r"(int iUnused\s*=\s*0;)", lambda m: m.group(1) + " " + HOSTILE_COMMENT, hostile["Tutorial10.cpp"])
    if marked == hostile["Tutorial10.cpp"]:
        sys.exit("make_class: the planted host code lost its iUnused line")
    hostile["Tutorial10.cpp"] = marked
    students[HOSTILE_NAME] = (hostile, {"<b>x<i>&\"'\udcff.h": b"// a header \xff\xfe <script>\n"})
    shader = dict(reference, **{"Gauss.frag": SHADER_SOLUTION})
    students["shader_a"] = (disguise(shader, rng), None)
    students["shader_b"] = (disguise(shader, rng), None)
    for name, (files, extra) in students.items():
        write(out, name, files, extra)
    expected = {"planted": [sorted(["host_a", HOSTILE_NAME]), ["shader_a", "shader_b"]],
                "reference_copies": ["ref_copy_1", "ref_copy_2"], "typists": ["typist_1", "typist_2", "typist_3"],
                "hostile": HOSTILE_NAME, "students": sorted(students)}
    with open(os.path.join(out, "expected.json"), "w", encoding="utf-8") as f:
        json.dump(expected, f, indent=1)  # ASCII: the hostile name holds a byte that is not UTF-8
    print(f"make_class: {len(students)} students in {out}/")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
