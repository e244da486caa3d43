#!/usr/bin/env python3
"""The steps of a Dockerfile, for make devcontainer-check to run in a Debian root without Docker.

usage: dockerfile_steps.py DOCKERFILE
Writes one record per instruction to stdout, each field ended by a NUL byte: the instruction, then its
argument with the Dockerfile's ARG and ENV values substituted where Docker substitutes them (FROM,
COPY, ENV, USER, WORKDIR; RUN is left to its shell, which gets ARG and ENV as its environment):
  FROM image | ARG name=value | ENV name=value (one record per pair) | COPY source dest (two fields) |
  RUN command | USER name | WORKDIR path | CMD json
Only these instructions are known: any other one (ADD, ENTRYPOINT, COPY --from, RUN --mount...) exits
1 naming its line, so that the check never skips a step it cannot run."""
import json
import re
import shlex
import sys

KNOWN = {"FROM", "ARG", "ENV", "COPY", "RUN", "USER", "WORKDIR", "CMD"}


def instructions(text):
    """(line number, instruction, argument): continuation lines joined, comments and blanks dropped."""
    out, pending, first = [], "", 0
    for number, line in enumerate(text.splitlines(), 1):
        stripped = line.strip()
        if not pending and (not stripped or stripped.startswith("#")):
            continue
        if pending and stripped.startswith("#"):
            continue  # a comment inside a continued instruction is dropped, as Docker does
        if not pending:
            first = number
        if line.rstrip().endswith("\\"):
            pending += line.rstrip()[:-1] + " "
            continue
        whole = (pending + line).strip()
        pending = ""
        word, _, rest = whole.partition(" ")
        out.append((first, word.upper(), rest.strip()))
    if pending:
        raise ValueError(f"line {first}: the instruction ends in a line continuation")
    return out


def substitute(text, values, number):
    def value(match):
        name = match.group(1) or match.group(2)
        if name not in values:
            raise ValueError(f"line {number}: ${name} is neither an ARG nor an ENV")
        return values[name]
    return re.sub(r"\$\{(\w+)\}|\$(\w+)", value, text)


def steps(text):
    values, out = {}, []
    for number, word, rest in instructions(text):
        if word not in KNOWN:
            raise ValueError(f"line {number}: {word}: this check does not run that instruction")
        if word in ("COPY", "RUN") and rest.startswith("--"):
            raise ValueError(f"line {number}: {word} {rest.split()[0]}: this check does not run that option")
        if word == "ARG":
            name, _, default = rest.partition("=")
            values[name] = default
            out.append((word, f"{name}={default}"))
        elif word == "ENV":
            pairs = shlex.split(substitute(rest, values, number))
            if not pairs or any("=" not in pair for pair in pairs):
                raise ValueError(f"line {number}: ENV: write name=value pairs")
            for pair in pairs:
                name, _, value = pair.partition("=")
                values[name] = value
                out.append((word, pair))
        elif word == "COPY":
            parts = shlex.split(substitute(rest, values, number))
            if len(parts) != 2:
                raise ValueError(f"line {number}: COPY: one source and one destination")
            out.append((word, parts[0] + "\0" + parts[1]))
        elif word == "CMD":
            json.loads(rest)  # the exec form only
            out.append((word, rest))
        elif word == "RUN":
            out.append((word, rest))
        else:
            out.append((word, substitute(rest, values, number)))
    return out


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    path = sys.argv[1]
    try:
        with open(path, encoding="utf-8") as handle:
            records = steps(handle.read())
    except OSError as error:
        print(f"dockerfile_steps: {path}: {error.strerror}", file=sys.stderr)
        return 1
    except (ValueError, json.JSONDecodeError) as error:
        print(f"dockerfile_steps: {path}: {error}", file=sys.stderr)
        return 1
    for word, argument in records:
        sys.stdout.write(f"{word}\0{argument}\0")
    return 0


if __name__ == "__main__":
    sys.exit(main())
