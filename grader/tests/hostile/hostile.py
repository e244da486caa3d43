#!/usr/bin/env python3
"""The hostile submissions of issues 19 and 29 and what must become of each: writes them (each stage
a copy of the Part 1 reference with one attack added; each TGA loader the project's loader wrapped in
one attack, and the cheat: tga_attacks.py), grades the stages beside honest copies of the reference
with t10-grade and, at the same time, the loaders with t10-grade-tga, under the isolation asked for,
then checks that every attack was contained.

usage: hostile.py namespaces|uid SOURCE_DIR T10_GRADE T10_GRADE_TGA FLIP OUT_DIR
(Never run these submissions unsandboxed as root: one of them sends kill(-1, SIGKILL).)
Exit 0 when every expectation holds, 1 with the failures listed, 77 (skipped) where the isolation
cannot be had on this machine (no working bwrap; not root for uid), or where FLIP is not installed
and the TGA loaders, which need no FLIP, passed alone.

Under uid the attacks whose outcome the fallback does not promise (a network connection; reading the
reference stage, readable by others in a checkout) are left out: their namespaces runs check them.

Each attack runs in a global constructor of Tutorial10.cpp (before main) or after the stage's run;
what it managed is printed with a marker (LEAK:, NET:, FORKS:, ALLOC:) into its run log, which only
the instructor sees in runs/<case>/run.log; the secrets themselves are planted by this script and
looked for in every file of the report folders."""
import glob
import hashlib
import json
import os
import secrets
import shutil
import socket
import subprocess
import sys
import threading
import time
import zlib
import struct

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from hostile_support import closed_folder, skip, Listener  # noqa: E402 (grader/tests/)
from tga_attacks import TgaAttacks  # noqa: E402 (grader/tests/hostile/)

if len(sys.argv) != 7 or sys.argv[1] not in ("namespaces", "uid"):
    sys.exit(__doc__)
MODE, SOURCE, GRADER, GRADER_TGA, FLIP, OUT = sys.argv[1:7]
STAGE = os.path.join(SOURCE, "tutorial10_part1_tonemap")
FAILURES = []


def fail(text):
    FAILURES.append(text)
    print("FAIL " + text)


# Without FLIP the stages cannot be graded: the TGA loaders still are.
STAGES = os.access(FLIP, os.X_OK)
if MODE == "uid" and os.geteuid() != 0:
    skip("the uid fallback needs root (one unprivileged uid per job)")
if MODE == "uid" and (closed_folder(SOURCE) or closed_folder(OUT)):
    # The grader refuses the uid fallback for a checkout its job uids cannot enter, by design (one line
    # naming the folder; grader/tests/private_checkout.py proves that refusal), so nothing here can run.
    skip(f"{closed_folder(SOURCE) or closed_folder(OUT)} lets no one else in: the uid fallback refuses such a checkout")
if MODE == "namespaces":
    probe = subprocess.run(["bwrap", "--unshare-all", "--die-with-parent", "--new-session", "--cap-drop", "ALL",
                            "--ro-bind", "/usr", "/usr", "--symlink", "usr/lib", "/lib", "--symlink", "usr/lib64",
                            "/lib64", "--proc", "/proc", "--dev", "/dev", "/usr/bin/true"],
                           capture_output=True, text=True) if shutil.which("bwrap") else None
    if probe is None or probe.returncode != 0:
        skip("bubblewrap cannot create namespaces here: " + (probe.stderr.strip() if probe else "bwrap not installed"))

shutil.rmtree(OUT, ignore_errors=True)
os.makedirs(OUT)
SUBS, REPORTS, CACHE, CWD = (os.path.join(OUT, d) for d in ("submissions", "reports", "cache", "cwd"))
for d in (SUBS, CWD):
    os.makedirs(d)
# The instructor's submissions folder is private (the uid fallback relies on it; see instructors.md).
os.chmod(SUBS, 0o700)

