#!/usr/bin/env python3
"""Students' TGA loaders graded by t10-grade-tga: the project's own loader and mutants of it, each a
tga.cpp written from common/content/src/tga.cpp, and what each must get. The helpers that write and
grade a loader are shared with the hostile suite (hostile/tga_attacks.py: the cheat and the attacks).

usage: tga_loaders.py mutants SOURCE_DIR T10_GRADE_TGA OUT_DIR
  the project's loader scores 100; each mutant (flip, swap, crash, hang, accept, throw) fails the case it
  breaks with its verdict (isolation auto); every score earns the malformed-file cases only in
  proportion to the valid files decoded, so the loader that throws on every file scores 0 (it scored
  35, 10 malformed cases of 28, before issue 38)
Exit 0 when every expectation holds, 1 with the failures listed, 77 (skipped) where no sandbox can be
had here (no working bwrap, and not root for the uid fallback)."""
import json
import os
import shutil
import subprocess
import sys
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from hostile_support import skip  # noqa: E402 (grader/tests/)

SIGNATURE = "Image8 loadTga(const std::string& path) {"
HEADER_BYTES = "const std::vector<std::uint8_t> header = readFile(path);\n"
# RLE true colour, 24 bits, bottom-left origin: rgb24_rle_bl and wide_rgb24_rle_bl.
IS_RLE24_BL = "header.size() > 17 && header[2] == 10 && header[16] == 24 && !(header[17] & 0x20)"


def project_loader(source):
    """common/content/src/tga.cpp, the loader every test loader starts from."""
    text = open(os.path.join(source, "common", "content", "src", "tga.cpp")).read()
    assert SIGNATURE in text, "common/content/src/tga.cpp changed: update tga_loaders.py"
    return text


def wrapped(loader, body, includes=""):
    """The project's loader renamed correctLoadTga, and a loadTga whose body is `body` (C++ in namespace t10)."""
    return (includes + loader.replace(SIGNATURE, "Image8 correctLoadTga(const std::string& path) {") +
            "\nnamespace t10 {\nImage8 loadTga(const std::string& path) {\n" + body + "\n}\n} // namespace t10\n")


def bwrap_works():
    """'' where bubblewrap can create namespaces here, else why not."""
    if not shutil.which("bwrap"):
        return "bwrap not installed"
    probe = subprocess.run(["bwrap", "--unshare-all", "--ro-bind", "/usr", "/usr", "--symlink", "usr/lib", "/lib",
                            "--symlink", "usr/lib64", "/lib64", "--proc", "/proc", "--dev", "/dev", "/usr/bin/true"],
                           capture_output=True, text=True)
    return "" if probe.returncode == 0 else probe.stderr.strip() or f"bwrap exit {probe.returncode}"


def write_loader(subs, name, text):
    folder = os.path.join(subs, name)
    os.makedirs(folder)
    with open(os.path.join(folder, "tga.cpp"), "w") as f:
        f.write(text)
    return folder


def grade_loader(grader, subs, reports, cwd, name, isolation, fail):
    """Grades SUBS/NAME: (the report as a dict, the finished process, seconds)."""
    report = os.path.join(reports, name + ".json")
    command = [grader, "--timeout", "2", "--report", report] + (["--isolation", isolation] if isolation else []) + [
        os.path.join(subs, name)]
    start = time.time()
    run = subprocess.run(command, cwd=cwd, capture_output=True, text=True, errors="replace", timeout=300)
    seconds = time.time() - start
    if run.returncode != 0:
        fail(f"{name}: t10-grade-tga exit {run.returncode}: {run.stderr[-500:]}")
        return {"score": -1, "status": "?", "cases": []}, run, seconds
    result = json.load(open(report))
    print(f"tga {name}: {result['status']}, score {result['score']} in {seconds:.1f} s")
    return result, run, seconds


def verdicts(result):
    return {c["file"]: c["verdict"] for c in result.get("cases", [])}


def grade_in_pairs(grader, subs, reports, cwd, names, isolation, fail):
    """Grades NAMES two at a time (each build and each case is a process of its own): {name: grade_loader's}."""
    results = {}
    threads = [threading.Thread(target=lambda n=n: results.__setitem__(n, grade_loader(grader, subs, reports, cwd, n, isolation, fail)))
               for n in names]
    for i in range(0, len(threads), 2):
        for t in threads[i:i + 2]:
            t.start()
        for t in threads[i:i + 2]:
            t.join()
    return results


