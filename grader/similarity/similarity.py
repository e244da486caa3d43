#!/usr/bin/env python3
"""Pairs of students of one part who share work beyond what the course hands out (issue 51).

usage: similarity.py --part 1|2|3 --report DIR --engine DIR [--threshold X] [--no-template]
                     [--manifest FILE] [--folder DIR] [--java JAVA] [SUBMISSION...]

Compares every pair of submissions with JPlag 4.3.0 (make similarity-deps installs it into ENGINE),
the host code and the shaders each in their own run, with the template excluded as JPlag's base
code: Part 0, the reference of the part and of the parts before it, and the tutorial's own snippets
where the reference fixed them (template/). Writes into DIR: similarity.json (the issue's shape),
similarity.csv, similarity.html (the pairs to review) and similarity/pair-NNNN.html (each pair side
by side, the shared fragments highlighted).

Submissions: SUBMISSION folders (named after their last component), every folder inside --folder DIR,
or --manifest FILE, pairs of NAME NUL PATH NUL (t10-grade --similarity writes one with the names of
its report folders). Their files are only read: regular files with a host (.cpp, .h ...)
or shader (.frag, .vert ...) suffix, no symlinks, 256 KiB each, 64 per submission.

--threshold X flags every pair whose similarity in either language reaches X (with 24 shared tokens)
instead of the class's own threshold (see flag_threshold); --no-template compares without the template (to see what it
removes). Exit 0 with the files written, 1 naming the fault (no Java, no engine, JPlag's failure), 2 on
bad usage.
"""
import argparse
import csv
import io
import json
import os
import shutil
import stat
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blocks  # noqa: E402  (beside this file)
import pages  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE_ROOT = os.path.dirname(os.path.dirname(HERE))
LOCK = os.path.join(HERE, "jplag.lock")
DRIVER = os.path.join(HERE, "JPlagPairs.java")

# Each language is compared in its own JPlag run; JPlag's C/C++ scanner reads both (GLSL is C-like).
LANGUAGES = {
    "host": (".cpp", ".cc", ".cxx", ".hpp", ".h", ".hh", ".inl"),
    "shader": (".vert", ".frag", ".geom", ".comp", ".tesc", ".tese", ".glsl"),
}
MAX_FILE_BYTES = 256 * 1024  # as t10-grade's copy of a submission
MAX_FILES = 64
MAX_DEPTH = 6
# The stage folders of the template: Part 0 and the reference of each part.
STAGES = ["tutorial10_part0_start", "tutorial10_part1_tonemap", "tutorial10_part2_bloom", "tutorial10_part3_gaussian"]
HANDED_OUT = ["common/shaders/FullScreenQuad.vert"]  # shaders a part uses but students do not write

# The class's threshold (flag_threshold): Tukey's far-out fence over the similarities of the pairs
# that share anything beyond the template, kept within [FLOOR, CEILING]; and a pair needs MIN_EVIDENCE
# shared tokens in the language that flags it.
FENCE_IQRS = 3.0
FLOOR = 0.3
CEILING = 0.8
MIN_SAMPLE = 20  # fewer pairs sharing anything give no quartiles worth the name: the floor
MIN_EVIDENCE = 24  # two minimum matches
MIN_MATCH = 12  # JPlag's default for its C/C++ scanner


class Fault(Exception):
    """A failure to report in one line with exit status 1."""


def shown(c):
    """Whether a character is shown as itself: not a control character nor a bidirectional override
    (which would let code read in another order than it runs)."""
    return c >= " " and c != "\x7f" and not ("\u202a" <= c <= "\u202e" or "\u2066" <= c <= "\u2069")


def display_name(raw):
    """A path or name as text: undecodable bytes, control characters and bidi overrides replaced."""
    text = os.fsencode(raw).decode("utf-8", "replace") if isinstance(raw, str) else raw.decode("utf-8", "replace")
    return "".join(c if shown(c) else "\ufffd" for c in text)


