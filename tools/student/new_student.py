#!/usr/bin/env python3
"""`make student PART=N`: creates a student's own folder for Part N of Tutorial 10.

usage: new_student.py --part N --student-dir DIR --source-root ROOT

Part 1 starts from tutorial10_part0_start/ (the program the tutorial starts from). Part N (2, 3) starts
from the student's own DIR/part(N-1)/ when it exists, else from the reference of Part N-1; the
message says which. An existing DIR/partN/ is never touched: the command refuses (exit 1). The copy
is made under a temporary name and renamed into place, so an interrupted run leaves no half folder.
The copy's Tutorial10.cpp gets a header comment naming it and the commands that build, check and
run it; everything else is copied as it is. Exit 0: created; 1: refused or failed; 2: bad usage.
"""
import argparse
import os
import shutil
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree

PARTS = {1: ("Tone Mapping", "1-16"), 2: ("Bloom", "17-25"), 3: ("Gaussian Blur", "26-36")}
REFERENCE = {0: "tutorial10_part0_start", 1: "tutorial10_part1_tonemap", 2: "tutorial10_part2_bloom",
             3: "tutorial10_part3_gaussian"}
HOST = "Tutorial10.cpp"


class Refused(Exception):
    pass


def shown_path(path):
    """A path as the student would type it: relative to the current folder when inside it."""
    relative = os.path.relpath(path)
    return path if relative.startswith("..") else relative


def header(part, origin):
    title, steps = PARTS[part]
    return (f"// student_part{part}: my version of Tutorial 10, Part {part} \"{title}\" (steps {steps}).\n"
            f"//\n"
            f"// Started by `make student PART={part}` from {origin}.\n"
            f"// This part's steps go into this file and the shaders of this folder (the program reads its\n"
            f"// shaders from here). Check it against Part {part}: make check PART={part}\n"
            f"// Run it: make run STAGE=student_part{part}\n")


def replace_header(source, new_header):
    """The leading block of // comment lines is the file's header; it is replaced, the rest kept."""
    lines = source.splitlines(keepends=True)
    i = 0
    while i < len(lines) and lines[i].lstrip().startswith("//"):
        i += 1
    return new_header + "".join(lines[i:])


def create(part, student_dir, source_root):
    target = os.path.join(student_dir, f"part{part}")
    shown = shown_path(target)
    if os.path.lexists(target):
        raise Refused(f"{shown}/ already exists: not overwritten, nothing was changed. To start Part {part} "
                      f"again, move or delete {shown}/ first.")
    own = os.path.join(student_dir, f"part{part - 1}")
    if part > 1 and os.path.isfile(os.path.join(own, HOST)):
        source, origin = own, f"my own {shown_path(own)}/"
        note = f"from your own {shown_path(own)}/ (Part {part - 1} as you wrote it)"
        files = None  # everything in the student's folder comes along
    else:
        reference = REFERENCE[part - 1]
        source, origin = os.path.join(source_root, reference), f"the reference {reference}/"
        why = "" if part == 1 else f"; there is no {shown_path(own)}/{HOST} of your own"
        note = f"from the reference {reference}/{why}"
        files = sorted(f for f in os.listdir(source) if f == HOST or f.endswith((".frag", ".vert")))
    if not os.path.isfile(os.path.join(source, HOST)):
        raise Refused(f"{os.path.join(source, HOST)}: not found, nothing to start Part {part} from")

    os.makedirs(student_dir, exist_ok=True)
    temporary = f"{target}.tmp-{os.getpid()}"
    try:
        if files is None:
            shutil.copytree(source, temporary, symlinks=True)
        else:
            os.mkdir(temporary)
            for name in files:
                shutil.copy2(os.path.join(source, name), os.path.join(temporary, name))
        host = os.path.join(temporary, HOST)
        with open(host, encoding="utf-8") as f:
            text = f.read()
        with open(host, "w", encoding="utf-8") as f:
            f.write(replace_header(text, header(part, origin)))
        # A folder created meanwhile (another make student) wins: rename never replaces a non-empty one.
        if os.path.lexists(target):
            raise Refused(f"{shown}/ appeared while copying: not overwritten")
        os.rename(temporary, target)
    finally:
        shutil.rmtree(temporary, ignore_errors=True)
    return shown, note


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--part", required=True)
    ap.add_argument("--student-dir", required=True)
    ap.add_argument("--source-root", required=True)
    args = ap.parse_args()
    if args.part not in ("1", "2", "3"):
        print(f"make student: PART={args.part or '(empty)'}: choose 1, 2 or 3 (make student PART=1)", file=sys.stderr)
        return 2
    part = int(args.part)
    try:
        shown, note = create(part, args.student_dir, args.source_root)
    except Refused as e:
        print(f"make student: {e}", file=sys.stderr)
        return 1
    except OSError as e:
        print(f"make student: {e.filename or args.student_dir}: {e.strerror or e}", file=sys.stderr)
        return 1
    title, steps = PARTS[part]
    print(f"created {shown}/ {note}.")
    print(f"Now do Part {part}, \"{title}\" (steps {steps}), in {shown}/, then:")
    print(f"  make check PART={part}             build it, grade it against Part {part}, say what to fix first")
    print(f"  make run STAGE=student_part{part}   open it in a window (or render it headless into out/)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
