#!/usr/bin/env python3
"""The grading step of the students' GitHub Classroom workflow (.github/workflows/grade.yml).

  classroom_grade.py T10_GRADE STUDENT_DIR REPORT_DIR

Grades STUDENT_DIR/part1..part3 (those that exist) with `t10-grade --format classroom` into
REPORT_DIR/partN/, merges the parts' results into one for the Classroom reporter (a test per part and
step; max_score 100 per part), and writes, for the steps after it:
  $GITHUB_OUTPUT        result=<base64 JSON> (the reporter's GRADE_RESULTS), score=<points>/<max>,
                        graded=<parts>, grader_failed=true|false
  $GITHUB_STEP_SUMMARY  the score of each part, its failed steps and where the reports are
Exit 0 when every present part got a result (whatever the score), 1 when the grader failed, 2 on
bad usage."""
import base64
import json
import os
import subprocess
import sys


def append(variable, text):
    path = os.environ.get(variable)
    if path:
        with open(path, "a", encoding="utf-8") as f:
            f.write(text)
    else:
        sys.stdout.write(text)


def main():
    if len(sys.argv) != 4:
        print(__doc__, file=sys.stderr)
        return 2
    t10_grade, student, report = sys.argv[1:]
    merged = {"version": 1, "status": "pass", "max_score": 0, "tests": []}
    summary = ["## Tutorial 10: my stages", ""]
    grader_failed = False
    graded = []
    for part in (1, 2, 3):
        folder = os.path.join(student, f"part{part}")
        if not os.path.isdir(folder):
            continue
        out = os.path.join(report, f"part{part}")
        code = subprocess.run([t10_grade, "--part", str(part), "--format", "classroom", "--fill-from-reference",
                               os.environ.get("T10_FILL_FROM_REFERENCE", "unchanged"), "--report", out, folder]).returncode
        result_path = os.path.join(out, f"part{part}", "classroom-result.json")
        try:
            with open(result_path, encoding="utf-8") as f:
                result = json.load(f)
            with open(os.path.join(out, f"part{part}", "report.json"), encoding="utf-8") as f:
                status = json.load(f).get("status", "?")
        except (OSError, ValueError) as error:
            print(f"classroom_grade.py: part {part}: t10-grade exited {code} and left no result: {error}", file=sys.stderr)
            result = {"status": "error", "max_score": 100, "tests": [
                {"name": f"Part {part}", "status": "error", "score": 0, "message": f"the grader failed (exit {code})"}]}
            status = "grader-error"
        grader_failed |= code != 0 or result["status"] == "error"
        graded.append(part)
        merged["max_score"] += result["max_score"]
        merged["tests"] += result["tests"]
        if result["status"] == "error" or (result["status"] == "fail" and merged["status"] == "pass"):
            merged["status"] = result["status"]
        points = sum(t["score"] for t in result["tests"])
        # "Part 3 step 20" -> "20", "Part 3 whole frame" -> "whole frame"
        failed = [t["name"].split(" ", 2)[-1].replace("step ", "") for t in result["tests"] if t["status"] != "pass"]
        summary.append(f"- **Part {part}**: {status}, {points:.2f} / {result['max_score']} points"
                       + (f"; failed steps: {', '.join(failed)}" if failed else "; every step passed"))
    if not graded:
        merged = {"version": 1, "status": "fail", "max_score": 100, "tests": [
            {"name": "student/partN", "status": "fail", "score": 0,
             "message": f"Nothing to grade: put your work in {student}/part1, part2 or part3."}]}
        summary.append(f"Nothing to grade: put your work in `{student}/part1`, `part2` or `part3`.")
    total = sum(t["score"] for t in merged["tests"])
    run = "{}/{}/actions/runs/{}".format(os.environ.get("GITHUB_SERVER_URL", "https://github.com"),
                                         os.environ.get("GITHUB_REPOSITORY", "OWNER/REPO"), os.environ.get("GITHUB_RUN_ID", "0"))
    summary += ["", f"Total: **{total:.2f} / {merged['max_score']}**. Each part's `report.html` (every check, what was "
                f"measured, the diagnosis, the frames) is in the artifact `grade-report` of [this run]({run}#artifacts).", ""]
    encoded = base64.b64encode(json.dumps(merged).encode("utf-8")).decode("ascii")
    append("GITHUB_OUTPUT", f"result={encoded}\nscore={total:.2f}/{merged['max_score']}\n"
                            f"graded={','.join(map(str, graded))}\ngrader_failed={'true' if grader_failed else 'false'}\n")
    append("GITHUB_STEP_SUMMARY", "\n".join(summary) + "\n")
    return 1 if grader_failed else 0


if __name__ == "__main__":
    sys.exit(main())
