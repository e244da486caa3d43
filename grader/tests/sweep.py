#!/usr/bin/env python3
"""make grade-sweep (issue 38): every fitted parameter of the mistake catalogue at values spread
across the range its fit searches, not only the two values of the test batch (make_submissions.FITTED).
Each value is one textual change of the current reference stage (make_submissions.write_mutant),
graded with the lowest part that has the parameter (Part 1: the luminance and tone-map constants; Part
2: the bloom's; Part 3: the blur's). What must hold for every value:
  - a value whose frame the grader finds off the reference (score below 100) is named with its
    catalogue id and its value measured within 10 % (every component, for the luminance weights), and
    nothing else is named;
  - a value within the tolerance scores 100: the NEAR values (the tutorial's value changed in the
    fourth or fifth significant digit) must, and a value of the spread (VALUES) must not, since each
    moves the frame by many 8-bit steps.
Prints one row per submission and the per-parameter table (named / measured within 10 %) as Markdown
(the instructors' page carries it). Exit 0 when every value holds, 1 otherwise.

usage: sweep.py T10_GRADE SOURCE_DIR OUT_DIR [JOBS] [--only PARAMETER,...] [--values N]
  --values N keeps N values of each spread (the ends first, then the middle): make test's subset."""
import argparse
import json
import os
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_submissions import HOST, write_mutant  # noqa: E402  (one way to make a submission)
from check_reports import CATALOGUE, within  # noqa: E402  (one reading of mistakes.tsv and of "within 10 %")


def glsl(value):
    """A GLSL float literal: 1e-18f, 0.25f, 2.0f."""
    text = repr(float(value))
    return text + "f"


# One row per fitted parameter and place: (label, catalogue id, parameter, part, file, old text, new text
# with {v} for the value, the spread, the near values). The spreads cover each fit's search range
# (grader/diagnosis/: kLogLuminanceParameters, kFrameParameters, kBlurParameters; the weights' least squares;
# the threshold's luminance interval; the key level's mip levels; the pass count's capture).
WEIGHTS = "vec3(0.2126f, 0.7152f, 0.0722f)"
EPSILON = "const float fEpsilon = 0.00000001f;"
WHITE = "const float fYwhite = 0.22f;"
SWEEP = [
    ("luminance weights (step 3)", "luminance-weights", "luminance_weights", 1, "PostProcessInit.frag", WEIGHTS,
     "vec3({v})", [[0.1, 0.8, 0.1], [0.15, 0.7, 0.15], [0.3, 0.6, 0.1], [0.33, 0.33, 0.34], [0.4, 0.5, 0.1],
                   [0.5, 0.4, 0.1], [0.6, 0.3, 0.1], [0.25, 0.5, 0.25]],
     [[0.2127, 0.7152, 0.0722]]),
    ("epsilon, log luminance (step 4)", "epsilon", "epsilon", 1, "PostProcessInit.frag", EPSILON,
     "const float fEpsilon = {v};", [1e-18, 1e-15, 1e-12, 1e-10, 1e-6, 1e-4, 1e-3, 1e-2, 5e-2], [1.0001e-8]),
    ("white point, range mapping (step 5)", "white-point", "white_point", 1, "PostProcessInit.frag", WHITE,
     "const float fYwhite = {v};", [0.03, 0.06, 0.1, 0.15, 0.3, 0.6, 1.5, 5.0, 15.0], [0.22001]),
    ("epsilon, range un-mapping (step 9)", "epsilon", "epsilon", 1, "PostProcess.frag", EPSILON,
     "const float fEpsilon = {v};", [1e-18, 1e-15, 1e-12, 1e-10, 1e-6, 1e-4, 1e-3, 1e-2, 5e-2], [1.0001e-8]),
    ("white point, tone map (step 9)", "white-point", "white_point", 1, "PostProcess.frag", WHITE,
     "const float fYwhite = {v};", [0.03, 0.06, 0.1, 0.15, 0.3, 0.6, 1.5, 5.0, 15.0], [0.22001]),
    ("middle grey (step 9)", "middle-grey", "middle_grey", 1, "PostProcess.frag", "1.03f - (2.0f",
     "{v} - (2.0f", [0.4, 0.7, 0.9, 0.97, 1.0, 1.06, 1.2, 1.6, 2.2, 2.9, 1.03001], [1.030001]),
    ("key level (step 8)", "key-level", "key_level", 1, "PostProcess.frag", "texture(s2LuminanceKeyTexture, v2UV, 1024)",
     "texture(s2LuminanceKeyTexture, v2UV, {v})", [0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0], [64.0]),
    ("bloom threshold (step 18)", "bloom-threshold", "bloom_threshold", 2, "PostProcessInit.frag", "fYwhite * 2.95f",
     "fYwhite * {v}", [0.5, 1.0, 1.5, 2.0, 2.5, 3.5, 5.0, 8.0, 12.0], [2.95001]),
    ("bloom weight (step 20)", "bloom-weight", "bloom_weight", 2, "PostProcess.frag", "(v3Bloom * 0.98f)",
     "(v3Bloom * {v})", [0.02, 0.1, 0.3, 0.6, 1.3, 2.5, 5.0, 9.0], [0.98001]),
    ("blur sigma (step 27)", "blur-sigma", "blur_sigma", 3, "Gauss.frag", "const float fGaussSigma = 2.5f;",
     "const float fGaussSigma = {v};", [0.3, 0.6, 1.0, 1.5, 2.0, 3.0, 4.5, 7.0, 10.0], [2.50001]),
    ("inner tap (step 27)", "blur-tap-inner", "blur_tap_inner", 3, "Gauss.frag", "0.524f * v2InvResolution",
     "{v} * v2InvResolution", [0.05, 0.1, 0.2, 0.35, 0.7, 1.0, 1.5, 2.5], [0.52401]),
    ("outer tap (step 27)", "blur-tap-outer", "blur_tap_outer", 3, "Gauss.frag", "1.282f * v2InvResolution",
     "{v} * v2InvResolution", [0.1, 0.3, 0.6, 0.9, 1.6, 2.2, 3.0, 4.5], [1.28201]),
    ("blur passes (step 34)", "blur-passes", "blur_passes", 3, HOST, "const int iBlurPasses = 5;",
     "const int iBlurPasses = {v};", [1, 2, 3, 4, 6, 7, 8, 10], []),
]


