#!/usr/bin/env python3
"""Checks the reports t10-grade wrote for the test submissions (make_submissions.py).

  check_reports.py reports REPORT_DIR NAME...    each named submission's report.json is as expected
  check_reports.py same BATCH_CSV SINGLE_CSV...   the rows of the single gradebooks equal the batch's
  check_reports.py docs INSTRUCTORS_MD            the page's table of known mistakes lists mistakes.tsv's ids
  check_reports.py utf8 DIR...                    every file t10-grade wrote under the folders is valid UTF-8

For a known mistake the check that guards its step must fail, name the mistake's catalogue id in
its diagnosis and cover the step; the score must drop. For the fitted batch (make_submissions.FITTED)
the mistake must be named with its value measured within 10 % and nothing else named; mistakes
outside the catalogue (OUTSIDE) and the unnamed constants (UNNAMED_ONLY) must fail with nothing
named; Part 1 with steps 6-10 missing must score lower than Part 1 with one wrong constant, and the
comparisons of make_submissions.FAIR must hold (one wrong constant, named or not, above whole steps
missing; one change never below the same change with steps missing). Every id named must be in mistakes.tsv, every
finding of a parameter must carry its estimate. Exit 0 when all hold, 1 otherwise."""
import csv
import json
import re
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_submissions import FAIR, FITTED, OUTSIDE, OUTSIDE2, UNNAMED, UNNAMED_ONLY  # noqa: E402  (one table of the values set)

CATALOGUE_PATH = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "diagnosis", "mistakes.tsv")


def load_catalogue():
    table = {}
    with open(CATALOGUE_PATH, encoding="utf-8") as f:
        for line in f:
            if not line.strip() or line.startswith("#"):
                continue
            mistake_id, parameter, tutorial, steps, _ = line.rstrip("\n").split("\t")
            table[mistake_id] = {"parameter": None if parameter == "-" else parameter,
                                 "steps": [int(s) for s in steps.split()]}
    return table


CATALOGUE = load_catalogue()

# name: (status, [(check id, catalogue id, step)]); an empty list means a score of 100.
EXPECTED = {
    "reference1": ("graded", []), "shaders1": ("graded", []), "equivalent1": ("graded", []),
    "reference2": ("graded", []), "shaders2": ("graded", []), "equivalent2": ("graded", []),
    "reference3": ("graded", []), "shaders3": ("graded", []), "equivalent": ("graded", []),
    "rec601": ("graded", [("pot.log-luminance", "luminance-weights", 3)]),
    "white_point": ("graded", [("pot.frame", "white-point", 9)]),
    "threshold": ("graded", [("pot.bloom-threshold", "bloom-threshold", 18)]),
    "weight": ("graded", [("pot.frame", "bloom-weight", 20)]),
    "tap": ("graded", [("pot.blur", "blur-tap-inner", 27), ("pot.blur-passes", "blur-tap-inner", 27)]),
    "sigma": ("graded", [("pot.blur", "blur-sigma", 27), ("pot.blur-passes", "blur-sigma", 27)]),
    "no_unmapping": ("graded", [("pot.frame", "missing-unmapping", 9)]),
    "log2_exp": ("graded", [("pot.frame", "log2-exp-mismatch", 9)]),
    "black_nan": ("graded", [("extremes.frame", "black-0-over-0", 9)]),
    "bloom_after": ("graded", [("pot.frame", "bloom-after-tonemap", 20)]),
    # Offsets in full-resolution texels are exactly a sigma of half the tutorial's.
    "full_res_offsets": ("graded", [("pot.blur", "blur-sigma", 27), ("pot.blur-passes", "blur-sigma", 27)]),
    "ceil_levels": ("graded", [("pot.luminance-levels", "ceil-log2-levels", 13)]),
    "swapped_subroutines": ("graded", [("pot.blur-passes", "swapped-subroutines", 33)]),
    "viewport_reset": ("graded", [("pot.frame", "viewport-reset", 35)]),
    "pass_count": ("graded", [("pot.blur", "blur-passes", 34), ("pot.blur-pass-count", "blur-passes", 34)]),
    "p1_steps_missing": ("graded", [("pot.frame", "tone-map-missing", 6), ("pot.frame", "tone-map-missing", 10)]),
    "p1_one_constant": ("graded", [("pot.frame", "white-point", 9)]),
    "p1_middle_grey_1_0": ("graded", [("pot.frame", "middle-grey", 9), ("extremes.frame", "middle-grey", 9)]),
    "p2_one_change": ("graded", [("pot.frame", "white-point", 9)]),
    # Two mistakes at once: no one model explains it, so only its score is checked (compare_scores).
    "p2_change_and_step_missing": ("graded", None),
    "no_compile": ("build-failed", []),
    "shader_error": ("shader-error", []),
    "shader_bytes": ("shader-error", []),
    "crash": ("crashed", []),
    "loop": ("timeout", []),
    "crash_npot": ("crashed", []),
    "loop_npot": ("timeout", []),
}
# The fitted batch: the id named, with the value set (make_submissions.FITTED).
for _name, (_id, _parameter, _value, _file, _changes) in FITTED.items():
    EXPECTED[_name] = ("graded", [])