# Planted secrets: a 0600 file of the instructor's, the grader's environment, and (namespaces only,
# where nothing of /etc but the loader's cache is visible) the machine's hostname file.
TOKEN = secrets.token_hex(8)
PRIVATE = os.path.join(OUT, "instructor-private.txt")
with open(PRIVATE, "w") as f:
    f.write(f"PRIVATE-{TOKEN}\n")
os.chmod(PRIVATE, 0o600)
ENV_SECRET = f"ENVSECRET-{TOKEN}"
HOSTNAME = open("/etc/hostname").read().strip() if os.path.exists("/etc/hostname") else ""
REFERENCE_SHADER = os.path.join(STAGE, "PostProcess.frag")

# A local server that records any connection (the network attack).
LISTENER = Listener()
PORT, connections = LISTENER.port, LISTENER.connections

REF_HOST = open(os.path.join(STAGE, "Tutorial10.cpp")).read()
REF_FRAG = open(REFERENCE_SHADER).read()
REF_INIT = open(os.path.join(STAGE, "PostProcessInit.frag")).read()
RUN_STAGE = "return t10::runStage(argc, argv, stage);"
# Pass-through: no tone map (what a forger hands in, hoping to get the reference's score).
PASS_FRAG = REF_FRAG.replace("v3ColourOut = toneMap(v3RetColour, v2UV);", "v3ColourOut = v3RetColour;")
assert RUN_STAGE in REF_HOST and PASS_FRAG != REF_FRAG, "the Part 1 reference changed: update hostile.py"

PRELUDE = """#include <arpa/inet.h>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <netinet/in.h>
#include <sstream>
#include <string>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>
namespace hostile {
inline std::string slurp(const char* path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return "";
    std::stringstream s; s << in.rdbuf(); return s.str();
}
inline void leak(const char* what, const char* path) {
    const std::string text = slurp(path);
    if (!text.empty()) std::printf("LEAK:%s:%s\\n", what, text.substr(0, 80).c_str());
    else std::printf("refused:%s\\n", what);
}
inline void tryWrite(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (out << text) std::printf("WROTE:%s\\n", path.c_str()); else std::printf("refused-write:%s\\n", path.c_str());
}
}
"""


def cstr(text):
    return json.dumps(text)  # a C string literal for plain ASCII paths


def ctor(body):
    return "namespace { struct Attack { Attack() {\n" + body + "\n std::fflush(stdout); } } attack; }\n"


def png64():
    """A valid 64x64 grey PNG (the frame FLIP cannot compare with a 128x128 reference)."""
    raw = b"".join(b"\x00" + b"\x80" * 64 for _ in range(64))
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 64, 64, 8, 0, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


PNG = ",".join(str(b) for b in png64())
HOST_TMP_FILE = f"/tmp/t10-hostile-{TOKEN}"
REPORT_OF = lambda name: os.path.join(REPORTS, name, "report.json")