# Values the grader does not yet name within 10 %, each with the reason measured (issue 38 lists them as
# not done). They are graded and printed like the others but do not fail the sweep; one that starts to
# hold fails it ("remove it from KNOWN"), so the list cannot go stale.
KNOWN = {
    "sweep05_middle_grey_10": "1.03001 is at the tolerance's edge (mean 0.0104 steps of 0.01): the white point and epsilon "
                              "fits explain it at the tutorial's values, the middle grey's does not reach the tolerance",
    "sweep10_blur_tap_inner_0": "below about 0.2 the inner tap moves a pass by less than the blur's tolerance: the fit "
                                "ends at its range's bound (0.02)",
    "sweep10_blur_tap_inner_1": "below about 0.2 the inner tap moves a pass by less than the blur's tolerance: the fit "
                                "ends at its range's bound (0.02)",
    "sweep11_blur_tap_outer_0": "at 0.1 the outer tap moves a pass by less than the blur's tolerance: the fit ends at its "
                                "range's bound (0.05)",
}


def literal(parameter, value):
    if parameter == "luminance_weights":
        return ", ".join(glsl(v) for v in value)
    if parameter == "blur_passes":
        return str(int(value))
    return glsl(value)


def spread(values, keep):
    """`keep` of the values: both ends first, then from the middle outwards; all when keep is None."""
    if keep is None or keep >= len(values):
        return list(values)
    order = [0, len(values) - 1]
    middle = len(values) // 2
    for k in range(len(values)):
        for i in (middle - k, middle + k):
            if 0 <= i < len(values) and i not in order:
                order.append(i)
    return [values[i] for i in sorted(order[:keep])]


def submissions(only, keep):
    """[(name, label, catalogue id, parameter, part, file, changes, value, near)]."""
    out = []
    for index, (label, mistake, parameter, part, file, old, new, values, near) in enumerate(SWEEP):
        if only and parameter not in only and mistake not in only:
            continue
        chosen = [(v, False) for v in spread(values, keep)] + [(v, True) for v in (near if keep is None else near[:1])]
        for k, (value, is_near) in enumerate(chosen):
            name = f"sweep{index:02d}_{parameter}_{'near' if is_near else k}"
            changes = [(old, new.replace("{v}", literal(parameter, value)))]
            out.append((name, label, mistake, parameter, part, file, changes, value, is_near))
    return out


