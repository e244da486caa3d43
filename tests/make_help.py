#!/usr/bin/env python3
"""Checks that `make help` names every target: each rule of the Makefile (but the helpers other
rules use, listed below) and each `make NAME` the README shows in code.

usage: make_help.py SOURCE_DIR
Prints what is missing and exits 1 if anything is.
"""
import pathlib
import re
import subprocess
import sys

# Rules that only other rules use: not for a person to type.
HELPERS = {"grade-args", "grade-deps-or-skip", "check-args", "platform-part", "run-stage"}


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    root = pathlib.Path(sys.argv[1])
    makefile = (root / "Makefile").read_text()
    targets = set()
    for line in makefile.splitlines():
        match = re.match(r"^([a-z][a-z0-9-]*):(?!=)", line)
        if match:
            targets.add(match.group(1))
    readme = (root / "README.md").read_text()
    named = set(re.findall(r"`make ([a-z][a-z0-9-]*)", readme))
    help_text = subprocess.run(["make", "-s", "-C", str(root), "help"], capture_output=True, text=True, check=True).stdout
    listed = set(re.findall(r"\bmake ([a-z][a-z0-9-]*)", help_text))
    missing = sorted((targets - HELPERS - listed) | (named - listed))
    for name in missing:
        where = "the Makefile" if name in targets else "README.md"
        print(f"make help does not list `make {name}` ({where} names it)")
    unknown = sorted(named - targets)
    for name in unknown:
        print(f"README.md names `make {name}`, which the Makefile does not have")
    if missing or unknown:
        return 1
    print(f"ok: make help lists all {len(targets - HELPERS)} targets the Makefile and README.md name")
    return 0


if __name__ == "__main__":
    sys.exit(main())
