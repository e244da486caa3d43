#!/usr/bin/env python3
"""Tests of the students' commands (tools/student/), each in a scratch folder: nothing is written under
the source tree (every student folder goes to --scratch through STUDENT_DIR / T10_STUDENT_DIR).

usage: students_test.py new   --source-root ROOT --scratch DIR
       students_test.py check --source-root ROOT --scratch DIR --grader T10_GRADE --flip FLIP
       students_test.py build --source-root ROOT --scratch DIR --generator NINJA-NAME

  new    `make student PART=1` copies tutorial10_part0_start/ under a header of its own and refuses to
         overwrite the folder (a marker written into it survives); Part 2 then starts from the student's
         own part1/, Part 3 with no part2/ from the reference of Part 2; a bad PART is bad usage (2).
  check  a Part 1 folder filled with the reference steps but the white point of step 9 changed
         (0.22 -> 0.25) fails `make check`'s grading (check.sh, what `make check` runs once it has
         built) naming a step from 6 to 10 (today: 6, the frame check's first) and the white point;
         with the white point put back it scores 100 and exits 0. Skipped (77) without FLIP.
  build  a scratch configure with a student folder that does not compile, one that does, one with a
         name that cannot be a target and one without Tutorial10.cpp: the configure succeeds, the
         commands of `all` build every reference stage and no student program, the broken folder's
         compile fails naming its file and line, the good one's compiles.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree


class Failure(Exception):
    pass


def run(argv, cwd=None, env=None, timeout=300):
    result = subprocess.run(argv, cwd=cwd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True, timeout=timeout)
    print(f"$ {' '.join(argv)}  -> exit {result.returncode}\n{result.stdout.rstrip()}\n", flush=True)
    return result.returncode, result.stdout


def expect(condition, message):
    if not condition:
        raise Failure(message)


def body(path):
    """A C++ file without its leading comment block (the header `make student` replaces)."""
    with open(path, encoding="utf-8") as f:
        lines = f.readlines()
    i = 0
    while i < len(lines) and lines[i].lstrip().startswith("//"):
        i += 1
    return "".join(lines[i:])


def read(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


def fresh(folder):
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    return folder


def make_student(root, students, part):
    # The Makefile's own target, with STUDENT_DIR pointing at the scratch folder.
    return run(["make", "--no-print-directory", "-C", root, "student", f"PART={part}", f"STUDENT_DIR={students}"])


def test_new(args):
    students = os.path.join(fresh(args.scratch), "students")
    before = os.path.exists(os.path.join(args.source_root, "student"))

    code, out = make_student(args.source_root, students, 1)
    part1 = os.path.join(students, "part1")
    expect(code == 0, "make student PART=1 failed")
    expect("from the reference tutorial10_part0_start/" in out, "the message does not say Part 1 starts from part0")
    start = os.path.join(args.source_root, "tutorial10_part0_start")
    expect(sorted(os.listdir(part1)) == sorted(os.listdir(start)), f"part1/ holds {os.listdir(part1)}")
    host = read(os.path.join(part1, "Tutorial10.cpp"))
    expect(host.startswith("// student_part1: "), "the copy's header comment does not name student_part1")
    expect(body(os.path.join(part1, "Tutorial10.cpp")) == body(os.path.join(start, "Tutorial10.cpp")),
           "the copy's code differs from tutorial10_part0_start's")
    expect(read(os.path.join(part1, "PostProcess.frag")) == read(os.path.join(start, "PostProcess.frag")),
           "the shader was not copied as it is")

    # The student's work so far: must survive a second make student.
    marker = "// my work, step 1\n"
    with open(os.path.join(part1, "Tutorial10.cpp"), "a", encoding="utf-8") as f:
        f.write(marker)
    code, out = make_student(args.source_root, students, 1)
    expect(code != 0, "make student PART=1 succeeded over an existing folder")
    expect("already exists: not overwritten" in out, "the refusal does not say the folder exists")
    expect(read(os.path.join(part1, "Tutorial10.cpp")).endswith(marker), "the student's file was overwritten")

    code, out = make_student(args.source_root, students, 2)
    expect(code == 0 and "from your own" in out, "Part 2 did not start from the student's own part1/")
    expect(read(os.path.join(students, "part2", "Tutorial10.cpp")).endswith(marker),
           "part2/ is not the student's part1/")
    expect(read(os.path.join(students, "part2", "Tutorial10.cpp")).startswith("// student_part2: "),
           "part2's header does not name student_part2")

    other = os.path.join(args.scratch, "other")
    code, out = make_student(args.source_root, other, 3)
    expect(code == 0 and "from the reference tutorial10_part2_bloom/" in out and "of your own" in out,
           "Part 3 without a part2/ did not start from the reference of Part 2, saying so")
    expect(body(os.path.join(other, "part3", "Tutorial10.cpp")) ==
           body(os.path.join(args.source_root, "tutorial10_part2_bloom", "Tutorial10.cpp")),
           "part3/ is not the reference of Part 2")

    code, out = make_student(args.source_root, other, 4)
    expect(code != 0 and "choose 1, 2 or 3" in out, "PART=4 was not refused as bad usage")
    expect(sorted(os.listdir(other)) == ["part3"], f"a refused make student left {os.listdir(other)}")
    expect(os.path.exists(os.path.join(args.source_root, "student")) == before,
           "the test created student/ in the source tree")
    print("ok: make student copies, names, chains and never overwrites")


def fill_part1(root, folder):
    """The reference steps of Part 1 under the student's own header, as a student who followed them."""
    reference = os.path.join(root, "tutorial10_part1_tonemap")
    for name in os.listdir(reference):
        if name.endswith(".frag"):
            shutil.copy(os.path.join(reference, name), os.path.join(folder, name))
    own = read(os.path.join(folder, "Tutorial10.cpp"))
    header = own[:len(own) - len(body(os.path.join(folder, "Tutorial10.cpp")))]
    with open(os.path.join(folder, "Tutorial10.cpp"), "w", encoding="utf-8") as f:
        f.write(header + body(os.path.join(reference, "Tutorial10.cpp")))


