#!/usr/bin/env python3
"""Checks the layering of common/: its folders are the layers of ARCHITECTURE.md.

usage: layers.py COMMON_DIR

Each layer folder holds include/t10/*.hpp and src/ (its sources; the frame layer's in a folder per
group of services, private headers beside them). A file may include (`#include "..."`)
only headers of its own layer or of the layers it sits on:

    base      (GL-free: contract, errors, files, median, sizes, JSON, CLI11 checks)
    reference base                               (the GL-free CPU reference, common/reference/)
    platform  reference, base
    content   platform, reference, base
    frame     content, platform, reference, base
    optional  content, platform, reference, base (t10_exact_key: extras and the bench)
    panel     frame, and all below frame         (t10_panel: Dear ImGui, extras only)

and the glad loader (`glad/gl.h`); never stage code, a test's or a tool's header (a bare `dumps.hpp`,
`../../tests/...`). A header is known by its path below its layer's include/ folder
(`t10/scene.hpp`), or by its file name where the layer has no include/ folder. `t10/stage.hpp`, what a stage offers the loop, may include nothing above the
platform layer. No two files may need each other: the include graph between units (a header and
its source, `views.hpp` + `views.cpp`) has no cycle. A code file in a folder that is no layer is a
problem too (a new folder gets its rule here first). System headers (`<...>`) are not checked.
Prints each problem with its file and line and exits 1 if there is any.

usage: layers.py --grader GRADER_DIR COMMON_DIR

checks the grader the same way: its folders are the stages of its pipeline, and a file may include
the headers of common/ (as above) and those of its own stage and the stages before it:

    isolation, intake, diagnosis, part (nothing of the grader below them)
    compile   isolation, intake       (a submission's host code compiled in the sandbox, cached)
    capture   compile, isolation, intake          (a case rendered in the sandbox; its outputs examined)
    checks    diagnosis, part, isolation (render results checked, FLIP run as a limited process; mistakes named)
    scoring   checks, diagnosis, part
    report    scoring, checks, diagnosis, part, intake (report.json, report.html, gradebook, class index)
    platforms report and what it may include          (the platforms' result files)
    tga       isolation, intake       (t10-grade-tga: a loader copied in and run like a stage)
    similarity  report                (--similarity: JPlag run over the class, the index's section)
    cli       every stage             (the command line on top)
    tests     the checks' core (checks, diagnosis, part), never what is around it (and GRADER_TEST_HEADERS)
    page      capture, checks, diagnosis, part, scoring (the page's check, Module.t10Check: the browser build)

A grader header is known by its path below the grader folder (`checks/checks.hpp`). No two grader
files may need each other.

The checks' core (checks/, diagnosis/ and part/ but for the files around it: GRADER_CORE_ADAPTERS)
runs on buffers in memory, so that a page can compile it: it includes no system header of the file
system, processes or POSIX (GRADER_CORE_SYSTEM_BANNED), no header of common/ that reads or writes files
(GRADER_CORE_COMMON_BANNED), and of the grader only the core's own headers. No file of the grader is
over GRADER_MAX_LINES lines.
"""
import pathlib
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')
# Each layer and the layers its files may include (itself included).
ALLOWED = {
    "base": {"base"},
    "reference": {"reference", "base"},
    "platform": {"platform", "reference", "base"},
    "content": {"content", "platform", "reference", "base"},
    "frame": {"frame", "content", "platform", "reference", "base"},
    "optional": {"optional", "content", "platform", "reference", "base"},
    "panel": {"panel", "frame", "content", "platform", "reference", "base"},
}
# Headers held to a stricter rule than their folder's.
STRICTER = {"t10/stage.hpp": {"platform", "reference", "base"}}
# Folders of common/ that hold data, not code.
DATA_FOLDERS = {"assets", "shaders"}
CODE_SUFFIXES = {".hpp", ".cpp", ".h", ".c"}
HEADER_SUFFIXES = {".hpp", ".h"}


def include_name(common, layer, path):
    """How code includes the header at `path`: below <layer>/include/, else its file name."""
    include_dir = common / layer / "include"
    try:
        return path.relative_to(include_dir).as_posix()
    except ValueError:
        return path.name


def code_files(common):
    """(layer, path) of every code file under common/; layer None for a folder that is no layer."""
    for path in sorted(common.rglob("*")):
        if path.suffix not in CODE_SUFFIXES or not path.is_file():
            continue
        top = path.relative_to(common).parts[0]
        if top in DATA_FOLDERS:
            continue
        yield (top if top in ALLOWED else None), path