# name: (host code: (constructor body, code after the stage's run), PostProcess.frag, description)
ATTACKS = {
    "read_secrets": (ctor(f"""
        hostile::leak("private", {cstr(PRIVATE)});
        hostile::leak("hostname", "/etc/hostname");
        hostile::leak("reference", {cstr(REFERENCE_SHADER)});
        hostile::leak("other-student", {cstr(os.path.join(SUBS, 'honest_first', 'PostProcess.frag'))});
        const char* env = std::getenv("T10_HOSTILE_SECRET");
        if (env) std::printf("LEAK:env:%s\\n", env);
        std::string cmdline = hostile::slurp("/proc/1/cmdline");
        for (char& c : cmdline) if (c == '\\0') c = ' ';
        std::printf("CMDLINE:%s\\n", cmdline.c_str());
        std::fflush(stdout);
        std::_Exit(1);"""), None, REF_FRAG,
        "reads a 0600 file, /etc/hostname, the reference shader, another student's file, the environment "
        "and /proc/1/cmdline, prints them and exits 1 so that its output lands in the report"),
    "include_secret": (f'#include "{PRIVATE}"\n#include "/etc/hostname"\n', None, REF_FRAG,
                       "#include of a 0600 file and /etc/hostname, hoping the compiler prints them"),
    "write_outside": (ctor(f"""
        hostile::tryWrite("pwned-relative", "x");
        hostile::tryWrite({cstr(os.path.join(CWD, 'pwned-cwd'))}, "x");
        hostile::tryWrite({cstr(os.path.join(CACHE, 'pwned-cache'))}, "x");
        hostile::tryWrite({cstr(REPORT_OF('honest_first'))}, "{{}}");
        hostile::tryWrite({cstr(HOST_TMP_FILE)}, "x");"""), None, REF_FRAG,
        "writes into the grader's working folder, the cache, another submission's report.json and /tmp"),
    "network": (ctor(f"""
        const int s = ::socket(AF_INET, SOCK_STREAM, 0);
        sockaddr_in a{{}}; a.sin_family = AF_INET; a.sin_port = htons({PORT}); a.sin_addr.s_addr = htonl(0x7f000001);
        if (s >= 0 && ::connect(s, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0) {{
            const char request[] = "GET /hostile HTTP/1.0\\r\\n\\r\\n";
            ::send(s, request, sizeof request - 1, 0);
            std::printf("NET:connected\\n");
        }} else std::printf("NET:refused\\n");"""), None, REF_FRAG, "connects to a server on 127.0.0.1 and sends an HTTP request"),
    "daemon": (ctor(f"""
        if (::fork() == 0) {{
            ::setsid();
            if (::fork() == 0) {{
                ::sleep(2);
                hostile::tryWrite({cstr(REPORT_OF('daemon'))}, "{{\\"score\\": 100}}");
                hostile::tryWrite({cstr(os.path.join(REPORTS, 'gradebook.csv'))}, "daemon,1,graded,100\\n");
                hostile::tryWrite({cstr(os.path.join(CWD, 'daemon-alive'))}, "x");
                std::_Exit(0);
            }}
            std::_Exit(0);
        }}"""), None, PASS_FRAG, "setsid() and a double fork; a second later rewrites its report and the gradebook"),
    "drop_shader_dir": (None, (f"""
    std::vector<char*> args;
    for (int i = 0; i < argc; ++i) {{
        if (std::string(argv[i]) == "--shader-dir") {{ ++i; continue; }}
        args.push_back(argv[i]);
    }}
    static std::string flag = "--shader-dir", reference = {cstr(STAGE)};
    args.push_back(flag.data()); args.push_back(reference.data());
    return t10::runStage(static_cast<int>(args.size()), args.data(), stage);""", True), PASS_FRAG,
        "pass-through shaders; main drops --shader-dir and points it at the reference stage's folder"),
    "copy_reference_dump": (None, (f"""
    const int rc = t10::runStage(argc, argv, stage);
    std::error_code e;
    for (auto& dir : std::filesystem::directory_iterator({cstr(CACHE)}, e))
        for (auto& c : std::filesystem::directory_iterator(dir.path(), e))
            for (auto& f : std::filesystem::directory_iterator(c.path(), e))
                if (std::filesystem::exists("unit15_level0.pfm") && f.path().filename().string().find("unit") == 0)
                    std::filesystem::copy_file(f.path(), f.path().filename(), std::filesystem::copy_options::overwrite_existing, e);
    return rc;""", False), PASS_FRAG, "pass-through shaders; copies the cached reference dump over its own"),
    "symlink_dump": (None, (f"""
    const int rc = t10::runStage(argc, argv, stage);
    std::error_code e;
    for (auto& f : std::filesystem::directory_iterator(".", e)) {{
        const std::string name = f.path().filename().string();
        std::filesystem::remove(name, e);
        std::filesystem::create_symlink({cstr(CACHE + '/reference/pot/')} + name, name, e);
    }}
    return rc;""", False), PASS_FRAG, "pass-through shaders; replaces its dump with symlinks into the cache"),
    "cache_poison": (ctor(f"""
        std::error_code e;
        for (auto& f : std::filesystem::recursive_directory_iterator({cstr(CACHE)}, e))
            if (f.is_regular_file(e)) hostile::tryWrite(f.path().string(), "poison");"""), None, REF_FRAG,
        "overwrites every file of the cache (reference frames, builds)"),
    "kill_grader": (ctor("""
        std::printf("KILL:getppid=%d:%d\\n", ::kill(::getppid(), SIGKILL), ::kill(-1, SIGKILL));"""), None, REF_FRAG,
        "kill(getppid(), SIGKILL) and kill(-1, SIGKILL)"),
    "frame_64x64": (None, (f"""
    const int rc = t10::runStage(argc, argv, stage);
    static const unsigned char png[] = {{{PNG}}};
    std::ofstream("frame.png", std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(png), sizeof png);
    return rc;""", False), REF_FRAG, "replaces its frame with a valid 64x64 PNG"),
    "fork_many": (ctor("""
        int forked = 0;
        for (int i = 0; i < 150; ++i) {
            const pid_t pid = ::fork();
            if (pid == 0) { ::sleep(1); std::_Exit(0); }
            if (pid < 0) break;
            ++forked;
        }
        std::printf("FORKS:%d\\n", forked);
        while (::wait(nullptr) > 0) {}"""), None, REF_FRAG, "forks 150 processes (each sleeps 1 s: all alive at once), then renders"),
    "big_file": (ctor("""
        std::ofstream out("big.bin", std::ios::binary);
        const std::string mib(1 << 20, 'x');
        for (int i = 0; i < 200 && out; ++i) out << mib;
        std::printf("BIG:written\\n");"""), None, REF_FRAG, "writes a 200 MB file into its output folder"),
    "huge_alloc": (ctor("""
        const std::size_t bytes = std::size_t(8) << 30;
        char* p = static_cast<char*>(std::malloc(bytes));
        if (p) { std::memset(p, 1, bytes); std::printf("ALLOC:ok\\n"); } else std::printf("ALLOC:refused\\n");"""),
        None, REF_FRAG, "allocates and touches 8 GiB"),
}
if MODE == "uid":
    # The fallback promises neither (instructors.md): the job has the host's network, and the reference
    # stage's shaders are readable by others in a checkout. The namespaces run checks both.
    for name in ("network", "drop_shader_dir"):
        del ATTACKS[name]
