#!/usr/bin/env python3
"""Runs a platform's packaged scripts end to end in a scratch root, as the platform would, and
validates what they leave where the platform reads it.

  platform_e2e.py gradescope|prairielearn SOURCE BUILD SUBMISSION OUT

gradescope: make gradescope's zip is unpacked into OUT/root/source (modes kept), setup.sh runs with
AUTOGRADER_ROOT=OUT/root and T10_SOURCE/T10_BUILD (reusing the built checkout), run_autograder is
copied to the root as Gradescope does and grades SUBMISSION laid out as student/part3/ (the students'
repository layout), then an empty upload. prairielearn: make prairielearn's folder, GRADE_ROOT=OUT/root,
SUBMISSION in student/, then an empty upload, then a grader that cannot start (gradable false).
Each results.json is validated (validate_*.py) and must say what happened. Exit 0 when all hold."""
import json
import os
import re
import shutil
import subprocess
import sys
import time
import zipfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import validate_gradescope  # noqa: E402
import validate_prairielearn  # noqa: E402

PACKAGE = os.path.join(HERE, "..", "..", "platforms", "package.py")
errors = []


def run(argv, env):
    started = time.monotonic()
    result = subprocess.run(argv, env={**os.environ, **env}, capture_output=True, text=True)
    print(f"$ {' '.join(argv)}  (exit {result.returncode}, {time.monotonic() - started:.1f} s)")
    if result.returncode != 0:
        print(result.stdout[-3000:], result.stderr[-3000:])
    return result


def results(path, validator, what):
    try:
        with open(path, "rb") as f:
            raw = f.read()
        data = json.loads(raw.decode("utf-8"))
    except (OSError, ValueError) as error:
        errors.append(f"{what}: no readable {path}: {error}")
        return None
    found = validator.validate(data, raw)
    errors.extend(f"{what}: {e}" for e in found)
    print(f"{what}: {path} ({len(raw)} bytes) {'valid' if not found else 'INVALID'}")
    return data


def fresh(path):
    shutil.rmtree(path, ignore_errors=True)
    os.makedirs(path)
    return path


def copy_files(source, target):
    os.makedirs(target, exist_ok=True)
    for name in os.listdir(source):
        shutil.copy(os.path.join(source, name), target)


def gradescope(source, build, submission, out):
    if run([sys.executable, PACKAGE, "gradescope", "3", source, os.path.join(out, "package")], {}).returncode != 0:
        errors.append("make gradescope's packaging failed")
        return
    root = fresh(os.path.join(out, "root"))
    with zipfile.ZipFile(os.path.join(out, "package", "autograder.zip")) as archive:
        for info in archive.infolist():
            path = archive.extract(info, os.path.join(root, "source"))
            os.chmod(path, (info.external_attr >> 16) & 0o777)
    env = {"AUTOGRADER_ROOT": root, "T10_SOURCE": source, "T10_BUILD": build}
    if run([os.path.join(root, "source", "setup.sh")], env).returncode != 0:
        errors.append("setup.sh failed")
        return
    shutil.copy(os.path.join(root, "source", "run_autograder"), root)
    copy_files(submission, os.path.join(root, "submission", "student", "part3"))
    if run([os.path.join(root, "run_autograder")], env).returncode != 0:
        errors.append("run_autograder failed on the mistaken submission")
    data = results(os.path.join(root, "results", "results.json"), validate_gradescope, "gradescope, mistaken")
    if data is not None:
        failed = [t["number"] for t in data["tests"] if t["status"] == "failed"]
        if not 0 < data["score"] < 100 or "20" not in failed:
            errors.append(f"gradescope, mistaken: score {data['score']}, failed steps {failed}: expected step 20 to fail")
        # Its failed frame check is shown with pictures: the student's frame, the reference, the heat-map.
        if data.get("output_format") != "html" or "the difference (heat-map)" not in data["output"] or "<img" not in data["output"]:
            errors.append(f"gradescope, mistaken: no inline heat-map in the output ({data.get('output_format')}, "
                          f"{len(data['output'])} characters)")
        else:
            print(f"gradescope, mistaken: {data['output'].count('<img')} inline images, results.json {len(json.dumps(data))} bytes")
    shutil.rmtree(os.path.join(root, "submission"))
    os.makedirs(os.path.join(root, "submission"))
    os.remove(os.path.join(root, "results", "results.json"))
    run([os.path.join(root, "run_autograder")], env)
    data = results(os.path.join(root, "results", "results.json"), validate_gradescope, "gradescope, empty upload")
    if data is not None and (data["score"] != 0 or "Nothing to grade" not in data["output"]):
        errors.append(f"gradescope, empty upload: {data}")


