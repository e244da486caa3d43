#!/usr/bin/env python3
"""A class graded as an instructor would after cloning it: alice/student/part3 and bob/student/part3
(copies of the reference3 and weight test submissions) share their last folder.

  check_class.py T10_GRADE SUBMISSIONS_DIR OUT

Checks that the batch is refused with a message saying how to name them; named from the first path
component (--name-from 1) or a pattern, it is graded and index.html and
grades-lms.csv list every submission, with bob's failure of step 20 in the step table; with a roster
(GitHub Classroom's export columns) the reports are named by student id; a name missing from the
roster, or a student id that cannot name a folder, is refused. Exit 0 when all hold, 1 otherwise."""
import csv
import os
import re
import shutil
import subprocess
import sys

errors = []


def grade(t10_grade, cwd, *args, code=0, words=()):
    # The test submissions hold only the files their mistake changes: the rest comes from the reference.
    argv = [t10_grade, "--part", "3", "--timeout", "20", "--fill-from-reference", "all", *args]
    result = subprocess.run(argv, cwd=cwd, capture_output=True, text=True)
    print(f"$ {' '.join(argv[1:])}: exit {result.returncode}")
    if result.returncode != code:
        errors.append(f"{' '.join(argv[1:])}: exit {result.returncode}, expected {code}: {result.stderr[-1500:]}")
    for w in words:
        if w not in result.stderr:
            errors.append(f"{' '.join(argv[1:])}: the message does not say '{w}': {result.stderr[:600]}")
    return result


def index_rows(report):
    """{submission: [classes of its step cells]} from index.html's step table."""
    with open(os.path.join(report, "index.html"), encoding="utf-8") as f:
        page = f.read()
    rows = {}
    for row in re.findall(r"<tr><td class=\"l\"><a href=\"([^\"]+)/report.html\">.*?</tr>", page):
        rows[row] = None
    for name in rows:
        line = re.search(r"<tr><td class=\"l\"><a href=\"" + re.escape(name) + r"/report.html\">(.*?)</tr>", page).group(1)
        rows[name] = re.findall(r"<td class=\"([fpno])\"", line)
    return rows, page


def check_index(report, expected, names=None):
    rows, page = index_rows(report)
    if sorted(rows) != sorted(expected):
        errors.append(f"{report}/index.html lists {sorted(rows)}, expected {sorted(expected)}")
        return
    for name, full in expected.items():
        if not os.path.exists(os.path.join(report, name, "report.html")):
            errors.append(f"{report}: the link {name}/report.html leads nowhere")
        cells = rows[name]
        if len(cells) != 36:
            errors.append(f"{name}: {len(cells)} step cells, expected 36 (one per step of Part 3)")
        if full != ("f" not in cells):
            errors.append(f"{name}: step cells {''.join(cells)} (f = failed), expected {'none' if full else 'some'} failed")
        if not full and cells[19] != "f":
            errors.append(f"{name}: step 20 is not marked failed")
    with open(os.path.join(report, "grades-lms.csv"), newline="") as f:
        lms = {row["student_id"]: row for row in csv.DictReader(f)}
    if sorted(lms) != sorted(expected):
        errors.append(f"grades-lms.csv has {sorted(lms)}, expected {sorted(expected)}")
    for name, full in expected.items():
        row = lms.get(name, {})
        if (row.get("score") == "100") != full or row.get("max_score") != "100":
            errors.append(f"grades-lms.csv {name}: {row}")
        if names and row.get("name") != names[name]:
            errors.append(f"grades-lms.csv {name}: name {row.get('name')!r}, expected {names[name]!r}")
        if names and names[name] not in page:
            errors.append(f"index.html does not show {names[name]}")
    print(f"{report}: index.html and grades-lms.csv list {', '.join(sorted(expected))}")


def main():
    if len(sys.argv) != 4:
        print(__doc__, file=sys.stderr)
        return 2
    t10_grade, submissions, out = sys.argv[1:]
    shutil.rmtree(out, ignore_errors=True)
    clazz = os.path.join(out, "class")
    for student, source in (("alice", "reference3"), ("bob", "weight")):
        shutil.copytree(os.path.join(submissions, "part3", source), os.path.join(clazz, student, "student", "part3"))
    folders = ["alice/student/part3", "bob/student/part3"]
    grade(t10_grade, clazz, "--report", "../r0", *folders, code=2,
          words=("two submissions are named 'part3'", "--name-from N", "--roster"))
    grade(t10_grade, clazz, "--report", "../r1", "--name-from", "1", *folders)
    check_index(os.path.join(out, "r1"), {"alice": True, "bob": False})
    grade(t10_grade, clazz, "--report", "../r2", "--name-from", "-1", *folders, code=2, words=("named 'part3'",))
    with open(os.path.join(out, "roster.csv"), "w", encoding="utf-8") as f:
        f.write('identifier,github_username,github_id,name\ns1001,alice,11,"Alice, A."\ns1002,bob,12,Bob B\ns1003,,,Carol C\n')
    grade(t10_grade, clazz, "--report", "../r3", "--name-from", "([^/]+)/student", "--roster", "../roster.csv", *folders)
    check_index(os.path.join(out, "r3"), {"s1001": True, "s1002": False}, {"s1001": "Alice, A.", "s1002": "Bob B"})
    with open(os.path.join(out, "short.csv"), "w", encoding="utf-8") as f:
        f.write("student_id,folder\ns1001,alice\n")
    grade(t10_grade, clazz, "--report", "../r4", "--name-from", "1", "--roster", "../short.csv", *folders, code=2,
          words=("'bob' is not in the roster",))
    grade(t10_grade, clazz, "--report", "../r5", "--name-from", "9", *folders, code=2, words=("has 3 components",))
    with open(os.path.join(out, "escape.csv"), "w", encoding="utf-8") as f:
        f.write("student_id,folder\n../../escaped,alice\ns1002,bob\n")
    grade(t10_grade, clazz, "--report", "../r6", "--name-from", "1", "--roster", "../escape.csv", *folders, code=2,
          words=("escape.csv:2: student id '../../escaped' cannot name a folder",))
    for error in errors:
        print(f"FAIL {error}")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
