#!/usr/bin/env python3
"""Students' TGA loaders graded by t10-grade-tga: the project's own loader, mutants of it, a cheat and
hostile loaders, each a tga.cpp written from common/content/src/tga.cpp, and what each must get.

usage: tga_loaders.py mutants|namespaces|uid SOURCE_DIR T10_GRADE_TGA OUT_DIR
  mutants     the project's loader scores 100; each mutant (flip, swap, crash, hang, accept) fails the
              case it breaks with its verdict (isolation auto)
  namespaces  the cheat (decodes the PNG lying beside the input, or the fixture's PNG in the checkout)
  uid         passes no valid case; the attacks (read the reference, write outside, network, fork
              bomb, hang) are contained and the loaders they wrap keep 100
Exit 0 when every expectation holds, 1 with the failures listed, 77 (skipped) where the isolation
cannot be had here (no working bwrap; not root for uid)."""
import json
import os
import secrets
import shutil
import socket
import subprocess
import sys
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from hostile_support import closed_folder, skip, Listener  # noqa: E402 (grader/tests/)

MODE, SOURCE, GRADER, OUT = sys.argv[1:5]
FIXTURES = os.path.join(SOURCE, "tests", "fixtures", "tga")
LOADER = open(os.path.join(SOURCE, "common", "content", "src", "tga.cpp")).read()
SIGNATURE = "Image8 loadTga(const std::string& path) {"
assert SIGNATURE in LOADER, "common/content/src/tga.cpp changed: update tga_loaders.py"
FAILURES = []
TOKEN = secrets.token_hex(6)


def fail(text):
    FAILURES.append(text)
    print("FAIL " + text)


def wrapped(body, includes=""):
    """The project's loader renamed correctLoadTga, and a loadTga whose body is `body` (C++ in namespace t10)."""
    return (includes + LOADER.replace(SIGNATURE, "Image8 correctLoadTga(const std::string& path) {") +
            "\nnamespace t10 {\nImage8 loadTga(const std::string& path) {\n" + body + "\n}\n} // namespace t10\n")


HEADER_BYTES = "const std::vector<std::uint8_t> header = readFile(path);\n"
# RLE true colour, 24 bits, bottom-left origin: rgb24_rle_bl and wide_rgb24_rle_bl.
IS_RLE24_BL = "header.size() > 17 && header[2] == 10 && header[16] == 24 && !(header[17] & 0x20)"

MUTANTS = {
    "reference": (LOADER, {}),
    "flip": (wrapped("""Image8 image = correctLoadTga(path);
        for (int y = 0; y < image.height / 2; ++y) for (int x = 0; x < image.width; ++x) for (int c = 0; c < image.channels; ++c)
            std::swap(image.at(x, y, c), image.at(x, image.height - 1 - y, c));
        return image;"""), {"rgb24_raw_bl": "wrong orientation"}),
    "swap": (wrapped("""Image8 image = correctLoadTga(path);
        if (image.channels >= 3) for (int y = 0; y < image.height; ++y) for (int x = 0; x < image.width; ++x)
            std::swap(image.at(x, y, 0), image.at(x, y, 2));
        return image;"""), {"rgb24_raw_bl": "wrong channel order"}),
    "crash": (wrapped("std::raise(SIGSEGV);\nreturn correctLoadTga(path);", "#include <csignal>\n"),
              {"rgb24_raw_bl": "crash", "malformed_empty": "crash"}),
    "hang": (wrapped(HEADER_BYTES + f"if ({IS_RLE24_BL}) for (;;) ::sleep(1);\nreturn correctLoadTga(path);", "#include <unistd.h>\n"),
             {"rgb24_rle_bl": "hang", "rgb24_raw_bl": "right pixels"}),
    "accept": (wrapped("try { return correctLoadTga(path); } catch (const Error&) { return Image8(1, 1, 3); }"),
               {"malformed_zero_width": "accepted a malformed file", "rgb24_raw_bl": "right pixels"}),
}

