#!/usr/bin/env python3
"""Builds the documentation site.

1. Copies the Jekyll sources (site/) into a work folder in the build tree.
2. Generates from the repository, into the work folder's _data/ and assets/:
   - the code of every step marker of every stage      -> _data/excerpts.json, _data/steps.json
   - what each stage is (its header comment)            -> _data/stages.json
   - the diff from each stage folder to the next        -> _data/diffs.json
   - the --help text of the stage binaries              -> _data/cli.json
   - the golden-image settings and tolerances           -> _data/goldens.json
   - the images the pages show, rendered by the stages  -> assets/images/ (PNG, and WebP at the widths
                                                           the pages offer, made by Debian's cwebp)
   - KaTeX (Debian's libjs-katex and fonts-katex)        -> assets/katex/
   - the embeds' shader editor: CodeMirror 5 (Debian's libjs-codemirror) and common/platform/web/'s
     editor.js and editor.css                             -> assets/editor/
   - the web stages' sizes and first-frame times         -> _data/web.json (web_stages.py)
3. Checks every excerpt and figure the pages ask for exists (an error names the page and line).
4. Runs `jekyll build` into the destination and fails on any warning it prints.
5. Copies the web stages (make web: out/web/<stage>/), when built, into the destination's web/.

Nothing is written into the source tree. Usage: see --help; site/CMakeLists.txt has the calls.
"""

import argparse
import concurrent.futures
import difflib
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
import time

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from markers import markers  # noqa: E402  (tools/ on PYTHONPATH)
import web_stages  # noqa: E402  (beside this script)

IMAGE_SIZE = "1280x720"
# The frames as pages show them (issue 50: a 3 MiB tutorial page): WebP at these widths, offered through
# srcset (figure.html; 960 fills the text column at 1280 px, 640 a phone's or half the column), the
# PNG behind a link. Quality 80: on these dim, noisy frames the difference from the PNG is invisible at
# the column's size, and a 960-px frame weighs 40-80 KB instead of the PNG's 1.0-1.6 MB.
WEBP_WIDTHS = (640, 960, 1280)
WEBP_QUALITY = "80"
# Files of site/ that are tooling, not pages.
NOT_PAGES = {"tools", "tests", "CMakeLists.txt", "README.md", "_site", ".jekyll-cache", "__pycache__"}
INCLUDE = re.compile(r"\{%-?\s*include\s+(?P<name>excerpt|figure|derived|live)\.html\s+(?P<args>.*?)\s*-?%\}")
# Figures computed from rendered frames by make_figure (tools/figures): name -> (mode, arguments,
# the renders it reads as (stage, camera, extra)). Crops are of the 1280x720 frames, X Y W H from the
# top left, enlarged 4 times; heat-maps reach white where a stage adds 128 levels of luma.
P1, P2, P3 = "tutorial10_part1_tonemap", "tutorial10_part2_bloom", "tutorial10_part3_gaussian"
DERIVED = {
    "crop-part1-part2": ("crop", ["736", "270", "120", "80", "4"], [(P1, "", ""), (P2, "", "")]),
    "crop-part2-part3": ("crop", ["736", "270", "120", "80", "4"], [(P2, "", ""), (P3, "", "")]),
    "heat-part1-part2": ("heat", ["128"], [(P1, "", ""), (P2, "", "")]),
    "heat-part2-part3": ("heat", ["128"], [(P2, "", ""), (P3, "", "")]),
}
ARG = re.compile(r"""(\w+)=(?:"([^"]*)"|'([^']*)'|(\S+))""")
# What `jekyll build` prints when all is well; any other line (a warning, a deprecation, a Ruby
# warning from a gem, a conflict report) fails the build.
JEKYLL_QUIET = re.compile(r"^\s*(Configuration file: |Source: |Destination: |Incremental build: disabled|"
                          r"Generating\.\.\.|done in [0-9.]+ seconds\.|Auto-regeneration: disabled|$)")


class SiteError(Exception):
    pass


def log(message):
    print(f"[site] {message}", flush=True)


# --- Stages -------------------------------------------------------------------------------------

def file_order(name):
    # Host code first (the tutorial's order: declare, initialise, render), then other code and
    # headers, then shaders, each by name; files in subfolders after the folder's own.
    base = name.rsplit("/", 1)[-1]
    rank = (0 if base == "Tutorial10.cpp" else 1 if base.endswith((".cpp", ".cc")) else
            2 if base.endswith((".hpp", ".h")) else 3 if markers.language_of(base) == "glsl" else 4)
    return (name.count("/"), rank, name)