# Not host code: a shader that overflowed the grader's regex, and submissions of links.
SPACES_FRAG = REF_FRAG.replace("#version 430 core\n", "#version 430 core\n// out" + " " * 50000 + "\n", 1)


def write_submission(name, host, frag, init=REF_INIT):
    folder = os.path.join(SUBS, name)
    os.makedirs(folder)
    with open(os.path.join(folder, "Tutorial10.cpp"), "w") as f:
        f.write(host)
    with open(os.path.join(folder, "PostProcess.frag"), "w") as f:
        f.write(frag)
    with open(os.path.join(folder, "PostProcessInit.frag"), "w") as f:
        f.write(init)
    return folder


# The attacks' code goes after the stage's first include, so that their builds take the grader's
# precompiled t10/app.hpp as a stage's do (0.1 s of CPU each instead of 0.8); include_secret's
# #include lines stay first, so one build reads the headers themselves.
FIRST_INCLUDE = '#include "t10/app.hpp"\n'
assert FIRST_INCLUDE in REF_HOST, "the Part 1 reference changed its first include: update hostile.py"


def after_first_include(host, text):
    at = host.index(FIRST_INCLUDE) + len(FIRST_INCLUDE)
    return host[:at] + text + host[at:]


def hostile_host(prefix, after):
    host = REF_HOST
    if prefix and not prefix.startswith("namespace"):
        host = prefix + PRELUDE + host
    else:
        host = after_first_include(host, PRELUDE + (prefix or ""))
    if after:
        body, needs_vector = after
        host = host.replace(RUN_STAGE, body.strip())
        if needs_vector:
            host = after_first_include(host, "#include <vector>\n")
    return host