# The grader's stages and the stages each may include (itself included).
REPORT_STAGES = {"report", "scoring", "checks", "diagnosis", "part", "intake"}
GRADER_ALLOWED = {
    "isolation": {"isolation"},
    "intake": {"intake"},
    "diagnosis": {"diagnosis"},
    "part": {"part"},
    "compile": {"compile", "isolation", "intake"},
    "capture": {"capture", "compile", "isolation", "intake"},
    "checks": {"checks", "diagnosis", "part", "isolation"},
    "scoring": {"scoring", "checks", "diagnosis", "part"},
    "report": REPORT_STAGES,
    "platforms": REPORT_STAGES | {"platforms"},
    "tga": {"tga", "isolation", "intake"},
    "similarity": {"similarity", "report"},
    "cli": {"cli", "isolation", "intake", "compile", "capture", "checks", "diagnosis", "part", "scoring", "report", "platforms",
            "similarity"},
    "tests": {"tests", "checks", "diagnosis", "part"},
    "page": {"page", "capture", "checks", "diagnosis", "part", "scoring"},
}

# The checks' core: these stages but for the units around them (a dump folder read, the catalogue's
# file, FLIP run as a process).
GRADER_CORE_STAGES = {"checks", "diagnosis", "part"}
GRADER_CORE_ADAPTERS = {"checks/dump_files", "checks/flip", "diagnosis/catalogue_file"}
GRADER_CORE_SYSTEM_BANNED = {"filesystem", "fstream", "cstdio", "stdio.h", "unistd.h", "fcntl.h", "dirent.h", "spawn.h",
                             "signal.h", "csignal", "thread", "future", "sys/"}
GRADER_CORE_COMMON_BANNED = {"t10/image_io.hpp", "t10/file.hpp", "t10/json.hpp", "t10/outputs.hpp"}
SYSTEM_INCLUDE = re.compile(r'^\s*#\s*include\s+<([^>]+)>')
GRADER_MAX_LINES = 700
# What the grader's tests include besides the core: the tests' Catch2 header and the catalogue compiled in.
GRADER_TEST_HEADERS = {"t10_catch.hpp", "mistakes_tsv.inc"}


def find_cycle(graph):
    """One cycle of `graph` (unit -> set of units) as a list of units, or None."""
    state = {}  # unit -> 1 while on the stack, 2 when done
    stack = []

    def visit(unit):
        state[unit] = 1
        stack.append(unit)
        for other in sorted(graph.get(unit, ())):
            if state.get(other) == 1:
                return stack[stack.index(other):] + [other]
            if other not in state:
                found = visit(other)
                if found:
                    return found
        stack.pop()
        state[unit] = 2
        return None

    for unit in sorted(graph):
        if unit not in state:
            found = visit(unit)
            if found:
                return found
    return None


def verdict(problems, graph, counted, fine):
    """Adds every file cycle of graph to problems (report one, drop its last edge, look again), prints
    them and the summary line; returns the exit status."""
    while (cycle := find_cycle(graph)) is not None:
        problems.append("cycle between files: " + " -> ".join(cycle) +
                        " (each needs the other; move what both need into a unit below them)")
        graph[cycle[-2]].discard(cycle[-1])
    for problem in problems:
        print(problem)
    print(f"{counted}: " + (fine if not problems else f"{len(problems)} problems"))
    return 1 if problems else 0


def core_include_problems(path, number, line):
    """The problem of one line of a file of the checks' core, if it includes a header of files or processes."""
    system = SYSTEM_INCLUDE.match(line)
    if system and any(system.group(1) == banned or (banned.endswith("/") and system.group(1).startswith(banned))
                      for banned in GRADER_CORE_SYSTEM_BANNED):
        return [f"{path}:{number}: includes <{system.group(1)}>: the checks' core runs on buffers in memory, without "
                "the file system or processes (move the file's part that needs it into an adapter)"]
    project = INCLUDE.match(line)
    if project and project.group(1) in GRADER_CORE_COMMON_BANNED:
        return [f"{path}:{number}: includes \"{project.group(1)}\", which reads or writes files: the checks' core runs on "
                "buffers in memory"]
    return []


