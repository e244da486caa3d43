#!/usr/bin/env python3
"""Checks the platform results t10-grade --format wrote for the test submissions (make_submissions.py).

  check_platforms.py results FORMAT REPORT_DIR NAME...  each NAME's result is valid (validate_FORMAT.py)
                                                       and says what its report.json says: reference3
                                                       full marks, weight step 20 failed with its score,
                                                       no_compile and crash score 0 with their status;
                                                       one score everywhere: the steps' whole points add
                                                       up to report.json's score, which the platform's
                                                       top score, gradebook.csv, grades-lms.csv and the
                                                       class index (index.html) show too
  check_platforms.py rejects REPORT_DIR/NAME            each validator rejects results broken on purpose
                                                       (a score over its maximum, a missing field, a
                                                       wrong type, a bad enumeration, over the size limit)
  check_platforms.py grader-error REPORT_DIR/NAME       the grader's own failure: PrairieLearn not gradable
                                                       (format_errors says why), Gradescope 0, Classroom error
Exit 0 when all hold, 1 otherwise."""
import copy
import csv
import json
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import validate_classroom  # noqa: E402
import validate_gradescope  # noqa: E402
import validate_prairielearn  # noqa: E402

FILES = {"gradescope": "gradescope-results.json", "prairielearn": "prairielearn-results.json",
         "classroom": "classroom-result.json"}
# name: (status, full marks, [a tutorial step that must fail])
EXPECTED = {"reference3": ("graded", True, []), "weight": ("graded", False, [20]),
            "no_compile": ("build-failed", False, []), "crash": ("crashed", False, [])}
EPSILON = 0.005


def load(path):
    with open(path, "rb") as f:
        raw = f.read()
    return json.loads(raw.decode("utf-8")), raw


def validate(fmt, folder, data, raw):
    if fmt == "gradescope":
        return validate_gradescope.validate(data, raw)
    if fmt == "prairielearn":
        return validate_prairielearn.validate(data, raw)
    with open(os.path.join(folder, "classroom-result.b64"), "rb") as f:
        return validate_classroom.validate(data, raw, f.read())


def tests_of(fmt, data):
    """[(step, points, max points or None, passed)] from a platform's tests."""
    out = []
    for t in data["tests"]:
        step = int(re.search(r"\bstep (\d+)", t["name"]).group(1))
        if fmt == "gradescope":
            out.append((step, t["score"], t["max_score"], t["status"] == "passed"))
        elif fmt == "prairielearn":
            out.append((step, t["points"], t["max_points"], t["points"] >= t["max_points"] - EPSILON))
        else:
            out.append((step, t["score"], None, t["status"] == "pass"))
    return out


