// t10-grade-tga: grades a student's TGA loader as t10-grade grades a stage.
//   t10-grade-tga [--timeout S] [--report FILE.json] [--isolation auto|namespaces|uid] [--no-sandbox] SUBMISSION
// SUBMISSION is a folder holding tga.cpp: the student's t10::loadTga, with the signature of the
// project's own loader (t10/tga.hpp: `Image8 loadTga(const std::string& path)`, throwing on a file it
// cannot decode). tga.cpp is copied in under t10-grade's intake rules (submission_files.hpp), built
// in the sandbox (sandbox.hpp) with a harness (tga_harness.cpp) that writes what the loader returns,
// and run once per case in the sandbox on a copy of the input, named input.tga, alone in its folder.
// The cases are every TGA fixture of tests/fixtures/tga (reference PNGs written by an independent
// writer, read only by the grader, never reachable from inside) and malformed files derived from
// them. Each case: right pixels, wrong orientation, wrong channel order, wrong pixels, rejected a
// valid file, no output, crash, hang, accepted a malformed file, rejected (for malformed files). The
// score is the share of cases passed, rounded down. Exit 0 when the submission got a result (graded,
// empty, missing-files, build-failed), 1 when the grader failed, 2 on bad usage.
#include "isolation/options.hpp"
#include "isolation/run_limited.hpp"
#include "isolation/sandbox.hpp"
#include "intake/submission_files.hpp"

#include "t10/error.hpp"
#include "t10/error_line.hpp"
#include "t10/image_io.hpp"
#include "t10/json.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;

namespace {

using t10::Error;
using t10::UsageError;
using namespace t10::grade;
using Bytes = std::vector<unsigned char>;

constexpr const char* kUsage =
    "usage: t10-grade-tga [--timeout S] [--report FILE.json] [--isolation auto|namespaces|uid] [--no-sandbox] SUBMISSION\n"
    "SUBMISSION is a folder holding tga.cpp, which defines t10::loadTga with t10/tga.hpp's signature.\n";
constexpr const char* kLoaderFile = "tga.cpp";

struct Config {
    double timeout = 10.0;
    std::string reportFile;
    std::string isolation = "auto"; // auto | namespaces | uid | none
    std::string submission;
    bool help = false;
};

struct Case {
    std::string name;
    fs::path input;
    fs::path expected; // empty for a malformed file
};

struct Outcome {
    std::string name;
    bool malformed = false;
    bool passed = false;
    std::string verdict;
    std::string detail;
};

// The grader's work: its private folder, the job's uid and the sandbox every student step runs in.
struct Job {
    fs::path work;
    SandboxRun base;
    fs::path loader; // the built loader, readable by the job's uid
};

// Fills `config` from argv as it goes (so that a failure's handler knows --report); throws
// UsageError for a bad argument, std::filesystem::filesystem_error for a folder it cannot look at.
void parseArgs(int argc, char** argv, Config& config) {
    Arguments args(argc, argv);
    while (args.next()) {
        const std::string& arg = args.arg();
        if (arg == "--help" || arg == "-h") {
            config.help = true;
        } else if (args.isolationOption(config.isolation)) {
            continue;
        } else if (arg == "--report") {
            config.reportFile = args.value();
        } else if (arg == "--timeout") {
            config.timeout = args.number(1, 600, "1 to 600 seconds");
        } else if (arg.rfind("--", 0) == 0) {
            throw UsageError("unknown option " + arg);
        } else if (!config.submission.empty()) {
            throw UsageError("unexpected argument " + arg + " (one SUBMISSION folder)");
        } else {
            config.submission = arg;
        }
    }
    if (!config.help && config.submission.empty()) throw UsageError("no SUBMISSION folder given");
    if (!config.help && config.submission.find("{in}") != std::string::npos) {
        throw UsageError("the command mode is gone: hand in the loader's source, a folder holding " + std::string(kLoaderFile) +
                         " (t10::loadTga, t10/tga.hpp's signature), which is built and run in the sandbox");
    }
    if (!config.help && !fs::is_directory(config.submission)) throw UsageError(config.submission + ": not a folder");
}

Bytes readBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path.string() + ": cannot open: " + std::strerror(errno));
    return Bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void writeBytes(const fs::path& path, const Bytes& bytes, mode_t mode = 0644) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, mode);
    if (fd < 0) throw Error(path.string() + ": cannot create: " + std::strerror(errno));
    const bool written = bytes.empty() || ::write(fd, bytes.data(), bytes.size()) == static_cast<ssize_t>(bytes.size());
    const int error = errno;
    ::fchmod(fd, mode);
    ::close(fd);
    if (!written) throw Error(path.string() + ": cannot write: " + std::strerror(error));
}

