#!/usr/bin/env python3
"""Checks the reports t10-grade wrote for the test submissions (make_submissions.py).

  check_reports.py reports REPORT_DIR NAME...    each named submission's report.json is as expected
  check_reports.py same BATCH_CSV SINGLE_CSV...   the rows of the single gradebooks equal the batch's

For a known mistake the check that guards its step must fail, name the mistake's catalogue id in
its diagnosis and cover the step; the score must drop. Exit 0 when all hold, 1 otherwise."""
import csv
import json
import os
import sys

# name: (status, [(check id, catalogue id, step)]); an empty list means a score of 100.
EXPECTED = {
    "reference1": ("graded", []), "shaders1": ("graded", []),
    "reference2": ("graded", []), "shaders2": ("graded", []),
    "reference3": ("graded", []), "shaders3": ("graded", []), "equivalent": ("graded", []),
    "rec601": ("graded", [("pot.log-luminance", "rec601", 3), ("pot.key", "rec601", 3), ("pot.bloom-threshold", "rec601", 18)]),
    "white_point": ("graded", [("pot.frame", "white-point", 9)]),
    "threshold": ("graded", [("pot.bloom-threshold", "bloom-threshold", 18)]),
    "weight": ("graded", [("pot.frame", "bloom-weight", 20)]),
    "tap": ("graded", [("pot.blur", "blur-tap", 27), ("pot.blur-passes", "blur-tap", 27)]),
    "sigma": ("graded", [("pot.blur", "blur-sigma", 27), ("pot.blur-passes", "blur-sigma", 27)]),
    "no_unmapping": ("graded", [("pot.frame", "missing-unmapping", 9)]),
    "log2_exp": ("graded", [("pot.frame", "log2-exp-mismatch", 9)]),
    "black_nan": ("graded", [("extremes.frame", "black-0-over-0", 9)]),
    "bloom_after": ("graded", [("pot.frame", "bloom-after-tonemap", 20)]),
    "full_res_offsets": ("graded", [("pot.blur", "blur-full-resolution-offsets", 32),
                                    ("pot.blur-passes", "blur-full-resolution-offsets", 32)]),
    "ceil_levels": ("graded", [("pot.luminance-levels", "ceil-log2-levels", 13)]),
    "swapped_subroutines": ("graded", [("pot.blur", "swapped-subroutines", 32),
                                       ("pot.blur-passes", "swapped-subroutines", 33)]),
    "viewport_reset": ("graded", [("pot.frame", "viewport-reset", 35)]),
    "pass_count": ("graded", [("pot.blur", "pass-count", 34), ("pot.blur-pass-count", "pass-count", 34)]),
    "no_compile": ("build-failed", []),
    "shader_error": ("shader-error", []),
    "crash": ("crashed", []),
    "loop": ("timeout", []),
}
# What the message of a submission that was not graded must say (the tool's own words).
MESSAGES = {"no_compile": ["no_compile/Tutorial10.cpp:", "error: expected"],
            "shader_error": ["shader_error/PostProcess.frag", "shader compilation failed"],
            "crash": ["signal 11"], "loop": ["timed out after 20 s"]}
# Per-pass checks (the capture of each blur pass): what their measurement or diagnosis must say.
PASS_WORDS = {"swapped_subroutines": [("pot.blur-passes", "first failing pass: pass 1 vertical")],
              "full_res_offsets": [("pot.blur-passes", "first failing pass: pass 1 horizontal")],
              "tap": [("pot.blur-passes", "first failing pass: pass 1 horizontal")],
              "pass_count": [("pot.blur-pass-count", "6 blur passes"), ("pot.blur-pass-count", "3 pairs instead of 5")],
              **{name: [(f"{case}.blur-passes", "10 passes within tolerance") for case in ("pot", "npot", "extremes", "hot")]
                 + [("pot.blur-pass-count", "10 blur passes")] for name in ("reference3", "shaders3", "equivalent")}}