def check_grader(grader, common):
    """The problems of the grader's includes (see the module's docstring)."""
    common_headers = {include_name(common, layer, path) for layer, path in code_files(common)
                      if layer is not None and path.suffix in HEADER_SUFFIXES}
    files = [path for path in sorted(grader.rglob("*")) if path.suffix in CODE_SUFFIXES and path.is_file()]
    owner = {path.relative_to(grader).as_posix(): path.relative_to(grader).parts[0]
             for path in files if path.suffix in HEADER_SUFFIXES}
    problems = []
    graph = {}
    for path in files:
        stage = path.relative_to(grader).parts[0]
        if stage not in GRADER_ALLOWED:
            problems.append(f"{path}: a code file outside the grader's stage folders ({', '.join(GRADER_ALLOWED)}); "
                            "give its folder a rule in tests/layers.py")
            continue
        unit = path.relative_to(grader).with_suffix("").as_posix()
        core = stage in GRADER_CORE_STAGES and unit not in GRADER_CORE_ADAPTERS
        for number, line in enumerate(path.read_text().splitlines(), 1):
            problems += core_include_problems(path, number, line) if core else []
            match = INCLUDE.match(line)
            if not match:
                continue
            target = match.group(1)
            if target in common_headers or target == "glad/gl.h" or (stage == "tests" and target in GRADER_TEST_HEADERS):
                continue
            if target not in owner:
                problems.append(f"{path}:{number}: includes \"{target}\", which is neither a header of common/ nor "
                                "of the grader (test and tool code sit outside both)")
                continue
            if owner[target] not in GRADER_ALLOWED[stage]:
                problems.append(f"{path}:{number}: includes \"{target}\" of {owner[target]}, a stage {stage} may not include")
            elif (core or stage == "tests") and (owner[target] not in GRADER_CORE_STAGES or
                                                 target.rsplit(".", 1)[0] in GRADER_CORE_ADAPTERS):
                problems.append(f"{path}:{number}: includes \"{target}\", which is not the checks' core: the core runs on "
                                "buffers in memory (see GRADER_CORE_ADAPTERS)")
            other = pathlib.PurePosixPath(target).with_suffix("").as_posix()
            if other != unit:
                graph.setdefault(unit, set()).add(other)
    for path in sorted(grader.rglob("*")):
        if path.is_file():
            lines = len(path.read_bytes().splitlines())
            if lines > GRADER_MAX_LINES:
                problems.append(f"{path}: {lines} lines, over {GRADER_MAX_LINES}: split it along its seams")
    return verdict(problems, graph, f"{len(files)} files in the stages of {grader}",
                   f"stages respected, no cycle, the checks' core free of files and processes, no file over {GRADER_MAX_LINES} lines")


def main():
    if len(sys.argv) == 4 and sys.argv[1] == "--grader":
        return check_grader(pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3]))
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    common = pathlib.Path(sys.argv[1])
    files = list(code_files(common))
    if not files:
        print(f"{common}: no code found")
        return 1
    owner = {}  # "t10/name.hpp" -> layer
    for layer, path in files:
        if layer is not None and path.suffix in HEADER_SUFFIXES:
            owner[include_name(common, layer, path)] = layer
    problems = []
    graph = {}  # unit ("views") -> units it includes
    for layer, path in files:
        if layer is None:
            problems.append(f"{path}: a code file outside the layer folders ({', '.join(ALLOWED)}); "
                            "give its folder a rule in tests/layers.py")
            continue
        name = include_name(common, layer, path)
        allowed = STRICTER.get(name, ALLOWED[layer])
        unit = path.stem
        for number, line in enumerate(path.read_text().splitlines(), 1):
            match = INCLUDE.match(line)
            if not match:
                continue
            target = match.group(1)
            if target == "glad/gl.h":
                continue
            if target not in owner:
                problems.append(f"{path}:{number}: includes \"{target}\", which is not a header of common/ "
                                "(stage, test and tool code sit above common/)")
                continue
            if owner[target] not in allowed:
                if name in STRICTER:
                    rule = f" ({path.name} may include only {', '.join(sorted(allowed))})"
                else:
                    rule = f", a layer {layer} may not include"
                problems.append(f"{path}:{number}: includes \"{target}\" of {owner[target]}{rule}")
            other = pathlib.PurePath(target).stem
            if other != unit:
                graph.setdefault(unit, set()).add(other)
    return verdict(problems, graph, f"{len(files)} files in the layers of {common}", "layers respected, no cycle")


if __name__ == "__main__":
    sys.exit(main())