// A folder of the grader's work tree, owned by `owner` (the job's uid) when the job writes there.
void makeDir(const fs::path& dir, uid_t owner, mode_t mode) {
    if (::mkdir(dir.c_str(), mode) != 0) throw Error(dir.string() + ": cannot create: " + std::strerror(errno));
    if (::chmod(dir.c_str(), mode) != 0) throw Error(dir.string() + ": chmod: " + std::strerror(errno));
    if (owner != 0 && ::chown(dir.c_str(), owner, owner) != 0) throw Error(dir.string() + ": chown: " + std::strerror(errno));
}

// The valid cases: every fixture with its reference PNG (read by the grader only).
std::vector<Case> validCases(const fs::path& fixtures) {
    std::vector<Case> cases;
    for (const auto& entry : fs::directory_iterator(fixtures)) {
        if (entry.path().extension() != ".tga") continue;
        fs::path png = entry.path();
        png.replace_extension(".png");
        if (fs::exists(png)) cases.push_back({entry.path().stem().string(), entry.path(), png});
    }
    std::sort(cases.begin(), cases.end(), [](const Case& a, const Case& b) { return a.name < b.name; });
    if (cases.empty()) throw Error(fixtures.string() + ": no TGA fixtures with reference PNGs");
    return cases;
}

// Malformed files, each derived from a valid fixture by one fault that the project's loader rejects.
std::vector<Case> malformedCases(const fs::path& fixtures, const fs::path& work) {
    const Bytes raw = readBytes(fixtures / "rgb24_raw_bl.tga");
    const Bytes rle = readBytes(fixtures / "rgb24_rle_bl.tga");
    std::vector<std::pair<std::string, Bytes>> files;
    auto patched = [](Bytes b, std::size_t at, std::initializer_list<unsigned char> values) {
        for (unsigned char v : values) b[at++] = v;
        return b;
    };
    files.push_back({"empty", {}});
    files.push_back({"truncated_header", Bytes(raw.begin(), raw.begin() + 7)});
    files.push_back({"zero_width", patched(raw, 12, {0, 0})});
    Bytes huge = patched(raw, 12, {0x00, 0x40, 0x00, 0x40}); // 16384 x 16384 with 10 bytes of data
    huge.resize(18 + 10);
    files.push_back({"huge_size_no_data", huge});
    files.push_back({"colour_mapped_type_1", patched(raw, 2, {1})});
    files.push_back({"no_image_type_0", patched(raw, 2, {0})});
    files.push_back({"depth_16", patched(raw, 16, {16})});
    files.push_back({"right_to_left", patched(raw, 17, {0x10})});
    // One byte short of the pixel data (a file may carry a footer after it).
    const std::size_t pixelEnd = 18 + raw[0] + std::size_t(raw[12] | raw[13] << 8) * std::size_t(raw[14] | raw[15] << 8) * 3;
    files.push_back({"pixel_data_truncated", Bytes(raw.begin(), raw.begin() + static_cast<long>(pixelEnd) - 1)});
    files.push_back({"rle_truncated", Bytes(rle.begin(), rle.begin() + static_cast<long>(18 + (rle.size() - 18) / 2))});
    makeDir(work, 0, 0700);
    std::vector<Case> cases;
    for (const auto& [name, bytes] : files) {
        const fs::path path = work / ("malformed_" + name + ".tga");
        writeBytes(path, bytes, 0600);
        cases.push_back({"malformed_" + name, path, {}});
    }
    return cases;
}

// Expands grey to RGB and adds an opaque alpha, so that a loader may return any channel count.
t10::Image8 toRgba(const t10::Image8& image) {
    t10::Image8 out(image.width, image.height, 4);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 4; ++c) {
                const int source = image.channels == 1 ? 0 : image.channels == 2 ? (c == 3 ? 1 : 0) : c;
                out.at(x, y, c) = c == 3 && image.channels != 4 && image.channels != 2 ? 255 : image.at(x, y, std::min(source, image.channels - 1));
            }
    return out;
}

