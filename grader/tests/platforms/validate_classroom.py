#!/usr/bin/env python3
"""Validates a GitHub Classroom grading reporter result (education/autograding-grading-reporter reads
it, base64-encoded, from one step output): version 1, status pass|fail|error, max_score > 0, tests
with name, status and score, the tests' scores adding up to at most max_score, and the base64 file
decoding to the same JSON within the 128 KiB Linux allows one environment variable (the reporter
gets it as <RUNNER>_RESULTS).

  validate_classroom.py RESULT_JSON [RESULT_B64]   prints every fault; exit 0 when there is none
validate(data, raw, b64) is used by check_platforms.py."""
import base64
import binascii
import json
import sys

from validate_common import check_strings, each_test, is_number

ENV_LIMIT = 131072 - len("GRADE_RESULTS=") - 1  # MAX_ARG_STRLEN: one "NAME=value" string, with its NUL
TOP = {"version", "status", "max_score", "tests"}
TEST = {"name", "status", "score", "message", "test_code", "filename", "line_no", "execution_time"}
STATUS = {"pass", "fail", "error"}
EPSILON = 0.005


def validate(data, raw, b64=None):
    errors = []
    if not isinstance(data, dict):
        return ["not a JSON object"]
    for key in data.keys() - TOP:
        errors.append(f"unknown top-level field '{key}'")
    if data.get("version") != 1:
        errors.append(f"version {data.get('version')!r} is not 1")
    if data.get("status") not in STATUS:
        errors.append(f"status {data.get('status')!r} is not one of {sorted(STATUS)}")
    most = data.get("max_score")
    if not (is_number(most) and most > 0):
        errors.append(f"max_score {most!r} is not a number > 0")
    tests = data.get("tests")
    if not isinstance(tests, list) or not tests:
        return errors + ["tests is not a non-empty list"]
    total = 0.0
    for where, test in each_test(tests, TEST, errors):
        if not isinstance(test.get("name"), str) or not test.get("name"):
            errors.append(f"{where}: no name")
        if test.get("status") not in STATUS:
            errors.append(f"{where}.status {test.get('status')!r} is not one of {sorted(STATUS)}")
        score = test.get("score")
        if not (is_number(score) and score >= 0):
            errors.append(f"{where}.score {score!r} is not a number >= 0")
        else:
            total += score
        check_strings(test, ("message", "test_code", "filename", "execution_time"), where + ".", errors)
        if "line_no" in test and not (isinstance(test["line_no"], int) and not isinstance(test["line_no"], bool)):
            errors.append(f"{where}.line_no is not an integer")
    if is_number(most) and total > most + EPSILON:
        errors.append(f"the tests' scores add up to {total:.2f}, over max_score {most}")
    if data.get("status") == "pass" and any(isinstance(t, dict) and t.get("status") != "pass" for t in tests):
        errors.append("status pass with a test that did not pass")
    if b64 is not None:
        text = b64.strip()
        if len(text) > ENV_LIMIT:
            errors.append(f"the base64 is {len(text)} bytes, over the {ENV_LIMIT} one environment variable holds")
        try:
            if json.loads(base64.b64decode(text, validate=True).decode("utf-8")) != data:
                errors.append("the base64 file does not decode to the same JSON")
        except (binascii.Error, ValueError) as error:
            errors.append(f"the base64 file does not decode: {error}")
    return errors


def main():
    if len(sys.argv) not in (2, 3):
        print(__doc__, file=sys.stderr)
        return 2
    try:
        with open(sys.argv[1], "rb") as f:
            raw = f.read()
        b64 = None
        if len(sys.argv) == 3:
            with open(sys.argv[2], "rb") as f:
                b64 = f.read()
        errors = validate(json.loads(raw.decode("utf-8")), raw, b64)
    except (OSError, ValueError) as error:
        errors = [str(error)]
    for error in errors:
        print(f"{sys.argv[1]}: {error}")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
