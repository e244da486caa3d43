#!/usr/bin/env python3
"""The short summary `make check` prints from t10-grade's report.json: the score, what to fix first
(the step t10-grade names in fix_first, else the failing check with the earliest tutorial step) with
its tutorial link, what was measured and what was expected, the views that show that buffer, and
where the full report is.

usage: summary.py REPORT.json [--site-url URL]

Reads only what report.json has today (status, score, message, checks[] with id, passed, steps,
measured, tolerance, diagnosis) and prefers, where a newer grader writes them, `fix_first`,
`summary`, per-step entries in `steps` and `mistakes` with their estimates. A field that is missing
or of an unexpected shape is passed over, never a crash. One line per fact: the grader's `summary` and
`fix_first` repeat the failed check's diagnosis and are shown only where they add to it; estimates
give the tutorial's value as the grader has it (0.2126, not 0.213) and the student's to the same
number of decimals. Exit 0 only for status graded at score 100;
1 otherwise; 2 when the report cannot be read.
"""
import argparse
import json
import os
import re
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree

# Where the built site (make site) puts the tutorial page; make site-serve serves it at this address.
SITE_PAGE = "tutorial10.html"
DEFAULT_SITE_URL = "http://127.0.0.1:4000/"

# The views (--view) that show the buffer a check looks at, by what the check id ends with.
VIEWS = [
    ("luminance", "luminance, key"),
    ("key", "key, luminance"),
    ("bloom-threshold", "bloom0, hdr"),
    ("bloom-downsample", "bloom1, bloom0"),
    ("blur", "blur, bloom1"),
    ("frame", "final, ev, key"),
    ("flip", "final, ev"),
    ("buffers", "nan, hdr"),
]


def text(value):
    """A printable string from a field that should be text, or '' for anything else."""
    if isinstance(value, str):
        return value.strip()
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return str(value)
    return ""


def step_numbers(steps):
    """Step numbers from `steps`: plain numbers today, or entries like {"step": 9, ...} later."""
    numbers = []
    if isinstance(steps, list):
        for s in steps:
            if isinstance(s, bool):
                continue
            if isinstance(s, int):
                numbers.append(s)
            elif isinstance(s, dict) and isinstance(s.get("step"), int):
                numbers.append(s["step"])
    return numbers


def failed_step_entries(steps):
    """Per-step entries a newer grader may write ({"step": N, "passed": false, ...}): the failed ones."""
    if not isinstance(steps, list):
        return []
    return [s["step"] for s in steps
            if isinstance(s, dict) and isinstance(s.get("step"), int) and s.get("passed") is False]


def span(numbers):
    if not numbers:
        return ""
    numbers = sorted(set(numbers))
    if numbers == list(range(numbers[0], numbers[-1] + 1)) and len(numbers) > 2:
        return f"steps {numbers[0]}-{numbers[-1]}"
    return ("step " if len(numbers) == 1 else "steps ") + ", ".join(str(n) for n in numbers)


def link(step, site_url):
    anchor = f"{SITE_PAGE}#step-{step}"
    return f"{site_url.rstrip('/')}/{anchor} (make site-serve; or build/site/{anchor} after make site)"


def views_for(check_id):
    for suffix, views in VIEWS:
        if check_id.split(".")[-1].startswith(suffix):
            return views
    return ""


def plural(words):
    """'luminance weights' and 'blur passes' are plural, 'white point' and 'blur sigma' are not."""
    last = words.split()[-1] if words.split() else ""
    return last.endswith("s") and not last.endswith("ss")


def decimals(number):
    """How many decimals `number` is written with (0.2126 -> 4, 2.5 -> 1, 5 -> 0); None for 1e-08."""
    written = repr(number) if isinstance(number, float) else str(number)
    if "e" in written or "E" in written:
        return None
    return len(written.split(".")[1]) if "." in written else 0