bool same(const t10::Image8& a, const t10::Image8& b, bool flip, bool swap) {
    if (a.width != b.width || a.height != b.height) return false;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            for (int c = 0; c < 4; ++c) {
                const int sy = flip ? a.height - 1 - y : y;
                const int sc = swap && c != 3 ? 2 - c : c;
                if (a.at(x, y, c) != b.at(x, sy, sc)) return false;
            }
    return true;
}

// The harness's output (tga_harness.cpp), read as hostile input: a regular file, never followed,
// whose header and size agree. Throws t10::Error saying what is wrong with it.
t10::Image8 readRaw(const fs::path& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    struct stat info {};
    if (fd < 0 || ::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
        if (fd >= 0) ::close(fd);
        throw Error("the loader's output is not a regular file");
    }
    std::string data(static_cast<std::size_t>(std::min<off_t>(info.st_size, 64 << 20)), '\0');
    const ssize_t got = ::read(fd, data.data(), data.size());
    ::close(fd);
    // The header is the first line; the pixels after it may hold any byte (so no scanf whitespace).
    const std::size_t newline = data.find('\n');
    int width = 0, height = 0, channels = 0, used = 0;
    if (got != static_cast<ssize_t>(data.size()) || newline == std::string::npos || newline > 64 ||
        std::sscanf(data.substr(0, newline).c_str(), "T10RAW %d %d %d%n", &width, &height, &channels, &used) != 3 ||
        static_cast<std::size_t>(used) != newline) {
        throw Error("the loader's output cannot be read");
    }
    const std::size_t header = newline + 1;
    if (width < 1 || height < 1 || width > 16384 || height > 16384 || channels < 1 || channels > 4 ||
        data.size() - header != std::size_t(width) * std::size_t(height) * std::size_t(channels)) {
        throw Error("the loader returned a " + std::to_string(width) + "x" + std::to_string(height) + " image of " +
                    std::to_string(channels) + " channels whose pixel data does not match that size");
    }
    t10::Image8 image(width, height, channels);
    std::copy(data.begin() + static_cast<long>(header), data.end(), image.data.begin());
    return image;
}

// What the loader's image is, compared with the reference PNG.
void judgePixels(const Case& c, const fs::path& raw, Outcome& o) {
    try {
        const t10::Image8 expected = toRgba(t10::readPng(c.expected.string()));
        const t10::Image8 actual = toRgba(readRaw(raw));
        if (same(expected, actual, false, false)) {
            o.passed = true;
            o.verdict = "right pixels";
        } else if (same(expected, actual, true, false)) {
            o.verdict = "wrong orientation";
            o.detail = "upside down: the origin bit (descriptor bit 5) is ignored or inverted";
        } else if (same(expected, actual, false, true)) {
            o.verdict = "wrong channel order";
            o.detail = "red and blue swapped: TGA stores BGR(A)";
        } else if (same(expected, actual, true, true)) {
            o.verdict = "wrong orientation and channel order";
        } else {
            o.verdict = "wrong pixels";
            o.detail = std::to_string(actual.width) + "x" + std::to_string(actual.height) + ", expected " +
                       std::to_string(expected.width) + "x" + std::to_string(expected.height);
        }
    } catch (const Error& error) {
        o.verdict = "wrong pixels";
        o.detail = error.what();
    }
}

// The verdict of one run of the loader.
Outcome judge(const Case& c, const RunResult& result, const fs::path& raw) {
    Outcome o;
    o.name = c.name;
    o.malformed = c.expected.empty();
    // The harness's own words (tga_harness.cpp) and the student's, shortened: the report is theirs.
    const std::string said = result.output.substr(0, 200);
    if (result.timedOut) {
        o.verdict = "hang";
        o.detail = result.describe();
    } else if (result.signal != 0) {
        o.verdict = "crash";
        o.detail = result.describe();
    } else if (o.malformed) {
        o.passed = result.exitCode != 0;
        o.verdict = o.passed ? "rejected" : "accepted a malformed file";
        o.detail = o.passed ? "exit code " + std::to_string(result.exitCode) : "exit code 0";
    } else if (result.exitCode != 0) {
        o.verdict = "rejected a valid file";
        o.detail = result.describe() + ": " + said;
    } else if (!fs::exists(fs::symlink_status(raw))) {
        o.verdict = "no output";
        o.detail = "the loader's image was not written (did the loader end the program?)";
    } else {
        judgePixels(c, raw, o);
    }
    return o;
}