def read_stage(name, folder):
    if not os.path.isdir(folder):
        raise SiteError(f"stage folder {folder} does not exist")
    files = {}
    for root, dirs, names in os.walk(folder):
        dirs[:] = sorted(d for d in dirs if not d.startswith("."))
        for fname in sorted(names):
            if fname.startswith("."):
                continue
            path = os.path.join(root, fname)
            rel = os.path.relpath(path, folder).replace(os.sep, "/")
            try:
                with open(path, encoding="utf-8") as f:
                    text = f.read()
            except UnicodeDecodeError:
                files[rel] = {"text": None, "lang": None, "blocks": [], "lines": []}
                continue
            lang = markers.language_of(rel)
            lines, blocks = markers.parse(text, f"{name}/{rel}") if lang else (text.split("\n"), [])
            files[rel] = {"text": text, "lang": lang, "blocks": blocks, "lines": lines}
    return {"name": name, "folder": folder, "files": files}


def header_comment(text):
    """The leading // comment of the host code, as paragraphs."""
    out = []
    for line in text.split("\n"):
        if line.startswith("//"):
            out.append(line[2:].strip())
        elif out or line.strip():
            break
    paragraphs, current = [], []
    for line in out:
        if line:
            current.append(line)
        elif current:
            paragraphs.append(" ".join(current))
            current = []
    if current:
        paragraphs.append(" ".join(current))
    return paragraphs


def describe(stage):
    host = next((f for f in sorted(stage["files"], key=file_order) if f.endswith(".cpp") and "/" not in f), None)
    paragraphs = header_comment(stage["files"][host]["text"]) if host else []
    info = {"title": stage["name"], "builds_on": "", "adds": "", "about": ""}
    if paragraphs and paragraphs[0].startswith(stage["name"] + ":"):
        info["title"] = paragraphs.pop(0)[len(stage["name"]) + 1:].strip().rstrip(".")
    # "Builds on: ..." and "Adds: ..." may share a paragraph; anything else is "about".
    text = " ".join(paragraphs)
    parts = re.split(r"\b(Builds on:|Adds[:,])", text)
    info["about"] = parts[0].strip()
    for label, body in zip(parts[1::2], parts[2::2]):
        # Drop the sentences that only explain the markers or name the next stage.
        sentences = re.split(r"(?<=\.)\s+", body.strip())
        body = " ".join(s for s in sentences if "[step N]" not in s and "is this file plus" not in s)
        if label == "Adds,":
            body = "Adds, " + body
        info["builds_on" if label == "Builds on:" else "adds"] = body.strip()
    if not info["adds"]:
        info["adds"] = info["about"]
    upper = lambda t: t[:1].upper() + t[1:]
    info["heading"] = upper(info["title"])
    info["adds"] = upper(info["adds"])
    return info


def step_blocks(stage, rel, step):
    """Blocks of `step` in one file that are not inside another block of the same step."""
    blocks = stage["files"][rel]["blocks"]
    nested = {id(c) for b in blocks if b.step == step for c in b.children if c.step == step}
    return [b for b in blocks if b.step == step and id(b) not in nested]


def excerpts_of(stages):
    excerpts, steps = {}, {}
    for stage in stages:
        per_stage = excerpts.setdefault(stage["name"], {})
        for rel in sorted(stage["files"], key=file_order):
            entry = stage["files"][rel]
            numbers = sorted({b.step for b in entry["blocks"]})
            for step in numbers:
                blocks = step_blocks(stage, rel, step)
                code_blocks = [{"first": b.first_line, "last": b.last_line, "title": b.title,
                                "code": markers.code_of(b, entry["lines"])} for b in blocks]
                per_stage.setdefault(rel, {})[str(step)] = {
                    "lang": entry["lang"], "title": blocks[0].title,
                    "lines": where_label(code_blocks),
                    "line_count": sum(b["code"].count("\n") + 1 for b in code_blocks),
                    "blocks": code_blocks,
                }
                home = steps.setdefault(str(step), {"stage": stage["name"], "files": []})
                if home["stage"] == stage["name"]:
                    home["files"].append(rel)
    return excerpts, steps


