#!/usr/bin/env python3
"""Checks the students' GitHub Classroom workflow.

  check_workflow.py yaml WORKFLOW_YML
      It parses as YAML (Debian's python3-yaml) and is wired as the Classroom reporter needs: a job named
      "Autograding Tests" with checks: write; `make grader` (not `make test`); a grading step whose outputs
      the later steps use (each steps.X.outputs.Y names a step id and an output classroom_grade.py
      writes); the reporter with runners whose <NAME>_RESULTS variable is set; the report artifact; and
      the job's result decided from FAIL_BELOW_100.
  check_workflow.py grade T10_GRADE SUBMISSIONS OUT
      Runs the grading step (classroom_grade.py) on a student folder with part1 (reference1) and part3
      (weight): the merged result is valid for the reporter (validate_classroom.py), worth 200 points,
      part 3 step 20 failed; the job summary names the failed step and the artifact.
Exit 0 when all hold, 1 otherwise."""
import base64
import json
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import validate_classroom  # noqa: E402

GRADE_SCRIPT = os.path.join(HERE, "..", "..", "platforms", "classroom_grade.py")


def check_yaml(path, errors):
    try:
        import yaml
    except ImportError:
        errors.append("python3-yaml is not installed (make test installs it: the Makefile's PACKAGES)")
        return
    with open(path, encoding="utf-8") as f:
        text = f.read()
    try:
        workflow = yaml.safe_load(text)
    except yaml.YAMLError as error:
        errors.append(f"{path}: not valid YAML: {error}")
        return
    # YAML 1.1 reads the key `on` as true.
    triggers = workflow.get("on", workflow.get(True))
    if not isinstance(triggers, dict) or "push" not in triggers:
        errors.append(f"triggers {triggers!r}: push is missing")
    if workflow.get("permissions", {}).get("checks") != "write":
        errors.append("permissions: checks: write is missing (the reporter updates the check run)")
    jobs = workflow.get("jobs", {})
    if len(jobs) != 1:
        errors.append(f"{len(jobs)} jobs, expected one")
        return
    job = next(iter(jobs.values()))
    if job.get("name") != "Autograding Tests":
        errors.append(f"the job is named {job.get('name')!r}: the reporter looks for the check run 'Autograding Tests'")
    if "FAIL_BELOW_100" not in job.get("env", {}):
        errors.append("no FAIL_BELOW_100 in the job's env (the instructor's switch)")
    steps = job.get("steps", [])
    ids = {s["id"]: s for s in steps if "id" in s}
    runs = "\n".join(s.get("run", "") for s in steps)
    if "make grader" not in runs:
        errors.append("no step runs `make grader`")
    if re.search(r"make\s+test\b", runs):
        errors.append("a step runs `make test`: the workflow must build only what grading needs")
    if "grade" not in ids or "classroom_grade.py" not in ids["grade"].get("run", ""):
        errors.append("no step with id grade running classroom_grade.py")
    with open(GRADE_SCRIPT, encoding="utf-8") as f:
        script = f.read()
    for step_id, output in re.findall(r"steps\.([\w-]+)\.outputs\.([\w-]+)", text):
        if step_id not in ids:
            errors.append(f"steps.{step_id}.outputs.{output}: no step has the id {step_id}")
        elif not re.search(r"\b" + re.escape(output) + r"=", script):
            errors.append(f"steps.{step_id}.outputs.{output}: classroom_grade.py never writes {output}=")
    reporters = [s for s in steps if str(s.get("uses", "")).split("@")[0].endswith("/autograding-grading-reporter")]
    if len(reporters) != 1:
        errors.append(f"{len(reporters)} reporter steps, expected one")
    else:
        reporter = reporters[0]
        for runner in str(reporter.get("with", {}).get("runners", "")).split(","):
            variable = runner.strip().upper() + "_RESULTS"
            if not runner.strip() or "steps.grade.outputs.result" not in str(reporter.get("env", {}).get(variable, "")):
                errors.append(f"runner {runner!r}: the reporter reads {variable}, which is not set from steps.grade.outputs.result")
        if reporter.get("continue-on-error") is not True:
            errors.append("the reporter fails its step on any failed test: it needs continue-on-error, the last step decides")
    if not any(str(s.get("uses", "")).startswith("actions/upload-artifact") and s.get("with", {}).get("name") == "grade-report"
               for s in steps):
        errors.append("no upload of the artifact grade-report")
    last = steps[-1] if steps else {}
    if "FAIL_BELOW_100" not in last.get("run", "") or last.get("if") != "always()":
        errors.append("the last step (if: always()) must decide the job's result from FAIL_BELOW_100")
    if not errors:
        used = sorted(set(re.findall(r"outputs\.([\w-]+)", text)))
        print(f"{path}: valid YAML; {len(steps)} steps; reporter runners {reporters[0]['with']['runners']}; outputs used: {used}")