def write_stages():
    """Writes every stage submission into SUBS; returns their names in grading order."""
    order = ["honest_first"]
    write_submission("honest_first", REF_HOST, REF_FRAG)
    for name, (prefix, after, frag, _) in ATTACKS.items():
        write_submission(name, hostile_host(prefix, after), frag)
        order.append(name)
    write_submission("shader_spaces", REF_HOST, SPACES_FRAG)
    order.append("shader_spaces")
    os.makedirs(os.path.join(SUBS, "symlinked_files"))
    for f in ("Tutorial10.cpp", "PostProcess.frag", "PostProcessInit.frag"):
        os.symlink(os.path.join(STAGE, f), os.path.join(SUBS, "symlinked_files", f))
    os.symlink(PRIVATE, os.path.join(SUBS, "symlinked_files", "tutorial10.CPP"))
    order.append("symlinked_files")
    os.symlink(STAGE, os.path.join(SUBS, "folder_symlink"))
    order.append("folder_symlink")
    write_submission("honest_last", REF_HOST, REF_FRAG)
    order.append("honest_last")
    return order


ISOLATE = ["--isolation", MODE]
reports = {}  # name: its report.json


def grade_stages(order):
    """Grades every stage submission in one t10-grade run; returns the finished process."""
    env = dict(os.environ, T10_HOSTILE_SECRET=ENV_SECRET)
    command = [GRADER, "--part", "1", "--jobs", "2", "--timeout", "15"] + ISOLATE + ["--cache", CACHE,
               "--report", REPORTS] + [os.path.join(SUBS, n) for n in order]
    start = time.time()
    graded = subprocess.run(command, cwd=CWD, env=env, capture_output=True, text=True, timeout=600)
    print(f"t10-grade ({MODE}) exit {graded.returncode} in {time.time() - start:.1f} s")
    print(graded.stdout + graded.stderr)
    if graded.returncode != 0:
        fail(f"t10-grade exit {graded.returncode}: the grader must survive every submission")
    return graded


def log_of(name, case="pot"):
    path = os.path.join(REPORTS, name, "runs", case, "run.log")
    return open(path, errors="replace").read() if os.path.exists(path) else ""


def expect(name, condition, what):
    r = reports[name]
    status = f"{r['status']} {r['score']}"
    if condition:
        print(f"ok   {name}: {what} ({status})")
    else:
        fail(f"{name}: expected {what}; got {status}: {r['message'][:300]}")


def read_reports(order):
    gradebook = open(os.path.join(REPORTS, "gradebook.csv")).read()
    rows = {line.split(",")[0]: line.split(",") for line in gradebook.splitlines()[1:]}
    for name in order:
        try:
            reports[name] = json.load(open(REPORT_OF(name)))
        except (OSError, ValueError) as error:
            fail(f"{name}: no readable report.json ({error})")
            reports[name] = {"status": "?", "score": -1, "message": "", "files": []}
        if name not in rows:
            fail(f"{name}: no gradebook row")
        elif rows[name][2] != reports[name]["status"] or int(rows[name][3]) != reports[name]["score"]:
            fail(f"{name}: the gradebook says {rows[name][2]} {rows[name][3]}, the report {reports[name]['status']} "
                 f"{reports[name]['score']}")
        if reports[name].get("isolation") != MODE:
            fail(f"{name}: isolation {reports[name].get('isolation')}, expected {MODE}")


def check_secrets():
    """No planted secret in anything the student sees (every file of every report folder)."""
    secrets_to_find = {"private file": f"PRIVATE-{TOKEN}", "environment": ENV_SECRET}
    if MODE == "namespaces" and HOSTNAME:
        secrets_to_find["/etc/hostname"] = HOSTNAME
    for path in glob.glob(os.path.join(REPORTS, "**"), recursive=True):
        if os.path.isfile(path):
            data = open(path, "rb").read()
            binary = path.endswith(".png")
            for what, secret in secrets_to_find.items():
                # A short secret (a hostname such as "vm") occurs by chance in compressed image data: a
                # PNG of 100 kB holds a given 2-byte string almost surely. In images only secrets of 8
                # bytes or more are looked for (a chance match then has odds of about 2^-64 a place);
                # a leak through the program's output still shows in the text files, searched for all.
                if binary and len(secret) < 8:
                    continue
                if secret.encode() in data:
                    fail(f"the {what} secret appears in {os.path.relpath(path, REPORTS)}")
    print(f"ok   no planted secret ({', '.join(secrets_to_find)}) in any file of the reports")
    message = reports["read_secrets"]["message"]
    leaks = [line for line in message.splitlines() if line.startswith("LEAK:")]
    allowed = [] if MODE == "namespaces" else ["LEAK:hostname", "LEAK:reference"]  # world-readable: the uid fallback's limit
    bad = [line for line in leaks if not any(line.startswith(a) for a in allowed)]
    expect("read_secrets", not bad and "refused:private" in message,
           f"private reads refused (leaked: {[line[:40] for line in leaks] or 'nothing'}; allowed here: {allowed or 'nothing'})")
    if MODE == "namespaces":
        cmdline = [line for line in message.splitlines() if line.startswith("CMDLINE:")]
        expect("read_secrets", cmdline and OUT not in cmdline[0] and "t10-grade" not in cmdline[0] and SOURCE not in cmdline[0],
               f"/proc/1/cmdline shows no host path ({cmdline[0][:100] if cmdline else 'none'})")
    expect("include_secret", reports["include_secret"]["status"] == "build-failed", "build-failed, nothing included")