def where_label(blocks):
    """'line 7', 'lines 7–9' or 'lines 7–9, 20, 31–33': where the blocks are in the file."""
    spans = [f"{b['first']}" if b["first"] >= b["last"] else f"{b['first']}–{b['last']}" for b in blocks]
    single = len(blocks) == 1 and blocks[0]["first"] >= blocks[0]["last"]
    return ("line " if single else "lines ") + ", ".join(spans)


def step_range(numbers):
    if not numbers:
        return ""
    numbers = sorted(numbers)
    runs, start, prev = [], numbers[0], numbers[0]
    for n in numbers[1:] + [None]:
        if n is not None and n == prev + 1:
            prev = n
            continue
        runs.append(f"{start}–{prev}" if prev != start else f"{start}")
        if n is not None:
            start = prev = n
    return ", ".join(runs)


def stage_table(stages):
    out, seen = [], set()
    for i, stage in enumerate(stages):
        mine = {b.step for f in stage["files"].values() for b in f["blocks"]}
        new = sorted(mine - seen)
        seen |= mine
        info = describe(stage)
        info.update({"name": stage["name"], "index": i, "steps": new, "step_range": step_range(new),
                     "files": sorted(stage["files"], key=file_order),
                     "previous": stages[i - 1]["name"] if i else "",
                     "image": f"assets/images/{stage['name']}.png"})
        out.append(info)
    return out


try:  # Debian's python3-pygments: language colouring inside the diffs (optional)
    import html as html_escape
    from pygments import highlight as pygments_highlight
    from pygments.formatters import HtmlFormatter
    from pygments.lexers import get_lexer_by_name
except ImportError:
    pygments_highlight = None


def highlighted_lines(text, lang):
    """The file's lines as HTML, coloured like the excerpts (Pygments and Rouge share class names)."""
    if lang:
        out = pygments_highlight(text, get_lexer_by_name(lang), HtmlFormatter(nowrap=True))
    else:
        out = html_escape.escape(text)
    lines = out.split("\n")
    if text.endswith("\n") or not text:
        lines = lines[:-1]
    return lines


def unified_range(start, length):
    first = start + 1
    if length == 1:
        return f"{first}"
    return f"{first - 1 if not length else first},{length}"


def diff_html(a_lines, b_lines, a_name, b_name, lang):
    """`diff -u` as HTML, one block per line (so that a line's background spans the width) and each
    line coloured in its own language."""
    a_text, b_text = "".join(a_lines), "".join(b_lines)
    a_html, b_html = highlighted_lines(a_text, lang), highlighted_lines(b_text, lang)
    esc = html_escape.escape
    out = [f'<span class="dl dl-file">--- {esc(a_name)}</span>', f'<span class="dl dl-file">+++ {esc(b_name)}</span>']
    matcher = difflib.SequenceMatcher(None, a_lines, b_lines)
    for group in matcher.get_grouped_opcodes(3):
        a0, a1, b0, b1 = group[0][1], group[-1][2], group[0][3], group[-1][4]
        out.append(f'<span class="dl dl-hunk">@@ -{unified_range(a0, a1 - a0)} +{unified_range(b0, b1 - b0)} @@</span>')
        for tag, i1, i2, j1, j2 in group:
            if tag == "equal":
                out += [f'<span class="dl"><span class="dm"> </span>{b_html[j]}</span>' for j in range(j1, j2)]
                continue
            if tag in ("replace", "delete"):
                out += [f'<span class="dl dl-del"><span class="dm">-</span>{a_html[i]}</span>' for i in range(i1, i2)]
            if tag in ("replace", "insert"):
                out += [f'<span class="dl dl-add"><span class="dm">+</span>{b_html[j]}</span>' for j in range(j1, j2)]
    return "".join(out)


