#!/usr/bin/env python3
"""Validates a Gradescope autograder results.json against the contract of Gradescope's autograder
specification: the known top-level and test fields, their types, the enumerations of output_format,
visibility and status, scores within [0, max_score], and the size limit we hold it to. An output in
HTML may show images only inline: every <img> a data URI whose bytes are a JPEG or PNG.

  validate_gradescope.py RESULTS_JSON...     prints every fault; exit 0 when there is none, 1 otherwise
validate(data, raw) is used by check_platforms.py."""
import base64
import binascii
import re
import sys

from validate_common import check_strings, each_test, is_number, main

FORMATS = {"text", "html", "simple_format", "md", "ansi"}
VISIBILITY = {"hidden", "after_due_date", "after_published", "visible"}
TOP = {"score", "execution_time", "output", "output_format", "test_output_format", "test_name_format", "visibility",
       "stdout_visibility", "extra_data", "tests", "leaderboard"}
TEST = {"score", "max_score", "status", "name", "name_format", "number", "output", "output_format", "tags",
        "visibility", "extra_data"}
# Gradescope states no size limit; a large result loads slowly on every student's page. The grader
# holds its results to 500 kB (platforms/formats.cpp, kGradescopeLimit), images included.
LIMIT = 500 * 1000
IMG = re.compile(r"<img\b[^>]*>", re.I)
SRC = re.compile(r"""\bsrc\s*=\s*["']([^"']*)["']""", re.I)
DATA = re.compile(r"data:image/(jpeg|png);base64,([A-Za-z0-9+/=]+)$")
MAGIC = {"jpeg": b"\xff\xd8\xff", "png": b"\x89PNG\r\n\x1a\n"}


def check_images(html, where, errors):
    """Every <img> of an HTML output: a data URI (no request leaves the student's page) of a JPEG or PNG."""
    for tag in IMG.findall(html):
        src = SRC.search(tag)
        data = DATA.match(src.group(1)) if src else None
        if not data:
            errors.append(f"{where}: an image that is not an inline JPEG or PNG: {tag[:120]!r}")
            continue
        try:
            raw = base64.b64decode(data.group(2), validate=True)
        except binascii.Error:
            errors.append(f"{where}: an image whose base64 does not decode: {tag[:120]!r}")
            continue
        if not raw.startswith(MAGIC[data.group(1)]):
            errors.append(f"{where}: an image whose bytes are not a {data.group(1).upper()}: {tag[:120]!r}")
EPSILON = 0.005  # points are written to 0.01


def validate(data, raw):
    errors = []
    if len(raw) > LIMIT:
        errors.append(f"{len(raw)} bytes, over {LIMIT}")
    if not isinstance(data, dict):
        return errors + ["not a JSON object"]
    for key in data.keys() - TOP:
        errors.append(f"unknown top-level field '{key}'")
    if "score" not in data and "tests" not in data:
        errors.append("neither 'score' nor 'tests'")
    if "score" in data and not (is_number(data["score"]) and data["score"] >= 0):
        errors.append(f"score {data['score']!r} is not a number >= 0")
    if "execution_time" in data and not (is_number(data["execution_time"]) and data["execution_time"] >= 0):
        errors.append(f"execution_time {data['execution_time']!r} is not a number >= 0")
    check_strings(data, ("output",), "", errors)
    if data.get("output_format") == "html" and isinstance(data.get("output"), str):
        check_images(data["output"], "output", errors)
    for key in ("output_format", "test_output_format"):
        if key in data and data[key] not in FORMATS:
            errors.append(f"{key} {data[key]!r} is not one of {sorted(FORMATS)}")
    for key in ("visibility", "stdout_visibility"):
        if key in data and data[key] not in VISIBILITY:
            errors.append(f"{key} {data[key]!r} is not one of {sorted(VISIBILITY)}")
    tests = data.get("tests", [])
    if not isinstance(tests, list):
        return errors + ["tests is not a list"]
    total_max = 0.0
    for where, test in each_test(tests, TEST, errors):
        check_strings(test, ("name", "output", "number"), where + ".", errors)
        if not test.get("name"):
            errors.append(f"{where}: no name")
        if test.get("output_format") == "html" and isinstance(test.get("output"), str):
            check_images(test["output"], where + ".output", errors)
        if "output_format" in test and test["output_format"] not in FORMATS:
            errors.append(f"{where}.output_format {test['output_format']!r} is not one of {sorted(FORMATS)}")
        if "visibility" in test and test["visibility"] not in VISIBILITY:
            errors.append(f"{where}.visibility {test['visibility']!r} is not one of {sorted(VISIBILITY)}")
        if "status" in test and test["status"] not in ("passed", "failed"):
            errors.append(f"{where}.status {test['status']!r} is not passed or failed")
        if "tags" in test and not (isinstance(test["tags"], list) and all(isinstance(t, str) for t in test["tags"])):
            errors.append(f"{where}.tags is not a list of strings")
        if "score" not in test and "status" not in test:
            errors.append(f"{where}: neither score nor status")
        if "score" in test and not (is_number(test["score"]) and test["score"] >= 0):
            errors.append(f"{where}.score {test['score']!r} is not a number >= 0")
        if "max_score" in test:
            if not (is_number(test["max_score"]) and test["max_score"] > 0):
                errors.append(f"{where}.max_score {test['max_score']!r} is not a number > 0")
            elif is_number(test.get("score")) and test["score"] > test["max_score"] + EPSILON:
                errors.append(f"{where}: score {test['score']} over max_score {test['max_score']}")
            else:
                total_max += test["max_score"]
    if is_number(data.get("score")) and tests and data["score"] > total_max + EPSILON:
        errors.append(f"score {data['score']} over the tests' total max_score {total_max}")
    return errors


if __name__ == "__main__":
    sys.exit(main(validate, __doc__))
