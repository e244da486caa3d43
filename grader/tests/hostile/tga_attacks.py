"""The hostile suite's TGA loaders (hostile.py grades them beside the hostile stages): the cheat of
issue 29 and loaders that attack the grader, each a tga.cpp handed to t10-grade-tga, and what each
must get. Every attack wraps the project's own loader, so a contained attack still scores 100.

  cheat           decodes the PNG lying beside its input (`cp "${1%.tga}.png" "$2"` scored 100 with the
                  old command mode), else the PNG of the fixture whose bytes the input has, found in the
                  checkout: must pass no valid case (uid: the checkout's fixtures are readable by others,
                  a documented limit the grader warns about)
  read_reference  reads the PNG beside the input, a fixture's PNG in the checkout and a 0600 file of the
                  instructor's, and rejects the file saying what it read
  write_outside   writes into the fixtures, the report folder, the grader's working folder, the
                  submissions and /tmp
  network         connects to the suite's listener on 127.0.0.1 (namespaces only: the uid fallback
                  has the host's network, documented)
  fork_bomb       forks until refused, every child sleeping a minute, then decodes
  hang            on RLE 24-bit files a detached child spins forever and so does the loader"""
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "tga"))
from tga_loaders import (HEADER_BYTES, IS_RLE24_BL, grade_in_pairs, project_loader, verdicts, wrapped,  # noqa: E402
                         write_loader)