for _name in list(OUTSIDE) + list(OUTSIDE2):
    EXPECTED[_name] = ("graded", [])
# Fairness named or not: only their scores are compared (FAIR); the unnamed constants must name nothing.
for _table in UNNAMED.values():
    for _name in _table:
        EXPECTED[_name] = ("graded", None)
EXPECTED["p2_bloom_missing"] = ("graded", [("pot.frame", "bloom-missing", 19), ("pot.frame", "bloom-missing", 20)])
# Values the older fixtures set, checked as the fitted batch is.
FIXTURE_VALUES = {"white_point": ("white-point", 0.25), "threshold": ("bloom-threshold", 2.5),
                  "weight": ("bloom-weight", 0.5), "tap": ("blur-tap-inner", 0.424), "sigma": ("blur-sigma", 2.0),
                  "full_res_offsets": ("blur-sigma", 1.25), "pass_count": ("blur-passes", 3),
                  "rec601": ("luminance-weights", [0.299, 0.587, 0.114]), "p1_one_constant": ("white-point", 0.3),
                  "p1_middle_grey_1_0": ("middle-grey", 1.0), "p2_one_change": ("white-point", 0.25)}
# What the message of a submission that was not graded must say (the tool's own words).
MESSAGES = {"no_compile": ["no_compile/Tutorial10.cpp:", "error: expected"],
            "shader_error": ["shader_error/PostProcess.frag", "shader compilation failed"],
            "shader_bytes": ["shader_bytes/PostProcess.frag", "shader compilation failed", "caf\ufffd"],
            "crash": ["signal 11", "caf\ufffd \ufffd\ufffd \x01\x07\x1b[0m <i>&lt;</i>"], "loop": [f"timed out after {os.environ.get('T10_GRADE_LOOP_TIMEOUT', '3')} s"],
            # Their second case fails: reported as that case's own process failed (make_submissions.LATER).
            "crash_npot": ["case npot", "signal 11"],
            "loop_npot": ["case npot", f"timed out after {os.environ.get('T10_GRADE_LOOP_TIMEOUT', '3')} s"]}
# What fix_first must say for a submission that was not graded: the first compiler or shader error
# with its file (relative to the submission) and line, else the first line of what happened.
FIX_FIRST = {"no_compile": r"^fix first: Tutorial10\.cpp:\d+: error: expected",
             "shader_error": r"^fix first: PostProcess\.frag:\d+: error: syntax error",
             "shader_bytes": r"^fix first: PostProcess\.frag:\d+: (preprocessor )?error: .*caf\ufffd",
             "crash": r"^fix first: case \w+ .*signal 11", "loop": r"^fix first: \S",
             "crash_npot": r"^fix first: case npot .*signal 11", "loop_npot": r"^fix first: case npot .*timed out"}
# In a sanitized build (make test-asan) UBSan stops the crash submission's null store before the signal:
# its report, then exit 1, is what the student reads (tests.cmake sets T10_GRADE_SANITIZED there).
if os.environ.get("T10_GRADE_SANITIZED") == "1":
    MESSAGES["crash"] = ["runtime error: store to null pointer", "caf\ufffd"]
    FIX_FIRST["crash"] = r"^fix first: case \w+ .*exit code 1"
    MESSAGES["crash_npot"] = ["case npot", "runtime error: store to null pointer"]
    FIX_FIRST["crash_npot"] = r"^fix first: case npot .*exit code 1"