def check_attacks():
    for honest in ("honest_first", "honest_last", "shader_spaces"):
        expect(honest, reports[honest]["status"] == "graded" and reports[honest]["score"] == 100, "graded 100 beside the attacks")
    check_secrets()
    # The host's /tmp is writable by any uid: the fallback cannot keep a submission out of it.
    for path in (os.path.join(CWD, "pwned-relative"), os.path.join(CWD, "pwned-cwd"), os.path.join(CACHE, "pwned-cache"),
                 os.path.join(CWD, "daemon-alive")) + ((HOST_TMP_FILE,) if MODE == "namespaces" else ()):
        if os.path.exists(path):
            fail(f"a submission wrote {path}")
            break
    else:
        print("ok   nothing written in the working folder, the cache" + (" or /tmp" if MODE == "namespaces" else ""))
    if os.path.exists(HOST_TMP_FILE):
        os.remove(HOST_TMP_FILE)
    expect("write_outside", "WROTE:" + REPORT_OF("honest_first") not in log_of("write_outside"), "another report not written")
    if MODE == "namespaces":
        mine = [c for c in connections if c.startswith(b"GET /hostile")]
        expect("network", not mine and "NET:refused" in log_of("network"), f"no connection ({len(mine)} received)")
        expect("drop_shader_dir", reports["drop_shader_dir"]["score"] < 100, "the reference shaders cannot be reached: scored below 100")
    expect("daemon", reports["daemon"]["status"] == "graded" and reports["daemon"]["score"] < 100,
           "its report is still the grader's after 3 s (pass-through scores below 100)")
    expect("copy_reference_dump", reports["copy_reference_dump"]["score"] < 100, "the cached dump cannot be read: below 100")
    expect("symlink_dump", reports["symlink_dump"]["status"] == "crashed" and "symlink" in reports["symlink_dump"]["message"],
           "crashed: a symlink in its output folder")
    expect("kill_grader", reports["kill_grader"]["status"] == "graded", "the grader survived; graded")
    expect("frame_64x64", reports["frame_64x64"]["status"] == "crashed" and "64x64" in reports["frame_64x64"]["message"],
           "crashed: its frame is 64x64 (not a grader error)")
    forks = [int(line[6:]) for line in log_of("fork_many").splitlines() if line.startswith("FORKS:")]
    expect("fork_many", forks and forks[0] < 150, f"fewer than 150 processes ({forks})")
    expect("big_file", reports["big_file"]["status"] == "crashed" and "size limit" in reports["big_file"]["message"],
           "crashed: killed at the file size limit")
    expect("huge_alloc", "ALLOC:refused" in log_of("huge_alloc") or reports["huge_alloc"]["status"] == "crashed",
           "8 GiB refused")
    expect("symlinked_files", reports["symlinked_files"]["status"] == "empty" and reports["symlinked_files"]["score"] == 0
           and not any(f["source"] == "submission" for f in reports["symlinked_files"]["files"]),
           "empty, 0: every link ignored")
    expect("folder_symlink", reports["folder_symlink"]["status"] == "empty", "empty: the folder link is not followed")


