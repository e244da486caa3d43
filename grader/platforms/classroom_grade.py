#!/usr/bin/env python3
"""The grading step of the students' GitHub Classroom workflow (.github/workflows/grade.yml).

  classroom_grade.py T10_GRADE STUDENT_DIR REPORT_DIR

Grades STUDENT_DIR/part1..part3 (those that exist) with `t10-grade --format classroom` into
REPORT_DIR/partN/ and hands each part to GitHub Classroom's grading reporter
(classroom-resources/autograding-grading-reporter@v1) as a runner of its own: a test per step, whole
points that add up to the part's score in report.json, max_score 100 per part. It writes, for the
steps after it:
  $GITHUB_OUTPUT        partN=<base64 JSON> for each graded part (the reporter's PARTN_RESULTS),
                        runners=part1,part3 (the reporter's input), result=<base64 JSON> (all parts in
                        one), score=<points>/<max>, graded=<parts>, grader_failed=true|false
  $GITHUB_STEP_SUMMARY  for each part: its score, the step to fix first with what was measured, what was
                        expected and the link to the step; then where the reports are
The links to the tutorial's steps go to $T10_TUTORIAL_URL#step-N when it is set (the course's
tutorial10.html), else to the step's line in site/tutorial10.md of this commit on GitHub.
Exit 0 when every present part got a result (whatever the score), 1 when the grader failed, 2 on
bad usage."""
import base64
import json
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))

def find_tutorial():
    """site/tutorial10.md of the checkout this script is in."""
    folder = HERE
    while os.path.dirname(folder) != folder:
        if os.path.isfile(os.path.join(folder, "site", "tutorial10.md")):
            return os.path.join(folder, "site", "tutorial10.md")
        folder = os.path.dirname(folder)
    return os.path.join(HERE, "site", "tutorial10.md")


TUTORIAL = find_tutorial()


def append(variable, text):
    path = os.environ.get(variable)
    if path:
        with open(path, "a", encoding="utf-8") as f:
            f.write(text)
    else:
        sys.stdout.write(text)


def step_lines():
    """{step: line} of the tutorial's step anchors ({:#step-N}) in site/tutorial10.md."""
    lines = {}
    try:
        with open(TUTORIAL, encoding="utf-8") as f:
            for number, line in enumerate(f, 1):
                for step in re.findall(r"\{:#step-(\d+)\}", line):
                    lines.setdefault(int(step), number)
    except OSError:
        pass
    return lines


def step_link(step, lines):
    url = os.environ.get("T10_TUTORIAL_URL", "").strip()
    if url:
        return f"{url.split('#')[0]}#step-{step}"
    repo = "{}/{}".format(os.environ.get("GITHUB_SERVER_URL", "https://github.com"),
                          os.environ.get("GITHUB_REPOSITORY", "OWNER/REPO"))
    line = f"#L{lines[step]}" if step in lines else ""
    return f"{repo}/blob/{os.environ.get('GITHUB_SHA', 'HEAD')}/site/tutorial10.md?plain=1{line}"


def relink(result, lines):
    """The grader writes 'tutorial: <page>#step-N' under a failed step; here it becomes a link the
    student can open from the Actions log."""
    for test in result.get("tests", []):
        code = test.get("test_code", "")
        test["test_code"] = re.sub(r"^tutorial: \S*#step-(\d+)$", lambda m: "tutorial: " + step_link(int(m.group(1)), lines),
                                   code, flags=re.M)
    return result


def part_summary(part, result, report):
    """The job summary's lines for one part: score, the step to fix first and what it measured."""
    points = sum(t["score"] for t in result["tests"])
    status = report.get("status", "?")
    lines = [f"### Part {part}: {report.get('score', points)} / {result['max_score']}"
             + ("" if status == "graded" else f" ({status})"), ""]
    first = next((t for t in result["tests"] if t["name"].endswith("fix this first")), None)
    if first is None:
        first = next((t for t in result["tests"] if t["status"] != "pass"), None)
    if first is None:
        return lines + ["Every step passed.", ""]
    lines.append(f"**Fix first: {first['name'].split(':')[0]}**" if first["status"] != "error"
                 else f"**{first['message']}**")
    lines.append("")
    for line in first.get("test_code", "").splitlines():
        link = re.match(r"^tutorial: (\S+)$", line)
        if link:
            lines.append(f"- tutorial: [{first['name'].split(':')[0]}]({link.group(1)})")
        elif line.strip():
            lines.append(f"- {line.strip()}")
    others = [t["name"].split(":")[0].rsplit(" ", 1)[-1] for t in result["tests"] if t["status"] != "pass" and t is not first]
    if others:
        lines.append(f"- also losing points: step{'s' if len(others) > 1 else ''} {', '.join(others)}")
    return lines + [""]