def stage_diffs(stages):
    diffs = []
    for old, new in zip(stages, stages[1:]):
        files = []
        for rel in sorted(set(old["files"]) | set(new["files"]), key=file_order):
            a = old["files"].get(rel)
            b = new["files"].get(rel)
            a_text = a["text"] if a else None
            b_text = b["text"] if b else None
            if a_text == b_text and a and b:
                continue
            if (a and a_text is None) or (b and b_text is None):
                files.append({"path": rel, "status": "binary", "added": 0, "removed": 0, "diff": ""})
                continue
            a_lines = a_text.splitlines(keepends=True) if a else []
            b_lines = b_text.splitlines(keepends=True) if b else []
            lines = list(difflib.unified_diff(
                a_lines, b_lines,
                fromfile=f"{old['name']}/{rel}" if a else "/dev/null",
                tofile=f"{new['name']}/{rel}" if b else "/dev/null", n=3))
            text = "".join(line if line.endswith("\n") else line + "\n\\ No newline at end of file\n"
                           for line in lines)
            added = sum(1 for l in lines if l.startswith("+") and not l.startswith("+++"))
            removed = sum(1 for l in lines if l.startswith("-") and not l.startswith("---"))
            touched = sorted({int(m["step"]) for l in lines if l[:1] in "+-"
                              for m in [markers.OPEN.match(l[1:])] if m})
            status = "added" if not a else "removed" if not b else "modified"
            html = ""
            if pygments_highlight:
                html = diff_html(a_lines, b_lines, f"{old['name']}/{rel}" if a else "/dev/null",
                                 f"{new['name']}/{rel}" if b else "/dev/null", markers.language_of(rel))
            files.append({"path": rel, "status": status, "added": added, "removed": removed,
                          "steps": touched, "diff": text.rstrip("\n"), "html": html})
        diffs.append({"from": old["name"], "to": new["name"], "files": files,
                      "added": sum(f["added"] for f in files), "removed": sum(f["removed"] for f in files)})
    return diffs


# --- Binaries -----------------------------------------------------------------------------------

def run(cmd, timeout=60, cwd=None, env=None):
    try:
        result = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                                timeout=timeout, cwd=cwd, env=env)
    except FileNotFoundError:
        raise SiteError(f"{cmd[0]}: not found (build the stages first: cmake --build build)")
    except subprocess.TimeoutExpired:
        raise SiteError(f"{' '.join(cmd)}: still running after {timeout} s")
    if result.returncode != 0:
        raise SiteError(f"{' '.join(cmd)} exited with {result.returncode}:\n{result.stdout}")
    return result.stdout


def cli_help(stages, bin_dir):
    groups = []
    for stage in stages:
        exe = os.path.join(bin_dir, stage["name"])
        text = run([exe, "--help"]).rstrip()
        version = run([exe, "--version"]).strip()
        generic = text.replace(stage["name"], "STAGE")
        for group in groups:
            if group["generic"] == generic:
                group["stages"].append(stage["name"])
                break
        else:
            groups.append({"generic": generic, "stages": [stage["name"]], "text": text, "version": version})
    for group in groups:
        del group["generic"]
    return {"groups": groups, "last": stages[-1]["name"]}


# Stages that take --then (common/frame/src/loop/app_native.cpp): each of their renders for the site is a run of
# one process per stage, which makes the driver, LLVM's code for the shaders and the scene once (the
# four stages' 15 pictures: 7.5 s instead of 9.6 s, the same bits). extras refuses it (its options
# are globals the runs would share).
THEN = "--then"
NO_THEN = {"extras"}
# make test's llvmpipe skips LLVM's optimisation passes (GALLIVM_PERF=nopt, Makefile), which pays where
# frames are small and compiling the shaders is most of the work; the site's frames are large, and
# drawing them with unoptimised shader code costs more than optimising it: the site's renders keep
# the driver's defaults (Part 1's frame and its ev view at 1280x720: 1.6 CPU s with nopt, 1.2
# without). The frames are the same bits either way (the test "llvmpipe: ... the same bits").
RENDER_ENV = {k: v for k, v in os.environ.items() if k != "GALLIVM_PERF"}


def render_images(renders, bin_dir, images_dir, source_root=None):
    """Renders run in the source root, so a figure's args can name files of the repository."""
    os.makedirs(images_dir, exist_ok=True)
    by_stage = {}
    for stage, camera, extra in sorted(renders):
        by_stage.setdefault(stage, []).append((camera, extra))
    for stage, runs in by_stage.items():
        groups = [[r] for r in runs] if stage in NO_THEN else [runs]
        for group in groups:
            cmd = [os.path.join(bin_dir, stage)]
            outs = []
            for camera, extra in group:
                out = os.path.join(images_dir, image_name(stage, camera, extra))
                if outs:
                    cmd.append(THEN)
                cmd += ["--headless", "--size", IMAGE_SIZE, "--frames", "1", "--output", out]
                if camera:
                    cmd += ["--camera", camera]
                cmd += shlex.split(extra)
                outs.append(out)
            started = time.monotonic()
            run(cmd, timeout=120, cwd=source_root, env=RENDER_ENV)
            for out in outs:
                if not os.path.isfile(out):
                    raise SiteError(f"{' '.join(cmd)} wrote no {out}")
            names = ", ".join(os.path.basename(o) for o in outs)
            log(f"rendered {names} ({time.monotonic() - started:.1f} s, one process)")