# Host folders a student-facing report must not name: the source tree and the tests' output tree.
SOURCE_ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
# Per-pass checks (the capture of each blur pass): what their measurement or diagnosis must say.
PASS_WORDS = {"swapped_subroutines": [("pot.blur-passes", "first failing pass: pass 1 vertical")],
              "tap": [("pot.blur-passes", "first failing pass: pass 1 horizontal")],
              "pass_count": [("pot.blur-pass-count", "6 blur passes"), ("pot.blur-pass-count", "your blur passes measure 3")],
              "full_res_offsets": [("pot.blur-passes", "first failing pass: pass 1 horizontal"), ("pot.blur", "exactly half")],
              **{name: [(f"{case}.blur-passes", "10 passes within tolerance") for case in ("pot", "npot", "extremes", "hot")]
                 + [("pot.blur-pass-count", "10 blur passes")] for name in ("reference3", "shaders3", "equivalent")}}
KEYS = {"id", "steps", "passed", "measured", "tolerance", "diagnosis", "blames", "mistakes"}


def within(measured, expected, fraction=0.10):
    """Each component of the measured value within `fraction` of the value set."""
    if isinstance(expected, list):
        return isinstance(measured, list) and len(measured) == len(expected) and all(
            abs(m - e) <= fraction * abs(e) for m, e in zip(measured, expected))
    if isinstance(measured, list):
        return False
    return abs(measured - expected) <= fraction * abs(expected) if expected != 0 else measured == 0


def check_findings(name, report, fail):
    """Every id named is in the catalogue, every parameter carries its estimate, and what the fitted
    and outside batches expect holds. Returns the named (id, value) pairs for the summary."""
    named = []
    for c in report["checks"]:
        for m in c["mistakes"]:
            entry = CATALOGUE.get(m["id"])
            if entry is None:
                fail(f"{c['id']} names [{m['id']}], which mistakes.tsv lacks")
                continue
            if entry["parameter"] and "estimate" not in m:
                fail(f"{c['id']} names [{m['id']}] without its estimate")
            if "estimate" in m and m["estimate"]["parameter"] != entry["parameter"]:
                fail(f"{c['id']} estimate names {m['estimate']['parameter']}, not {entry['parameter']}")
            named.append((c["id"], m["id"], m.get("estimate", {}).get("value")))
    expected = None
    if name in FITTED:
        expected = FITTED[name][0], FITTED[name][2]
    elif name in FIXTURE_VALUES:
        expected = FIXTURE_VALUES[name]
    if expected is not None:
        mistake_id, value = expected
        mine = [(check, v) for check, i, v in named if i == mistake_id]
        others = sorted({i for _, i, _ in named if i != mistake_id})
        if not mine:
            fail(f"[{mistake_id}] is not named; named: {others}")
        for check, v in mine:
            if not within(v, value):
                fail(f"{check}: [{mistake_id}] measures {v}, set {value} (more than 10 % off)")
        if others:
            fail(f"wrong names beside [{mistake_id}]: {others}")
        # One wrong constant costs its own steps only: a case where the mistake's model does not hold
        # would charge another (step 5 for step 4's epsilon at 1e-3, before issue 38's log-luminance
        # tolerance).
        own = {step for c in report["checks"] for m in c["mistakes"] if m["id"] == mistake_id for step in m["steps"]}
        extra = sorted(set(report["failed_steps"]) - own) if mine else []
        if extra:
            fail(f"[{mistake_id}] costs steps {sorted(own)}, but steps {extra} are lost too")
        if mine and not others and not extra and all(within(v, value) for _, v in mine):
            values = sorted({json.dumps(v) for _, v in mine})
            print(f"{name}: [{mistake_id}] set {value}, measured {', '.join(values)} in {len(mine)} checks; "
                  f"score {report['score']}, failed steps {report['failed_steps']}")
    if name in OUTSIDE or name in OUTSIDE2 or name in UNNAMED_ONLY:
        if named:
            fail(f"a mistake outside the catalogue got names: {named}")
        elif report["score"] >= 100:
            fail("score 100 for a mistake outside the catalogue")
        else:
            first = next(c for c in report["checks"] if not c["passed"])
            print(f"{name}: no name, score {report['score']}; {first['id']}: {first['diagnosis'][:160]}")
    return named


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
    for output in ("report.json", "report.html"):
        if not os.path.exists(os.path.join(report_dir, name, output)):
            continue
        with open(os.path.join(report_dir, name, output), encoding="utf-8", errors="replace") as f:
            text = f.read()
        for host in (SOURCE_ROOT + "/", os.path.dirname(os.path.dirname(os.path.abspath(report_dir))) + "/"):
            if host in text:
                fail(f"{output} shows the host folder {host}")
    if report["status"] != status:
        fail(f"status {report['status']}, expected {status} ({report['message'][:300]})")
        return
    if not os.path.exists(os.path.join(report_dir, name, "report.html")):
        fail("no report.html")
    if status != "graded":
        if report["score"] != 0:
            fail(f"score {report['score']} for status {status}")
        if not re.search(FIX_FIRST[name], report.get("fix_first", "")):
            fail(f"fix_first {report.get('fix_first')!r} does not match {FIX_FIRST[name]!r}")
        for words in MESSAGES[name]:
            if words not in report["message"]:
                fail(f"message does not say '{words}': {report['message'][:400]}")
        print(f"{name}: {status} as expected ({report['message'].splitlines()[0][:120]})")
        return
    checks = {c["id"]: c for c in report["checks"]}
    check_findings(name, report, fail)
    failed_ids = [c["id"] for c in report["checks"] if not c["passed"]]
    if (report["score"] == 100) != (not failed_ids):
        fail(f"score {report['score']} with failed checks {failed_ids}")
    if not report.get("fix_first", "") and failed_ids:
        fail("failed checks but no fix_first line")
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
    if name in FITTED or name in OUTSIDE or name in OUTSIDE2:
        return
    if failures is None:
        if report["score"] >= 100:
            fail("score 100 for a submission with a mistake")
        else:
            print(f"{name}: score {report['score']}")
        return
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

