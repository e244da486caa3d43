#!/usr/bin/env python3
"""Checks the students' GitHub Classroom workflow.

  check_workflow.py yaml WORKFLOW_YML
      It parses as YAML (Debian's python3-yaml) and is wired as GitHub Classroom's own workflows are: one
      job, run-autograding-tests, with no other display name; `make grader` (not `make test`); a grading
      step whose outputs the later steps use (each steps.X.outputs.Y names a step id and an output
      classroom_grade.py writes); classroom-resources/autograding-grading-reporter@v1 with the runners
      the grading step names and PART1..3_RESULTS from its partN outputs; the report artifact; and the
      job's result decided from FAIL_BELOW_100.
  check_workflow.py grade T10_GRADE SUBMISSIONS OUT
      Runs the grading step (classroom_grade.py) on a student folder with part1 (reference1) and part3
      (weight): each part's result is valid for the reporter (validate_classroom.py) with whole points
      that add up to its report.json score, part 3 step 20 failed; the job summary gives each part's
      score and the step to fix first with what was measured, what was expected and the link to the
      step's line in site/tutorial10.md. Then runs GitHub Classroom's released reporter
      (tests/fixtures/classroom-reporter/main.js, with node) on those outputs as the Action does and
      reads the log a student sees: the failed step's line, its measured and expected values and link,
      and the notice "Points X/200" with X the sum of the report.json scores. Exit 77 without node.
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


def find_up(*parts):
    """A path of the checkout this script is in (it moves with the grader's folder)."""
    folder = HERE
    while os.path.dirname(folder) != folder:
        if os.path.exists(os.path.join(folder, *parts)):
            return os.path.join(folder, *parts)
        folder = os.path.dirname(folder)
    return os.path.join(HERE, *parts)


REPORTER = find_up("tests", "fixtures", "classroom-reporter", "main.js")
TUTORIAL = find_up("site", "tutorial10.md")


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
    jobs = workflow.get("jobs", {})
    if list(jobs) != ["run-autograding-tests"]:
        errors.append(f"jobs {list(jobs)}: expected the one job run-autograding-tests, as Classroom's own workflows have")
        return
    job = jobs["run-autograding-tests"]
    if job.get("name", "run-autograding-tests") != "run-autograding-tests":
        errors.append(f"the job is named {job.get('name')!r}: its check run must keep the id run-autograding-tests")
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
        # partN= is written as f"part{part}=" for each part graded.
        elif not re.search(r"\b" + re.escape(output) + r"=", script) and not (
                re.fullmatch(r"part[123]", output) and 'f"part{part}="' in script):
            errors.append(f"steps.{step_id}.outputs.{output}: classroom_grade.py never writes {output}=")
    reporters = [s for s in steps if str(s.get("uses", "")).split("@")[0].endswith("/autograding-grading-reporter")]
    if len(reporters) != 1:
        errors.append(f"{len(reporters)} reporter steps, expected one")
    else:
        reporter = reporters[0]
        if reporter.get("uses") != "classroom-resources/autograding-grading-reporter@v1":
            errors.append(f"the reporter is {reporter.get('uses')}: use classroom-resources/autograding-grading-reporter@v1")
        if str(reporter.get("with", {}).get("runners", "")).replace(" ", "") != "${{steps.grade.outputs.runners}}":
            errors.append("the reporter's runners must be the grading step's output runners (the parts graded)")
        for part in (1, 2, 3):
            value = str(reporter.get("env", {}).get(f"PART{part}_RESULTS", "")).replace(" ", "")
            if value != f"${{{{steps.grade.outputs.part{part}}}}}":
                errors.append(f"the reporter reads PART{part}_RESULTS for runner part{part}: set it from steps.grade.outputs.part{part}")
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
        print(f"{path}: valid YAML; {len(steps)} steps; reporter {reporters[0]['uses']}, runners "
              f"{reporters[0]['with']['runners']}; outputs used: {used}")


def step_line(step):
    """The line of the tutorial's anchor {:#step-N} in site/tutorial10.md."""
    with open(TUTORIAL, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            if "{:#step-%d}" % step in line:
                return number
    return None


def check_grade(t10_grade, submissions, out, errors):
    if shutil.which("node") is None:
        print("SKIP: node is not installed (Debian's nodejs: make test installs it); GitHub Classroom's reporter cannot run")
        return 77
    shutil.rmtree(out, ignore_errors=True)
    student = os.path.join(out, "student")
    shutil.copytree(os.path.join(submissions, "part1", "reference1"), os.path.join(student, "part1"))
    shutil.copytree(os.path.join(submissions, "part3", "weight"), os.path.join(student, "part3"))
    env = {**os.environ, "GITHUB_OUTPUT": os.path.join(out, "output.txt"),
           "GITHUB_STEP_SUMMARY": os.path.join(out, "summary.md"), "GITHUB_REPOSITORY": "student/t10", "GITHUB_RUN_ID": "42",
           "GITHUB_SHA": "0123abc", "T10_TUTORIAL_URL": "",
           # The test submissions hold only the files their mistake changes.
           "T10_FILL_FROM_REFERENCE": "all"}
    code = subprocess.run([sys.executable, GRADE_SCRIPT, t10_grade, student, os.path.join(out, "grade-report")], env=env).returncode
    if code != 0:
        errors.append(f"classroom_grade.py exited {code}")
    with open(env["GITHUB_OUTPUT"], encoding="utf-8") as f:
        outputs = dict(line.split("=", 1) for line in f.read().splitlines())
    scores = {}
    for part in (1, 3):
        with open(os.path.join(out, "grade-report", f"part{part}", f"part{part}", "report.json"), encoding="utf-8") as f:
            scores[part] = json.load(f)["score"]
        raw = base64.b64decode(outputs.get(f"part{part}", ""))
        result = json.loads(raw)
        errors.extend(f"part{part}: {e}" for e in validate_classroom.validate(result, raw, outputs[f"part{part}"].encode()))
        points = [t["score"] for t in result["tests"]]
        if any(not isinstance(p, int) for p in points) or sum(points) != scores[part]:
            errors.append(f"part{part}: test points {points} do not add up in whole numbers to report.json's {scores[part]}")
    if not 0 < scores[3] < 100 or outputs.get("runners") != "part1,part3" or "part2" in outputs:
        errors.append(f"outputs: runners {outputs.get('runners')}, part 3 score {scores[3]}: expected part1,part3 and a mistake")
    if outputs.get("graded") != "1,3" or outputs.get("grader_failed") != "false" or outputs.get("score") != f"{100 + scores[3]}/200":
        errors.append(f"outputs {{graded: {outputs.get('graded')}, grader_failed: {outputs.get('grader_failed')}, "
                      f"score: {outputs.get('score')}}}")
    link = f"https://github.com/student/t10/blob/0123abc/site/tutorial10.md?plain=1#L{step_line(20)}"
    with open(env["GITHUB_STEP_SUMMARY"], encoding="utf-8") as f:
        summary = f.read()
    for words in ("### Part 1: 100 / 100", f"### Part 3: {scores[3]} / 100", "**Fix first: Part 3 step 20**",
                  "[bloom-weight] your bloom weight measures 0.50; the tutorial's is 0.98", "- measured: ", "- expected: ",
                  f"[Part 3 step 20]({link})", "student/t10/actions/runs/42#artifacts"):
        if words not in summary:
            errors.append(f"the job summary does not say '{words}':\n{summary}")
    log = run_reporter(outputs, errors)
    # What the student reads in the Actions log, as GitHub Classroom's reporter prints it.
    expected = [f"❌ Part 3 step 20: 0/", "points - fix this first\nTest code:\npot.", "measured: ", "expected: ",
                f"tutorial: {link}\n", f"::notice title=Autograding complete::Points {100 + scores[3]}/200\n",
                "Total points for part1: 100.00/100"]
    for words in expected:
        if words not in log:
            errors.append(f"the reporter's log does not say {words!r}:\n{log}")
    if not errors:
        notice = re.search(r"::notice title=Autograding complete::(.*)", log).group(1)
        print(f"each part valid: score {outputs['score']}; the reporter says '{notice}'\n{summary}\n--- reporter log ---\n{log}")
    return 0


def run_reporter(outputs, errors):
    """Runs GitHub Classroom's released reporter on the grading step's outputs as the Action does (the input
    runners in INPUT_RUNNERS, each runner's result in <RUNNER>_RESULTS); returns its log without colours."""
    env = {"PATH": os.environ.get("PATH", "/usr/bin:/bin"), "INPUT_RUNNERS": outputs.get("runners", "")}
    for runner in outputs.get("runners", "").split(","):
        env[runner.strip().upper() + "_RESULTS"] = outputs.get(runner.strip(), "")
    done = subprocess.run(["node", REPORTER], env=env, capture_output=True, text=True, timeout=60)
    log = re.sub(r"\x1b\[[0-9;]*m", "", done.stdout + done.stderr)
    # It fails its step when any test failed: part 3 has a mistake.
    if done.returncode != 1 or "::error::Some tests failed." not in log:
        errors.append(f"the reporter exited {done.returncode} (expected 1: part 3 has a failed step):\n{log}")
    return log


def main():
    errors = []
    if len(sys.argv) == 3 and sys.argv[1] == "yaml":
        check_yaml(sys.argv[2], errors)
    elif len(sys.argv) == 5 and sys.argv[1] == "grade":
        if check_grade(*sys.argv[2:], errors) == 77:
            return 77
    else:
        print(__doc__, file=sys.stderr)
        return 2
    for error in errors:
        print(f"FAIL {error}")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