def make_derived(derived, bin_dir, images_dir):
    """Writes each derived figure into images_dir; returns {name: {width, height, command}} for the pages."""
    table = {}
    for name in sorted(derived):
        mode, extra, sources = DERIVED[name]
        out = os.path.join(images_dir, name + ".png")
        inputs = [os.path.join(images_dir, image_name(*r)) for r in sources]
        if mode == "crop":
            cmd = [os.path.join(bin_dir, "make_figure"), "crop", out] + extra + inputs
        else:
            cmd = [os.path.join(bin_dir, "make_figure"), "heat", out] + extra + inputs
        run(cmd)
        with open(out, "rb") as f:
            head = f.read(24)  # PNG: the IHDR chunk holds width and height at bytes 16-23
        table[name] = {"width": int.from_bytes(head[16:20], "big"), "height": int.from_bytes(head[20:24], "big"),
                       "command": " ".join(["make_figure", mode] + extra + [image_name(*r) for r in sources])}
        log(f"derived {name}.png")
    return table


def compress_frames(images_dir, names, cwebp):
    """<name>-<width>.webp beside each rendered <name>.png, for every width of WEBP_WIDTHS (two at a time:
    cwebp is single-threaded)."""
    jobs = [(os.path.join(images_dir, n), w) for n in sorted(names) for w in WEBP_WIDTHS]

    def encode(job):
        png, width = job
        run([cwebp, "-quiet", "-q", WEBP_QUALITY, "-m", "4", "-resize", str(width), "0", png,
             "-o", png[:-len(".png")] + f"-{width}.webp"])

    started = time.monotonic()
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        list(pool.map(encode, jobs))
    log(f"{len(jobs)} WebP versions of {len(names)} frames ({time.monotonic() - started:.1f} s)")


def slugify(text):
    """Jekyll's default `slugify`: lower case, runs of anything but letters and digits to '-'."""
    return re.sub(r"[^a-z0-9]+", "-", text.lower()).strip("-")


def image_name(stage, camera="", extra=""):
    """<stage>[--<camera>][--<slug of the extra options>].png; figure.html builds the same name."""
    return "--".join([stage] + [p for p in (camera, slugify(extra)) if p]) + ".png"


# --- Goldens ------------------------------------------------------------------------------------

def goldens(source_root, stage_names):
    folder = os.path.join(source_root, "tests", "golden")
    args = ""
    render_args = os.path.join(folder, "render_args.sh")
    if os.path.isfile(render_args):
        with open(render_args, encoding="utf-8") as f:
            m = re.search(r"T10_GOLDEN_ARGS=\(([^)]*)\)", f.read())
            args = " ".join(m[1].split()) if m else ""
    entries = []
    for name in stage_names:
        tol_path = os.path.join(folder, f"{name}.tolerance")
        bounds = []
        if os.path.isfile(tol_path):
            with open(tol_path, encoding="utf-8") as f:
                for line in f:
                    m = re.match(r"\s*(\w+)\s*=\s*([^#\s]+)\s*(?:#\s*(.*))?$", line)
                    if m:
                        bounds.append({"key": m[1], "value": m[2], "reason": (m[3] or "").strip()})
        entries.append({"stage": name, "png": os.path.isfile(os.path.join(folder, f"{name}.png")),
                        "tolerance": bounds})
    # Stages that reuse another stage's golden: t10_add_stage(<stage> SAME_GOLDEN_AS <other>).
    same = {}
    for cmake in [os.path.join(source_root, "CMakeLists.txt")] + [
            os.path.join(source_root, n, "CMakeLists.txt") for n in stage_names]:
        if os.path.isfile(cmake):
            with open(cmake, encoding="utf-8") as f:
                for m in re.finditer(r"t10_add_stage\(\s*([^\s)]+)[^)]*?\bSAME_GOLDEN_AS\s+([^\s)]+)", f.read()):
                    same[m[1]] = m[2]
    for e in entries:
        e["same_as"] = same.get(e["stage"], "")
    # Stages whose tolerance files say the same thing share one row group on the page.
    groups = []
    for e in entries:
        key = json.dumps(e["tolerance"]) if e["tolerance"] else None
        group = next((g for g in groups if key and g["key"] == key), None)
        if group:
            group["stages"].append(e["stage"])
            group["missing"] += [] if e["png"] else [e["stage"]]
        else:
            groups.append({"key": key, "stages": [e["stage"]], "tolerance": e["tolerance"],
                           "same_as": e["same_as"],
                           "missing": [] if e["png"] or e["same_as"] else [e["stage"]]})
    for g in groups:
        del g["key"]
    return {"args": args, "stages": entries, "groups": groups, "any": any(e["png"] for e in entries)}


