#!/usr/bin/env python3
"""Checks .devcontainer/devcontainer.json against the dev container specification's base schema
(tests/fixtures/devcontainer-spec/devContainer.base.schema.json, JSON Schema 2019-09, validated
offline with Debian's python3-jsonschema), and that it is what issue 37 asks for: built from the
Dockerfile beside it, port 6080 forwarded and labelled, a user other than root, the project built on
creation and the desktop started.

devcontainer.json is JSON with comments (// and /* */; the schema says "allowComments": true and
"allowTrailingCommas": false): they are removed outside strings only, so "http://x" stays whole.

  devcontainer_schema.py SCHEMA DEVCONTAINER_JSON              every fault; exit 0 when there is none
  devcontainer_schema.py --self-test SCHEMA DEVCONTAINER_JSON  breaks copies in known ways; exit 0 only
                                                               when every broken copy is rejected
Exit 77 (skipped) when jsonschema is not installed (make test installs python3-jsonschema)."""
import copy
import json
import sys

try:
    import jsonschema
except ImportError:
    jsonschema = None


def strip_comments(text):
    """The text with // and /* */ comments replaced by spaces (newlines kept), strings untouched.
    An unterminated block comment or string raises ValueError."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if c == '"':
            j = i + 1
            while j < n and text[j] != '"':
                j += 2 if text[j] == "\\" else 1
            if j >= n:
                raise ValueError("a string is not closed")
            out.append(text[i:j + 1])
            i = j + 1
        elif text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            if j < 0:
                raise ValueError("a /* comment is not closed")
            out.append("".join(ch if ch == "\n" else " " for ch in text[i:j + 2]))
            i = j + 2
        else:
            out.append(c)
            i += 1
    return "".join(out)


def load_jsonc(text):
    return json.loads(strip_comments(text))


def project_faults(config):
    """What this project needs of its devcontainer.json beyond the schema."""
    faults = []
    build = config.get("build", {})
    if build.get("dockerfile") != "Dockerfile" or build.get("context") != "..":
        faults.append('build: not {"dockerfile": "Dockerfile", "context": ".."} (the image reads the Makefile)')
    ports = config.get("forwardPorts", [])
    if not isinstance(ports, list) or 6080 not in ports:
        faults.append("forwardPorts: 6080 (noVNC) is not forwarded")
    attributes = config.get("portsAttributes", {}).get("6080", {})
    if not isinstance(attributes, dict) or not attributes.get("label"):
        faults.append("portsAttributes: port 6080 has no label")
    for key in ("remoteUser", "containerUser"):
        if config.get(key) in (None, "root"):
            faults.append(f"{key}: the container's user must not be root")
    if "make" not in str(config.get("postCreateCommand", "")):
        faults.append("postCreateCommand: does not build the project")
    if "t10-desktop" not in str(config.get("postStartCommand", "")):
        faults.append("postStartCommand: does not start the desktop (t10-desktop)")
    return faults


def faults_of(schema, text):
    try:
        config = load_jsonc(text)
    except ValueError as error:  # json.JSONDecodeError is a ValueError
        return [f"not JSON with comments: {error}"]
    errors = list(jsonschema.Draft201909Validator(schema).iter_errors(config))
    faults = []
    if errors:
        # The file is a oneOf of container kinds, and a property failing there leaves it "unevaluated"
        # at the top: the deepest error of any branch says what is wrong.
        def leaves(error):
            return [leaf for child in error.context for leaf in leaves(child)] if error.context else [error]
        found = [leaf for error in errors for leaf in leaves(error)]
        best = max(found, key=lambda e: (e.validator != "unevaluatedProperties", len(e.absolute_path)))
        message = best.message if len(best.message) <= 160 else best.message[:157] + "..."
        faults.append(f"schema: {'/'.join(str(p) for p in best.absolute_path) or '(top)'}: {message}")
    if isinstance(config, dict):
        faults += project_faults(config)
    return faults


def broken_copies(text):
    """(what is broken, the kind of fault that must reject it, the broken text)."""
    config = load_jsonc(text)
    out = []

    def broken(what, kind, change):
        copied = copy.deepcopy(config)
        change(copied)
        out.append((what, kind, json.dumps(copied, indent=4)))

    # The schema's own rules: each of these passes the project's checks, so only the schema rejects it.
    broken("forwardPorts a string, not an array", "schema", lambda c: c.update(forwardPorts="6080"))
    broken('a forwardPorts entry "6080/tcp" (neither a number nor host:port)', "schema",
           lambda c: c.update(forwardPorts=[6080, "6080/tcp"]))
    broken("a port number above 65535", "schema", lambda c: c.update(forwardPorts=[6080, 65536]))
    broken('portsAttributes onAutoForward "popup"', "schema",
           lambda c: c["portsAttributes"]["6080"].update(onAutoForward="popup"))
    broken("portsAttributes 6080 a string, not an object", "schema", lambda c: c["portsAttributes"].update({"5901": "VNC"}))
    broken("an unknown top-level property", "schema", lambda c: c.update(forwardedPorts=[6080]))
    broken("remoteUser a number", "schema", lambda c: c.update(remoteUser=1000))
    broken("both build and image", "schema", lambda c: c.update(image="debian:bookworm"))
    broken("securityOpt a string", "schema", lambda c: c.update(securityOpt="seccomp=unconfined"))
    broken("hostRequirements cpus a string", "schema", lambda c: c["hostRequirements"].update(cpus="two"))
    # The project's: valid for the schema, wrong for this repository.
    broken("the container's user root", "project", lambda c: c.update(remoteUser="root", containerUser="root"))
    broken("port 6080 not forwarded", "project", lambda c: c.update(forwardPorts=[5901]))
    broken("port 6080 without a label", "project", lambda c: c["portsAttributes"]["6080"].pop("label"))
    broken("the desktop not started", "project", lambda c: c.pop("postStartCommand"))
    # Comments and commas: a trailing comma (the schema allows none), an unclosed block comment.
    out.append(("a trailing comma", "parse", text.rstrip().rstrip("}").rstrip() + ",\n}\n"))
    out.append(("an unclosed /* comment", "parse", text + "\n/* not closed\n"))
    return out


def self_test(schema, text):
    good = faults_of(schema, text)
    if good:
        print("devcontainer_schema: the file itself fails, so the self-test proves nothing:", *good, sep="\n  ")
        return 1
    # The comment stripper keeps strings whole and removes every comment form.
    sample = '{"a": "http://x/*y*/", // c\n "b": /* d\n e */ "\\"//\\""}'
    if load_jsonc(sample) != {"a": "http://x/*y*/", "b": '"//"'}:
        print("devcontainer_schema: the comment stripper changes strings or keeps comments")
        return 1
    accepted = []
    copies = broken_copies(text)
    prefixes = {"schema": "schema: ", "parse": "not JSON with comments: "}
    for what, kind, broken in copies:
        faults = faults_of(schema, broken)
        # Each copy must be rejected by the rule it breaks: the schema's, the parser's or the project's.
        mine = [f for f in faults if f.startswith(prefixes[kind])] if kind in prefixes else \
               [f for f in faults if not any(f.startswith(p) for p in prefixes.values())]
        if mine:
            print(f"rejected ({what}): {mine[0]}")
        else:
            accepted.append(f"{what}: no {kind} fault; got {faults or 'none'}")
    if accepted:
        print("devcontainer_schema: broken copies accepted:", *accepted, sep="\n  ")
        return 1
    print(f"ok: every one of {len(copies)} broken copies is rejected by the rule it breaks")
    return 0


def main(argv):
    test = argv[:1] == ["--self-test"]
    if test:
        argv = argv[1:]
    if len(argv) != 2:
        print(__doc__)
        return 2
    if jsonschema is None:
        print("SKIP: python3-jsonschema is not installed (make test installs it)")
        return 77
    schema_path, config_path = argv
    try:
        with open(schema_path, encoding="utf-8") as handle:
            schema = json.load(handle)
        with open(config_path, encoding="utf-8") as handle:
            text = handle.read()
    except OSError as error:
        print(f"devcontainer_schema: {error.filename}: {error.strerror}")
        return 1
    if test:
        return self_test(schema, text)
    faults = faults_of(schema, text)
    for fault in faults:
        print(f"{config_path}: {fault}")
    if faults:
        return 1
    print(f"ok: {config_path} matches the dev container specification's base schema")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
