#!/usr/bin/env python3
"""Validates a PrairieLearn external grader results.json against PrairieLearn's documented schema:
score in [0, 1] (required when gradable), gradable a boolean, format_errors a string or a list of
strings when not gradable, images as {label, url} with a base64 data URI, tests with name,
description, points <= max_points, message and output; and the whole file within 1 MB.

  validate_prairielearn.py RESULTS_JSON...   prints every fault; exit 0 when there is none, 1 otherwise
validate(data, raw) is used by check_platforms.py."""
import base64
import binascii
import re
import sys

from validate_common import check_strings, each_test, is_number, main

LIMIT = 1000 * 1000  # PrairieLearn rejects results over 1 MB; the decimal megabyte is the safe reading
TOP = {"gradable", "score", "format_errors", "message", "output", "images", "tests", "succeeded"}
TEST = {"name", "description", "points", "max_points", "message", "output", "images"}
DATA_URI = re.compile(r"^data:image/(png|jpeg|gif|svg\+xml);base64,([A-Za-z0-9+/]*={0,2})$")
EPSILON = 0.005


def check_images(images, where, errors):
    if not isinstance(images, list):
        errors.append(f"{where} is not a list")
        return
    for i, image in enumerate(images):
        url = image if isinstance(image, str) else image.get("url") if isinstance(image, dict) else None
        if isinstance(image, dict):
            if image.keys() - {"label", "url"}:
                errors.append(f"{where}[{i}]: unknown fields {sorted(image.keys() - {'label', 'url'})}")
            if "label" in image and not isinstance(image["label"], str):
                errors.append(f"{where}[{i}].label is not a string")
        match = DATA_URI.match(url) if isinstance(url, str) else None
        if not match:
            errors.append(f"{where}[{i}]: url is not a base64 image data URI")
            continue
        try:
            payload = base64.b64decode(match.group(2), validate=True)
        except binascii.Error as error:
            errors.append(f"{where}[{i}]: bad base64 ({error})")
            continue
        if match.group(1) == "png" and not payload.startswith(b"\x89PNG\r\n\x1a\n"):
            errors.append(f"{where}[{i}]: the data is not a PNG")


def validate(data, raw):
    errors = []
    if len(raw) > LIMIT:
        errors.append(f"{len(raw)} bytes, over PrairieLearn's {LIMIT}")
    if not isinstance(data, dict):
        return errors + ["not a JSON object"]
    for key in data.keys() - TOP:
        errors.append(f"unknown top-level field '{key}'")
    gradable = data.get("gradable", True)
    if not isinstance(gradable, bool):
        errors.append(f"gradable {gradable!r} is not a boolean")
    if gradable is not False or "score" in data:
        if "score" not in data:
            errors.append("no score (required when gradable)")
        elif not (is_number(data["score"]) and 0.0 <= data["score"] <= 1.0):
            errors.append(f"score {data['score']!r} is not a number in [0, 1]")
    if gradable is False:
        fe = data.get("format_errors")
        if not (isinstance(fe, str) and fe) and not (isinstance(fe, list) and fe and all(isinstance(x, str) for x in fe)):
            errors.append("not gradable, but format_errors is not a string or a list of strings saying why")
    check_strings(data, ("message", "output"), "", errors)
    if "images" in data:
        check_images(data["images"], "images", errors)
    tests = data.get("tests", [])
    if not isinstance(tests, list):
        return errors + ["tests is not a list"]
    for where, test in each_test(tests, TEST, errors):
        check_strings(test, ("name", "description", "message", "output"), where + ".", errors)
        if not test.get("name"):
            errors.append(f"{where}: no name")
        points, most = test.get("points"), test.get("max_points")
        if "max_points" in test and not (is_number(most) and most >= 0):
            errors.append(f"{where}.max_points {most!r} is not a number >= 0")
        if "points" in test and not (is_number(points) and points >= 0):
            errors.append(f"{where}.points {points!r} is not a number >= 0")
        if is_number(points) and is_number(most) and points > most + EPSILON:
            errors.append(f"{where}: points {points} over max_points {most}")
        if "images" in test:
            check_images(test["images"], f"{where}.images", errors)
    return errors


if __name__ == "__main__":
    sys.exit(main(validate, __doc__))