def prairielearn(source, build, submission, out):
    package = os.path.join(out, "package")
    if run([sys.executable, PACKAGE, "prairielearn", "3", source, package], {}).returncode != 0:
        errors.append("make prairielearn's packaging failed")
        return
    with open(os.path.join(package, "info.json")) as f:
        options = json.load(f)["externalGradingOptions"]
    if not options["entrypoint"].endswith("/run.sh"):
        errors.append(f"info.json: entrypoint {options['entrypoint']}")
    # PrairieLearn shows the tests and images only where the question holds the results element; the
    # upload asks for exactly the files grade_one.sh takes from a Part 3 submission.
    with open(os.path.join(package, "question.html"), encoding="utf-8") as f:
        question = f.read()
    with open(os.path.join(os.path.dirname(PACKAGE), "grade_one.sh"), encoding="utf-8") as f:
        script = f.read()
    taken = re.search(r'^files="([^"]*)"', script, re.M).group(1).split() + \
        re.search(r'^\[ "\$T10_PART" = 3 \] && files="\$files ([^"]*)"', script, re.M).group(1).split()
    upload = re.search(r'<pl-file-upload file-names="([^"]*)"', question)
    if "<pl-external-grader-results></pl-external-grader-results>" not in question.split("<pl-submission-panel>")[-1]:
        errors.append("question.html: no <pl-external-grader-results> in the submission panel")
    if upload is None or [f.strip() for f in upload.group(1).split(",")] != taken:
        errors.append(f"question.html: the upload asks for {upload and upload.group(1)}, grade_one.sh takes {taken}")
    root = fresh(os.path.join(out, "root"))
    env = {"GRADE_ROOT": root, "T10_SOURCE": source, "T10_BUILD": build}
    copy_files(submission, os.path.join(root, "student"))
    run([os.path.join(package, "run.sh")], env)
    path = os.path.join(root, "results", "results.json")
    data = results(path, validate_prairielearn, "prairielearn, mistaken")
    if data is not None and not (data.get("gradable") is True and 0 < data["score"] < 1):
        errors.append(f"prairielearn, mistaken: gradable {data.get('gradable')}, score {data.get('score')}")
    for what, setup, extra in (("empty upload", lambda: shutil.rmtree(os.path.join(root, "student")), {}),
                               ("grader cannot start", lambda: copy_files(submission, os.path.join(root, "student")),
                                {"T10_BUILD": os.path.join(out, "no-such-build")})):
        setup()
        os.makedirs(os.path.join(root, "student"), exist_ok=True)
        os.remove(path)
        run([os.path.join(package, "run.sh")], {**env, **extra})
        data = results(path, validate_prairielearn, f"prairielearn, {what}")
        if data is not None and (data.get("gradable") is not False or not data.get("format_errors")):
            errors.append(f"prairielearn, {what}: expected gradable false with format_errors: {data}")


def main():
    if len(sys.argv) != 6 or sys.argv[1] not in ("gradescope", "prairielearn"):
        print(__doc__, file=sys.stderr)
        return 2
    platform, source, build, submission, out = sys.argv[1:]
    fresh(out)
    (gradescope if platform == "gradescope" else prairielearn)(source, build, submission, out)
    for error in errors:
        print(f"FAIL {error}")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