KEYS = {"id", "steps", "passed", "measured", "tolerance", "diagnosis"}


def check_report(report_dir, name, errors):
    path = os.path.join(report_dir, name, "report.json")
    try:
        with open(path, encoding="utf-8") as f:
            report = json.load(f)
    except (OSError, ValueError) as error:
        errors.append(f"{path}: {error}")
        return
    status, failures = EXPECTED[name]
    def fail(text):
        errors.append(f"{name}: {text}")
    if report["status"] != status:
        fail(f"status {report['status']}, expected {status} ({report['message'][:300]})")
        return
    if not os.path.exists(os.path.join(report_dir, name, "report.html")):
        fail("no report.html")
    if status != "graded":
        if report["score"] != 0:
            fail(f"score {report['score']} for status {status}")
        for words in MESSAGES[name]:
            if words not in report["message"]:
                fail(f"message does not say '{words}': {report['message'][:400]}")
        print(f"{name}: {status} as expected ({report['message'].splitlines()[0][:120]})")
        return
    checks = {c["id"]: c for c in report["checks"]}
    for c in report["checks"]:
        if set(c) - {"images"} != KEYS:
            fail(f"check {c.get('id')} has keys {sorted(c)}")
        if not c["steps"] or not c["tolerance"]:
            fail(f"check {c['id']} has no steps or no tolerance")
        if not c["passed"] and not c["diagnosis"]:
            fail(f"failed check {c['id']} has no diagnosis")
        for image in c.get("images", {}).values():
            if not os.path.exists(os.path.join(report_dir, name, image)):
                fail(f"check {c['id']}: image {image} is missing")
    # The per-pass checks exist, name the first pass that goes wrong, and count the passes drawn.
    for check_id, words in PASS_WORDS.get(name, []):
        if check_id not in checks:
            fail(f"no check {check_id}")
            continue
        text = checks[check_id]["measured"] + " " + checks[check_id]["diagnosis"]
        if words not in text:
            fail(f"{check_id} does not say '{words}': {text[:300]}")
    if not failures:
        failed = [c["id"] for c in report["checks"] if not c["passed"]]
        if report["score"] != 100 or failed:
            fail(f"score {report['score']}, expected 100; failed: {failed}")
        else:
            print(f"{name}: 100, all {len(checks)} checks passed")
        return
    if report["score"] >= 100:
        fail("score 100 for a known mistake")
    for check_id, mistake, step in failures:
        c = checks.get(check_id)
        if c is None:
            fail(f"no check {check_id}")
        elif c["passed"]:
            fail(f"{check_id} passed ({c['measured']})")
        elif f"[{mistake}]" not in c["diagnosis"]:
            fail(f"{check_id} diagnosis does not name [{mistake}]: {c['diagnosis']}")
        elif step not in c["steps"]:
            fail(f"{check_id} covers steps {c['steps']}, not step {step}")
        else:
            print(f"{name}: score {report['score']}, {check_id} failed as [{mistake}] (step {step}): {c['measured']}")
    if name == "pass_count" and "3 pairs" not in checks["pot.blur"]["diagnosis"]:
        fail("the pass count diagnosis does not say 3 pairs")


def rows(path):
    with open(path, newline="", encoding="utf-8") as f:
        return {row["submission"]: row for row in csv.DictReader(f)}


def main():
    if len(sys.argv) < 3 or sys.argv[1] not in ("reports", "same"):
        print(__doc__, file=sys.stderr)
        return 2
    errors = []
    if sys.argv[1] == "reports":
        for name in sys.argv[3:]:
            check_report(sys.argv[2], name, errors)
    else:
        batch = rows(sys.argv[2])
        for single in sys.argv[3:]:
            for name, row in rows(single).items():
                if batch.get(name) != row:
                    errors.append(f"{name}: batch row {batch.get(name)} differs from the single run's {row}")
                else:
                    print(f"{name}: the same row in the batch (--jobs 2) and alone: {','.join(row.values())}")
    for error in errors:
        print("FAIL:", error)
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