def judge(report, mistake, value, near):
    """'' when the report is as the sweep requires, else what is wrong; and the value measured."""
    if report.get("status") != "graded":
        return f"status {report.get('status')}: {report.get('message', '')[:200]}", None
    named = [(c["id"], m["id"], m.get("estimate", {}).get("value")) for c in report["checks"] for m in c["mistakes"]]
    if report["score"] == 100:
        return ("" if near else "scores 100: the grader finds no difference"), None
    # A failed check that names nothing may stand only where it costs no step the mistake does not:
    # the score must be what the named mistake alone costs.
    steps = {s for c in report["checks"] for m in c["mistakes"] if m["id"] == mistake for s in m["steps"]}
    unexplained = [c for c in report["checks"] if not c["passed"] and not c["mistakes"]
                   and not c["diagnosis"].startswith("follows from") and not set(c["blames"]) <= steps]
    if unexplained:
        return (f"score {report['score']}, {unexplained[0]['id']} names nothing and costs steps {unexplained[0]['blames']}: "
                f"{unexplained[0]['diagnosis'][:200]}"), None
    mine = [v for _, i, v in named if i == mistake]
    others = sorted({i for _, i, _ in named if i != mistake})
    if not mine:
        first = next((c for c in report["checks"] if not c["passed"]), {"id": "?", "diagnosis": ""})
        return f"score {report['score']}, [{mistake}] not named; {first['id']}: {first['diagnosis'][:220]}", None
    wrong = [v for v in mine if v is None or not within(v, value)]
    if wrong:
        return f"[{mistake}] measures {wrong[0]}, set {value} (more than 10 % off)", wrong[0]
    if others:
        return f"wrong names beside [{mistake}]: {others}", mine[0]
    return "", mine[0]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("grader")
    parser.add_argument("source")
    parser.add_argument("out")
    parser.add_argument("jobs", nargs="?", default="2")
    parser.add_argument("--only", default="")
    parser.add_argument("--values", type=int, default=None)
    parser.add_argument("--timeout", default="20")
    args = parser.parse_args()
    only = {s for s in args.only.split(",") if s}
    for mistake in {row[1] for row in SWEEP}:
        if mistake not in CATALOGUE or CATALOGUE[mistake]["parameter"] is None:
            sys.exit(f"sweep.py: [{mistake}] is not a parameter of mistakes.tsv")
    subs = submissions(only, args.values)
    if not subs:
        sys.exit(f"sweep.py: --only {args.only} selects nothing")
    shutil.rmtree(args.out, ignore_errors=True)
    folder = os.path.join(args.out, "submissions")
    for name, _, _, _, part, file, changes, _, _ in subs:
        if not write_mutant(args.source, folder, part, name, file, changes):
            return 1
    timings = []
    for part in sorted({s[4] for s in subs}):
        names = [s[0] for s in subs if s[4] == part]
        start = time.monotonic()
        run = subprocess.run([args.grader, "--part", str(part), "--jobs", args.jobs, "--timeout", args.timeout,
                              "--fill-from-reference", "all", "--report", os.path.join(args.out, "reports")]
                             + [os.path.join(folder, f"part{part}", n) for n in names],
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        timings.append((part, len(names), time.monotonic() - start))
        if run.returncode != 0:
            print(run.stdout[-3000:])
            print(f"FAIL: t10-grade --part {part} exit {run.returncode}")
            return 1
    failures, table = [], {}
    for name, label, mistake, parameter, part, _, _, value, near in subs:
        with open(os.path.join(args.out, "reports", name, "report.json"), encoding="utf-8") as f:
            report = json.load(f)
        fault, measured = judge(report, mistake, value, near)
        row = table.setdefault(label, {"id": mistake, "part": part, "values": 0, "named": 0, "near": 0, "near100": 0,
                                       "worst": 0.0, "set": []})
        if near:
            row["near"] += 1
            row["near100"] += report.get("score") == 100
        else:
            row["values"] += 1
            row["set"].append(value)
            if not fault:
                row["named"] += 1
                for m, v in zip(measured if isinstance(measured, list) else [measured],
                                value if isinstance(value, list) else [value]):
                    row["worst"] = max(row["worst"], abs(m - v) / abs(v) if v else abs(m))
        shown = json.dumps(measured) if measured is not None else "-"
        known = KNOWN.get(name)
        verdict = ("known" if fault else "HOLDS") if known else ("FAIL" if fault else "ok  ")
        print(f"{verdict} {name}: set {json.dumps(value)}, score {report.get('score')}, measured {shown}"
              + (f": {fault}" if fault else "") + (f" (known: {known})" if known else ""))
        if known:
            row["known"] = row.get("known", 0) + (1 if fault else 0)
            if not fault:
                failures.append(f"{name} (set {json.dumps(value)}) holds now: remove it from KNOWN")
        elif fault:
            failures.append(f"{name} (set {json.dumps(value)}): {fault}")
    print()
    print("| parameter (part) | id | values set | named, within 10 % | largest error | near value scores 100 |")
    print("|---|---|---|---|---|---|")
    for label, row in table.items():
        values = ", ".join(json.dumps(v).replace(" ", "") for v in row["set"])
        known = f" ({row['known']} known, not yet)" if row.get("known") else ""
        print(f"| {label} (Part {row['part']}) | `{row['id']}` | {values} | {row['named']} of {row['values']}{known} | "
              f"{100 * row['worst']:.2f} % | {row['near100']} of {row['near']} |")
    print()
    for part, count, wall in timings:
        print(f"Part {part}: {count} submissions graded in {wall:.0f} s (--jobs {args.jobs})")
    for failure in failures:
        print("FAIL:", failure)
    known = sum(row.get("known", 0) for row in table.values())
    print(f"{len(subs) - len(failures) - known} of {len(subs)} values hold, {known} known not to yet (KNOWN), "
          f"{len(failures)} fail")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