def check_results(fmt, report_dir, names):
    errors = []
    for name in names:
        folder = os.path.join(report_dir, name)
        report, _ = load(os.path.join(folder, "report.json"))
        data, raw = load(os.path.join(folder, FILES[fmt]))
        errors += [f"{name}: {e}" for e in validate(fmt, folder, data, raw)]
        status, full, failing = EXPECTED[name]
        if report["status"] != status:
            errors.append(f"{name}: report.json status {report['status']}, expected {status}")
        tests = tests_of(fmt, data)
        part_steps = {"1": 16, "2": 25, "3": 36}[str(report["part"])]
        # A test per step of the part, worth the step's whole points (rubric.hpp's wholePoints); it
        # fails exactly when the step is in report.json's "failed_steps" (or the submission was not
        # graded).
        every = list(range(1, part_steps + 1))
        if sorted(t[0] for t in tests) != every:
            errors.append(f"{name}: the tests are not one per tutorial step: {[t[0] for t in tests]}")
        # One score everywhere: whole points per step (maxima adding up to exactly 100) whose earned
        # part adds up to report.json's score, which every other output shows as it is.
        maxima = [t[2] for t in tests if t[2] is not None]
        if any(not isinstance(p, int) or isinstance(p, bool) for t in tests for p in t[1:3] if p is not None):
            errors.append(f"{name}: step points that are not whole numbers: {[t[1:3] for t in tests][:5]}")
        if maxima and sum(maxima) != 100:
            errors.append(f"{name}: the steps' maxima add up to {sum(maxima)}, not 100")
        earned = sum(t[1] for t in tests)
        if earned != report["score"]:
            errors.append(f"{name}: the {fmt} steps' points add up to {earned}, report.json's score is {report['score']}")
        score = {"gradescope": lambda: data["score"], "prairielearn": lambda: round(data["score"] * 100, 6),
                 "classroom": lambda: earned}[fmt]()
        if score != report["score"]:
            errors.append(f"{name}: {fmt} score {score} but report.json says {report['score']}")
        errors += [f"{name}: {e}" for e in class_outputs(report_dir, name, report["score"])]
        failed = set(report.get("failed_steps", [])) if report["status"] == "graded" else set(every)
        if full and (report["score"] != 100 or not all(t[3] for t in tests)):
            errors.append(f"{name}: expected full marks, got {score} with failed steps {[t[0] for t in tests if not t[3]]}")
        if not full and score >= 100:
            errors.append(f"{name}: full marks for a submission with a mistake")
        for step in failing:
            if any(t[3] for t in tests if t[0] == step):
                errors.append(f"{name}: step {step} passed although its mistake is in it")
        wrong = [t[0] for t in tests if t[3] == (t[0] in failed)]
        if wrong:
            errors.append(f"{name}: the pass/fail of steps {wrong} disagrees with report.json's failed_steps")
        if status != "graded":
            text = {"gradescope": lambda: data["output"], "prairielearn": lambda: data["output"],
                    "classroom": lambda: data["tests"][0]["message"]}[fmt]()
            if status not in text:
                errors.append(f"{name}: the student-facing text does not say '{status}': {text[:200]!r}")
            if fmt == "prairielearn" and data.get("gradable") is not True:
                errors.append(f"{name}: {status} is the student's fault, yet not gradable")
        if fmt == "classroom" and data["status"] != ("pass" if full else "fail"):
            errors.append(f"{name}: classroom status {data['status']}")
        if fmt == "gradescope" and name == "weight":
            # Each failed image check shows the student's frame, the reference and the heat-map inline.
            alts = re.findall(r'<img [^>]*alt="([^"]*)"', data["output"]) if data.get("output_format") == "html" else []
            for what in ("your frame", "the reference", "the difference (heat-map)"):
                if not any(what in alt for alt in alts) and "left out" not in data["output"]:
                    errors.append(f"{name}: a failed image check, but no inline image of {what} and no note that it was left out")
        if fmt == "prairielearn" and name == "weight":
            labels = [i["label"] for i in data.get("images", [])]
            if not any("heat-map" in label for label in labels) and "Images left out" not in data["output"]:
                errors.append(f"{name}: a failed image check, but no heat-map and no note that it was left out")
        print(f"{name}: {fmt} result valid ({len(raw)} bytes, score {score:.2f}, {len(tests)} steps)")
    return errors


def class_outputs(report_dir, name, score):
    """Where the class's files (gradebook.csv, grades-lms.csv, index.html) show another score for NAME."""
    errors = []
    for table, key in (("gradebook.csv", "submission"), ("grades-lms.csv", "student_id")):
        with open(os.path.join(report_dir, table), encoding="utf-8") as f:
            rows = [r for r in csv.DictReader(f) if r.get(key) == name]
        if [r.get("score") for r in rows] != [str(score)]:
            errors.append(f"{table} shows {[r.get('score') for r in rows]}, report.json {score}")
    with open(os.path.join(report_dir, "index.html"), encoding="utf-8") as f:
        cells = re.findall(r'href="' + re.escape(name) + r'/report\.html">[^<]*</a>[^<]*</td><td>([^<]*)</td>', f.read())
    if cells != [str(score)]:
        errors.append(f"the class index shows {cells}, report.json {score}")
    return errors