# --- Pages --------------------------------------------------------------------------------------

def page_includes(work):
    """Every excerpt/figure include in the pages: (page, line, name, args)."""
    found = []
    for fname in sorted(os.listdir(work)):
        if not fname.endswith((".md", ".html")):
            continue
        with open(os.path.join(work, fname), encoding="utf-8") as f:
            for number, line in enumerate(f, 1):
                for m in INCLUDE.finditer(line):
                    args = {a[0]: a[1] or a[2] or a[3] for a in ARG.findall(m["args"])}
                    found.append((fname, number, m["name"], args))
    return found


def check_includes(includes, excerpts, steps, stage_names):
    renders, derived, problems = set(), set(), []
    for page, line, name, args in includes:
        where = f"site/{page}:{line}"
        optional = args.get("optional") == "true"
        stage = args.get("stage")
        if name == "derived":
            image = args.get("image", "")
            if image not in DERIVED:
                problems.append(f"{where}: no derived figure '{image}' (build_site.py DERIVED: {', '.join(DERIVED)})")
            elif all(r[0] in stage_names for r in DERIVED[image][2]):
                derived.add(image)
                renders.update(DERIVED[image][2])
            elif not optional:
                problems.append(f"{where}: derived figure '{image}' needs a stage that does not exist")
            continue
        if name in ("figure", "live"):  # live.html shows the stage's still frame too
            if not stage and args.get("step", "") in steps:
                stage = steps[args["step"]]["stage"]
            if not stage:
                if not (optional and args.get("step", "").isdigit()):
                    problems.append(f"{where}: figure needs stage= (or step=N of a step some stage has)")
            elif stage in stage_names:
                renders.add((stage, args.get("camera", ""), args.get("args", "")))
            elif not optional:
                problems.append(f"{where}: no stage {stage} (stages: {', '.join(stage_names)})")
            continue
        step = args.get("step")
        if not step or not step.isdigit():
            problems.append(f"{where}: excerpt needs step=N")
            continue
        if not stage:
            if step not in steps and not optional:
                problems.append(f"{where}: no stage has a [step {step}] marker")
            continue
        if stage not in stage_names:
            if not optional:
                problems.append(f"{where}: no stage {stage}")
            continue
        file = args.get("file")
        files = [file] if file else [f for f, s in excerpts[stage].items() if step in s]
        if file and file not in excerpts[stage]:
            problems.append(f"{where}: {stage}/{file} has no step markers (or does not exist)")
        elif not files or any(step not in excerpts[stage][f] for f in files):
            problems.append(f"{where}: {stage}/{file or '*'} has no [step {step}] marker")
    if problems:
        raise SiteError("the pages ask for code or images that do not exist:\n  " + "\n  ".join(problems))
    return renders, derived


# --- KaTeX --------------------------------------------------------------------------------------

def copy_katex(katex, dest):
    needed = ["katex.min.js", "katex.min.css", "contrib/auto-render.js"]
    for rel in needed + ["fonts"]:
        if not os.path.exists(os.path.join(katex, rel)):
            raise SiteError(f"{katex}/{rel} is missing: apt-get install libjs-katex fonts-katex")
    os.makedirs(os.path.join(dest, "contrib"), exist_ok=True)
    for rel in needed:
        shutil.copyfile(os.path.join(katex, rel), os.path.join(dest, rel))
    fonts = os.path.realpath(os.path.join(katex, "fonts"))
    shutil.copytree(fonts, os.path.join(dest, "fonts"), dirs_exist_ok=True)
    if not any(n.endswith(".woff2") for n in os.listdir(os.path.join(dest, "fonts"))):
        raise SiteError(f"{fonts} holds no KaTeX fonts: apt-get install fonts-katex")


