"""What the platform validators (validate_gradescope.py, validate_prairielearn.py,
validate_classroom.py) share: the number test, the walk over a result's tests and the command line
that validates files one by one. Each validator keeps its own platform's rules."""
import json
import sys


def is_number(value):
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def check_strings(obj, keys, where, errors):
    """Each of `keys` that `obj` has must be a string ("tests[0].name is not a string")."""
    for key in keys:
        if key in obj and not isinstance(obj[key], str):
            errors.append(f"{where}{key} is not a string")


def each_test(tests, fields, errors):
    """Yields (where, test) for each test that is an object, after naming the ones that are not and
    every field a test has beyond `fields`."""
    for i, test in enumerate(tests):
        where = f"tests[{i}]"
        if not isinstance(test, dict):
            errors.append(f"{where} is not an object")
            continue
        for key in test.keys() - fields:
            errors.append(f"{where}: unknown field '{key}'")
        yield where, test


def main(validate, doc):
    """validate_X.py RESULTS_JSON...: prints every fault of each file as 'FILE: fault'; exit 0 when
    there is none, 1 otherwise, 2 without a file."""
    if len(sys.argv) < 2:
        print(doc, file=sys.stderr)
        return 2
    bad = 0
    for path in sys.argv[1:]:
        try:
            with open(path, "rb") as f:
                raw = f.read()
            errors = validate(json.loads(raw.decode("utf-8")), raw)
        except (OSError, ValueError) as error:
            errors = [str(error)]
        for error in errors:
            print(f"{path}: {error}")
        bad += bool(errors)
    return 1 if bad else 0