# Decodes the PNG beside the input (the cheat of issue 29: `cp "${1%.tga}.png" "$2"` scored 100), or
# failing that the PNG of the fixture whose bytes the input has, found in the checkout.
CHEAT = f"""#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>
#include "t10/error.hpp"
#include "t10/file.hpp"
#include "t10/tga.hpp"
#include <dirent.h>
#include <string>
namespace t10 {{
namespace {{
Image8 decodePng(const std::string& png) {{
    int w = 0, h = 0, n = 0;
    unsigned char* pixels = stbi_load(png.c_str(), &w, &h, &n, 0);
    if (pixels == nullptr) throw Error(png + ": no PNG to copy");
    Image8 image(w, h, n);
    for (int y = 0; y < h; ++y) for (int x = 0; x < w; ++x) for (int c = 0; c < n; ++c)
        image.at(x, h - 1 - y, c) = pixels[(static_cast<std::size_t>(y) * w + x) * n + c];
    stbi_image_free(pixels);
    return image;
}}
std::string fixtureLike(const std::string& path) {{
    const std::vector<std::uint8_t> input = readFile(path);
    DIR* dir = ::opendir({json.dumps(FIXTURES)});
    if (dir == nullptr) return "";
    std::string found;
    while (const dirent* e = ::readdir(dir)) {{
        const std::string name = e->d_name;
        if (name.size() < 4 || name.substr(name.size() - 4) != ".tga") continue;
        const std::string full = std::string({json.dumps(FIXTURES)}) + "/" + name;
        try {{ if (readFile(full) == input) found = full.substr(0, full.size() - 4) + ".png"; }} catch (const Error&) {{}}
    }}
    ::closedir(dir);
    return found;
}}
}} // namespace
Image8 loadTga(const std::string& path) {{
    try {{ return decodePng(path.substr(0, path.size() - 4) + ".png"); }} catch (const Error&) {{}}
    return decodePng(fixtureLike(path));
}}
}} // namespace t10
"""

if MODE not in ("mutants", "namespaces", "uid"):
    sys.exit(f"tga_loaders.py: {MODE}: choose mutants, namespaces or uid")
if MODE == "uid" and os.geteuid() != 0:
    skip("the uid fallback needs root (one unprivileged uid per job)")
if MODE == "uid" and (closed_folder(SOURCE) or closed_folder(OUT)):
    # The grader refuses the uid fallback for a checkout its job uids cannot enter, by design (one line
    # naming the folder; grader/tests/private_checkout.py proves that refusal), so nothing here can run.
    skip(f"{closed_folder(SOURCE) or closed_folder(OUT)} lets no one else in: the uid fallback refuses such a checkout")
if MODE in ("namespaces", "mutants") and not (MODE == "mutants" and os.geteuid() == 0):
    # mutants grade with --isolation auto: bwrap, else the uid fallback (root only), else no sandbox
    probe = subprocess.run(["bwrap", "--unshare-all", "--ro-bind", "/usr", "/usr", "--symlink", "usr/lib", "/lib",
                            "--symlink", "usr/lib64", "/lib64", "--proc", "/proc", "--dev", "/dev", "/usr/bin/true"],
                           capture_output=True, text=True) if shutil.which("bwrap") else None
    if probe is None or probe.returncode != 0:
        skip("bubblewrap cannot create namespaces here" + (" and the uid fallback needs root" if MODE == "mutants" else "")
             + ": " + (probe.stderr.strip() if probe else "bwrap not installed"))

shutil.rmtree(OUT, ignore_errors=True)
SUBS, REPORTS, CWD = (os.path.join(OUT, d) for d in ("submissions", "reports", "cwd"))
for d in (SUBS, REPORTS, CWD):
    os.makedirs(d)
os.chmod(SUBS, 0o700)
PRIVATE = os.path.join(OUT, "instructor-private.txt")
with open(PRIVATE, "w") as f:
    f.write(f"PRIVATE-{TOKEN}\n")
os.chmod(PRIVATE, 0o600)
HOST_TMP = f"/tmp/t10-tga-hostile-{TOKEN}"
OUTSIDE = [os.path.join(FIXTURES, f"pwned-{TOKEN}"), os.path.join(REPORTS, "pwned"), os.path.join(CWD, "pwned"),
           os.path.join(SUBS, "pwned"), HOST_TMP]

# A local server that records any connection (the network attack).
LISTENER = Listener()
PORT, connections = LISTENER.port, LISTENER.connections

READS = {"beside": "path.substr(0, path.size() - 4) + \".png\"", "reference": json.dumps(os.path.join(FIXTURES, "rgb24_raw_bl.png")),
         "private": json.dumps(PRIVATE)}