def display_text(data):
    """File contents as text with lines: UTF-8 (else U+FFFD), what display_name replaces but tabs replaced."""
    text = data.decode("utf-8", "replace").replace("\r\n", "\n").replace("\r", "\n")
    return "".join(c if c in "\n\t" or shown(c) else "\ufffd" for c in text)


def read_regular(path):
    """The bytes of the regular file at `path` (never through a symlink), or None (too big, not regular)."""
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK)
    except OSError:
        return None
    with os.fdopen(fd, "rb") as f:
        info = os.fstat(f.fileno())
        if not stat.S_ISREG(info.st_mode) or info.st_size > MAX_FILE_BYTES:
            return None
        return f.read(MAX_FILE_BYTES + 1)[:MAX_FILE_BYTES]


def language_of(name):
    lower = name.lower()
    for language, suffixes in LANGUAGES.items():
        if lower.endswith(suffixes):
            return language
    return None


def collect(folder):
    """[(relative path as text, language, text)] of a submission's code files, sorted by path."""
    found = []

    def walk(path, rel, depth):
        try:
            entries = sorted(os.scandir(path), key=lambda e: e.name)
        except OSError:
            return
        for entry in entries:
            if len(found) >= MAX_FILES:
                return
            name = os.path.join(rel, entry.name) if rel else entry.name
            if entry.is_dir(follow_symlinks=False):
                if depth < MAX_DEPTH:
                    walk(entry.path, name, depth + 1)
            elif entry.is_file(follow_symlinks=False) and language_of(entry.name):
                data = read_regular(entry.path)
                if data is not None:
                    found.append((display_name(name), language_of(entry.name), display_text(data)))

    walk(folder, "", 0)
    return found


class Submission:
    def __init__(self, index, name, path):
        self.id = f"s{index:04d}"
        self.name = display_name(name)  # what the report shows: valid UTF-8, no control characters
        self.files = collect(path)
        self.staged = {}  # language -> {staged file name: (index into files, its first line there - 1)}


def write_blocks(text, folder, stem, suffix):
    """Writes each top-level block of `text` into folder/<stem>b<NNN><suffix>; returns {file name: the
    line of `text` before the block's first}."""
    lines = text.split("\n")
    written = {}
    for j, (first, last) in enumerate(blocks.blocks(lines)):
        name = f"{stem}b{j:03d}{suffix}"
        with open(os.path.join(folder, name), "w", encoding="utf-8") as out:
            out.write("\n".join(lines[first: last + 1]) + "\n")
        written[name] = first
    return written


def stage(submissions, work):
    """Copies each language's files of each submission under work/<language>/<id>/, a file per top-level
    block (blocks.py says why), with plain names."""
    for s in submissions:
        for i, (rel, language, text) in enumerate(s.files):
            folder = os.path.join(work, language, s.id)
            os.makedirs(folder, exist_ok=True)
            for name, offset in write_blocks(text, folder, f"f{i:02d}", os.path.splitext(rel)[1].lower()).items():
                s.staged.setdefault(language, {})[name] = (i, offset)


def template_files(part):
    """The repository paths of the template of `part` (what the course hands out)."""
    paths = []
    for stage_folder in STAGES[: part + 1]:
        folder = os.path.join(SOURCE_ROOT, stage_folder)
        paths += [f"{stage_folder}/{n}" for n in sorted(os.listdir(folder)) if language_of(n)]
    paths += [p for p in HANDED_OUT if os.path.isfile(os.path.join(SOURCE_ROOT, p))]
    snippets = os.path.join(HERE, "template")
    paths += [f"grader/similarity/template/{n}" for n in sorted(os.listdir(snippets)) if language_of(n)]
    return paths


def stage_template(paths, work):
    """work/template-<language>/ with the template's files of each language (flattened, numbered)."""
    for i, path in enumerate(paths):
        language = language_of(path)
        folder = os.path.join(work, f"template-{language}")
        os.makedirs(folder, exist_ok=True)
        with open(os.path.join(SOURCE_ROOT, path), encoding="utf-8") as source:
            write_blocks(source.read(), folder, f"t{i:02d}", os.path.splitext(path)[1])