def check_grade(t10_grade, submissions, out, errors):
    shutil.rmtree(out, ignore_errors=True)
    student = os.path.join(out, "student")
    shutil.copytree(os.path.join(submissions, "part1", "reference1"), os.path.join(student, "part1"))
    shutil.copytree(os.path.join(submissions, "part3", "weight"), os.path.join(student, "part3"))
    env = {**os.environ, "GITHUB_OUTPUT": os.path.join(out, "output.txt"),
           "GITHUB_STEP_SUMMARY": os.path.join(out, "summary.md"), "GITHUB_REPOSITORY": "student/t10", "GITHUB_RUN_ID": "42",
           # The test submissions hold only the files their mistake changes.
           "T10_FILL_FROM_REFERENCE": "all"}
    code = subprocess.run([sys.executable, GRADE_SCRIPT, t10_grade, student, os.path.join(out, "grade-report")], env=env).returncode
    if code != 0:
        errors.append(f"classroom_grade.py exited {code}")
    with open(env["GITHUB_OUTPUT"], encoding="utf-8") as f:
        outputs = dict(line.split("=", 1) for line in f.read().splitlines())
    raw = base64.b64decode(outputs["result"])
    result = json.loads(raw)
    errors.extend(f"merged result: {e}" for e in validate_classroom.validate(result, raw, outputs["result"].encode()))
    if result["max_score"] != 200 or result["status"] != "fail":
        errors.append(f"merged result: max_score {result['max_score']}, status {result['status']}: expected 200, fail")
    failed = [t["name"] for t in result["tests"] if t["status"] != "pass"]
    if "Part 3 step 20" not in failed or any(name.startswith("Part 1") for name in failed):
        errors.append(f"failed tests {failed}: expected Part 3 step 20 and no Part 1 step")
    if outputs.get("graded") != "1,3" or outputs.get("grader_failed") != "false":
        errors.append(f"outputs {{graded: {outputs.get('graded')}, grader_failed: {outputs.get('grader_failed')}}}")
    with open(env["GITHUB_STEP_SUMMARY"], encoding="utf-8") as f:
        summary = f.read()
    for words in ("**Part 1**: graded, 100.00 / 100 points", "**Part 3**: graded", "20", "grade-report",
                  "student/t10/actions/runs/42#artifacts"):
        if words not in summary:
            errors.append(f"the job summary does not say '{words}':\n{summary}")
    if not errors:
        print(f"merged result valid: score {outputs['score']}, failed {failed[:3]}...\n{summary}")


def main():
    errors = []
    if len(sys.argv) == 3 and sys.argv[1] == "yaml":
        check_yaml(sys.argv[2], errors)
    elif len(sys.argv) == 5 and sys.argv[1] == "grade":
        check_grade(*sys.argv[2:], errors)
    else:
        print(__doc__, file=sys.stderr)
        return 2
    for error in errors:
        print(f"FAIL {error}")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
