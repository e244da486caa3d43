#!/usr/bin/env python3
"""The page's workbench contract (common/platform/web/workbench.js) driven in headless Chromium.

usage: workbench_test.py --web OUT_WEB --out DIR --source ROOT --case STAGE [--case STAGE ...] [options]

Each --case is a stage page loaded once at the goldens' settings (web_test.py's GOLDEN_QUERY), in one
Chromium, and judged by the project's imgcompare against tests/golden/STAGE.png as web_test.py judges:
  1. Module.t10Shaders() lists the stage folder's .vert and .frag files with the repository's text.
  2. A syntax error on line L of PostProcess.frag (one the translator passes on, so WebGL's compiler
     finds it) is answered {ok: false} with line L, the line of the student's file. The file is sent
     with #version on line 1, where the translation puts its precisions and a `#line 2` on lines 2 and
     3 of its text, so the same error is on line L + 2 of the translated text: a page that reported
     the translated text's line fails here. The frame drawn before the edit stays: it still matches the golden.
  3. A character GLSL lacks on line L2 (the translator's own error) is answered with line L2 too.
  4. A wrong but valid edit (the white point Yw 1.0 instead of 0.22, step 9) is applied and redrawn:
     the frame must no longer match the golden (the edits reach the frame; the comparison can fail).
     The first case then runs Module.t10Check(): t10-grade's checks must fail the frame and name the
     white point with its value within 1 % of 1.0 (the check can fail; the value is measured).
  5. The reference's own files through Module.t10SetShader: the frame matches the golden again, and
     Module.t10Check() scores 100 with every check of t10-grade's camera cases (pot, npot) passed.
The first case also sends what must be refused, each with a clear message and the page still drawing:
a file the stage does not have, a source over the translator's bound, bytes that are not UTF-8, a
string with a lone surrogate, a source that is not text, loops the page cannot bound (a `while (true)`,
a while loop ANGLE compiles that never ends, and two nested loops of 100 inside main(): refused by
t10SetShader itself at their lines, so no caller can hang the tab; a page without the refusal answers
ANGLE's "Infinite loop detected", hangs on the second (measured: no reply within 60 s) or answers ok
on the third, and fails here), and
a program that compiles but does not link (the previous file is put back and the stage rebuilt with it).
After the cases, the last page's WebGL context is lost (WEBGL_lose_context.loseContext(), as when the
browser's GPU watchdog stops a shader): the page must go to "error" with dataset.t10Lost "lost" and its
status line (role=status) must say that WebGL stopped and to reload; t10SetShader, t10Check and t10Set
must answer at once with that message, a wheel notch must draw no frame (the loop stopped), and once the
context is restored (restoreContext()) the page must say so and its reload button must bring back a
frame. A page without the handling stays "rendered" or answers a compile error, and fails. Screenshot:
OUT/STAGE-context-lost.png.
Exit 0: passed; 1: failed (what and why on stderr); 77: no page or no Chromium, said why.
"""
import argparse
import json
import os
import shutil
import sys
import time

sys.dont_write_bytecode = True
import web_test  # noqa: E402  (beside this file: the page, the golden judgement, the query)
from web import cdp  # noqa: E402

Failure = cdp.Failure
EDITED = "PostProcess.frag"  # every part has it; its tone map is the frame's last pass
WHITE_POINT = ("const float fYwhite = 0.22f;", "const float fYwhite = 1.0f;")


def set_shader(page, file, source):
    """Module.t10SetShader(file, source) awaited; `source` is a str, or bytes sent as a Uint8Array."""
    if isinstance(source, (bytes, bytearray)):
        argument = f"new Uint8Array({json.dumps(list(source))})"
    else:
        argument = json.dumps(source)
    return page.evaluate(f"Module.t10SetShader({json.dumps(file)}, {argument})", await_promise=True)


def expect_error(answer, line, what):
    if not isinstance(answer, dict) or answer.get("ok") is not False or not answer.get("errors"):
        raise Failure(f"{what}: expected {{ok: false, errors}}, got {answer!r}")
    first = answer["errors"][0]
    print(f"  {what}: line {first['line']}: {first['message']}", flush=True)
    if line is not None and first["line"] != line:
        raise Failure(f"{what}: the error is on line {first['line']}, not on the file's line {line}: {answer!r}")
    return first


def still_drawing(args, page, stage, name):
    """The page is still 'rendered' and its frame still matches the golden."""
    state = page.state()
    if state["state"] != "rendered":
        raise Failure(f"after {name} the page is {state['state']!r}: {state['error']!r}{page.problems()}")
    frame = os.path.join(args.out, f"{stage}-{name}.png")
    page.capture(frame)
    web_test.judge(args, frame, stage, [])