def check_engine(engine, java):
    """The java program to run; Fault naming what to install when Java or the engine is missing."""
    program = shutil.which(java) if java else shutil.which("java")
    if java and not program:
        raise Fault(f"--java {java}: no such program")
    if not program:
        raise Fault("Java is not installed: make similarity-deps installs it (Debian's default-jre-headless) "
                    "and JPlag")
    try:
        with open(os.path.join(engine, "lock"), encoding="utf-8") as installed, open(LOCK, encoding="utf-8") as lock:
            current = installed.read() == lock.read()
    except OSError:
        current = False
    if not current:
        raise Fault(f"JPlag is not installed in {engine}/ (or not the version of grader/similarity/jplag.lock): "
                    "run make similarity-deps")
    return program


def locked_version():
    """JPlag's version in jplag.lock (what the report says when no run printed its own)."""
    with open(LOCK, encoding="utf-8") as lock:
        for line in lock:
            if line.startswith("de.jplag:jplag:"):
                return line.split()[0].split(":")[2]
    return ""


# A class of up to SMALL_CLASS students is a few seconds of JPlag, which the JVM spends mostly compiling:
# there its optimising compiler (C2) and the parallel collector's threads cost more CPU than they save,
# so it runs with the quick compiler alone and one collector thread (make test's generated class of 40:
# 10.7 CPU s with the defaults, 6.6 with these, the same pairs and scores). A larger class (make
# bench-similarity's 900) keeps the JVM's defaults, where C2's code pays for itself.
SMALL_CLASS = 200
SMALL_CLASS_JVM = ["-XX:TieredStopAtLevel=1", "-XX:CICompilerCount=1", "-XX:+UseSerialGC"]


def run_engine(java, engine, work, language, no_template):
    """Runs JPlagPairs over work/<language>/; returns the lines of its output, split on tabs."""
    out = os.path.join(work, f"{language}.tsv")
    base = os.path.join(work, f"template-{language}")
    if no_template or not os.path.isdir(base):
        base = "-"  # none
    small = len(os.listdir(os.path.join(work, language))) <= SMALL_CLASS
    command = [java] + (SMALL_CLASS_JVM if small else []) + [
        "-cp", os.path.join(engine, "lib", "*"), DRIVER, "cpp", os.path.join(work, language), base,
        ",".join(LANGUAGES[language]), str(MIN_MATCH), out]
    result = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, errors="replace")
    if result.returncode != 0 and "Not enough valid submissions" in result.stderr:
        return []  # fewer than two submissions with a block of 12 tokens in this language: nothing to pair
    if result.returncode != 0:
        tail = "\n".join(result.stderr.strip().splitlines()[-5:])
        raise Fault(f"JPlag failed on the {language} code (exit {result.returncode}): {tail}")
    with open(out, encoding="utf-8") as f:
        return [line.rstrip("\n").split("\t") for line in f]


def quantile(values, q):
    """The q-quantile of sorted `values` (linear between neighbours)."""
    if not values:
        return 0.0
    at = q * (len(values) - 1)
    low = int(at)
    high = min(low + 1, len(values) - 1)
    return values[low] + (values[high] - values[low]) * (at - low)


def flag_threshold(similarities):
    """The class's threshold for one language: Q3 + 3 IQR of the similarities of the pairs that share
    anything beyond the template (a far outlier of this class's coincidences: JPlag matches any run of
    12 tokens, and the scanner's tokens are few, so honest students share short runs), never below
    FLOOR (less is a small part of what two students wrote beyond the template) nor above CEILING (a
    class with many copies would otherwise raise its own fence above them); FLOOR itself where fewer
    than MIN_SAMPLE pairs share anything. Returns (threshold, q1, q3)."""
    values = sorted(similarities)
    if len(values) < MIN_SAMPLE:
        return FLOOR, None, None
    q1, q3 = quantile(values, 0.25), quantile(values, 0.75)
    return min(CEILING, max(FLOOR, q3 + FENCE_IQRS * (q3 - q1))), q1, q3


