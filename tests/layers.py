#!/usr/bin/env python3
"""Checks the layering of common/: stages -> services in common/ -> GL and platform.

usage: layers.py INCLUDE_DIR

Every `#include "..."` of a header in INCLUDE_DIR/t10/ must name another header of that folder
(`t10/...`) or the glad loader (`glad/gl.h`): never stage code, a test's or a tool's header
(`reference.hpp`, `compare.hpp`, `../../tests/...`). Headers of the core library (t10_common) must
not include the Dear ImGui host of t10_panel (`t10/imgui_host.hpp`), which only extras links.
System headers (`<...>`) are not checked. Prints each offending include with its file and line and
exits 1 if there is any.
"""
import pathlib
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')
# Headers of the t10_panel library (a layer above t10_common: it needs Dear ImGui).
PANEL_HEADERS = {"t10/imgui_host.hpp"}


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    root = pathlib.Path(sys.argv[1])
    headers = sorted((root / "t10").glob("*.hpp"))
    if not headers:
        print(f"{root}/t10: no headers found")
        return 1
    own = {f"t10/{h.name}" for h in headers}
    problems = []
    for header in headers:
        name = f"t10/{header.name}"
        for number, line in enumerate(header.read_text().splitlines(), 1):
            match = INCLUDE.match(line)
            if not match:
                continue
            target = match.group(1)
            if target == "glad/gl.h":
                continue
            if target not in own:
                problems.append(f"{header}:{number}: includes \"{target}\", which is not a header of common/ "
                                "(stage, test and tool code sit above common/)")
            elif target in PANEL_HEADERS and name not in PANEL_HEADERS:
                problems.append(f"{header}:{number}: includes \"{target}\" of t10_panel (Dear ImGui), a layer "
                                "above t10_common")
    for problem in problems:
        print(problem)
    print(f"{len(headers)} headers of {root}/t10: " + ("layers respected" if not problems
                                                       else f"{len(problems)} includes from a higher layer"))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