def cheat(fixtures):
    """Decodes the PNG beside the input, or the PNG of the checkout's fixture with the input's bytes."""
    return f"""#define STB_IMAGE_IMPLEMENTATION
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
    DIR* dir = ::opendir({json.dumps(fixtures)});
    if (dir == nullptr) return "";
    std::string found;
    while (const dirent* e = ::readdir(dir)) {{
        const std::string name = e->d_name;
        if (name.size() < 4 || name.substr(name.size() - 4) != ".tga") continue;
        const std::string full = std::string({json.dumps(fixtures)}) + "/" + name;
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


class TgaAttacks:
    """Writes the loaders into OUT/tga/submissions, grades them (grade(), from a thread) and checks them
    (check(), after grade()). `fail` records a failure; the private file and the listener are the suite's."""

    def __init__(self, mode, source, grader, out, private, token, port, fail):
        self.mode, self.grader, self.fail, self.private, self.token = mode, grader, fail, private, token
        self.fixtures = os.path.join(source, "tests", "fixtures", "tga")
        self.subs, self.reports, self.cwd = (os.path.join(out, "tga", d) for d in ("submissions", "reports", "cwd"))
        for d in (self.subs, self.reports, self.cwd):
            os.makedirs(d)
        os.chmod(self.subs, 0o700)
        self.host_tmp = f"/tmp/t10-tga-hostile-{token}"
        self.outside = [os.path.join(self.fixtures, f"pwned-{token}"), os.path.join(self.reports, "pwned"),
                        os.path.join(self.cwd, "pwned"), os.path.join(self.subs, "pwned"), self.host_tmp]
        loader = project_loader(source)
        reads = {"beside": "path.substr(0, path.size() - 4) + \".png\"",
                 "reference": json.dumps(os.path.join(self.fixtures, "rgb24_raw_bl.png")), "private": json.dumps(private)}
        self.loaders = {
            "cheat": cheat(self.fixtures),
            "read_reference": wrapped(loader, "std::string leaked;\n" + "".join(
                f"try {{ const auto b = readFile({expr}); leaked += \"LEAK:{what}:\" + std::string(b.begin(), b.begin() + "
                f"std::min<std::size_t>(b.size(), 12)) + \" \"; }} catch (const Error&) {{}}\n"
                for what, expr in reads.items()) + "if (!leaked.empty()) throw Error(leaked);\nreturn correctLoadTga(path);",
                "#include <algorithm>\n"),
            "write_outside": wrapped(loader, "".join(f"std::ofstream({json.dumps(p)}) << \"x\";\n" for p in self.outside) +
                                     "return correctLoadTga(path);", "#include <fstream>\n"),
            "network": wrapped(loader, f"""const int s = ::socket(AF_INET, SOCK_STREAM, 0);
        sockaddr_in a{{}}; a.sin_family = AF_INET; a.sin_port = htons({port}); a.sin_addr.s_addr = htonl(0x7f000001);
        if (s >= 0 && ::connect(s, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0) ::send(s, "GET /tga", 8, 0);
        return correctLoadTga(path);""", "#include <arpa/inet.h>\n#include <netinet/in.h>\n#include <sys/socket.h>\n"),
            "fork_bomb": wrapped(loader, """int forks = 0;
        for (; forks < 5000; ++forks) { const pid_t pid = ::fork(); if (pid == 0) { ::sleep(60); ::_exit(0); } if (pid < 0) break; }
        std::fprintf(stderr, "FORKS:%d\\n", forks);
        return correctLoadTga(path);""", "#include <cstdio>\n#include <unistd.h>\n"),
            "hang": wrapped(loader, HEADER_BYTES + f"""if ({IS_RLE24_BL}) {{
            if (::fork() == 0) {{ ::setsid(); for (volatile unsigned long i = 0;; ++i) {{}} }}
            for (;;) ::pause();
        }}
        return correctLoadTga(path);""", "#include <unistd.h>\n"),
        }
        if mode == "uid":
            # The fallback has the host's network (documented): nothing to expect of a connection.
            del self.loaders["network"]
        for name, text in self.loaders.items():
            write_loader(self.subs, name, text)
        self.results = {}

    def grade(self):
        try:
            self.results = grade_in_pairs(self.grader, self.subs, self.reports, self.cwd, list(self.loaders), self.mode, self.fail)
        except Exception as error:  # a thread's exception would only be printed: make it a failure
            self.fail(f"tga: grading the loaders failed: {error!r}")

    def job_uids(self):
        """The job uids the graders named (other graders may run beside this test with uids of their own)."""
        uids = set()
        for _, run, _ in self.results.values():
            for line in run.stderr.splitlines():
                if "(job uids " in line:
                    uids.add(int(line.split("(job uids ", 1)[1].rstrip(")")))
        return uids

    def expect(self, name, condition, what):
        print(f"ok   tga {name}: {what}") if condition else self.fail(f"tga {name}: expected {what}")

    def check(self, connections):
        """CONNECTIONS: the first bytes of every connection the suite's listener received."""
        mode, results = self.mode, self.results
        if sorted(results) != sorted(self.loaders):
            self.fail(f"tga: graded {sorted(results)}, expected {sorted(self.loaders)}")
            return
        valid = lambda result: [c for c in result.get("cases", []) if not c["malformed"]]
        text = {}
        for name in self.loaders:
            path = os.path.join(self.reports, name + ".json")
            text[name] = open(path, errors="replace").read() if os.path.exists(path) else ""
        for name, (result, run, _) in results.items():
            self.expect(name, result.get("isolation") == mode, f"graded with isolation {mode} (got {result.get('isolation')})")
            self.expect(name, f"PRIVATE-{self.token}" not in text[name] + run.stdout, "the instructor's 0600 file does not show")

        cheat_result, cheat_run, _ = results["cheat"]
        passed_valid = [c["file"] for c in valid(cheat_result) if c["passed"]]
        if mode == "namespaces":
            self.expect("cheat", not passed_valid and cheat_result["cases"],
                        f"no valid case passed (score {cheat_result['score']}; passed {passed_valid})")
        else:
            # The uid fallback's documented limit: a checkout readable by others shows its fixtures' PNGs.
            readable = os.stat(self.fixtures).st_mode & 0o004
            self.expect("cheat", "readable by others" in cheat_run.stderr if readable else not passed_valid,
                        "warned that the fixtures are readable by others" if readable else "no valid case passed")
            print(f"known limit (uid): the cheat that searches the checkout scored {cheat_result['score']} "
                  f"({len(passed_valid)} valid cases)")

        leaks = text["read_reference"]
        allowed = ("LEAK:reference",) if mode == "uid" else ()
        bad = [w for w in ("LEAK:beside", "LEAK:reference", "LEAK:private") if w in leaks and w not in allowed]
        self.expect("read_reference", not bad,
                    f"nothing read beside the input, in the checkout or of the instructor's (leaked: {bad or 'nothing'})")
        if mode == "namespaces":
            self.expect("read_reference", results["read_reference"][0]["score"] == 100, "its loader keeps 100")
        written = [p for p in self.outside if os.path.exists(p) and (mode == "namespaces" or p != self.host_tmp)]
        self.expect("write_outside", not written, f"nothing written outside (wrote {written or 'nothing'})")
        self.expect("write_outside", results["write_outside"][0]["score"] == 100, "its loader keeps 100")
        for p in self.outside:
            if os.path.exists(p):
                os.remove(p)
        if mode == "namespaces":
            mine = [c for c in connections if c.startswith(b"GET /tga")]
            self.expect("network", not mine and results["network"][0]["score"] == 100,
                        f"no connection ({len(mine)} received), its loader keeps 100")
        bomb, _, bomb_seconds = results["fork_bomb"]
        self.expect("fork_bomb", bomb["status"] == "graded" and bomb_seconds < 120,
                    f"graded in {bomb_seconds:.0f} s (score {bomb['score']})")
        hang, _, hang_seconds = results["hang"]
        got = verdicts(hang)
        self.expect("hang", got.get("rgb24_rle_bl") == "hang" and got.get("rgb24_raw_bl") == "right pixels" and hang_seconds < 60,
                    f"killed at the limit on RLE files, graded on the others in {hang_seconds:.0f} s")