def repository_shaders(args, stage):
    folder = os.path.join(args.source, stage)
    names = sorted(n for n in os.listdir(folder) if n.endswith((".vert", ".frag")))
    return {n: open(os.path.join(folder, n), encoding="utf-8").read() for n in names}


def check_listing(page, stage, expected):
    listed = page.evaluate("Module.t10Shaders()")
    got = {entry["file"]: entry["source"] for entry in listed or []}
    if list(got) != list(expected) or got != expected:
        raise Failure(f"Module.t10Shaders() lists {sorted(got)} (or other text), the folder has {sorted(expected)}")
    print(f"  t10Shaders(): {', '.join(expected)}, the repository's text", flush=True)


def check_errors(args, page, stage, source):
    # The file without its header comment, so that #version is on line 1: then the translation's text
    # has its precisions and `#line 2` on lines of their own (2 and 3) and every later line of the
    # file two lines further down. (With comments above #version the precisions take its line and the
    # two numberings agree, which could not tell them apart.)
    lines = source.split("\n")
    lines = lines[next(i for i, text in enumerate(lines) if text.startswith("#version")):]
    main = next(i for i, text in enumerate(lines) if text.startswith("void main"))
    line = main + 3  # inside main(): a statement the translator passes on and the compiler refuses
    broken = lines[:line - 1] + ["    float t10Broken = ;"] + lines[line - 1:]
    expect_error(set_shader(page, EDITED, "\n".join(broken)), line, f"a syntax error on line {line}")
    still_drawing(args, page, stage, "after-syntax-error")
    bad = lines[:line - 1] + ["    float t10Broken = 1.0 @ 2.0;"] + lines[line - 1:]
    expect_error(set_shader(page, EDITED, "\n".join(bad)), line, f"'@' on line {line} (the translator's error)")


def check_refusals(args, page, stage, files):
    name = next(iter(files))
    first = expect_error(set_shader(page, "Missing.frag", "x"), 0, "an unknown file")
    if name not in first["message"]:
        raise Failure(f"the refusal of an unknown file does not list the stage's files: {first['message']!r}")
    huge = page.evaluate(f"Module.t10SetShader({json.dumps(name)}, '//'.padEnd(2 * 1024 * 1024, 'x'))",
                         await_promise=True)
    expect_error(huge, 0, "a 2 MiB source")
    expect_error(set_shader(page, name, b"#version 430 core\n// caf\xe9\n"), 2, "Latin-1 bytes (not UTF-8)")
    lone = page.evaluate(f"Module.t10SetShader({json.dumps(name)}, '#version 430 core\\n\\n// \\uD800')",
                         await_promise=True)
    expect_error(lone, 3, "a lone surrogate")
    expect_error(page.evaluate(f"Module.t10SetShader({json.dumps(name)}, 42)", await_promise=True), 0, "a number")
    check_loops(page, files[EDITED])
    # Compiles, but does not link (an input the vertex shader does not write): the previous file is put
    # back and the stage rebuilt with it, so the page keeps drawing the reference's frame.
    lines = files[EDITED].split("\n")
    main = next(i for i, text in enumerate(lines) if text.startswith("void main"))
    unlinked = lines[:main] + ["in vec3 t10NotFromTheVertexShader;"] + lines[main:main + 2] + [
        "    if (t10NotFromTheVertexShader.x > 2.0) discard;"] + lines[main + 2:]
    first = expect_error(set_shader(page, EDITED, "\n".join(unlinked)), 0, "a program that does not link")
    if "link" not in first["message"]:
        raise Failure(f"the link error does not say so: {first['message']!r}")
    still_drawing(args, page, stage, "after-refusals")


def check_loops(page, source):
    """Loops the page cannot bound, inside main() where they would run: refused at their lines."""
    lines = source.split("\n")
    body = next(i for i, text in enumerate(lines) if text.startswith("void main")) + 1  # main()'s first line, 0-based
    spin = lines[:body] + ["    while (true) { }"] + lines[body:]
    first = expect_error(set_shader(page, EDITED, "\n".join(spin)), body + 1, "while (true) in main()")
    if "while loop" not in first["message"] or "1024" not in first["message"]:
        raise Failure(f"the refusal of while (true) does not say why and how to write it: {first['message']!r}")
    # ANGLE refuses an empty while (true) itself ("Infinite loop detected"); this one it compiles, and
    # without the page's refusal the draw never ends: the tab hangs (measured on SwiftShader: no reply
    # within 60 s, no context lost).
    sly = lines[:body] + ["    float t10X = gl_FragCoord.x; while (t10X >= 0.0) { t10X += 1.0; } if (t10X < 0.0) discard;"] + lines[body:]
    first = expect_error(set_shader(page, EDITED, "\n".join(sly)), body + 1, "a while loop that never ends in main()")
    if "while loop" not in first["message"]:
        raise Failure(f"the refusal of a while loop that never ends does not say why: {first['message']!r}")
    nested = lines[:body] + ["    for (int i = 0; i < 100; ++i)", "        for (int j = 0; j < 100; ++j) { }"] + lines[body:]
    first = expect_error(set_shader(page, EDITED, "\n".join(nested)), body + 2, "nested loops of 100 x 100 in main()")
    if "10000 times" not in first["message"]:
        raise Failure(f"the refusal of nested loops does not count their iterations: {first['message']!r}")