def compare_part1(report_dir, names, errors):
    """Five missing steps cost more than one wrong constant (each of Part 1's one-constant submissions)."""
    scores = {}
    for name in ["p1_steps_missing"] + names:
        with open(os.path.join(report_dir, name, "report.json"), encoding="utf-8") as f:
            scores[name] = json.load(f)["score"]
    for name in names:
        if scores["p1_steps_missing"] >= scores[name]:
            errors.append(f"Part 1 with steps 6-10 missing scores {scores['p1_steps_missing']}, not below one wrong "
                          f"constant's {scores[name]} ({name})")
        else:
            print(f"Part 1: steps 6-10 missing scores {scores['p1_steps_missing']}, one wrong constant ({name}) {scores[name]}")


def compare_fair(report_dir, names, errors):
    """make_submissions.FAIR's comparisons whose two submissions are both in this batch: the higher
    scores above the lower (strict) or never below it."""
    for part, higher, lower, strict in FAIR:
        if higher not in names or lower not in names:
            continue
        scores = {}
        for name in (higher, lower):
            with open(os.path.join(report_dir, name, "report.json"), encoding="utf-8") as f:
                scores[name] = json.load(f)["score"]
        holds = scores[higher] > scores[lower] if strict else scores[higher] >= scores[lower]
        relation = "above" if strict else "at least"
        line = f"Part {part}: {higher} scores {scores[higher]}, {lower} {scores[lower]} (must be {relation})"
        if holds:
            print(line)
        else:
            errors.append(line)


def compare_scores(report_dir, one_change, with_step_missing, errors):
    """The reference with one change never scores below the same change with a step missing."""
    scores = {}
    for name in (one_change, with_step_missing):
        with open(os.path.join(report_dir, name, "report.json"), encoding="utf-8") as f:
            scores[name] = json.load(f)["score"]
    if scores[one_change] < scores[with_step_missing]:
        errors.append(f"{one_change} scores {scores[one_change]}, below {with_step_missing}'s {scores[with_step_missing]}")
    else:
        print(f"one change ({one_change}) scores {scores[one_change]}, the change and a step missing "
              f"({with_step_missing}) {scores[with_step_missing]}")