// Runs the loader on one case: a copy of the input alone in /case, the harness's output in /out.
Outcome runCase(const Job& job, const Case& c, int index, double timeout) {
    const fs::path dir = job.work / ("case-" + std::to_string(index));
    makeDir(dir, 0, 0711);
    makeDir(dir / "in", 0, 0755);
    writeBytes(dir / "in" / "input.tga", readBytes(c.input), 0644);
    makeDir(dir / "out", job.base.uid, 0700);
    SandboxRun run = job.base;
    run.limits = SandboxLimits{timeout, static_cast<int>(timeout) + 5, 2048, 64, 64, 16, 16};
    run.mounts = {{job.loader.string(), "/t10/bin/loader", false}, {(dir / "in").string(), "/case", false},
                  {(dir / "out").string(), "/out", true}};
    run.workingDirectory = "/out";
    const bool namespaces = run.isolation == Isolation::Namespaces;
    const std::string home = namespaces ? "/tmp" : (dir / "out").string();
    run.env = {"PATH=/usr/bin:/bin", "LC_ALL=C", "HOME=" + home, "TMPDIR=" + home};
    const RunResult result = runSandboxed(run, {run.path("/t10/bin/loader"), run.path("/case/input.tga"), run.path("/out/image.raw")},
                                          (job.work / "logs" / (c.name + ".log")).string());
    Outcome outcome = judge(c, result, dir / "out" / "image.raw");
    std::error_code ignored;
    fs::remove_all(dir, ignored);
    return outcome;
}

// The kit the loader is built with, copied into the grader's work folder so that the job's uid can
// read it wherever the checkout lies: the headers a loader may include (t10/image.hpp, t10/error.hpp,
// t10/file.hpp, t10/tga.hpp), and the harness and t10::readFile compiled by the project's build
// (grader/CMakeLists.txt, T10_GRADE_TGA_KIT). Nothing else of the project.
void stageKit(const fs::path& kit) {
    const fs::path source = T10_GRADE_TGA_SOURCE_DIR;
    makeDir(kit, 0, 0755);
    makeDir(kit / "include", 0, 0755);
    makeDir(kit / "include" / "t10", 0, 0755);
    for (const char* header : {"base/include/t10/image.hpp", "base/include/t10/error.hpp", "base/include/t10/file.hpp",
                               "content/include/t10/tga.hpp"}) {
        writeBytes(kit / "include" / "t10" / fs::path(header).filename(), readBytes(source / "common" / header));
    }
    for (const char* object : {"file.o", "tga_harness.o"}) writeBytes(kit / object, readBytes(fs::path(T10_GRADE_TGA_KIT) / object));
}

// Builds the copied tga.cpp with the kit in the sandbox; false with the compiler's words in `log`.
bool buildLoader(Job& job, const fs::path& copied, std::string& log) {
    const fs::path kit = job.work / "kit", out = job.work / "build";
    stageKit(kit);
    makeDir(out, job.base.uid, 0700);
    SandboxRun run = job.base;
    run.limits = SandboxLimits{120.0, 120, 4096, 64, 256, 64, 256};
    run.mounts = {{kit.string(), "/t10/kit", false}, {copied.string(), "/submission", false}, {out.string(), "/out", true}};
    run.workingDirectory = "/out";
    const std::string home = run.isolation == Isolation::Namespaces ? "/tmp" : out.string();
    run.env = {"PATH=/usr/bin:/bin", "LC_ALL=C", "HOME=" + home, "TMPDIR=" + home};
    // The flags the kit's objects were compiled with (grader/CMakeLists.txt names them once).
    std::vector<std::string> command{T10_GRADE_TGA_COMPILER};
    std::istringstream flags(T10_GRADE_TGA_FLAGS);
    for (std::string flag; flags >> flag;) command.push_back(flag);
    command.insert(command.end(), {"-I" + run.path("/t10/kit/include"), run.path("/submission/tga.cpp"),
                                   run.path("/t10/kit/tga_harness.o"), run.path("/t10/kit/file.o"), "-o",
                                   run.path("/out/loader")});
    const RunResult result = runSandboxed(run, command, (job.work / "logs" / "build.log").string());
    // The compiler names the submission's file by its path inside: the student knows it as tga.cpp.
    log = result.output;
    for (const std::string& prefix : {run.path("/submission/"), run.path("/t10/kit/")}) {
        for (auto at = log.find(prefix); at != std::string::npos; at = log.find(prefix, at)) log.erase(at, prefix.size());
    }
    if (result.timedOut) log += "\nthe build " + result.describe();
    const fs::path built = out / "loader";
    if (!result.ok() || !fs::is_regular_file(fs::symlink_status(built))) return false;
    // The job's copy: read-only to it, so a case cannot change the loader the next case runs.
    job.loader = job.work / "loader";
    writeBytes(job.loader, readBytes(built), 0755);
    return true;
}