def mutations(fmt):
    """(what, function(data) -> data) that each make a result invalid."""
    def drop(key):
        return lambda d: {k: v for k, v in d.items() if k != key}

    def set_test(key, value):
        def f(d):
            d = copy.deepcopy(d)
            d["tests"][0][key] = value
            return d
        return f

    def set_top(key, value):
        def f(d):
            d = copy.deepcopy(d)
            d[key] = value
            return d
        return f
    pad = "x" * 1_100_000
    if fmt == "gradescope":
        return [("a test's score over its max_score", set_test("score", 1000)),
                ("a negative score", set_top("score", -1)),
                ("no score and no tests", lambda d: drop("tests")(drop("score")(d))),
                ("an unknown visibility", set_top("visibility", "sometimes")),
                ("an unknown output_format", set_test("output_format", "pdf")),
                ("a test's name missing", lambda d: {**d, "tests": [{k: v for k, v in d["tests"][0].items() if k != "name"}]}),
                ("a score as a string", set_top("score", "82")),
                ("the top score over the tests' total", set_top("score", 100.5)),
                ("over 1 MB", set_top("output", pad)),
                ("an image fetched from elsewhere", set_top("output", '<img src="http://example.com/a.png">')),
                ("an inline image that is not a JPEG", set_top("output", '<img src="data:image/jpeg;base64,aGVsbG8=">'))]
    if fmt == "prairielearn":
        return [("score over 1", set_top("score", 1.5)),
                ("no score while gradable", drop("score")),
                ("not gradable without format_errors", lambda d: drop("format_errors")({**d, "gradable": False})),
                ("points over max_points", set_test("points", 99)),
                ("gradable as a string", set_top("gradable", "yes")),
                ("an image that is not a data URI", set_top("images", [{"label": "x", "url": "http://example.com/a.png"}])),
                ("over 1 MB", set_top("output", pad))]
    return [("version 2", set_top("version", 2)),
            ("an unknown status", set_top("status", "ok")),
            ("no max_score", drop("max_score")),
            ("scores over max_score", set_test("score", 150)),
            ("a test without status", lambda d: {**d, "tests": [{k: v for k, v in d["tests"][0].items() if k != "status"}]}),
            ("pass with a failed test", lambda d: {**set_test("status", "fail")(d), "status": "pass"})]


def check_rejects(folder):
    errors = []
    for fmt, name in FILES.items():
        data, raw = load(os.path.join(folder, name))
        base = validate(fmt, folder, data, raw)
        if base:
            errors.append(f"{fmt}: the unbroken result is already invalid: {base}")
            continue
        for what, mutate in mutations(fmt):
            broken = mutate(data)
            text = json.dumps(broken).encode()
            found = (validate_classroom.validate(broken, text, None) if fmt == "classroom"
                     else validate(fmt, folder, broken, text))
            if found:
                print(f"{fmt}: {what}: rejected ({found[0]})")
            else:
                errors.append(f"{fmt}: {what}: accepted")
    # The classroom base64 must match its JSON.
    data, raw = load(os.path.join(folder, FILES["classroom"]))
    import base64
    other = base64.b64encode(json.dumps({**data, "max_score": 50}).encode())
    if not validate_classroom.validate(data, raw, other):
        errors.append("classroom: a base64 file of another JSON: accepted")
    else:
        print("classroom: a base64 file of another JSON: rejected")
    return errors


def check_grader_error(folder):
    errors = []
    for fmt, name in FILES.items():
        data, raw = load(os.path.join(folder, name))
        errors += [f"{fmt}: {e}" for e in validate(fmt, folder, data, raw)]
    pl, _ = load(os.path.join(folder, FILES["prairielearn"]))
    if pl.get("gradable") is not False or "grader failed" not in " ".join(pl.get("format_errors", [])):
        errors.append(f"prairielearn: the grader's failure must be gradable false with format_errors saying so: {pl}")
    gs, _ = load(os.path.join(folder, FILES["gradescope"]))
    if gs["score"] != 0 or "grader-error" not in gs["output"]:
        errors.append(f"gradescope: expected score 0 and grader-error in the output: {gs['score']}, {gs['output'][:200]!r}")
    cr, _ = load(os.path.join(folder, FILES["classroom"]))
    if cr["status"] != "error":
        errors.append(f"classroom: status {cr['status']}, expected error")
    if not errors:
        print(f"grader error: PrairieLearn not gradable ({pl['format_errors'][0][:100]}), Gradescope 0, Classroom error")
    return errors


def main():
    args = sys.argv[1:]
    if len(args) >= 4 and args[0] == "results" and args[1] in FILES:
        errors = check_results(args[1], args[2], args[3:])
    elif len(args) == 2 and args[0] == "rejects":
        errors = check_rejects(args[1])
    elif len(args) == 2 and args[0] == "grader-error":
        errors = check_grader_error(args[1])
    else:
        print(__doc__, file=sys.stderr)
        return 2
    for error in errors:
        print(f"FAIL {error}")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
