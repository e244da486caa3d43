#!/usr/bin/env python3
"""Packs the grader for a platform (make gradescope / make prairielearn).

  package.py gradescope PART SOURCE OUT     OUT/autograder.zip: setup.sh and run_autograder at its root,
                                            grade_one.sh, t10.conf (the part) and the checkout's tracked
                                            files under t10/ (setup.sh builds them in the image)
  package.py prairielearn PART SOURCE OUT   OUT/run.sh (the entrypoint), grade_one.sh, t10.conf,
                                            info.json (the keys to merge into the question's info.json)
                                            and question.html (the file upload, and the results element
                                            without which PrairieLearn shows no tests and no images)

Files are written under temporary names and renamed into place. Exit 0 on success, 1 on failure
(with the file and the reason), 2 on bad usage."""
import json
import os
import subprocess
import sys
import tempfile
import zipfile

HERE = os.path.dirname(os.path.abspath(__file__))


def fail(message, code=1):
    print(f"package.py: error: {message}", file=sys.stderr)
    sys.exit(code)


def tracked_files(source):
    try:
        out = subprocess.run(["git", "-C", source, "ls-files", "-z"], check=True, capture_output=True).stdout
    except (OSError, subprocess.CalledProcessError) as error:
        fail(f"{source}: cannot list the checkout's files with git ls-files ({error}); package from a git checkout")
    return [name for name in out.decode().split("\0") if name]


def add(archive, path, arcname, mode=None):
    info = zipfile.ZipInfo(arcname, date_time=(2020, 1, 1, 0, 0, 0))
    st = os.stat(path)
    info.external_attr = ((mode if mode is not None else st.st_mode & 0o777) | 0o100000) << 16
    info.compress_type = zipfile.ZIP_DEFLATED
    with open(path, "rb") as f:
        archive.writestr(info, f.read())


def write_text(path, text, mode=0o644):
    temporary = path + ".tmp"
    with open(temporary, "w", encoding="utf-8") as f:
        f.write(text)
    os.chmod(temporary, mode)
    os.replace(temporary, path)


def copy(source, target, mode):
    with open(source, encoding="utf-8") as f:
        write_text(target, f.read(), mode)


def gradescope(part, source, out):
    target = os.path.join(out, "autograder.zip")
    files = tracked_files(source)
    fd, temporary = tempfile.mkstemp(prefix="autograder.", suffix=".zip.tmp", dir=out)
    os.close(fd)
    try:
        with zipfile.ZipFile(temporary, "w") as archive:
            add(archive, os.path.join(HERE, "gradescope", "setup.sh"), "setup.sh", 0o755)
            add(archive, os.path.join(HERE, "gradescope", "run_autograder"), "run_autograder", 0o755)
            add(archive, os.path.join(HERE, "grade_one.sh"), "grade_one.sh", 0o755)
            archive.writestr(zipfile.ZipInfo("t10.conf", date_time=(2020, 1, 1, 0, 0, 0)), f"T10_PART={part}\n")
            for name in files:
                path = os.path.join(source, name)
                if os.path.isfile(path) and not os.path.islink(path):
                    add(archive, path, "t10/" + name)
        os.chmod(temporary, 0o644)
        os.replace(temporary, target)
    except OSError as error:
        os.unlink(temporary)
        fail(f"{target}: {error}")
    print(f"wrote {target} ({os.path.getsize(target) // 1024} KiB, {len(files)} files of the checkout)")


# The part's files (grade_one.sh copies these, and only these, out of a submission).
PART_FILES = {1: ["Tutorial10.cpp", "PostProcess.frag", "PostProcessInit.frag"],
              2: ["Tutorial10.cpp", "PostProcess.frag", "PostProcessInit.frag"],
              3: ["Tutorial10.cpp", "PostProcess.frag", "PostProcessInit.frag", "Gauss.frag"]}


def question_html(part):
    """The question's HTML: PrairieLearn renders the external grader's tests, messages and images only
    where the submission panel holds <pl-external-grader-results>."""
    files = ", ".join(PART_FILES[part])
    return f"""<pl-question-panel>
  <p>Tutorial 10, Part {part}: upload your <code>Tutorial10.cpp</code> and the part's shaders. The grader
  builds and renders them against the reference and scores each tutorial step.</p>
  <pl-file-upload file-names="{files}"></pl-file-upload>
</pl-question-panel>

<pl-submission-panel>
  <pl-external-grader-results></pl-external-grader-results>
  <pl-file-preview></pl-file-preview>
</pl-submission-panel>
"""


def prairielearn(part, out):
    copy(os.path.join(HERE, "prairielearn", "run.sh"), os.path.join(out, "run.sh"), 0o755)
    copy(os.path.join(HERE, "grade_one.sh"), os.path.join(out, "grade_one.sh"), 0o755)
    write_text(os.path.join(out, "t10.conf"), f"T10_PART={part}\n")
    # The keys to merge into the question's info.json (its title, topic and uuid stay the course's).
    info = {
        "gradingMethod": "External",
        "externalGradingOptions": {
            "enabled": True,
            "image": "REPLACE-WITH-YOUR-IMAGE (grader/platforms/Dockerfile: a checkout built with make grader at /opt/t10)",
            "serverFilesCourse": [f"t10/part{part}/"],
            "entrypoint": f"/grade/serverFilesCourse/t10/part{part}/run.sh",
            "timeout": 600,
        },
    }
    write_text(os.path.join(out, "info.json"), json.dumps(info, indent=2) + "\n")
    write_text(os.path.join(out, "question.html"), question_html(part))
    print(f"wrote {out}/run.sh, grade_one.sh, t10.conf, info.json and question.html (copy the folder to "
          f"serverFilesCourse/t10/part{part}/; question.html and info.json's keys go to the question's folder)")


def main():
    if len(sys.argv) != 5 or sys.argv[1] not in ("gradescope", "prairielearn") or sys.argv[2] not in ("1", "2", "3"):
        fail("usage: package.py gradescope|prairielearn 1|2|3 SOURCE OUT", 2)
    platform, part, source, out = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4]
    try:
        os.makedirs(out, exist_ok=True)
    except OSError as error:
        fail(f"{out}: cannot create: {error.strerror}")
    if platform == "gradescope":
        gradescope(part, source, out)
    else:
        prairielearn(part, out)


if __name__ == "__main__":
    main()
