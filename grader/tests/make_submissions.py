#!/usr/bin/env python3
"""Writes the grader's test submissions into OUT_DIR/<part>/<name>/: each reference stage, a
shaders-only copy of each, an equivalent rewrite of each part's tone map, every known mistake of the
catalogue applied to a copy of Part 3, and submissions that do not build, whose shader does not
compile, that crash and that loop forever. Then the fitted batch (FITTED): every parameter of the
catalogue at two values the grader's own fixtures above do not use, mistakes outside the catalogue
(OUTSIDE), and Part 1 with steps 6-10 missing beside Part 1 with one wrong constant (PART1; the
middle grey 1.0 among them, which issue 38 found unnamed), and per part a constant the catalogue does
not model beside the part with steps missing (UNNAMED, compared as FAIR lists). make grade-sweep (sweep.py) spreads every
fitted parameter across its fit's range.

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
    # An #error line holding bytes that are not UTF-8 (Latin-1 'é', 0xff 0xfe), control characters and
    # markup: every file the grader writes stays valid UTF-8, its HTML free of control characters.
    "shader_bytes": ("PostProcess.frag", [("float fYNew", "#error caf\udce9 \udcff\udcfe \x01\x1b[31m <b>&amp;</b> </pre><script>x</script>\n"
                                                    "    float fYNew")]),
    # Prints the same kind of bytes before it crashes: the program's output reaches the report too.
    "crash": (HOST, [("#include <glm/glm.hpp>", "#include <glm/glm.hpp>\n#include <cstdio>"), ("bool GL_Init(t10::App& app)\n{", "bool GL_Init(t10::App& app)\n{\n"
                      "    std::fputs(\"caf\\xe9 \\xff\\xfe \\x01\\x07\\x1b[0m <i>&lt;</i> </pre><script>x</script>\\n\", stdout);\n"
                      "    std::fflush(stdout);\n    volatile int* piNull = nullptr;\n    *piNull = 42;\n")]),
    # A host loop: Mesa's llvmpipe caps shader loops (65535 iterations), so a looping shader ends.
    "loop": (HOST, [("void GL_Render(t10::App& app)\n{", "void GL_Render(t10::App& app)\n{\n    volatile bool bWait = true;\n    while (bWait) {}\n")]),
}

# Failures of a later case only (part3-later, graded with the loop under its short limit, not in the
# batches): t10-grade renders every case in one process, then a case that process did not finish
# alone, so the report must name the case that failed, with its own process's time limit.
LATER = {
    "crash_npot": (HOST, [("void GL_Render(t10::App& app)\n{", "void GL_Render(t10::App& app)\n{\n"
                          "    if (app.width() != app.height()) {\n        volatile int* piNull = nullptr;\n        *piNull = 42;\n    }\n")]),
    "loop_npot": (HOST, [("void GL_Render(t10::App& app)\n{", "void GL_Render(t10::App& app)\n{\n"
                         "    volatile bool bWait = app.width() != app.height();\n    while (bWait) {}\n")]),
}


# The fitted batch: name -> (catalogue id, parameter, value set, file, [(old, new), ...]) on Part 3.
# check_reports.py reads this table: the id must be named with its value measured within 10 %.
def _value(name, parameter, value, file, changes, mistake_id=None):
    return name, (mistake_id or parameter.replace("_", "-"), parameter, value, file, changes)


WEIGHTS = "vec3(0.2126f, 0.7152f, 0.0722f)"
FITTED = dict([
    _value("fit_weights_a", "luminance_weights", [0.25, 0.65, 0.10], "PostProcessInit.frag",
           [(WEIGHTS, "vec3(0.25f, 0.65f, 0.10f)")]),
    _value("fit_weights_b", "luminance_weights", [0.30, 0.60, 0.10], "PostProcessInit.frag",
           [(WEIGHTS, "vec3(0.30f, 0.60f, 0.10f)")]),
    _value("fit_epsilon_a", "epsilon", 1e-4, "PostProcess.frag",
           [("const float fEpsilon = 0.00000001f;", "const float fEpsilon = 0.0001f;")]),
    # Step 4's epsilon (the log of level 0), where a narrower mapped range spreads the same log error
    # over more R16 steps: at 1e-3 the lamps' texels at 160x90 are 7 steps off the model (issue 38).
    _value("fit_epsilon_b", "epsilon", 1e-3, "PostProcessInit.frag",
           [("const float fEpsilon = 0.00000001f;", "const float fEpsilon = 0.001f;")]),
    # So low a white point takes the extremes case's brightest channels past what llvmpipe's 8-bit store
    # can hold (2^31 / 255: it writes 0), which the frame models must follow (ref::storeUnorm8, issue 38).
    _value("fit_white_a", "white_point", 0.03, "PostProcess.frag",
           [("const float fYwhite = 0.22f;", "const float fYwhite = 0.03f;")]),
    _value("fit_white_b", "white_point", 0.4, "PostProcess.frag",
           [("const float fYwhite = 0.22f;", "const float fYwhite = 0.4f;")]),
    _value("fit_grey_a", "middle_grey", 1.1, "PostProcess.frag", [("1.03f - (2.0f", "1.1f - (2.0f")]),
    _value("fit_grey_b", "middle_grey", 0.95, "PostProcess.frag", [("1.03f - (2.0f", "0.95f - (2.0f")]),
    _value("fit_threshold_a", "bloom_threshold", 2.0, "PostProcessInit.frag", [("fYwhite * 2.95f", "fYwhite * 2.0f")]),
    _value("fit_threshold_b", "bloom_threshold", 4.0, "PostProcessInit.frag", [("fYwhite * 2.95f", "fYwhite * 4.0f")]),
    _value("fit_weight_a", "bloom_weight", 0.75, "PostProcess.frag", [("(v3Bloom * 0.98f)", "(v3Bloom * 0.75f)")]),
    _value("fit_weight_b", "bloom_weight", 1.5, "PostProcess.frag", [("(v3Bloom * 0.98f)", "(v3Bloom * 1.5f)")]),
    _value("fit_sigma_a", "blur_sigma", 1.0, "Gauss.frag",
           [("const float fGaussSigma = 2.5f;", "const float fGaussSigma = 1.0f;")]),
    _value("fit_sigma_b", "blur_sigma", 3.5, "Gauss.frag",
           [("const float fGaussSigma = 2.5f;", "const float fGaussSigma = 3.5f;")]),
    _value("fit_inner_a", "blur_tap_inner", 0.824, "Gauss.frag", [("0.524f * v2InvResolution", "0.824f * v2InvResolution")]),
    _value("fit_inner_b", "blur_tap_inner", 0.3, "Gauss.frag", [("0.524f * v2InvResolution", "0.3f * v2InvResolution")]),
    _value("fit_outer_a", "blur_tap_outer", 1.0, "Gauss.frag", [("1.282f * v2InvResolution", "1.0f * v2InvResolution")]),
    _value("fit_outer_b", "blur_tap_outer", 1.8, "Gauss.frag", [("1.282f * v2InvResolution", "1.8f * v2InvResolution")]),
    _value("fit_passes_a", "blur_passes", 2, HOST, [("const int iBlurPasses = 5;", "const int iBlurPasses = 2;")]),
    _value("fit_passes_b", "blur_passes", 7, HOST, [("const int iBlurPasses = 5;", "const int iBlurPasses = 7;")]),
    _value("fit_key_level_a", "key_level", 0, "PostProcess.frag",
           [("texture(s2LuminanceKeyTexture, v2UV, 1024)", "texture(s2LuminanceKeyTexture, v2UV)")]),
    _value("fit_key_level_b", "key_level", 2, "PostProcess.frag",
           [("texture(s2LuminanceKeyTexture, v2UV, 1024)", "texture(s2LuminanceKeyTexture, v2UV, 2.0f)")]),
])
# Mistakes outside the catalogue: they must fail, and no check may name a catalogue mistake.
OUTSIDE = {
    "out_gamma": ("PostProcess.frag", [("v3ColourOut = toneMap(v3RetColour, v2UV);",
                                        "v3ColourOut = pow(toneMap(v3RetColour, v2UV), vec3(1.0f / 2.2f));")]),
    "out_swizzle": ("PostProcess.frag", [("v3ColourOut = toneMap(v3RetColour, v2UV);",
                                          "v3ColourOut = toneMap(v3RetColour, v2UV).bgr;")]),
    "out_blur_centre": ("Gauss.frag", [("v3ColourOut = v3Filtered / 5.0f;",
                                        "v3ColourOut = (v3Filtered + texture(s2InputTexture, v2UV).rgb) / 6.0f;")]),
    "out_threshold_max": ("PostProcessInit.frag", [("(fY >= fYwhite * 2.95f)",
                                                    "(max(v3AccumColour.r, max(v3AccumColour.g, v3AccumColour.b)) >= fYwhite * 2.95f)")]),
    # The blur's inverse resolution in full-resolution texels, so its UV too: level 1 is black
    # because the passes blur a dark corner, not because nothing was drawn into it (issue 29).
    "out_full_res_uv": (HOST, [("1.0f / vec2((float)(g_iWindowWidth / 2), (float)(g_iWindowHeight / 2))",
                                "1.0f / vec2((float)g_iWindowWidth, (float)g_iWindowHeight)")]),
}
# Part 2's mistakes outside the catalogue (graded in the part 2 batch), as OUTSIDE: the bloom read
# without the mip bias takes level 0; where level 0's pixels are saturated anyway the frame looks as
# if no bloom were added, but not in every case, so "bloom-missing" must not be named (issue 29).
OUTSIDE2 = {"out_p2_no_mip_bias": ("PostProcess.frag", [("texture(s2BloomTexture, v2UV, 1024)", "texture(s2BloomTexture, v2UV)")])}
EQUIVALENT = [("return log2(fVal) * 0.30102999566374217366165225171822f;", "return log(fVal) / log(10.0f);"),
              ("float fY = dot(v3RetColour, v3LuminanceConvert);",
               "float fY = v3RetColour.r * 0.2126f + v3RetColour.g * 0.7152f + v3RetColour.b * 0.0722f;")]
# Part 1: steps 6-10 not done (the frame is the accumulation colour) against one wrong constant.
PART1 = {
    "p1_steps_missing": ("PostProcess.frag", [("v3ColourOut = toneMap(v3RetColour, v2UV);", "v3ColourOut = v3RetColour;")]),
    "p1_one_constant": ("PostProcess.frag", [("const float fYwhite = 0.22f;", "const float fYwhite = 0.3f;")]),
    # Issue 38's regression: middle grey 1.0 read "no constant factor or shift explains it" and lost
    # steps 6-10 (70) after the fits were shortened; the extremes case passes only within 5e-7 of 1.0.
    "p1_middle_grey_1_0": ("PostProcess.frag", [("1.03f - (2.0f", "1.0f - (2.0f")]),
    "equivalent1": ("PostProcess.frag", EQUIVALENT),
}
# Part 2: the reference with one change, and the same change with a step missing (the bloom not added,
# steps 19-20): the first must never score below the second (issue 38).
PART2 = {"equivalent2": ("PostProcess.frag", EQUIVALENT),
         "p2_one_change": ("PostProcess.frag", [("const float fYwhite = 0.22f;", "const float fYwhite = 0.25f;")]),
         "p2_change_and_step_missing": ("PostProcess.frag", [("const float fYwhite = 0.22f;", "const float fYwhite = 0.25f;"),
                                                             ("v3RetColour = bloom(v3RetColour, v2UV);", "")])}

# Fairness, named or not (issue 38): one wrong constant in a place or form the catalogue does not model
# (so nothing is named) against the same part with whole steps missing, and against the same constant
# with steps missing too. FAIR lists the comparisons check_reports.py makes: (part, higher, lower,
# strict): `higher` scores above `lower` (strict) or never below it. The constants sit in the tone
# map, so "tone map not applied" makes them irrelevant: that frame is the steps-missing one exactly.
TONE_MAP_OFF = ("v3ColourOut = toneMap(v3RetColour, v2UV);", "v3ColourOut = v3RetColour;")
BLOOM_OFF = ("v3RetColour = bloom(v3RetColour, v2UV);", "")
# The operator's denominator (1 + Yr): the white point fit changes the numerator only.
DENOMINATOR = ("/ (1.0f + fYr);", "/ (1.5f + fYr);")
# The 2 in the middle grey's 2 / (2 + log10(Ya + 1)): the middle-grey fit changes the 1.03 only.
GREY_TWO = ("(2.0f / (2.0f + log10(fYa + 1.0f)))", "(2.0f / (2.5f + log10(fYa + 1.0f)))")
UNNAMED = {
    1: {"p1_unnamed_constant": [DENOMINATOR], "p1_unnamed_and_steps_missing": [DENOMINATOR, TONE_MAP_OFF]},
    2: {"p2_unnamed_constant": [GREY_TWO], "p2_bloom_missing": [BLOOM_OFF],
        "p2_unnamed_and_tone_map_missing": [GREY_TWO, TONE_MAP_OFF]},
    3: {"p3_unnamed_constant": [DENOMINATOR], "p3_unnamed_and_tone_map_missing": [DENOMINATOR, TONE_MAP_OFF],
        "p3_unnamed_and_bloom_missing": [DENOMINATOR, BLOOM_OFF]},
}
# The submissions of UNNAMED that carry only the unnamed constant: every check must name nothing.
UNNAMED_ONLY = {"p1_unnamed_constant", "p2_unnamed_constant", "p3_unnamed_constant"}
FAIR = [
    (1, "p1_unnamed_constant", "p1_steps_missing", True),
    (1, "p1_one_constant", "p1_steps_missing", True),
    (1, "p1_unnamed_constant", "p1_unnamed_and_steps_missing", False),
    (2, "p2_unnamed_constant", "p2_bloom_missing", True),
    (2, "p2_one_change", "p2_bloom_missing", True),
    (2, "p2_unnamed_constant", "p2_unnamed_and_tone_map_missing", False),
    (2, "p2_one_change", "p2_change_and_step_missing", False),
    (3, "p3_unnamed_constant", "p3_unnamed_and_tone_map_missing", True),
    (3, "p3_unnamed_constant", "p3_unnamed_and_bloom_missing", False),
    (3, "white_point", "p3_unnamed_and_bloom_missing", True),
]


def write_mutant(source, out, part, name, file, changes, folder_name=None):
    with open(os.path.join(source, STAGES[part], file), encoding="utf-8") as f:
        text = f.read()
    for old, new in changes:
        if old not in text:
            print(f"make_submissions.py: {name}: '{old}' not found in {STAGES[part]}/{file}", file=sys.stderr)
            return False
        text = text.replace(old, new)
    folder = os.path.join(out, folder_name or f"part{part}", name)
    os.makedirs(folder)
    with open(os.path.join(folder, file), "w", encoding="utf-8") as f:
        f.write(text)
    return True


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
        with open(os.path.join(folder, file), "w", encoding="utf-8", errors="surrogateescape") as f:
            f.write(text)
    batches = [(3, name, entry[3], entry[4]) for name, entry in FITTED.items()]
    batches += [(3, name, file, changes) for name, (file, changes) in OUTSIDE.items()]
    batches += [(1, name, file, changes) for name, (file, changes) in PART1.items()]
    batches += [(2, name, file, changes) for name, (file, changes) in PART2.items()]
    batches += [(2, name, file, changes) for name, (file, changes) in OUTSIDE2.items()]
    batches += [(part, name, "PostProcess.frag", changes) for part, table in UNNAMED.items() for name, changes in table.items()]
    for part, name, file, changes in batches:
        if not write_mutant(source, out, part, name, file, changes):
            return 1
    for name, (file, changes) in LATER.items():
        if not write_mutant(source, out, 3, name, file, changes, "part3-later"):
            return 1
    print(f"wrote the test submissions into {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