class Language:
    """One language's run: its submissions, pairs (scored) and threshold.

    A pair's similarity is JPlag's average similarity, 2 M / (A + B), over the code that can match: A
    and B count a submission's tokens beyond the template in the blocks of at least JPlag's minimum
    match (a shorter block matches nothing, the template included, and JPlag's own count would weigh
    it, and one end-of-file token per block, against every pair)."""

    def __init__(self, name, rows, by_id):
        self.name = name
        self.version, self.module, self.min_match = "", "", 0
        self.compared, self.unreadable = [], []
        self.pairs = {}  # (id a, id b) -> [similarity, matched tokens, [(a side, b side, tokens)]]
        matchable = {}  # id -> tokens that can match, beyond the template
        current = None
        for row in rows:
            if row[0] == "V":
                self.version, self.module, self.min_match = row[1], row[2], int(row[3])
            elif row[0] == "S":
                current = row[1]
                (self.compared if row[4] == "1" else self.unreadable).append(current)
                matchable[current] = -int(row[3])
            elif row[0] == "F" and int(row[2]) >= self.min_match:
                matchable[current] += int(row[2])
            elif row[0] == "P":
                a, b = sorted((row[1], row[2]), key=lambda i: by_id[i].name)
                swap = a != row[1]
                current = self.pairs[(a, b)] = [0.0, int(row[4]), [], swap]
                current[0] = min(1.0, 2 * current[1] / max(1, matchable[a] + matchable[b]))
            elif row[0] == "M":
                first, second = (row[1:4], row[4:7]) if not current[3] else (row[4:7], row[1:4])
                current[2].append((first, second, int(row[7])))
        self.threshold, self.q1, self.q3 = flag_threshold([p[0] for p in self.pairs.values()])

    def flags(self, key, override):
        similarity, matched = self.pairs[key][0], self.pairs[key][1]
        threshold = self.threshold if override is None else override
        return similarity >= threshold and matched >= MIN_EVIDENCE


def fragment_text(submission, language, side):
    """'file:first-last' in the lines of the student's file."""
    staged, first, last = side
    index, offset = submission.staged[language][staged]
    return f"{submission.files[index][0]}:{int(first) + offset}-{int(last) + offset}"


def build_pairs(languages, by_id, override):
    """The issue's pair records, sorted by score (then shared tokens, then names), and per pair the
    details the pages need."""
    keys = sorted({key for lang in languages.values() for key in lang.pairs})
    pairs = []
    for key in keys:
        a, b = by_id[key[0]], by_id[key[1]]
        score, matched, flagged, fragments, detail = 0.0, 0, False, [], {}
        for name, lang in languages.items():
            if key not in lang.pairs:
                continue
            similarity, tokens, matches, _ = lang.pairs[key]
            score, matched = max(score, similarity), matched + tokens
            flagged = flagged or lang.flags(key, override)
            detail[name] = similarity
            for first, second, length in matches:
                fragments.append({"a": fragment_text(a, name, first), "b": fragment_text(b, name, second)})
        record = {"a": a.name, "b": b.name, "score": round(score, 4), "matched_tokens": matched, "flagged": flagged,
                  "fragments": fragments}
        pairs.append((record, detail, (a, b)))
    pairs.sort(key=lambda p: (-p[0]["score"], -p[0]["matched_tokens"], p[0]["a"], p[0]["b"]))
    return pairs


def write_atomically(path, text):
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    partial = path + ".partial"
    with open(partial, "w", encoding="utf-8", newline="") as out:
        out.write(text)
    os.replace(partial, path)


def spreadsheet_cell(text):
    """A cell a spreadsheet shows as text: a leading =, +, - or @ would make it a formula."""
    return "'" + text if text[:1] in ("=", "+", "-", "@", "\t", "\r") else text