def mutants(loader):
    """name: (tga.cpp, {case: the verdict it must get})."""
    return {
        "reference": (loader, {}),
        "flip": (wrapped(loader, """Image8 image = correctLoadTga(path);
        for (int y = 0; y < image.height / 2; ++y) for (int x = 0; x < image.width; ++x) for (int c = 0; c < image.channels; ++c)
            std::swap(image.at(x, y, c), image.at(x, image.height - 1 - y, c));
        return image;"""), {"rgb24_raw_bl": "wrong orientation"}),
        "swap": (wrapped(loader, """Image8 image = correctLoadTga(path);
        if (image.channels >= 3) for (int y = 0; y < image.height; ++y) for (int x = 0; x < image.width; ++x)
            std::swap(image.at(x, y, 0), image.at(x, y, 2));
        return image;"""), {"rgb24_raw_bl": "wrong channel order"}),
        "crash": (wrapped(loader, "std::raise(SIGSEGV);\nreturn correctLoadTga(path);", "#include <csignal>\n"),
                  {"rgb24_raw_bl": "crash", "malformed_empty": "crash"}),
        "hang": (wrapped(loader, HEADER_BYTES + f"if ({IS_RLE24_BL}) for (;;) ::sleep(1);\nreturn correctLoadTga(path);",
                         "#include <unistd.h>\n"),
                 {"rgb24_rle_bl": "hang", "rgb24_raw_bl": "right pixels"}),
        "accept": (wrapped(loader, "try { return correctLoadTga(path); } catch (const Error&) { return Image8(1, 1, 3); }"),
                   {"malformed_zero_width": "accepted a malformed file", "rgb24_raw_bl": "right pixels"}),
        # Decodes nothing: it rejects every malformed file too, which must earn nothing (issue 38).
        "throw": (wrapped(loader, 'throw Error(path + ": not supported");'),
                  {"rgb24_raw_bl": "rejected a valid file", "malformed_empty": "rejected"}),
    }


def fair_score(result):
    """The score the cases' verdicts earn: every case weighs the same, a rejected malformed file only the
    share of the valid files decoded (so a loader that decodes nothing scores 0), in whole points."""
    cases = result.get("cases", [])
    valid = [c for c in cases if not c["malformed"]]
    decoded = sum(c["passed"] for c in valid)
    rejected = sum(c["passed"] for c in cases if c["malformed"])
    if not cases or not valid:
        return 0
    return 100 * (decoded * len(valid) + rejected * decoded) // (len(cases) * len(valid))


def main():
    if len(sys.argv) != 5 or sys.argv[1] != "mutants":
        sys.exit(__doc__)
    _, _, source, grader, out = sys.argv
    failures = []

    def fail(text):
        failures.append(text)
        print("FAIL " + text)

    # --isolation auto: bwrap, else the uid fallback (root only), else no sandbox at all.
    why = "" if os.geteuid() == 0 else bwrap_works()
    if why:
        skip("bubblewrap cannot create namespaces here and the uid fallback needs root: " + why)
    shutil.rmtree(out, ignore_errors=True)
    subs, reports, cwd = (os.path.join(out, d) for d in ("submissions", "reports", "cwd"))
    for d in (subs, reports, cwd):
        os.makedirs(d)
    os.chmod(subs, 0o700)  # the instructor's submissions folder is private (instructors.md)
    table = mutants(project_loader(source))
    for name, (text, _) in table.items():
        write_loader(subs, name, text)
    results = grade_in_pairs(grader, subs, reports, cwd, list(table), None, fail)
    for name, (_, expected) in table.items():
        result = results[name][0]
        got = verdicts(result)

        def expect(condition, what):
            print(f"ok   {name}: {what}") if condition else fail(f"{name}: expected {what}")
        if name == "reference":
            expect(result["score"] == 100, f"score 100 (got {result['score']})")
        for case, verdict in expected.items():
            expect(got.get(case) == verdict, f"{case}: {verdict} (got {got.get(case)})")
        if name != "reference":
            expect(result["score"] < 100, f"below 100 (got {result['score']})")
        expect(result["score"] == fair_score(result), f"score {fair_score(result)}, the malformed cases earned in proportion "
               f"to the valid files decoded (got {result['score']})")
        if name == "throw":
            expect(result["score"] == 0, f"score 0 for a loader that decodes nothing (got {result['score']})")
    shutil.rmtree(out, ignore_errors=True)
    print(f"{len(failures)} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