void printAndReport(const Config& config, const nlohmann::json& report, const std::vector<Outcome>& outcomes) {
    int passed = 0;
    for (const Outcome& o : outcomes) {
        passed += o.passed ? 1 : 0;
        std::cout << (o.passed ? "pass  " : "FAIL  ") << o.name << ": " << o.verdict << (o.detail.empty() ? "" : " (" + o.detail + ")") << "\n";
    }
    std::cout << report.at("status").get<std::string>() << ", score " << report.at("score").get<int>() << " (" << passed
              << " of " << outcomes.size() << " cases)\n";
    if (report.at("status") != "graded") std::cout << report.at("message").get<std::string>() << "\n";
    if (!config.reportFile.empty()) t10::writeJsonFile(config.reportFile, report);
}

// The score: every case weighs the same, but a malformed file's case earns only the share of the
// valid files the loader decodes. Rejecting a malformed file proves nothing by itself: a loader that
// throws on every file rejects them all, and scores 0, not the malformed cases' share of 100.
int score(const std::vector<Outcome>& outcomes) {
    int valid = 0, decoded = 0, rejected = 0;
    for (const Outcome& o : outcomes) {
        valid += o.malformed ? 0 : 1;
        decoded += !o.malformed && o.passed ? 1 : 0;
        rejected += o.malformed && o.passed ? 1 : 0;
    }
    if (outcomes.empty() || valid == 0) return 0;
    // (decoded + rejected * decoded / valid) of the cases, in whole points, rounded down.
    const long earned = 100L * (static_cast<long>(decoded) * valid + static_cast<long>(rejected) * decoded);
    return static_cast<int>(earned / (static_cast<long>(outcomes.size()) * valid));
}

// Grades the submission in `job`'s work folder; the report as report.json holds it.
nlohmann::json grade(const Config& config, Job& job, std::vector<Outcome>& outcomes) {
    nlohmann::json report{{"submission", fs::path(config.submission).lexically_normal().filename().string()},
                          {"isolation", isolationName(job.base.isolation)}, {"status", "graded"}, {"score", 0}, {"message", ""}};
    const fs::path copy = job.work / "submission";
    const CopiedSubmission copied = copySubmission(fs::absolute(config.submission).string(), {{kLoaderFile}, {kLoaderFile}}, "",
                                                   FillPolicy::None, copy.string());
    report["files"] = nlohmann::json::array();
    for (const SubmissionFile& f : copied.files)
        report["files"].push_back({{"name", f.name}, {"source", f.source}, {"reason", f.reason}, {"bytes", f.bytes}});
    if (copied.empty || !copied.missing.empty()) {
        report["status"] = copied.empty ? "empty" : "missing-files";
        report["message"] = std::string("the submission has no ") + kLoaderFile + " (see the file list: a name in the wrong case "
                            "or a symlink is not taken)";
        return report;
    }
    std::string log;
    if (!buildLoader(job, copy, log)) {
        report["status"] = "build-failed";
        report["message"] = std::string(kLoaderFile) + " does not build with the harness (t10::loadTga, t10/tga.hpp):\n" + log.substr(0, 4000);
        return report;
    }
    const fs::path fixtures = T10_GRADE_TGA_FIXTURES;
    std::vector<Case> cases = validCases(fixtures);
    const std::vector<Case> malformed = malformedCases(fixtures, job.work / "malformed");
    cases.insert(cases.end(), malformed.begin(), malformed.end());
    int passed = 0;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        outcomes.push_back(runCase(job, cases[i], static_cast<int>(i), config.timeout));
        passed += outcomes.back().passed ? 1 : 0;
    }
    report["score"] = score(outcomes);
    report["cases"] = nlohmann::json::array();
    for (const Outcome& o : outcomes) {
        report["cases"].push_back({{"file", o.name}, {"malformed", o.malformed}, {"passed", o.passed}, {"verdict", o.verdict},
                                   {"detail", o.detail}});
    }
    return report;
}