def written(value, like=None):
    """A value (a number or a list of them) as text: the tutorial's as it is written, the student's to
    the same precision as the tutorial's value at the same place (`like`)."""
    if isinstance(value, list):
        likes = like if isinstance(like, list) and len(like) == len(value) else [None] * len(value)
        parts = [written(v, l) for v, l in zip(value, likes)]
        return "(" + ", ".join(parts) + ")" if all(parts) else ""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return text(value)
    if like is None or isinstance(like, bool) or not isinstance(like, (int, float)):
        return f"{value:g}" if isinstance(value, float) else str(value)
    places = decimals(like)
    if places is None:  # written with an exponent (1e-08): three significant digits, as the grader writes
        return f"{value:.3g}"
    return f"{value:.{places}f}"


def estimates(check):
    """Lines like 'your white point measures 0.25; the tutorial's is 0.22' from `mistakes`."""
    lines = []
    mistakes = check.get("mistakes")
    if not isinstance(mistakes, list):
        return lines
    for m in mistakes:
        if not isinstance(m, dict):
            continue
        estimate = m.get("estimate")
        if isinstance(estimate, dict) and text(estimate.get("parameter")):
            tutorial = estimate.get("tutorial")
            value = written(estimate.get("value"), tutorial)
            if not value:
                continue
            words = text(estimate["parameter"]).replace("_", " ")
            many = plural(words)
            line = f"your {words} {'measure' if many else 'measures'} {value}"
            if written(tutorial):
                line += f"; the tutorial's {'are' if many else 'is'} {written(tutorial)}"
            lines.append(line)
        elif text(m.get("id")):
            lines.append(f"likely mistake: {text(m['id'])}")
    return lines


def whole_part(numbers):
    """A check that covers every step of its part (1-16, 1-25, 1-36: the frame against the reference,
    buffers that are missing) says that something is wrong, not where."""
    return len(numbers) >= 16 and sorted(set(numbers)) == list(range(1, max(numbers) + 1))


def first_to_fix(checks):
    """The failed check to fix first: the one whose earliest step comes first in the tutorial (a later
    check usually follows from it), checks that cover the whole part after those that name steps; report
    order breaks ties."""
    failed = [c for c in checks if isinstance(c, dict) and c.get("passed") is not True]
    if not failed:
        return None, []
    def key(item):
        index, c = item
        numbers = failed_step_entries(c.get("steps")) or step_numbers(c.get("steps"))
        return (whole_part(numbers), min(numbers) if numbers else 10**6, index)
    ordered = [c for _, c in sorted(enumerate(failed), key=key)]
    return ordered[0], ordered[1:]


