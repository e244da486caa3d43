#!/usr/bin/env python3
"""Unit tests of tools/student/summary.py on hand-written reports: today's report.json, the fields a
newer grader adds (fix_first, summary, per-step entries, mistakes with estimates), missing or oddly
shaped optional fields, statuses other than graded, and files that are not reports.

usage: PYTHONPATH=tools summary_test.py SCRATCH_DIR
"""
import json
import os
import subprocess
import sys
import unittest

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
HERE = os.path.dirname(os.path.abspath(__file__))
from student import summary  # noqa: E402  (tools/ on PYTHONPATH)

SCRATCH = None


def check(cid, steps, passed, **extra):
    c = {"id": cid, "steps": steps, "passed": passed, "measured": f"{cid} measured",
         "tolerance": f"{cid} tolerance", "diagnosis": f"{cid} diagnosis" if not passed else ""}
    c.update(extra)
    return c


def report(checks, status="graded", score=None, **extra):
    passed = sum(1 for c in checks if c.get("passed") is True)
    r = {"submission": "part2", "path": "student/part2", "part": 2, "status": status,
         "score": score if score is not None else (passed * 100 // len(checks) if checks else 0),
         "message": "", "seconds": 3.2, "checks": checks}
    r.update(extra)
    return r


def summarize(r):
    lines, passed = summary.summarize(r, "/r/part2/report.json")
    return "\n".join(lines), passed


class TodaysReports(unittest.TestCase):
    def test_the_earliest_named_step_comes_first(self):
        text, passed = summarize(report([
            check("pot.flip", list(range(1, 26)), False),
            check("pot.key", [3, 4, 5, 15], True),
            check("pot.bloom-downsample", [22, 24], False),
            check("pot.bloom-threshold", [17, 18], False),
            check("pot.frame", [6, 7, 8, 9, 10, 19, 20], False),
        ]))
        self.assertFalse(passed)
        self.assertIn("score 20/100 (1 of 5 checks passed)", text)
        self.assertIn("Fix first: step 6: check pot.frame (steps 6, 7, 8, 9, 10, 19, 20)", text)
        self.assertIn("  measured: pot.frame measured", text)
        self.assertIn("  expected: pot.frame tolerance", text)
        self.assertIn("  what:     pot.frame diagnosis", text)
        self.assertIn("tutorial10.html#step-6", text)
        self.assertIn("--view final, ev, key", text)
        # The whole-part check comes last, after the ones that name steps.
        self.assertIn("Also failing: pot.bloom-threshold, pot.bloom-downsample, pot.flip", text)
        self.assertIn("Full report: /r/part2/report.json", text)

    def test_only_whole_part_checks_fail(self):
        text, _ = summarize(report([check("pot.buffers", list(range(1, 17)), False),
                                    check("pot.flip", list(range(1, 17)), False)]))
        self.assertIn("Fix first: step 1: check pot.buffers (steps 1-16)", text)

    def test_score_100_passes(self):
        text, passed = summarize(report([check("pot.key", [3, 4, 5, 15], True)]))
        self.assertTrue(passed)
        self.assertIn("score 100/100", text)
        self.assertNotIn("Fix first", text)

    def test_100_with_another_status_does_not_pass(self):
        _, passed = summarize(report([], status="crashed", score=100))
        self.assertFalse(passed)

    def test_build_failed_shows_the_compiler_message(self):
        text, passed = summarize(report([], status="build-failed",
                                        message="Tutorial10.cpp does not build:\nTutorial10.cpp:33:5: error: expected ';'"))
        self.assertFalse(passed)
        self.assertIn("status build-failed", text)
        self.assertIn("  Tutorial10.cpp:33:5: error: expected ';'", text)

    def test_missing_optional_fields(self):
        text, passed = summarize({"status": "graded", "checks": [{"id": "pot.key", "passed": False}]})
        self.assertFalse(passed)
        self.assertIn("score ?/100", text)
        self.assertIn("Fix first: check pot.key", text)
        self.assertNotIn("measured:", text)
        text, passed = summarize({})
        self.assertFalse(passed)
        self.assertIn("status unknown", text)

    def test_odd_shapes_are_passed_over(self):
        text, passed = summarize({"status": "graded", "score": "100", "part": [2], "checks": [
            "not a check", {"id": 7, "passed": "no", "steps": "9", "measured": {"x": 1}, "mistakes": "?"},
            {"id": "pot.frame", "passed": False, "steps": [True, 9, "10", None], "mistakes": [1, {"estimate": 3}]}]})
        self.assertFalse(passed)  # a score that is not a number is not 100
        self.assertIn("Fix first: step 9: check pot.frame (step 9)", text)


class NewerReports(unittest.TestCase):
    def test_fix_first_summary_step_entries_and_estimates(self):
        steps = [{"step": 6, "points": 2, "passed": True}, {"step": 9, "points": 3, "passed": False},
                 {"step": 10, "points": 1, "passed": True}]
        mistakes = [{"id": "white-point", "estimate": {"parameter": "white_point", "value": 0.25, "tutorial": 0.22}}]
        text, passed = summarize(report(
            [check("pot.key", [3, 4, 5, 15], False), check("pot.frame", steps, False, mistakes=mistakes)],
            summary="2 of 16 steps lose points", fix_first={"step": 9, "check": "pot.frame", "text": "step 9: the white point"},
            files=[{"name": "PostProcess.frag", "source": "submission"}]))
        self.assertFalse(passed)
        self.assertIn("2 of 16 steps lose points", text)
        self.assertIn("Fix first: step 9: check pot.frame (step 9)", text)
        self.assertIn("  note:     step 9: the white point", text)
        self.assertIn("  your white point measures 0.25; the tutorial's is 0.22", text)
        self.assertIn("tutorial10.html#step-9", text)
        self.assertIn("Also failing: pot.key", text)

    def test_fix_first_as_text(self):
        text, _ = summarize(report([check("pot.key", [3, 4, 5, 15], False)], fix_first="step 4: epsilon"))
        self.assertIn("Fix first: step 3: check pot.key", text)
        self.assertIn("  note:     step 4: epsilon", text)

    def test_empty_status(self):
        text, passed = summarize(report([], status="empty"))
        self.assertFalse(passed)
        self.assertIn("none of this part's files", text)


class OneLinePerFact(unittest.TestCase):
    """The shape t10-grade writes: `summary` and `fix_first` repeat the failed check's diagnosis."""
    def lines(self, diagnosis, estimate):
        c = check("p1.luminance", [3], False, blames=[3], diagnosis=diagnosis,
                  mistakes=[{"id": "luminance-weights", "steps": [3], "estimate": estimate}])
        r = report([c, check("p1.key", [4, 5], True)], score=97,
                   summary="score 97: steps 3 lose points; fix first: step 3 - p1.luminance: " + diagnosis,
                   fix_first="fix first: step 3 - p1.luminance: " + diagnosis)
        return summarize(r)[0]

    def test_the_fix_is_said_once(self):
        diagnosis = "[luminance-weights] your luminance weights measure (0.2130, 0.7150, 0.0720) (step 3)"
        text = self.lines(diagnosis, {"parameter": "luminance_weights", "value": [0.213, 0.715, 0.072],
                                      "tutorial": [0.2126, 0.7152, 0.0722]})
        self.assertEqual(text.lower().count("fix first"), 1, text)
        self.assertEqual(text.count("(0.2130, 0.7150, 0.0720)"), 1, text)
        self.assertIn("Fix first: step 3: check p1.luminance (step 3)", text)

    def test_values_as_the_tutorial_writes_them(self):
        text = self.lines("", {"parameter": "luminance_weights", "value": [0.21304, 0.71497, 0.07199],
                               "tutorial": [0.2126, 0.7152, 0.0722]})
        self.assertIn("your luminance weights measure (0.2130, 0.7150, 0.0720); "
                      "the tutorial's are (0.2126, 0.7152, 0.0722)", text)
        text = self.lines("", {"parameter": "epsilon", "value": 1.04e-6, "tutorial": 1e-8})
        self.assertIn("your epsilon measures 1.04e-06; the tutorial's is 1e-08", text)
        text = self.lines("", {"parameter": "blur_sigma", "value": 1.2504, "tutorial": 2.5})
        self.assertIn("your blur sigma measures 1.3; the tutorial's is 2.5", text)


class TheGradersStep(unittest.TestCase):
    def test_the_step_the_grader_blames_not_the_checks_first(self):
        # A wrong bloom weight fails the frame check of steps 6-10, 19, 20 and 35; the grader blames 20.
        diagnosis = "[bloom-weight] your bloom weight measures 0.50; the tutorial's is 0.98 (step 20)"
        text, _ = summarize(report([check("pot.frame", [6, 7, 8, 9, 10, 19, 20, 35], False, blames=[20], diagnosis=diagnosis),
                                    check("pot.key", [3, 4, 5], True)],
                                   fix_first="fix first: step 20 - pot.frame: " + diagnosis))
        self.assertIn("Fix first: step 20: check pot.frame", text)
        self.assertIn("tutorial10.html#step-20", text)
        self.assertNotIn("#step-6", text)


class CommandLine(unittest.TestCase):
    def run_on(self, content):
        path = os.path.join(SCRATCH, "report.json")
        with open(path, "w", encoding="utf-8") as f:
            f.write(content)
        return subprocess.run([sys.executable, os.path.join(os.path.dirname(HERE), "summary.py"), path],
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)

    def test_exit_codes(self):
        self.assertEqual(self.run_on(json.dumps(report([check("a", [1], True)]))).returncode, 0)
        self.assertEqual(self.run_on(json.dumps(report([check("a", [1], False)]))).returncode, 1)
        bad = self.run_on("{not json")
        self.assertEqual(bad.returncode, 2)
        self.assertIn("report.json: not valid JSON", bad.stderr)
        self.assertEqual(self.run_on("[1, 2]").returncode, 2)
        missing = subprocess.run([sys.executable, os.path.join(os.path.dirname(HERE), "summary.py"),
                                  os.path.join(SCRATCH, "none.json")], stderr=subprocess.PIPE, text=True)
        self.assertEqual(missing.returncode, 2)
        self.assertIn("none.json: cannot read: No such file or directory", missing.stderr)


if __name__ == "__main__":
    SCRATCH = sys.argv.pop(1)
    os.makedirs(SCRATCH, exist_ok=True)
    unittest.main(verbosity=2)