def replace_in(path, old, new):
    text = read(path)
    expect(old in text, f"{path}: '{old}' not found (the reference changed?)")
    with open(path, "w", encoding="utf-8") as f:
        f.write(text.replace(old, new))


def test_check(args):
    if not os.access(args.flip, os.X_OK):
        print(f"SKIP: {args.flip} is not installed (make grade-deps installs FLIP into a venv under build/)")
        return 77
    students = os.path.join(fresh(args.scratch), "students")
    code, _ = make_student(args.source_root, students, 1)
    expect(code == 0, "make student PART=1 failed")
    part1 = os.path.join(students, "part1")
    fill_part1(args.source_root, part1)
    check = [os.path.join(args.source_root, "tools", "student", "check.sh"), args.grader, "1",
             os.path.join(args.scratch, "report")]
    shader = os.path.join(part1, "PostProcess.frag")
    right, wrong = "const float fYwhite = 0.22f;", "const float fYwhite = 0.25f;"

    replace_in(shader, right, wrong)
    code, out = run(check + [part1])
    expect(code == 1, f"make check exited {code} on a wrong white point, expected 1")
    expect(re.search(r"score (\d+)/100", out) and "score 100/100" not in out, "no score below 100 printed")
    # The white point is step 9; today's grader sees it in the frame check of steps 6-10, so the step
    # named first may be any of those, and the link must lead to the same step.
    first = re.search(r"Fix first: step (\d+)", out)
    expect(first and 6 <= int(first.group(1)) <= 10, "the summary does not name a step from 6 to 10 first")
    expect(f"tutorial10.html#step-{first.group(1)}" in out, f"no link to step {first.group(1)} of the tutorial page")
    expect(re.search(r"white[ _]point", out, re.I), "the summary does not say the white point is wrong")
    expect(re.search(r"measured: .*8-bit steps", out) and "expected: " in out, "measured / expected not printed")
    expect(re.search(r"Full report: \S+report\.html", out), "the full report's path is not printed")

    replace_in(shader, wrong, right)
    code, out = run(check + [part1])
    expect(code == 0 and "score 100/100" in out, "the reference steps do not score 100 with exit 0")
    print("ok: make check names the step of a known mistake, and passes the reference steps")
    return 0