def csv_text(pairs, pages_of):
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(["rank", "a", "b", "score", "host_similarity", "shader_similarity", "matched_tokens", "flagged", "page"])
    for rank, (record, detail, _) in enumerate(pairs, 1):
        writer.writerow([rank, spreadsheet_cell(record["a"]), spreadsheet_cell(record["b"]), record["score"],
                         round(detail.get("host", 0.0), 4), round(detail.get("shader", 0.0), 4), record["matched_tokens"],
                         "yes" if record["flagged"] else "no", pages_of.get(rank, "")])
    return out.getvalue()


def parse_args(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--part", type=int, choices=(1, 2, 3), required=True)
    parser.add_argument("--report", required=True)
    parser.add_argument("--engine", required=True)
    parser.add_argument("--threshold", type=float)
    parser.add_argument("--no-template", action="store_true")
    parser.add_argument("--manifest")
    parser.add_argument("--folder")
    parser.add_argument("--java")
    parser.add_argument("submissions", nargs="*")
    args = parser.parse_args(argv)
    if args.threshold is not None and not 0.0 < args.threshold <= 1.0:
        parser.error(f"--threshold {args.threshold}: choose a similarity in (0, 1]")
    return parser, args


def submissions_of(parser, args):
    """[(name, path)] from the arguments; a usage error for a folder that is not one, or a repeated name."""
    named = []
    if args.manifest:
        try:
            with open(args.manifest, "rb") as f:
                fields = f.read().split(b"\0")
        except OSError as error:
            parser.error(f"--manifest {args.manifest}: {error.strerror}")
        if len(fields) % 2 != 1 or fields[-1]:
            parser.error(f"--manifest {args.manifest}: not NAME NUL PATH NUL pairs")
        named += [(os.fsdecode(fields[i]), os.fsdecode(fields[i + 1])) for i in range(0, len(fields) - 1, 2)]
    if args.folder:
        if not os.path.isdir(args.folder):
            parser.error(f"--folder {args.folder}: not a folder")
        named += [(e.name, e.path) for e in sorted(os.scandir(args.folder), key=lambda e: e.name)
                  if e.is_dir(follow_symlinks=False)]
    named += [(os.path.basename(os.path.normpath(p)), p) for p in args.submissions]
    seen = set()
    for name, path in named:
        if not os.path.isdir(path):
            parser.error(f"{display_name(path)}: not a folder")
        if name in seen:
            parser.error(f"two submissions are named '{display_name(name)}'")
        seen.add(name)
    if len(named) < 2:
        parser.error("give at least two submissions to compare")
    return named


def main(argv):
    parser, args = parse_args(argv)
    named = submissions_of(parser, args)
    try:
        java = check_engine(args.engine, args.java)
        submissions = [Submission(i, name, path) for i, (name, path) in enumerate(named)]
        by_id = {s.id: s for s in submissions}
        template = [] if args.no_template else template_files(args.part)
        with tempfile.TemporaryDirectory(prefix="t10-similarity-") as work:
            stage(submissions, work)
            stage_template(template, work)
            languages = {}
            for language in LANGUAGES:
                having = [s for s in submissions if language in s.staged]
                if len(having) >= 2:
                    languages[language] = Language(language, run_engine(java, args.engine, work, language,
                                                                         args.no_template), by_id)
        pairs = build_pairs(languages, by_id, args.threshold)
        version = next((lang.version for lang in languages.values() if lang.version), locked_version())
        result = {"engine": "JPlag", "version": version, "template": template, "pairs": [p[0] for p in pairs]}
        write_atomically(os.path.join(args.report, "similarity.json"), json.dumps(result, indent=1, ensure_ascii=False) + "\n")
        pages_of = pages.write_pages(write_atomically, args.report, pairs, languages, submissions, args.threshold, template, args.part)
        write_atomically(os.path.join(args.report, "similarity.csv"), csv_text(pairs, pages_of))
    except Fault as fault:
        print(f"similarity: error: {fault}", file=sys.stderr)
        return 1
    flagged = sum(1 for p in pairs if p[0]["flagged"])
    print(f"similarity: {len(submissions)} submissions, {flagged} pairs to review; wrote similarity.json, "
          f"similarity.csv and similarity.html in {args.report}/")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
