"""The HTML of the similarity report: similarity.html (the pairs to review, the class's thresholds and
the rule) and similarity/pair-NNNN.html (two submissions side by side, each shared fragment
highlighted in both). Names, paths and contents are the students' and hostile: every one is escaped,
control characters were already replaced (similarity.display_text), and the files are UTF-8.
"""
import html
import os

# Pages are written for the flagged pairs (the first MAX_PAGES) and for the best unflagged ones after
# them, for context.
UNFLAGGED_PAGES = 20
MAX_PAGES = 300
# The overview's table stops here; similarity.csv and similarity.json have every pair.
OVERVIEW_ROWS = 200
CONTEXT = 3  # lines shown around each shared fragment on a pair's page
COLOURS = ["#ffe08a", "#a8e6a1", "#9fd3ff", "#f7b2d9", "#c9b8ff", "#ffc59e", "#b8f0e6", "#e0e0a0"]

STYLE = ("body{font-family:sans-serif;margin:1.5em;color:#111;background:#fff}table{border-collapse:collapse}"
         "td,th{border:1px solid #bbb;padding:.2em .5em;text-align:left}.yes{background:#fdd}"
         ".cols{display:grid;grid-template-columns:minmax(0,1fr) minmax(0,1fr);gap:1em}h1,h2,h3,td{overflow-wrap:anywhere}.file{margin:0 0 1em 0}"
         "pre{margin:0;font-size:12px;line-height:1.35;overflow-x:auto;border:1px solid #ccc;background:#fafafa}"
         "pre span{display:block;white-space:pre}pre b{display:inline-block;width:3.5em;color:#666;font-weight:normal;"
         "user-select:none}.gap{color:#666;background:#eee;font-style:italic}.note{max-width:60em}" +
         "".join(f".m{i}{{background:{c}}}" for i, c in enumerate(COLOURS)))


def esc(text):
    return html.escape(str(text), quote=True)


def head(title, depth):
    return (f"<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>{esc(title)}</title>\n"
            f"<meta name=\"viewport\" content=\"width=device-width\"><style>{STYLE}</style></head><body>\n")


def rule_text(languages, override):
    if override is not None:
        return f"threshold {override:.2f} in either language, the instructor's (--threshold)"
    parts = []
    for name, lang in languages.items():
        if lang.q1 is None:
            count = f"{len(lang.pairs)} pair shares" if len(lang.pairs) == 1 else f"{len(lang.pairs)} pairs share"
            parts.append(f"{name} code {lang.threshold:.2f} (the floor: {count} anything, too few for quartiles)")
        else:
            parts.append(f"{name} code {lang.threshold:.2f} ({len(lang.pairs)} pairs share anything: Q1 "
                         f"{lang.q1:.2f}, Q3 {lang.q3:.2f})")
    return "thresholds: " + "; ".join(parts)


def explanation(template, part):
    return ("<p class=\"note\">Pairs to review, not a verdict. JPlag compared every two submissions of Part "
            f"{part}, the host code and the shaders each in its own run, after removing what the course hands out "
            f"({len(template)} template files: Part 0, the reference of each part up to this one, and the tutorial's "
            "own snippets where the reference fixed them), so two students who typed the tutorial are not paired. "
            "A pair is flagged when its similarity in one language is a far outlier among this class's pairs that "
            "share anything (Q3 + 3 IQR, kept between 0.30 and 0.80; 0.30 when fewer than 20 pairs share anything) "
            "and rests on at least 24 shared tokens. Shared code can "
            "have an honest cause (working together where allowed, a common source the course did not hand out): "
            "open each page and compare the highlighted fragments before you decide anything.</p>\n")


def line_classes(fragments, side):
    """{file: {line: (fragment index, first line of it?)}} of one side's highlighted lines."""
    marks = {}
    for k, fragment in enumerate(fragments):
        where, _, lines = fragment[side].rpartition(":")
        first, _, last = lines.partition("-")
        for line in range(int(first), int(last) + 1):
            marks.setdefault(where, {}).setdefault(line, (k, line == int(first)))
    return marks


def file_block(side, rel, text, marks):
    """One file of one side: the highlighted lines with CONTEXT lines around them; what lies between is
    one line saying how many lines it holds."""
    lines = text.split("\n")
    shown_lines = {n for line in marks for n in range(line - CONTEXT, line + CONTEXT + 1) if 1 <= n <= len(lines)}
    out = [f"<div class=\"file\"><h3>{esc(rel)}</h3><pre>"]
    skipped = 0
    for number, line in enumerate(lines, 1):
        if number not in shown_lines:
            skipped += 1
            continue
        if skipped:
            out.append(f"<span class=\"gap\"><b></b>({skipped} lines)</span>")
            skipped = 0
        mark = marks.get(number)
        if mark is None:
            out.append(f"<span><b>{number}</b>{esc(line)}</span>")
        else:
            anchor = f" id=\"{side}{mark[0] + 1}\"" if mark[1] else ""
            out.append(f"<span class=\"m{mark[0] % len(COLOURS)}\"{anchor} title=\"fragment {mark[0] + 1}\">"
                       f"<b>{number}</b>{esc(line)}</span>")
    if skipped:
        out.append(f"<span class=\"gap\"><b></b>({skipped} lines)</span>")
    out.append("</pre></div>")
    return "".join(out)