HOSTILE = {
    "cheat": CHEAT,
    # Reads the PNG beside the input, a fixture's PNG in the checkout and a 0600 file of the
    # instructor's; rejects the file saying what it read, so that a leak lands in the report.
    "read_reference": wrapped("std::string leaked;\n" + "".join(
        f"try {{ const auto b = readFile({expr}); leaked += \"LEAK:{what}:\" + std::string(b.begin(), b.begin() + std::min<std::size_t>(b.size(), 12)) + \" \"; }} catch (const Error&) {{}}\n"
        for what, expr in READS.items()) + "if (!leaked.empty()) throw Error(leaked);\nreturn correctLoadTga(path);", "#include <algorithm>\n"),
    "write_outside": wrapped("".join(f"std::ofstream({json.dumps(p)}) << \"x\";\n" for p in OUTSIDE) +
                             "return correctLoadTga(path);", "#include <fstream>\n"),
    "network": wrapped(f"""const int s = ::socket(AF_INET, SOCK_STREAM, 0);
        sockaddr_in a{{}}; a.sin_family = AF_INET; a.sin_port = htons({PORT}); a.sin_addr.s_addr = htonl(0x7f000001);
        if (s >= 0 && ::connect(s, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0) ::send(s, "GET /tga", 8, 0);
        return correctLoadTga(path);""", "#include <arpa/inet.h>\n#include <netinet/in.h>\n#include <sys/socket.h>\n"),
    # Forks until refused; every child sleeps a minute. Then decodes.
    "fork_bomb": wrapped("""int forks = 0;
        for (; forks < 5000; ++forks) { const pid_t pid = ::fork(); if (pid == 0) { ::sleep(60); ::_exit(0); } if (pid < 0) break; }
        std::fprintf(stderr, "FORKS:%d\\n", forks);
        return correctLoadTga(path);""", "#include <cstdio>\n#include <unistd.h>\n"),
    # On RLE 24-bit files: a detached child spins forever and so does the loader.
    "hang": wrapped(HEADER_BYTES + f"""if ({IS_RLE24_BL}) {{
            if (::fork() == 0) {{ ::setsid(); for (volatile unsigned long i = 0;; ++i) {{}} }}
            for (;;) ::pause();
        }}
        return correctLoadTga(path);""", "#include <unistd.h>\n"),
}


def write(name, text):
    folder = os.path.join(SUBS, name)
    os.makedirs(folder)
    with open(os.path.join(folder, "tga.cpp"), "w") as f:
        f.write(text)
    return folder


def grade(name, isolation):
    report = os.path.join(REPORTS, name + ".json")
    command = [GRADER, "--timeout", "2", "--report", report] + (["--isolation", isolation] if isolation else []) + [os.path.join(SUBS, name)]
    start = time.time()
    run = subprocess.run(command, cwd=CWD, capture_output=True, text=True, errors="replace", timeout=300)
    seconds = time.time() - start
    if run.returncode != 0:
        fail(f"{name}: t10-grade-tga exit {run.returncode}: {run.stderr[-500:]}")
        return {"score": -1, "status": "?", "cases": []}, run, seconds
    result = json.load(open(report))
    print(f"{name}: {result['status']}, score {result['score']} in {seconds:.1f} s")
    return result, run, seconds


def verdicts(result):
    return {c["file"]: c["verdict"] for c in result.get("cases", [])}


def expect(name, condition, what):
    if condition:
        print(f"ok   {name}: {what}")
    else:
        fail(f"{name}: expected {what}")


if MODE == "mutants":
    for name, (text, expected) in MUTANTS.items():
        write(name, text)
    # Two at a time: each build and each case is a process of its own.
    results = {}
    threads = [threading.Thread(target=lambda n=n: results.__setitem__(n, grade(n, None))) for n in MUTANTS]
    for i in range(0, len(threads), 2):
        for t in threads[i:i + 2]:
            t.start()
        for t in threads[i:i + 2]:
            t.join()
    for name, (_, expected) in MUTANTS.items():
        result = results[name][0]
        got = verdicts(result)
        if name == "reference":
            expect(name, result["score"] == 100, f"score 100 (got {result['score']})")
        for case, verdict in expected.items():
            expect(name, got.get(case) == verdict, f"{case}: {verdict} (got {got.get(case)})")
        if name != "reference":
            expect(name, result["score"] < 100, f"below 100 (got {result['score']})")
    shutil.rmtree(OUT, ignore_errors=True)
    print(f"{len(FAILURES)} failure(s)")
    sys.exit(1 if FAILURES else 0)