def summarize(report, report_path, site_url=DEFAULT_SITE_URL):
    """Returns (lines, passed)."""
    out = []
    name = text(report.get("path")) or text(report.get("submission")) or "the submission"
    part = text(report.get("part")) or "?"
    status = text(report.get("status")) or "unknown"
    score = report.get("score")
    score = score if isinstance(score, int) and not isinstance(score, bool) else None
    checks = report.get("checks") if isinstance(report.get("checks"), list) else []
    passed_count = sum(1 for c in checks if isinstance(c, dict) and c.get("passed") is True)
    passed = status == "graded" and score == 100

    head = f"{name}: Part {part}, score {score if score is not None else '?'}/100"
    if checks:
        head += f" ({passed_count} of {len(checks)} checks passed)"
    if status != "graded":
        head += f", status {status}"
    out.append(head)

    # The grader's own one-line summary repeats the score and what to fix first, which the lines below
    # say once each: it is shown only when it says something else.
    overall = text(report.get("summary"))
    if overall and "fix first" not in overall.lower() and not overall.lower().startswith("score"):
        out.append(overall)
    message = text(report.get("message"))
    if status != "graded":
        meaning = {
            "build-failed": "Tutorial10.cpp does not build: fix the first compiler error (file:line) below.",
            "shader-error": "a shader does not compile or link: the driver's message (file and line) is below.",
            "crashed": "the program crashed or wrote no frame; its last output is below.",
            "timeout": "the program did not finish a frame in time (a loop that never ends?).",
            "empty": "none of this part's files is in the folder (check the file names and their case).",
        }.get(status, "")
        if meaning:
            out.append(meaning)
        if message:
            out.extend("  " + line for line in message.splitlines()[-25:])
    elif not passed:
        fix_first = report.get("fix_first")
        check, others = first_to_fix(checks)
        step = None
        wanted = ""
        if isinstance(fix_first, dict):
            step = fix_first.get("step") if isinstance(fix_first.get("step"), int) else None
            wanted = text(fix_first.get("check"))
        elif isinstance(fix_first, str):
            # t10-grade's own choice, "fix first: step 20 - pot.frame: ...": the earliest step a failed
            # check blames (not the check's first step), the same step GitHub Classroom's log marks.
            chosen = re.match(r"fix first: step (\d+) - ([^:\s]+):", fix_first)
            if chosen:
                step, wanted = int(chosen.group(1)), chosen.group(2)
        if wanted:
            named = [c for c in ([check] + others if check is not None else others) if text(c.get("id")) == wanted]
            if named:
                others = [o for o in [check] + others if o is not named[0]]
                check = named[0]
        if check is not None:
            numbers = failed_step_entries(check.get("steps")) or step_numbers(check.get("steps"))
            if step is None and numbers:
                step = min(numbers)
            cid = text(check.get("id")) or "(unnamed check)"
            where = span(numbers)
            first = f"Fix first: step {step}" if step is not None else "Fix first"
            out.append(f"{first}: check {cid}" + (f" ({where})" if where else ""))
            # One line per fact: the diagnosis once; the grader's fix-first text only where it adds to it.
            diagnosis = text(check.get("diagnosis"))
            if diagnosis:
                out.append(f"  what:     {diagnosis}")
            note = fix_first if isinstance(fix_first, str) else (
                fix_first.get("text") or fix_first.get("message") if isinstance(fix_first, dict) else "")
            note = text(note)
            if note.lower().startswith("fix first:"):
                note = note[len("fix first:"):].strip()
            if note and (not diagnosis or diagnosis not in note):
                out.append(f"  {'note' if diagnosis else 'what'}:     {note}")
            if text(check.get("measured")):
                out.append(f"  measured: {text(check['measured'])}")
            if text(check.get("tolerance")):
                out.append(f"  expected: {text(check['tolerance'])}")
            for line in estimates(check):
                if line.split(";")[0] not in diagnosis:
                    out.append(f"  {line}")
            if step is not None:
                out.append(f"  tutorial: {link(step, site_url)}")
            views = views_for(cid)
            if views:
                out.append(f"  look at:  --view {views} (V in the window of make run STAGE=student_part{part})")
        if others:
            ids = [text(c.get("id")) for c in others if text(c.get("id"))]
            shown = ", ".join(ids[:6]) + (f" and {len(ids) - 6} more" if len(ids) > 6 else "")
            out.append(f"Also failing: {shown}")
    else:
        out.append("Every check passed: this part matches the reference.")

    folder = os.path.dirname(report_path)
    html = os.path.join(folder, "report.html")
    full = html if os.path.isfile(html) else report_path
    out.append(f"Full report: {full}")
    return out, passed


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("report")
    ap.add_argument("--site-url", default=DEFAULT_SITE_URL)
    args = ap.parse_args()
    try:
        with open(args.report, encoding="utf-8") as f:
            report = json.load(f)
    except OSError as e:
        print(f"make check: {args.report}: cannot read: {e.strerror}", file=sys.stderr)
        return 2
    except ValueError as e:
        print(f"make check: {args.report}: not valid JSON: {e}", file=sys.stderr)
        return 2
    if not isinstance(report, dict):
        print(f"make check: {args.report}: not a grader report (no JSON object)", file=sys.stderr)
        return 2
    lines, passed = summarize(report, args.report, args.site_url)
    print("\n".join(lines))
    return 0 if passed else 1


if __name__ == "__main__":
    sys.exit(main())