def docs_ids(path):
    """The ids in the first column of the table under "## Known mistakes"."""
    ids, inside = [], False
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("## "):
                inside = line.startswith("## Known mistakes")
            elif inside and line.startswith("| `"):
                ids.append(line.split("`")[1])
    return ids


# Control characters HTML calls parse errors: C0 but tab, line feed, form feed and carriage return; DEL; C1.
HTML_CONTROLS = re.compile("[\x00-\x08\x0b\x0e-\x1f\x7f-\x9f]")


def check_text_files(folders, errors):
    """Every JSON, HTML and CSV file under FOLDERS decodes as strict UTF-8; JSON parses, HTML holds no
    control character and no tag the grader did not write (a student's </pre> or <script> escaped),
    CSV parses. Returns how many files were read."""
    count = 0
    for folder in folders:
        for root, _, files in os.walk(folder):
            for name in files:
                path = os.path.join(root, name)
                if not name.endswith((".json", ".html", ".csv")):
                    continue
                count += 1
                with open(path, "rb") as f:
                    data = f.read()
                try:
                    text = data.decode("utf-8")
                except UnicodeDecodeError as error:
                    errors.append(f"{path}: not valid UTF-8: {error} (bytes {data[max(0, error.start - 20):error.end + 20]!r})")
                    continue
                try:
                    if name.endswith(".json"):
                        json.loads(text)
                    elif name.endswith(".csv"):
                        list(csv.reader(text.splitlines()))
                except (ValueError, csv.Error) as error:
                    errors.append(f"{path}: does not parse: {error}")
                if name.endswith(".html"):
                    control = HTML_CONTROLS.search(text)
                    if control:
                        errors.append(f"{path}: control character U+{ord(control.group()):04X} at {control.start()}: "
                                      f"{text[max(0, control.start() - 40):control.start() + 20]!r}")
                    if "<script" in text:
                        errors.append(f"{path}: a <script> tag the grader did not write")
    return count


def rows(path):
    with open(path, newline="", encoding="utf-8") as f:
        return {row["submission"]: row for row in csv.DictReader(f)}


def main():
    if len(sys.argv) < 3 or sys.argv[1] not in ("reports", "same", "docs", "utf8"):
        print(__doc__, file=sys.stderr)
        return 2
    errors = []
    if sys.argv[1] == "utf8":
        count = check_text_files(sys.argv[2:], errors)
        if count == 0:
            errors.append(f"no JSON, HTML or CSV file under {sys.argv[2:]}")
        elif not errors:
            print(f"{count} JSON, HTML and CSV files under {len(sys.argv) - 2} folders: valid UTF-8, JSON and CSV parse, "
                  "HTML without control characters or a student's tags")
    elif sys.argv[1] == "docs":
        listed = docs_ids(sys.argv[2])
        if listed != list(CATALOGUE):
            missing = [i for i in CATALOGUE if i not in listed]
            extra = [i for i in listed if i not in CATALOGUE]
            errors.append(f"{sys.argv[2]}: the table of known mistakes differs from mistakes.tsv (order included): "
                          f"missing {missing}, not in the catalogue {extra}")
        else:
            print(f"{sys.argv[2]} lists the {len(listed)} mistakes of mistakes.tsv in its order")
    elif sys.argv[1] == "reports":
        for name in sys.argv[3:]:
            check_report(sys.argv[2], name, errors)
        if "p2_one_change" in sys.argv[3:] and "p2_change_and_step_missing" in sys.argv[3:]:
            compare_scores(sys.argv[2], "p2_one_change", "p2_change_and_step_missing", errors)
        compare_fair(sys.argv[2], sys.argv[3:], errors)
        constants = [n for n in ("p1_one_constant", "p1_middle_grey_1_0") if n in sys.argv[3:]]
        if "p1_steps_missing" in sys.argv[3:] and constants:
            compare_part1(sys.argv[2], constants, errors)
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