LOSE_CONTEXT = """(() => {
  const gl = document.getElementById('canvas').getContext('webgl2');
  window.__t10Lose = gl && gl.getExtension('WEBGL_lose_context');
  if (!window.__t10Lose) return 'no WEBGL_lose_context';
  window.__t10Lose.loseContext();
  return '';
})()"""
STATUS = "JSON.stringify({text: document.getElementById('t10-status').textContent, " \
         "role: document.getElementById('t10-status').getAttribute('role'), lost: document.body.dataset.t10Lost || '', " \
         "reload: !document.getElementById('t10-reload').hidden})"


def check_context_loss(args, page, stage, source):
    """The context lost, then restored, then the page reloaded from its button."""
    missing = page.evaluate(LOSE_CONTEXT)
    if missing:
        raise Failure(f"the context-loss check needs WEBGL_lose_context, which this Chromium lacks ({missing})")
    state = page.wait(lambda s: s["state"] == "error", "no 'error' after the WebGL context was lost", 20)
    status = json.loads(page.evaluate(STATUS))
    print(f"  context lost: {status['text']}", flush=True)
    if status["role"] != "status" or status["lost"] != "lost" or not status["reload"]:
        raise Failure(f"after the context was lost the status line is {status}: role=status, dataset.t10Lost "
                      f"'lost' and a reload button expected")
    if "WebGL stopped" not in status["text"] or "reload" not in status["text"]:
        raise Failure(f"the status line does not say what happened and what to do: {status['text']!r}")
    page.screenshot(os.path.join(args.out, f"{stage}-context-lost.png"))
    started = time.monotonic()
    answer = set_shader(page, EDITED, source)
    report = page.evaluate("Module.t10Check()", await_promise=True)
    refused = page.evaluate("Module.t10Set('fov', '50')")
    took = time.monotonic() - started
    if answer.get("ok") is not False or "WebGL stopped" not in answer["errors"][0]["message"]:
        raise Failure(f"t10SetShader after the context was lost answered {answer!r}")
    if "WebGL stopped" not in str(report.get("error")) or "WebGL stopped" not in refused:
        raise Failure(f"after the context was lost t10Check answered {report!r} and t10Set {refused!r}")
    if took > 5:
        raise Failure(f"the refusals after the context was lost took {took:.1f} s (they must answer at once)")
    page.evaluate("document.getElementById('canvas').dispatchEvent(new WheelEvent('wheel', {deltaY: 100, bubbles: true}))")
    time.sleep(1)
    if page.state()["frames"] != state["frames"]:
        raise Failure(f"a frame was drawn after the context was lost ({state['frames']} -> {page.state()['frames']}): "
                      "the loop did not stop")
    print(f"  refused at once ({took:.2f} s): {answer['errors'][0]['message'][:60]}...; the loop stopped", flush=True)
    page.evaluate("window.__t10Lose.restoreContext()")
    status = cdp.wait_until(lambda: json.loads(page.evaluate(STATUS)), lambda v: v["lost"] == "restored", 20,
                            "the page did not notice the context's restoring", lambda v: f": {v}")
    if "reload" not in status["text"]:
        raise Failure(f"restored, the status line does not offer the reload: {status['text']!r}")
    page.evaluate("document.getElementById('t10-reload').click()")
    state = page.wait(lambda s: s["state"] == "rendered", "no frame after the reload button", args.timeout * 0.3)
    if page.evaluate("document.body.dataset.t10Lost || ''"):
        raise Failure(f"the reload button did not bring the frame back: {state['state']!r} {state['error']!r}")
    print(f"  restored: {status['text'][:70]}...; reloaded: a frame again", flush=True)


def run_check(page, stage):
    started = time.monotonic()
    report = page.evaluate("Module.t10Check()", await_promise=True)
    if not isinstance(report, dict) or "error" in report or "score" not in report:
        raise Failure(f"Module.t10Check() answered {report!r}")
    failed = [c["id"] for c in report["checks"] if not c["passed"]]
    print(f"  t10Check(): score {report['score']}, {len(report['checks'])} checks, failed {failed or 'none'}, "
          f"{time.monotonic() - started:.1f} s; not judged: {', '.join(n['what'] for n in report['not_judged'])}", flush=True)
    return report, failed


