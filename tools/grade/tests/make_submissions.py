#!/usr/bin/env python3
"""Writes the grader's test submissions into OUT_DIR/<part>/<name>/: each reference stage, a
shaders-only copy of each, an equivalent rewrite of Part 3's tone map, every known mistake of the
catalogue applied to a copy of Part 3, and submissions that do not build, whose shader does not
compile, that crash and that loop forever.

Every mistake is one textual change of the current reference file, so it never drifts from it; a
change whose text is no longer found is an error (exit 1), not a silently unchanged copy.
usage: make_submissions.py SOURCE_DIR OUT_DIR"""
import os
import shutil
import sys

STAGES = {1: "tutorial10_part1_tonemap", 2: "tutorial10_part2_bloom", 3: "tutorial10_part3_gaussian"}
HOST = "Tutorial10.cpp"

# name: (file, [(old, new), ...]) applied to Part 3. Shader mistakes are shaders-only submissions (the
# reference host code is used); host mistakes carry only Tutorial10.cpp.
MISTAKES = {
    # Not a mistake: the same operator written differently (log10 through log, the luminance as a sum)
    # must still score 100, so the tolerances leave room for float rounding.
    "equivalent": ("PostProcess.frag", [("return log2(fVal) * 0.30102999566374217366165225171822f;",
                                         "return log(fVal) / log(10.0f);"),
                                        ("float fY = dot(v3RetColour, v3LuminanceConvert);",
                                         "float fY = v3RetColour.r * 0.2126f + v3RetColour.g * 0.7152f + v3RetColour.b * 0.0722f;")]),
    "rec601": ("PostProcessInit.frag", [("vec3(0.2126f, 0.7152f, 0.0722f)", "vec3(0.299f, 0.587f, 0.114f)")]),
    "white_point": ("PostProcess.frag", [("const float fYwhite = 0.22f;", "const float fYwhite = 0.25f;")]),
    "threshold": ("PostProcessInit.frag", [("fYwhite * 2.95f", "fYwhite * 2.5f")]),
    "weight": ("PostProcess.frag", [("(v3Bloom * 0.98f)", "(v3Bloom * 0.5f)")]),
    "tap": ("Gauss.frag", [("0.524f * v2InvResolution", "0.424f * v2InvResolution")]),
    "sigma": ("Gauss.frag", [("const float fGaussSigma = 2.5f;", "const float fGaussSigma = 2.0f;")]),
    "no_unmapping": ("PostProcess.frag", [("fYa = (fYa * (log(fYwhite) - log(fEpsilon))) + log(fEpsilon);", "")]),
    "log2_exp": ("PostProcess.frag", [("fYa = (fYa * (log(fYwhite) - log(fEpsilon))) + log(fEpsilon);",
                                       "fYa = (fYa * (log2(fYwhite) - log2(fEpsilon))) + log2(fEpsilon);")]),
    "black_nan": ("PostProcess.frag", [("return (fY > 0.0f) ? v3RetColour * (fYNew / fY) : vec3(0.0f);",
                                        "return v3RetColour * (fYNew / fY);")]),
    "bloom_after": ("PostProcess.frag", [("v3RetColour = bloom(v3RetColour, v2UV);", ""),
                                         ("v3ColourOut = toneMap(v3RetColour, v2UV);",
                                          "v3ColourOut = bloom(toneMap(v3RetColour, v2UV), v2UV);")]),
    "full_res_offsets": ("Gauss.frag", [("v2InvResolution.x * fGaussSigma", "0.5f * v2InvResolution.x * fGaussSigma"),
                                        ("v2InvResolution.y * fGaussSigma", "0.5f * v2InvResolution.y * fGaussSigma")]),
    "ceil_levels": (HOST, [("int iLevels = (int)floorf(log2f((float)max(g_iWindowWidth, g_iWindowHeight))) + 1;",
                            "int iLevels = (int)ceilf(log2f((float)max(g_iWindowWidth, g_iWindowHeight)));")]),
    "swapped_subroutines": (HOST, [("glUniformSubroutinesuiv(GL_FRAGMENT_SHADER, 1, &uiSubRoutines[1]);",
                                    "glUniformSubroutinesuiv(GL_FRAGMENT_SHADER, 1, &uiSubRoutines[0]);")]),
    "viewport_reset": (HOST, [("// [step 35] Reset viewport\n    glViewport(0, 0, g_iWindowWidth, g_iWindowHeight);",
                               "// [step 35] Reset viewport")]),
    "pass_count": (HOST, [("const int iBlurPasses = 5;", "const int iBlurPasses = 3;")]),
    # Statuses other than graded.
    "no_compile": (HOST, [("bool GL_Init(t10::App& app)\n{", "bool GL_Init(t10::App& app)\n{\n    int iMissingSemicolon = 1\n")]),
    "shader_error": ("PostProcess.frag", [("float fYNew", "flot fYNew")]),
    "crash": (HOST, [("bool GL_Init(t10::App& app)\n{", "bool GL_Init(t10::App& app)\n{\n    volatile int* piNull = nullptr;\n    *piNull = 42;\n")]),
    # A host loop: Mesa's llvmpipe caps shader loops (65535 iterations), so a looping shader ends.
    "loop": (HOST, [("void GL_Render(t10::App& app)\n{", "void GL_Render(t10::App& app)\n{\n    volatile bool bWait = true;\n    while (bWait) {}\n")]),
}


def stage_files(source, stage):
    folder = os.path.join(source, stage)
    return sorted(f for f in os.listdir(folder) if f == HOST or f.endswith((".frag", ".vert")))


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    source, out = sys.argv[1], sys.argv[2]
    shutil.rmtree(out, ignore_errors=True)
    for part, stage in STAGES.items():
        files = stage_files(source, stage)
        reference = os.path.join(out, f"part{part}", f"reference{part}")
        shaders = os.path.join(out, f"part{part}", f"shaders{part}")
        os.makedirs(reference)
        os.makedirs(shaders)
        for f in files:
            shutil.copy(os.path.join(source, stage, f), reference)
            if f != HOST:
                shutil.copy(os.path.join(source, stage, f), shaders)
    stage = os.path.join(source, STAGES[3])
    for name, (file, changes) in MISTAKES.items():
        with open(os.path.join(stage, file), encoding="utf-8") as f:
            text = f.read()
        for old, new in changes:
            if old not in text:
                print(f"make_submissions.py: {name}: '{old}' not found in {STAGES[3]}/{file}", file=sys.stderr)
                return 1
            text = text.replace(old, new)
        folder = os.path.join(out, "part3", name)
        os.makedirs(folder)
        with open(os.path.join(folder, file), "w", encoding="utf-8") as f:
            f.write(text)
    print(f"wrote the test submissions into {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