for name, text in HOSTILE.items():
    write(name, text)
results = {name: grade(name, MODE) for name in HOSTILE}
valid = lambda result: [c for c in result.get("cases", []) if not c["malformed"]]
report_text = {name: open(os.path.join(REPORTS, name + ".json"), errors="replace").read() if os.path.exists(os.path.join(REPORTS, name + ".json")) else ""
               for name in HOSTILE}
for name, (result, run, _) in results.items():
    expect(name, result.get("isolation") == MODE, f"graded with isolation {MODE} (got {result.get('isolation')})")
    expect(name, f"PRIVATE-{TOKEN}" not in report_text[name] + run.stdout, "the instructor's 0600 file does not show")

cheat, cheat_run, _ = results["cheat"]
passed_valid = [c["file"] for c in valid(cheat) if c["passed"]]
if MODE == "namespaces":
    expect("cheat", not passed_valid and cheat["cases"], f"no valid case passed (score {cheat['score']}; passed {passed_valid})")
else:
    # The uid fallback's documented limit: a checkout readable by others shows its fixtures' PNGs.
    readable = os.stat(FIXTURES).st_mode & 0o004
    expect("cheat", "readable by others" in cheat_run.stderr if readable else not passed_valid,
           "warned that the fixtures are readable by others" if readable else "no valid case passed")
    print(f"known limit (uid): the cheat that searches the checkout scored {cheat['score']} ({len(passed_valid)} valid cases)")

leaks = report_text["read_reference"]
allowed = ("LEAK:reference",) if MODE == "uid" else ()
bad = [w for w in ("LEAK:beside", "LEAK:reference", "LEAK:private") if w in leaks and w not in allowed]
expect("read_reference", not bad, f"nothing read beside the input, in the checkout or of the instructor's (leaked: {bad or 'nothing'})")
if MODE == "namespaces":
    expect("read_reference", results["read_reference"][0]["score"] == 100, "its loader keeps 100")
written = [p for p in OUTSIDE if os.path.exists(p) and (MODE == "namespaces" or p != HOST_TMP)]
expect("write_outside", not written, f"nothing written outside (wrote {written or 'nothing'})")
expect("write_outside", results["write_outside"][0]["score"] == 100, "its loader keeps 100")
for p in OUTSIDE:
    if os.path.exists(p):
        os.remove(p)
if MODE == "namespaces":
    expect("network", not connections and results["network"][0]["score"] == 100,
           f"no connection ({len(connections)} received), its loader keeps 100")
bomb, _, bomb_seconds = results["fork_bomb"]
expect("fork_bomb", bomb["status"] == "graded" and bomb_seconds < 120, f"graded in {bomb_seconds:.0f} s (score {bomb['score']})")
hang, _, hang_seconds = results["hang"]
got = verdicts(hang)
expect("hang", got.get("rgb24_rle_bl") == "hang" and got.get("rgb24_raw_bl") == "right pixels" and hang_seconds < 60,
       f"killed at the limit on RLE files, graded on the others in {hang_seconds:.0f} s")

# The job uids the grader named (other graders may run beside this test with uids of their own).
job_uids = set()
for _, run, _ in results.values():
    for line in run.stderr.splitlines():
        if "(job uids " in line:
            job_uids.add(int(line.split("(job uids ", 1)[1].rstrip(")")))
if os.geteuid() == 0 and not job_uids:
    fail("the grader ran as root but named no job uid")
leftover = []
for pid in filter(str.isdigit, os.listdir("/proc")):
    try:
        if os.stat(f"/proc/{pid}").st_uid in job_uids:
            leftover.append(pid)
    except OSError:
        pass
expect("all", not leftover, f"no process of the job uids {sorted(job_uids)} left ({leftover or 'none'})")
LISTENER.close()
shutil.rmtree(OUT, ignore_errors=True)
print(f"{len(FAILURES)} failure(s)")
sys.exit(1 if FAILURES else 0)