def named_job_uids(stderr):
    """The job uids t10-grade names on stderr ("job uids A,B")."""
    uids = set()
    for line in stderr.splitlines():
        if "job uids" in line:
            uids.update(int(u) for u in line.split("job uids", 1)[1].replace(")", "").split(",") if u.strip().isdigit())
    return uids


def check_cache():
    """The cache is the grader's: an honest copy graded again on it scores 100 without re-rendering, and
    a cache changed behind the grader's back is noticed and rendered again."""
    again = subprocess.run([GRADER, "--part", "1"] + ISOLATE + ["--cache", CACHE, "--report",
                            os.path.join(OUT, "reports-again"), os.path.join(SUBS, "honest_last")],
                           cwd=CWD, capture_output=True, text=True, timeout=300)
    if "does not match its recorded hashes" in again.stderr:
        fail("the cache was changed by a submission: " + again.stderr[:300])
    if "score 100" not in again.stdout:
        fail("an honest copy graded on the same cache: " + again.stdout + again.stderr)
    print("ok   the cache is unchanged after the attacks: honest_last again scores 100")
    frames = glob.glob(os.path.join(CACHE, "reference-*", "pot", "frame.png"))
    with open(frames[0], "r+b") as f:
        f.seek(100)
        f.write(b"tampered")
    again = subprocess.run([GRADER, "--part", "1"] + ISOLATE + ["--cache", CACHE, "--report",
                            os.path.join(OUT, "reports-tampered"), os.path.join(SUBS, "honest_last")],
                           cwd=CWD, capture_output=True, text=True, timeout=300)
    if "does not match its recorded hashes" not in again.stderr or "score 100" not in again.stdout:
        fail("a tampered reference frame was not noticed and rendered again: " + again.stdout + again.stderr)
    print("ok   a tampered reference frame is noticed and rendered again")


def check_leftovers(job_uids):
    """Nothing of any submission or loader is left running: no process of the job uids the graders
    named, nor any whose command line names this suite's folder."""
    if os.geteuid() == 0 and not job_uids:
        fail("the graders ran as root but named no job uids")
    leftover = []
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            uid = os.stat(f"/proc/{pid}").st_uid
            cmd = open(f"/proc/{pid}/cmdline", "rb").read()
        except OSError:
            continue
        if int(pid) in (os.getpid(), os.getppid()):
            continue
        if uid in job_uids or OUT.encode() in cmd:
            leftover.append(pid)
    if leftover:
        fail(f"processes of the submissions still run: {leftover}")
    print(f"ok   no process of any submission is left (job uids {sorted(job_uids)})")


# The loaders are graded beside the stages: most of their time is waiting for a hang or a fork bomb.
tga = TgaAttacks(MODE, SOURCE, GRADER_TGA, OUT, PRIVATE, TOKEN, PORT, fail)
tga_thread = threading.Thread(target=tga.grade)
tga_thread.start()
stage_uids = set()
if STAGES:
    order = write_stages()
    graded = grade_stages(order)
    finished = time.time()
    stage_uids = named_job_uids(graded.stderr)
    if os.geteuid() == 0 and not stage_uids:
        fail("t10-grade ran as root but named no job uids")
    check_cache()  # while the daemon's 2 s pass
    time.sleep(max(0.0, finished + 3 - time.time()))  # the daemon writes 2 s after its run
    read_reports(order)
    check_attacks()
else:
    print(f"SKIP (the stages): {FLIP} is not installed (make grade-deps); the TGA loaders are graded alone")
tga_thread.join()
tga.check(connections)
if MODE == "namespaces":
    if connections:
        fail(f"the listener received {len(connections)} connection(s): {connections[:3]}")
check_leftovers(stage_uids | tga.job_uids())
LISTENER.close()
print(f"{len(FAILURES)} failure(s)")
if FAILURES:
    sys.exit(1)
if not STAGES:
    skip(f"{FLIP} is not installed (make grade-deps): the stages were not graded (the TGA loaders passed)")
sys.exit(0)