def test_build(args):
    students = os.path.join(fresh(args.scratch), "students")
    code, _ = make_student(args.source_root, students, 1)
    expect(code == 0, "make student PART=1 failed")
    broken = os.path.join(students, "broken")
    shutil.copytree(os.path.join(students, "part1"), broken)
    replace_in(os.path.join(broken, "Tutorial10.cpp"), "bool GL_Init(t10::App& app)\n{",
               "bool GL_Init(t10::App& app)\n{\n    int iMissingSemicolon = 1")
    line = read(os.path.join(broken, "Tutorial10.cpp")).splitlines().index("    int iMissingSemicolon = 1") + 1
    os.makedirs(os.path.join(students, "bad-name"))
    shutil.copy(os.path.join(students, "part1", "Tutorial10.cpp"), os.path.join(students, "bad-name"))
    os.makedirs(os.path.join(students, "notes"))  # no Tutorial10.cpp: not a stage

    build = os.path.join(args.scratch, "build")
    code, out = run(["cmake", "-S", args.source_root, "-B", build, "-G", args.generator,
                     "-DCMAKE_BUILD_TYPE=Debug", f"-DT10_STUDENT_DIR={students}", "-DT10_BUILD_TESTS=OFF",
                     "-DT10_BUILD_EXTRAS=OFF"])
    expect(code == 0, "the configure failed with a broken student folder")
    expect("student_broken;student_part1" in out, "the configure did not find the two student folders")
    expect("bad-name: not built" in " ".join(out.split()), "the folder with a bad name was not named in a warning")
    with open(os.path.join(build, "student_stages.txt"), encoding="utf-8") as f:
        listed = [l.split(" ", 1)[0] for l in f.read().splitlines() if l]
    expect(listed == ["student_broken", "student_part1"], f"student_stages.txt lists {listed}")

    # Everything `all` (make build, make test) would run: every reference stage, no student program.
    commands = subprocess.run(["ninja", "-C", build, "-t", "commands", "all"], stdout=subprocess.PIPE,
                              text=True, check=True).stdout
    for stage in ("tutorial10_part0_start", "tutorial10_part1_tonemap", "tutorial10_part2_bloom",
                  "tutorial10_part3_gaussian"):
        expect(f"-o bin/{stage}" in commands, f"all does not build {stage}")
    # A student program is a student_* binary or a compile of a file in the students' folder (not any
    # line with "student" in it: the checkout itself may be in /home/student).
    built = [l[:200] for l in commands.splitlines() if "bin/student_" in l or students + os.sep in l]
    expect(not built, f"all builds a student program: {built[:1]}")

    # The student programs are built by name; the broken one's error names its file and line.
    def object_of(target):
        targets = subprocess.run(["ninja", "-C", build, "-t", "targets", "all"], stdout=subprocess.PIPE,
                                 text=True, check=True).stdout
        objects = [l.split(":")[0] for l in targets.splitlines() if f"{target}.dir/" in l and l.split(":")[0].endswith(".o")]
        expect(len(objects) == 1, f"{target}: expected one object file, found {objects}")
        return objects[0]
    code, out = run(["ninja", "-C", build, object_of("student_broken")])
    expect(code != 0, "the broken student folder compiled")
    # GCC reports the missing semicolon at the next token: on that line or the one after.
    # Ninja passes the file by a path relative to the build folder when it is near it.
    errors = re.findall(r"^(\S*Tutorial10\.cpp):(\d+):\d+: error:", out, re.M)
    named = os.path.realpath(os.path.join(build, errors[0][0])) if errors else None
    expect(named == os.path.realpath(os.path.join(broken, "Tutorial10.cpp")) and line <= int(errors[0][1]) <= line + 1,
           f"the first compiler error does not name {broken}/Tutorial10.cpp:{line} (errors: {errors[:3]})")
    code, out = run(["ninja", "-C", build, object_of("student_part1")])
    expect(code == 0, "the good student folder does not compile")
    print("ok: a student folder that does not build stays out of all, and names its file and line")
    shutil.rmtree(args.scratch, ignore_errors=True)
    return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("test", choices=["new", "check", "build"])
    ap.add_argument("--source-root", required=True)
    ap.add_argument("--scratch", required=True, help="emptied first")
    ap.add_argument("--grader")
    ap.add_argument("--flip")
    ap.add_argument("--generator", default="Ninja")
    args = ap.parse_args()
    args.source_root = os.path.abspath(args.source_root)
    args.scratch = os.path.abspath(args.scratch)
    if args.test == "new":
        test_new(args)
        return 0
    if args.test == "check":
        return test_check(args)
    return test_build(args)


if __name__ == "__main__":
    try:
        sys.exit(main())
    except (Failure, subprocess.SubprocessError) as e:
        print(f"FAIL: {e}", file=sys.stderr)
        sys.exit(1)