# --- The shader editor (issue 52) ------------------------------------------------------------------

# The files the editor loads, flat in assets/editor/ (the layout cmake/T10Web.cmake gives out/web/editor/).
CODEMIRROR_FILES = ["lib/codemirror.js", "lib/codemirror.css", "mode/clike/clike.js"]
EDITOR_FILES = ["editor.js", "editor.css"]


def copy_editor(codemirror, source_root, dest):
    os.makedirs(dest, exist_ok=True)
    for rel in CODEMIRROR_FILES:
        if not os.path.isfile(os.path.join(codemirror, rel)):
            raise SiteError(f"{codemirror}/{rel} is missing: apt-get install libjs-codemirror")
        shutil.copyfile(os.path.join(codemirror, rel), os.path.join(dest, os.path.basename(rel)))
    for name in EDITOR_FILES:
        shutil.copyfile(os.path.join(source_root, "common", "platform", "web", name), os.path.join(dest, name))


# --- Jekyll -------------------------------------------------------------------------------------

# Jekyll empties its destination before writing: build/site/ holds nothing else (CMake's binary
# folder for site/ is build/site-cmake/, see the top-level CMakeLists.txt).
def jekyll_build(jekyll, work, dest):
    env = dict(os.environ, JEKYLL_ENV="production", LC_ALL="C.UTF-8", LANG="C.UTF-8")
    cmd = [jekyll, "build", "--source", work, "--destination", dest, "--disable-disk-cache",
           "--config", os.path.join(work, "_config.yml")]
    try:
        result = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                                timeout=300, env=env, cwd=work)
    except FileNotFoundError:
        raise SiteError(f"{jekyll}: not found: apt-get install jekyll")
    output = re.sub(r"\x1b\[[0-9;]*m", "", result.stdout)  # no colour codes in logs
    if result.returncode != 0:
        # Jekyll follows its message with a Ruby backtrace: keep the message, drop the frames.
        message = "\n".join(l for l in output.splitlines() if not l.lstrip().startswith("from /"))
        raise SiteError(f"jekyll build failed ({result.returncode}):\n{message}")
    warnings = [line for line in output.splitlines() if not JEKYLL_QUIET.match(line)]
    if warnings:
        raise SiteError("jekyll printed warnings (treated as errors):\n  " + "\n  ".join(warnings)
                        + "\n\nfull output:\n" + output)
    return output


# --- Main ---------------------------------------------------------------------------------------