// The private work folder: only the grader lists it; the job passes through to its own folders.
Job prepareJob(const Config& config) {
    Job job;
    const bool root = ::geteuid() == 0;
    const uid_t uid = root && config.isolation != "none" ? pickJobUids(1).front() : 0;
    job.base.isolation = chooseIsolation(config.isolation, uid, "t10-grade-tga", std::cerr);
    job.base.uid = job.base.isolation == Isolation::None ? 0 : uid;
    // Not root: the loader's process limit is counted in its sandbox's own user namespace where the
    // kernel can, else with every process of this user (graders beside it share it).
    std::string shared;
    if (job.base.isolation == Isolation::Namespaces && job.base.uid == 0) shared = probeOwnProcessLimit();
    job.base.ownProcessLimit = job.base.isolation == Isolation::Namespaces && job.base.uid == 0 && shared.empty();
    std::cerr << "t10-grade-tga: the loader runs with isolation " << isolationName(job.base.isolation);
    if (job.base.uid != 0) std::cerr << " (job uids " << job.base.uid << ")";
    if (job.base.ownProcessLimit) std::cerr << " (its process limit counted in its own user namespace)";
    if (!shared.empty()) std::cerr << " (its process limit shared with this user's other processes: " << shared << ")";
    std::cerr << "\n";
    std::random_device random;
    job.work = fs::temp_directory_path() / ("t10-grade-tga." + std::to_string(::getpid()) + "." + std::to_string(random()));
    makeDir(job.work, 0, 0711);
    makeDir(job.work / "logs", 0, 0700);
    if (job.base.isolation == Isolation::Uid) {
        struct stat info {};
        if (::stat(T10_GRADE_TGA_FIXTURES, &info) == 0 && (info.st_mode & S_IROTH)) {
            std::cerr << "t10-grade-tga: warning: --isolation uid: " << T10_GRADE_TGA_FIXTURES
                      << " is readable by others, so a loader can read the reference PNGs there (chmod o-rwx it)\n";
        }
    }
    return job;
}

} // namespace

// Every exception ends here: one line on stderr naming what failed (a path and the system's reason
// for a system error) and, with --report, a grader-error report there.
int main(int argc, char** argv) {
    Config config;
    Job job;
    try {
        parseArgs(argc, argv, config);
        if (config.help) {
            std::cout << kUsage;
            return 0;
        }
        job = prepareJob(config);
        std::vector<Outcome> outcomes;
        const nlohmann::json report = grade(config, job, outcomes);
        printAndReport(config, report, outcomes);
        std::error_code ignored;
        fs::remove_all(job.work, ignored);
        return 0;
    } catch (const UsageError& error) {
        std::cerr << "t10-grade-tga: error: " << error.what() << "\n" << kUsage;
        return 2;
    } catch (...) {
        const std::string why = t10::errorLine(std::current_exception());
        std::cerr << "t10-grade-tga: error: " << why << "\n";
        std::error_code ignored;
        if (!job.work.empty()) fs::remove_all(job.work, ignored);
        if (!config.reportFile.empty()) {
            try {
                t10::writeJsonFile(config.reportFile, {{"submission", fs::path(config.submission).lexically_normal().filename().string()},
                                                       {"status", "grader-error"}, {"score", 0},
                                                       {"message", "the grader failed: " + why}});
            } catch (...) {
                std::cerr << "t10-grade-tga: error: " << t10::errorLine(std::current_exception()) << "\n";
            }
        }
        return 1;
    }
}
