#!/usr/bin/env python3
"""Checks the limits that keep the platforms' code in files of their own and the folders readable.

usage: source_limits.py ROOT

Over the C and C++ files under ROOT (not third_party/, .git/, nor the build trees and out/ at its
top: build/, build-web/, ...):

- The browser build is a set of file swaps chosen in CMake (common/CMakeLists.txt), as Windows is:
  `__EMSCRIPTEN__` appears on at most MAX_EMSCRIPTEN_LINES lines in at most MAX_EMSCRIPTEN_FILES
  files, each a branch of a line or two, and on none in common/content/ (what is drawn does not know
  the platform: its platform parts are platform_parts.cpp / platform_parts_web.cpp).
- The frame loop's app.cpp (common/frame/src/loop/app.cpp) has at most MAX_APP_LINES lines: the
  platforms' loops live in app_native.cpp and app_web.cpp.
- No source folder (one holding .cpp or .c files) holds more than MAX_FOLDER_FILES files: a layer's
  sources are split into folders by service group (common/frame/src/loop/, options/, ...). A
  layer's headers stay together in <layer>/include/t10/, which holds no sources (so that an
  #include does not change when a file moves between layers or groups).

Prints each problem with its file and exits 1 if there is any.
"""
import pathlib
import re
import sys

MAX_EMSCRIPTEN_LINES = 10
MAX_EMSCRIPTEN_FILES = 6
NO_EMSCRIPTEN_UNDER = "common/content/"
APP = "common/frame/src/loop/app.cpp"
MAX_APP_LINES = 350
MAX_FOLDER_FILES = 20

CODE_SUFFIXES = {".cpp", ".hpp", ".h", ".c", ".cc"}
SOURCE_SUFFIXES = {".cpp", ".c", ".cc"}
SKIP_PARTS = {"third_party", ".git", "node_modules"}
TOP_OUTPUT = re.compile(r"^(build($|-)|out$)")  # build trees (CMakePresets.json) and make's out/


def files(root):
    """Every file under root outside the skipped folders, as (path relative to root, path)."""
    for path in sorted(root.rglob("*")):
        if not path.is_file():
            continue
        parts = path.relative_to(root).parts
        if SKIP_PARTS & set(parts) or TOP_OUTPUT.match(parts[0]):
            continue
        yield path.relative_to(root).as_posix(), path


def emscripten_problems(code):
    """The __EMSCRIPTEN__ limits over code: a list of (relative path, path)."""
    problems = []
    lines = []  # (relative path, line number)
    for relative, path in code:
        for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
            if "__EMSCRIPTEN__" in line:
                lines.append((relative, number))
                if relative.startswith(NO_EMSCRIPTEN_UNDER):
                    problems.append(f"{relative}:{number}: __EMSCRIPTEN__ in {NO_EMSCRIPTEN_UNDER} (a platform's part "
                                    "is a file of its own, chosen in common/CMakeLists.txt)")
    marked = sorted({relative for relative, _ in lines})
    where = ", ".join(f"{relative}:{number}" for relative, number in lines)
    if len(lines) > MAX_EMSCRIPTEN_LINES:
        problems.append(f"__EMSCRIPTEN__ on {len(lines)} lines, over {MAX_EMSCRIPTEN_LINES} ({where}): "
                        "swap whole files in CMake instead")
    if len(marked) > MAX_EMSCRIPTEN_FILES:
        problems.append(f"__EMSCRIPTEN__ in {len(marked)} files, over {MAX_EMSCRIPTEN_FILES} ({', '.join(marked)})")
    print(f"__EMSCRIPTEN__: {len(lines)} lines in {len(marked)} files")
    return problems


def app_problems(root):
    path = root / APP
    if not path.is_file():
        return [f"{APP}: not found (the frame loop's file moved: update tests/source_limits.py)"]
    count = len(path.read_text().splitlines())
    print(f"{APP}: {count} lines")
    if count > MAX_APP_LINES:
        return [f"{APP} is {count} lines, over {MAX_APP_LINES} (a platform's loop goes into app_native.cpp / app_web.cpp)"]
    return []


def folder_problems(every):
    by_folder = {}
    for relative, path in every:
        by_folder.setdefault(str(pathlib.PurePosixPath(relative).parent), []).append(path)
    problems = []
    largest = (0, "")
    for folder, paths in sorted(by_folder.items()):
        if not any(path.suffix in SOURCE_SUFFIXES for path in paths):
            continue
        largest = max(largest, (len(paths), folder))
        if len(paths) > MAX_FOLDER_FILES:
            problems.append(f"{folder}/: {len(paths)} files, over {MAX_FOLDER_FILES} (split it into folders by service group)")
    print(f"largest source folder: {largest[1]}/ with {largest[0]} files")
    return problems


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    root = pathlib.Path(sys.argv[1])
    every = list(files(root))
    code = [(relative, path) for relative, path in every if path.suffix in CODE_SUFFIXES]
    if not code:
        print(f"{root}: no code found")
        return 1
    problems = emscripten_problems(code) + app_problems(root) + folder_problems(every)
    for problem in problems:
        print(problem)
    print(f"source limits: {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