def grade_part(t10_grade, part, folder, report):
    """Grades one part; returns (classroom result, report.json as a dict, whether the grader failed)."""
    out = os.path.join(report, f"part{part}")
    code = subprocess.run([t10_grade, "--part", str(part), "--format", "classroom", "--fill-from-reference",
                           os.environ.get("T10_FILL_FROM_REFERENCE", "unchanged"), "--report", out, folder]).returncode
    try:
        with open(os.path.join(out, f"part{part}", "classroom-result.json"), encoding="utf-8") as f:
            result = json.load(f)
        with open(os.path.join(out, f"part{part}", "report.json"), encoding="utf-8") as f:
            report_json = json.load(f)
    except (OSError, ValueError) as error:
        print(f"classroom_grade.py: part {part}: t10-grade exited {code} and left no result: {error}", file=sys.stderr)
        result = {"version": 1, "status": "error", "max_score": 100, "tests": [
            {"name": f"Part {part}", "status": "error", "score": 0, "message": f"the grader failed (exit {code})",
             "test_code": "", "filename": "", "line_no": 0, "execution_time": "0s"}]}
        report_json = {"status": "grader-error", "score": 0}
    return result, report_json, code != 0 or result["status"] == "error"


def main():
    if len(sys.argv) != 4:
        print(__doc__, file=sys.stderr)
        return 2
    t10_grade, student, report = sys.argv[1:]
    lines = step_lines()
    merged = {"version": 1, "status": "pass", "max_score": 0, "tests": []}
    summary = ["## Tutorial 10: my stages", ""]
    outputs = []
    grader_failed = False
    graded = []
    for part in (1, 2, 3):
        folder = os.path.join(student, f"part{part}")
        if not os.path.isdir(folder):
            continue
        result, report_json, failed = grade_part(t10_grade, part, folder, report)
        relink(result, lines)
        grader_failed |= failed
        graded.append(part)
        merged["max_score"] += result["max_score"]
        merged["tests"] += result["tests"]
        if result["status"] == "error" or (result["status"] == "fail" and merged["status"] == "pass"):
            merged["status"] = result["status"]
        outputs.append(f"part{part}=" + base64.b64encode(json.dumps(result).encode("utf-8")).decode("ascii"))
        summary += part_summary(part, result, report_json)
    if not graded:
        merged = {"version": 1, "status": "fail", "max_score": 100, "tests": [
            {"name": "student/partN", "status": "fail", "score": 0,
             "message": f"Nothing to grade: put your work in {student}/part1, part2 or part3.",
             "test_code": f"Nothing to grade: put your work in {student}/part1, part2 or part3.",
             "filename": "", "line_no": 0, "execution_time": "0s"}]}
        outputs.append("part1=" + base64.b64encode(json.dumps(merged).encode("utf-8")).decode("ascii"))
        summary.append(f"Nothing to grade: put your work in `{student}/part1`, `part2` or `part3`.")
    total = sum(t["score"] for t in merged["tests"])
    run = "{}/{}/actions/runs/{}".format(os.environ.get("GITHUB_SERVER_URL", "https://github.com"),
                                         os.environ.get("GITHUB_REPOSITORY", "OWNER/REPO"), os.environ.get("GITHUB_RUN_ID", "0"))
    summary += ["", f"Total: **{total} / {merged['max_score']}**. Each part's `report.html` (every check, what was "
                f"measured, the diagnosis, the frames) is in the artifact `grade-report` of [this run]({run}#artifacts).", ""]
    encoded = base64.b64encode(json.dumps(merged).encode("utf-8")).decode("ascii")
    runners = ",".join(f"part{p}" for p in graded) or "part1"
    append("GITHUB_OUTPUT", "\n".join(outputs) + f"\nrunners={runners}\nresult={encoded}\nscore={total}/{merged['max_score']}\n"
                            f"graded={','.join(map(str, graded))}\ngrader_failed={'true' if grader_failed else 'false'}\n")
    append("GITHUB_STEP_SUMMARY", "\n".join(summary) + "\n")
    return 1 if grader_failed else 0


if __name__ == "__main__":
    sys.exit(main())