def check_white_point(page, stage):
    report, failed = run_check(page, stage)
    found = [m for c in report["checks"] if not c["passed"] for m in c["mistakes"] if m["id"] == "white-point"]
    if not found or not all(abs(m["estimate"]["value"] - 1.0) <= 0.01 for m in found):
        raise Failure(f"with the white point 1.0 the check names {[(c['id'], c['mistakes']) for c in report['checks'] if not c['passed']]}")
    if 9 not in report["failed_steps"] or report["score"] >= 100:
        raise Failure(f"with the white point 1.0 the score is {report['score']}, the failed steps {report['failed_steps']}")


def check_reference(page, stage):
    report, failed = run_check(page, stage)
    if failed or report["score"] != 100:
        raise Failure(f"the reference's shaders score {report['score']} in the page, failing {failed}")
    judged = {c["id"].split(".")[0] for c in report["checks"]}
    if judged != {"pot", "npot"}:
        raise Failure(f"the page judged the cases {sorted(judged)}, not t10-grade's camera cases pot and npot")


def run_case(args, page, stage, first):
    web_test.page_folder(args, stage)
    started = time.monotonic()
    page.open(stage, web_test.GOLDEN_QUERY)
    web_test.rendered(page, stage)
    files = repository_shaders(args, stage)
    check_listing(page, stage, files)
    check_errors(args, page, stage, files[EDITED])
    if first:
        check_refusals(args, page, stage, files)
    wrong = files[EDITED].replace(*WHITE_POINT)
    if wrong == files[EDITED]:
        raise Failure(f"{stage}/{EDITED} has no {WHITE_POINT[0]!r} to change")
    answer = set_shader(page, EDITED, wrong)
    if answer != {"ok": True, "errors": []}:
        raise Failure(f"the white point 1.0 was not applied: {answer!r}")
    mutant = os.path.join(args.out, f"{stage}-white-point-1.png")
    page.capture(mutant)
    try:
        web_test.judge(args, mutant, stage, [])
    except Failure:
        print("  the white point 1.0 is applied: the frame no longer matches the golden (as it must)", flush=True)
    else:
        raise Failure("with the white point 1.0 applied the frame still matches the golden: the edit did not "
                      "reach the frame, or the comparison cannot fail")
    if first:
        check_white_point(page, stage)
    for name, source in files.items():
        answer = set_shader(page, name, source)
        if answer != {"ok": True, "errors": []}:
            raise Failure(f"the reference's {name} through t10SetShader: {answer!r}")
    still_drawing(args, page, stage, "reference-again")
    check_reference(page, stage)
    print(f"{stage}: passed in {time.monotonic() - started:.1f} s", flush=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--web", required=True, help="the built pages (out/web)")
    ap.add_argument("--out", required=True, help="folder for frames and the browser's log")
    ap.add_argument("--source", required=True, help="the repository's root (the stages' shader files)")
    ap.add_argument("--case", action="append", required=True, help="a stage whose page is tested")
    ap.add_argument("--goldens", required=True)
    ap.add_argument("--tolerance", default=None, help="default: GOLDENS/web.tolerance")
    ap.add_argument("--imgcompare", required=True)
    ap.add_argument("--chromium", default="chromium")
    ap.add_argument("--renderer", choices=sorted(cdp.RENDERERS), default="llvmpipe")
    ap.add_argument("--timeout", type=float, default=150, help="seconds for the whole test")
    args = ap.parse_args()

    args.tolerance = args.tolerance or os.path.join(args.goldens, "web.tolerance")
    args.query, args.name = "", None
    if not shutil.which(args.chromium):
        print(f"SKIP: {args.chromium}: not found (apt-get install chromium)", file=sys.stderr)
        return 77
    os.makedirs(args.out, exist_ok=True)
    for stage in args.case:
        web_test.page_folder(args, stage)
    page = web_test.Page(args)
    try:
        for i, stage in enumerate(args.case):
            try:
                run_case(args, page, stage, i == 0)
            except Failure as failure:
                raise Failure(f"{stage}: {failure}{page.problems()}") from None
        stage = args.case[-1]
        try:
            check_context_loss(args, page, stage, repository_shaders(args, stage)[EDITED])
        except Failure as failure:
            raise Failure(f"{stage}, the WebGL context lost: {failure}{page.problems()}") from None
    finally:
        page.close()
    print("ok")
    return 0


if __name__ == "__main__":
    cdp.run_main(main)