def side_column(side, submission, fragments):
    marks = line_classes(fragments, side)
    blocks = [file_block(side, rel, text, marks.get(rel, {})) for rel, _, text in submission.files if rel in marks]
    others = [rel for rel, _, _ in submission.files if rel not in marks]
    more = f"<p>Also handed in, nothing shared: {esc(', '.join(others))}</p>" if others else ""
    return f"<div><h2>{esc(submission.name)}</h2>{''.join(blocks)}{more}</div>"


def pair_page(rank, record, detail, sides, languages, override):
    a, b = sides
    title = f"Pair {rank} to review: {record['a']} and {record['b']}"
    rows = []
    for k, fragment in enumerate(record["fragments"]):
        rows.append(f"<tr><td class=\"m{k % len(COLOURS)}\">{k + 1}</td><td><a href=\"#a{k + 1}\">{esc(fragment['a'])}</a>"
                    f"</td><td><a href=\"#b{k + 1}\">{esc(fragment['b'])}</a></td></tr>")
    similarities = ", ".join(f"{name} code {value:.2f}" for name, value in sorted(detail.items()))
    verdict = ("above this class's threshold: worth a look" if record["flagged"]
               else "below this class's threshold: shown for context")
    return (head(title, 1) + f"<p><a href=\"../similarity.html\">All pairs to review</a></p>\n<h1>{esc(title)}</h1>\n"
            f"<p>Score {record['score']:.2f} ({similarities}); {record['matched_tokens']} shared tokens beyond the "
            f"template; {verdict}; {esc(rule_text(languages, override))}. The same colour marks the same fragment "
            "on both sides; the lines between fragments are left out. Nothing here was run: the files were only read.</p>\n"
            f"<table><tr><th>fragment</th><th>{esc(record['a'])}</th><th>{esc(record['b'])}</th></tr>\n"
            + "\n".join(rows) + "</table>\n<div class=\"cols\">" + side_column("a", a, record["fragments"])
            + side_column("b", b, record["fragments"]) + "</div>\n</body></html>\n")


def overview(pairs, pages_of, languages, submissions, override, template, part):
    flagged = sum(1 for p in pairs if p[0]["flagged"])
    out = [head(f"Tutorial 10 Part {part}: pairs to review", 0),
           f"<h1>Tutorial 10 Part {part}: {flagged} pairs to review</h1>\n", explanation(template, part),
           f"<p>This class's {esc(rule_text(languages, override))}. {len(submissions)} submissions; "
           f"{len(pairs)} pairs share something beyond the template. Every pair is in "
           "<a href=\"similarity.csv\">similarity.csv</a> and <a href=\"similarity.json\">similarity.json</a>.</p>\n"]
    unread = sorted({s for lang in languages.values() for s in lang.unreadable})
    if unread:
        names = {s.id: s.name for s in submissions}
        out.append("<p>JPlag could not read (not compared in that language): "
                   + esc(", ".join(names[i] for i in unread)) + "</p>\n")
    out.append("<table><tr><th>rank</th><th>a</th><th>b</th><th>score</th><th>shared tokens</th><th>flagged</th>"
               "<th>side by side</th></tr>\n")
    for rank, (record, _, _) in enumerate(pairs[:OVERVIEW_ROWS], 1):
        page = pages_of.get(rank)
        link = f"<a href=\"{esc(page)}\">pair {rank}</a>" if page else ""
        cls = " class=\"yes\"" if record["flagged"] else ""
        out.append(f"<tr{cls}><td>{rank}</td><td>{esc(record['a'])}</td><td>{esc(record['b'])}</td>"
                   f"<td>{record['score']:.2f}</td><td>{record['matched_tokens']}</td>"
                   f"<td>{'yes' if record['flagged'] else 'no'}</td><td>{link}</td></tr>\n")
    out.append("</table>\n</body></html>\n")
    return "".join(out)


def write_pages(write, report, pairs, languages, submissions, override, template, part):
    """Writes the overview and the pair pages with write(path, text); returns {rank: page path relative
    to report}."""
    folder = os.path.join(report, "similarity")
    os.makedirs(folder, exist_ok=True)
    for name in os.listdir(folder):  # pages of an earlier run
        if name.startswith("pair-") and name.endswith(".html"):
            os.unlink(os.path.join(folder, name))
    pages_of = {}
    unflagged = 0
    for rank, (record, detail, sides) in enumerate(pairs, 1):
        if not record["flagged"]:
            unflagged += 1
            if unflagged > UNFLAGGED_PAGES:
                continue
        if len(pages_of) >= MAX_PAGES:
            break
        page = f"similarity/pair-{rank:04d}.html"
        write(os.path.join(report, page), pair_page(rank, record, detail, sides, languages, override))
        pages_of[rank] = page
    write(os.path.join(report, "similarity.html"),
                     overview(pairs, pages_of, languages, submissions, override, template, part))
    return pages_of