def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--source-root", required=True, help="repository root (stage folders, tests/golden)")
    ap.add_argument("--site", help="Jekyll sources (default: SOURCE_ROOT/site)")
    ap.add_argument("--work", required=True, help="work folder in the build tree (emptied first)")
    ap.add_argument("--dest", required=True, help="where jekyll writes the site")
    ap.add_argument("--bin", help="folder of the stage binaries")
    ap.add_argument("--stages", required=True, help="stage folders in tutorial order, comma-separated")
    ap.add_argument("--stage-dir", action="append", default=[], metavar="NAME=DIR",
                    help="read stage NAME's sources from DIR instead (tests)")
    ap.add_argument("--reuse", metavar="WORK",
                    help="take the rendered images and --help texts from an earlier work folder "
                         "instead of running the binaries (tests)")
    ap.add_argument("--katex", default="/usr/share/javascript/katex", help="KaTeX distribution")
    ap.add_argument("--codemirror", default="/usr/share/javascript/codemirror", help="CodeMirror 5 distribution")
    ap.add_argument("--jekyll", default="jekyll", help="jekyll executable")
    ap.add_argument("--cwebp", default="cwebp", help="cwebp executable (Debian: webp)")
    ap.add_argument("--web", help="the web stages (make web: out/web), copied into the site when built")
    ap.add_argument("--web-measurements", help="measure_web.py's JSON: the time to each web stage's first frame")
    args = ap.parse_args()

    started = time.monotonic()
    source_root = os.path.abspath(args.source_root)
    site = os.path.abspath(args.site or os.path.join(source_root, "site"))
    work, dest = os.path.abspath(args.work), os.path.abspath(args.dest)
    if work.startswith(site + os.sep) or dest.startswith(site + os.sep):
        raise SiteError("--work and --dest must be outside the source tree")
    names = [n for n in args.stages.split(",") if n]
    if not names:
        raise SiteError("--stages is empty")
    overrides = dict(o.split("=", 1) for o in args.stage_dir)

    # 1. A fresh copy of the Jekyll sources.
    if os.path.isdir(work):
        shutil.rmtree(work)
    shutil.copytree(site, work, ignore=lambda d, ns: [n for n in ns if d == site and n in NOT_PAGES])
    data = os.path.join(work, "_data")
    os.makedirs(data, exist_ok=True)

    # 2. Data from the stage sources.
    stages = [read_stage(n, os.path.abspath(overrides.get(n, os.path.join(source_root, n)))) for n in names]
    excerpts, steps = excerpts_of(stages)
    table = stage_table(stages)
    generated = {
        "stages.json": table,
        "stage_names.json": {s["name"]: i for i, s in enumerate(table)},
        "excerpts.json": excerpts,
        "steps.json": steps,
        "diffs.json": stage_diffs(stages),
        "goldens.json": goldens(source_root, names),
        "web.json": web_stages.web_data(args.web and os.path.abspath(args.web), names, args.web_measurements, log),
    }
    if not pygments_highlight:
        log("note: python3-pygments is not installed, so the diffs are coloured by line only")
    log(f"{len(stages)} stages, {len(steps)} steps with code, "
        f"{sum(len(b['blocks']) for s in excerpts.values() for f in s.values() for b in f.values())} blocks")

    # 3. Every excerpt and figure the pages ask for must exist.
    renders, derived = check_includes(page_includes(work), excerpts, steps, names)
    renders |= {(n, "", "") for n in names}  # the home page shows every stage

    # 4. Binaries: --help and the images (or an earlier build's, for the tests).
    images = os.path.join(work, "assets", "images")
    if args.reuse:
        with open(os.path.join(args.reuse, "_data", "cli.json"), encoding="utf-8") as f:
            generated["cli.json"] = json.load(f)
        os.makedirs(images, exist_ok=True)
        for render in renders:
            shutil.copyfile(os.path.join(args.reuse, "assets", "images", image_name(*render)),
                            os.path.join(images, image_name(*render)))
        with open(os.path.join(args.reuse, "_data", "derived.json"), encoding="utf-8") as f:
            generated["derived.json"] = {k: v for k, v in json.load(f).items() if k in derived}
        for name in derived:
            shutil.copyfile(os.path.join(args.reuse, "assets", "images", name + ".png"),
                            os.path.join(images, name + ".png"))
    else:
        if not args.bin:
            raise SiteError("--bin is required (or --reuse)")
        generated["cli.json"] = cli_help(stages, os.path.abspath(args.bin))
        render_images(renders, os.path.abspath(args.bin), images, source_root)
        generated["derived.json"] = make_derived(derived, os.path.abspath(args.bin), images)
    if not shutil.which(args.cwebp):
        raise SiteError(f"{args.cwebp}: not found (install the Debian package webp)")
    compress_frames(images, [image_name(*r) for r in renders], args.cwebp)

    for name, value in generated.items():
        with open(os.path.join(data, name), "w", encoding="utf-8") as f:
            json.dump(value, f, indent=1, ensure_ascii=False)
    copy_katex(args.katex, os.path.join(work, "assets", "katex"))
    copy_editor(args.codemirror, source_root, os.path.join(work, "assets", "editor"))

    # 5. Jekyll.
    jekyll_started = time.monotonic()
    output = jekyll_build(args.jekyll, work, dest)
    log(f"jekyll build: {time.monotonic() - jekyll_started:.1f} s, no warnings")
    if args.web:
        web_stages.copy_stages(os.path.abspath(args.web), names, dest)
    if os.environ.get("T10_SITE_VERBOSE"):
        print(output)
    log(f"site written to {dest} in {time.monotonic() - started:.1f} s")


if __name__ == "__main__":
    try:
        main()
    except (SiteError, markers.MarkerError, web_stages.WebError) as e:
        print(f"[site] error: {e}", file=sys.stderr)
        sys.exit(1)
