// t10-grade: grades students' versions of a Tutorial 10 stage.
//   t10-grade --part 1|2|3 [--report DIR] [--jobs N] [--timeout S] [--cache DIR] [--format F]...
//             [--name-from N|PATTERN] [--roster CSV] SUBMISSION...
// A submission is a folder with any of Tutorial10.cpp and the part's shaders; what it lacks comes
// from the reference stage. Its host code is built against common/ in a build folder of its own,
// then it renders four cases under limits (a power-of-two size with one camera, a
// non-power-of-two size with another, and two synthetic inputs: black pixels next to pixels far
// above the white point, and one hot pixel), and checks.hpp compares every buffer with the CPU
// reference and the frame with the reference stage (FLIP). Part 3 programs are built with
// pass_capture.cpp, which records each blur pass beside the dump. Writes DIR/<submission>/report.json and
// report.html (and the platforms' results of --format, formats.hpp), DIR/gradebook.csv, and the class
// index DIR/index.html with DIR/grades-lms.csv (class_index.hpp). Exit 0 when every submission got a
// report, 1 when the grader failed, 2 on bad usage.
#include "checks.hpp"
#include "class_index.hpp"
#include "formats.hpp"
#include "report.hpp"
#include "run_limited.hpp"

#include "t10/error.hpp"
#include "t10/image_io.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>
#include <regex>
#include <set>
#include <sstream>
#include <thread>

namespace fs = std::filesystem;

namespace {

using t10::Error;
using t10::UsageError;
using namespace t10::grade;

struct PartInfo {
    const char* stage;
    std::vector<std::string> shaders;
};

PartInfo partInfo(int part) {
    switch (part) {
    case 1: return {"tutorial10_part1_tonemap", {"PostProcess.frag", "PostProcessInit.frag"}};
    case 2: return {"tutorial10_part2_bloom", {"PostProcess.frag", "PostProcessInit.frag"}};
    default: return {"tutorial10_part3_gaussian", {"PostProcess.frag", "PostProcessInit.frag", "Gauss.frag"}};
    }
}

struct CaseSpec {
    std::string id;
    std::string description;
    bool camera;
    std::vector<std::string> args; // "{inputs}" is replaced by the synthetic inputs' folder
};

// Small sizes keep a submission to a few seconds on a CPU renderer; 160x90 halves to 80x45 and its
// luminance chain passes odd sizes (45, 5), unlike 128x128.
std::vector<CaseSpec> cases(int part) {
    std::vector<CaseSpec> list{
        {"pot", "128x128 (power of two), camera default", true, {"--size", "128x128", "--camera", "default"}},
        {"npot", "160x90 (not a power of two), camera lights", true, {"--size", "160x90", "--camera", "lights"}},
        {"extremes", "64x64 input: black pixels, and every pixel a different luminance from 0.001 to 50", false,
         {"--input", "{inputs}/ramp.exr"}},
    };
    if (part >= 2) list.push_back({"hot", "128x128 input: one hot 2x2 block on grey", false, {"--input", "{inputs}/hot.exr"}});
    return list;
}

struct Config {
    int part = 0;
    std::string reportDir = "grade-report";
    int jobs = 1;
    double timeout = 60.0;
    std::string cacheDir = T10_GRADE_CACHE_DIR;
    std::vector<std::string> submissions;
    std::vector<std::string> formats;  // platform results (formats.hpp)
    std::string nameFrom;              // how a submission is named: "" (its last folder), a component index or a pattern
    std::string roster;                // a CSV mapping those names to student ids (class_index.hpp)
    std::vector<std::string> names;    // per submission: its report folder's name
    std::map<std::string, std::string> studentNames;  // per name: the student's name from the roster
};

constexpr const char* kUsage =
    "usage: t10-grade --part 1|2|3 [--report DIR] [--jobs N] [--timeout SECONDS] [--cache DIR] [--format F]... [--name-from N|PATTERN]\n"
    "                 [--roster CSV] SUBMISSION...\n"
    "  SUBMISSION  a folder with any of Tutorial10.cpp and the part's shaders (the rest comes from the reference)\n"
    "  --report    where report.json/report.html per submission and gradebook.csv go (default grade-report)\n"
    "  --jobs      submissions graded in parallel (default 1)\n"
    "  --timeout   wall-clock limit of one render, in seconds (default 60); builds get 300\n"
    "  --cache     where built submissions and the reference renders are kept (default " T10_GRADE_CACHE_DIR ")\n"
    "  --format    also write a platform's result beside each report.json: gradescope, prairielearn or classroom\n"
    "              (repeatable)\n"
    "  --name-from name each submission after a component of its path: N counts from the start (1 = the first\n"
    "              folder; -1, the default, is the last), or a regular expression whose first group (or whole\n"
    "              match) is the name, e.g. --name-from '([^/]+)/student'\n"
    "  --roster    a CSV (columns folder or github_username, student_id or identifier, optional name): names\n"
    "              each submission by the student id of its name; writes index.html and grades-lms.csv by id\n";

std::string submissionName(const std::string& path) {
    fs::path p = fs::path(path).lexically_normal();
    if (p.filename().empty()) p = p.parent_path();
    return p.filename().string();
}

// The name --name-from gives the submission at `path`; throws UsageError when there is none.
std::string nameFrom(const std::string& path, const std::string& how) {
    if (how.empty()) return submissionName(path);
    std::string name;
    if (std::regex_match(how, std::regex("-?[0-9]+"))) {
        std::vector<std::string> parts;
        for (const fs::path& part : fs::path(path).lexically_normal())
            if (!part.empty() && part != "." && part != fs::path(path).root_path()) parts.push_back(part.string());
        const long index = std::strtol(how.c_str(), nullptr, 10);
        const long at = index > 0 ? index - 1 : static_cast<long>(parts.size()) + index;
        if (index == 0 || at < 0 || at >= static_cast<long>(parts.size()))
            throw UsageError("--name-from " + how + ": " + path + " has " + std::to_string(parts.size()) + " components");
        name = parts[static_cast<std::size_t>(at)];
    } else {
        std::regex pattern;
        try {
            pattern = std::regex(how);
        } catch (const std::regex_error& error) {
            throw UsageError("--name-from " + how + ": not a component index nor a valid regular expression (" + error.what() + ")");
        }
        std::smatch match;
        if (!std::regex_search(path, match, pattern)) throw UsageError("--name-from " + how + ": does not match " + path);
        name = match.size() > 1 && match[1].matched ? match[1].str() : match[0].str();
    }
    if (name.empty() || name == "." || name == ".." || name.find('/') != std::string::npos)
        throw UsageError("--name-from " + how + ": gives " + path + " the name '" + name + "', which cannot name a report folder");
    return name;
}

Config parse(int argc, char** argv) {
    Config config;
    auto number = [](const std::string& option, const std::string& text, double low, double high) {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (text.empty() || *end != '\0' || !(value >= low && value <= high)) {
            std::ostringstream message;
            message << option << " " << text << ": expected a number from " << low << " to " << high;
            throw UsageError(message.str());
        }
        return value;
    };
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw UsageError(arg + " needs a value");
            return argv[++i];
        };
        if (arg == "--help" || arg == "-h") {
            std::cout << kUsage;
            std::exit(0);
        } else if (arg == "--part") {
            const std::string v = value();
            if (v != "1" && v != "2" && v != "3") throw UsageError("--part " + v + ": choose 1, 2 or 3");
            config.part = std::stoi(v);
        } else if (arg == "--report") {
            config.reportDir = value();
        } else if (arg == "--jobs") {
            config.jobs = static_cast<int>(number(arg, value(), 1, 64));
        } else if (arg == "--timeout") {
            config.timeout = number(arg, value(), 1, 3600);
        } else if (arg == "--cache") {
            config.cacheDir = value();
        } else if (arg == "--format") {
            const std::string v = value();
            const std::vector<std::string>& known = formatNames();
            if (std::find(known.begin(), known.end(), v) == known.end())
                throw UsageError("--format " + v + ": choose gradescope, prairielearn or classroom");
            if (std::find(config.formats.begin(), config.formats.end(), v) == config.formats.end()) config.formats.push_back(v);
        } else if (arg == "--name-from") {
            config.nameFrom = value();
        } else if (arg == "--roster") {
            config.roster = value();
        } else if (arg.rfind("--", 0) == 0) {
            throw UsageError("unknown option " + arg);
        } else {
            config.submissions.push_back(arg);
        }
    }
    if (config.part == 0) throw UsageError("--part is required (1, 2 or 3)");
    if (config.submissions.empty()) throw UsageError("no SUBMISSION folder given");
    std::map<std::string, RosterEntry> roster;
    if (!config.roster.empty()) {
        try {
            roster = readRoster(config.roster);
        } catch (const Error& error) {
            throw UsageError(error.what());
        }
    }
    std::map<std::string, std::string> names;  // name -> the submission that has it
    const fs::path report = fs::weakly_canonical(fs::absolute(config.reportDir));
    for (const std::string& s : config.submissions) {
        if (!fs::is_directory(s)) throw UsageError(s + ": not a folder");
        std::string name = nameFrom(s, config.nameFrom);
        if (!config.roster.empty()) {
            const auto entry = roster.find(name);
            if (entry == roster.end()) throw UsageError(s + ": '" + name + "' is not in the roster " + config.roster);
            name = entry->second.studentId;
            if (!entry->second.name.empty()) config.studentNames[name] = entry->second.name;
        }
        if (!names.emplace(name, s).second) {
            throw UsageError("two submissions are named '" + name + "' (" + names[name] + " and " + s +
                             "): name them after another component of their path with --name-from N (1 = the first "
                             "folder, -1 = the last) or --name-from PATTERN (a regular expression whose first group is "
                             "the name), or by student id with --roster CSV");
        }
        config.names.push_back(name);
        // The report folder of a submission is emptied first: it must not be, or hold, the submission.
        const fs::path folder = fs::weakly_canonical(fs::absolute(s));
        const fs::path target = report / name;
        const auto [end, unused] = std::mismatch(target.begin(), target.end(), folder.begin(), folder.end());
        if (end == target.end()) throw UsageError("--report " + config.reportDir + " would overwrite the submission " + s);
    }
    return config;
}

std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path + ": cannot open");
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::string tail(const std::string& text, std::size_t lines) {
    std::size_t pos = text.size();
    for (std::size_t n = 0; n <= lines; ++n) {
        if (pos == 0) return text;
        pos = text.rfind('\n', pos - 1);
        if (pos == std::string::npos) return text;
    }
    return text.substr(pos + 1);
}

// The NaN probe: a copy of the submission's shaders whose PostProcess.frag paints every NaN output
// magenta. GL leaves the 8-bit conversion of NaN to the driver and Mesa writes 0, so without the probe
// a tone map that divides 0 by 0 on black pixels renders exactly like a guarded one. Returns "" when
// the shader's main() or its vec3/vec4 output cannot be found (the case then runs unprobed).
std::string writeNanProbe(const std::string& submissionDir, const std::string& referenceDir, const std::string& probeDir) {
    fs::create_directories(probeDir);
    for (const auto& entry : fs::directory_iterator(submissionDir)) {
        if (entry.is_regular_file()) fs::copy_file(entry.path(), fs::path(probeDir) / entry.path().filename(), fs::copy_options::overwrite_existing);
    }
    const fs::path own = fs::path(submissionDir) / "PostProcess.frag";
    const std::string source = readFile(fs::exists(own) ? own.string() : referenceDir + "/PostProcess.frag");
    const std::regex mainPattern(R"(\bvoid\s+main\s*\(\s*(void)?\s*\))");
    const std::regex outPattern(R"(\bout\s+(vec3|vec4)\s+(\w+)\s*;)");
    std::smatch output;
    if (!std::regex_search(source, mainPattern) || !std::regex_search(source, output, outPattern)) return "";
    const std::string magenta = output[1] == "vec3" ? "vec3(1.0, 0.0, 1.0)" : "vec4(1.0, 0.0, 1.0, 1.0)";
    std::ofstream(fs::path(probeDir) / "PostProcess.frag")
        << std::regex_replace(source, mainPattern, "void t10gradeStudentMain()")
        << "\n// Added by t10-grade: NaN outputs are painted magenta so that the 8-bit frame shows them.\n"
        << "void main() {\n    t10gradeStudentMain();\n    if (any(isnan(" << output[2].str() << "))) " << output[2].str()
        << " = " << magenta << ";\n}\n";
    return probeDir;
}

// FNV-1a: names a build folder after what was built.
std::string hashOf(const std::string& text) {
    std::uint64_t hash = 1469598103934665603ull;
    for (const unsigned char c : text) {
        hash ^= c;
        hash *= 1099511628211ull;
    }
    std::ostringstream out;
    out << std::hex << hash;
    return out.str();
}

// A folder is filled under a temporary name and renamed into place, so that parallel graders (or
// jobs) sharing the cache never see half of it.
void publishDirectory(const fs::path& temporary, const fs::path& target) {
    std::error_code error;
    fs::rename(temporary, target, error);
    if (error) fs::remove_all(temporary); // another grader got there first: keep theirs
}

std::string uniqueSuffix() {
    static std::atomic<int> counter{0};
    return "." + std::to_string(::getpid()) + "." + std::to_string(counter++);
}

// The compile and link recipe the build wrote for submissions (tools/grade/CMakeLists.txt).
struct HostKit {
    std::string compiler;
    std::vector<std::string> flags, includes, defines, libs;
    std::string text;
};

std::vector<std::string> splitList(const std::string& text) {
    std::vector<std::string> items;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, ';');)
        if (!item.empty()) items.push_back(item);
    return items;
}

HostKit loadHostKit() {
    HostKit kit;
    kit.text = readFile(T10_GRADE_HOST_KIT);
    std::stringstream in(kit.text);
    for (std::string line; std::getline(in, line);) {
        const auto space = line.find(' ');
        const std::string key = line.substr(0, space);
        const std::string value = space == std::string::npos ? "" : line.substr(space + 1);
        if (key == "compiler") kit.compiler = value;
        else if (key == "flags") kit.flags = splitList(value);
        else if (key == "includes") kit.includes = splitList(value);
        else if (key == "defines") kit.defines = splitList(value);
        else if (key == "libs") kit.libs = splitList(value);
    }
    if (kit.compiler.empty()) throw Error(std::string(T10_GRADE_HOST_KIT) + ": no compiler line");
    return kit;
}

class Grader {
public:
    explicit Grader(Config config) : config_(std::move(config)), info_(partInfo(config_.part)), kit_(loadHostKit()) {
        if (!fs::exists(T10_GRADE_FLIP)) {
            throw Error(std::string(T10_GRADE_FLIP) + ": FLIP (the perceptual image metric) is not installed; run "
                        "`make grade-deps` (a pinned flip-evaluator in a venv under build/)");
        }
        referenceBinary_ = std::string(T10_GRADE_BIN_DIR) + "/" + info_.stage;
        if (!fs::exists(referenceBinary_)) throw Error(referenceBinary_ + ": the reference stage is not built");
        fs::create_directories(config_.cacheDir);
        fs::create_directories(config_.reportDir);
        prepareInputs();
        prepareReference();
        if (config_.part == 3) {
            // Shaders-only submissions share the reference host code built with the pass capture:
            // built once here rather than by each of the parallel jobs.
            std::string log;
            if (build(referenceHost(), log).empty()) throw Error(referenceHost() + " with the pass capture does not build:\n" + log);
        }
    }

    Report grade(const std::string& submission, const std::string& name) const;

private:
    void prepareInputs();
    void prepareReference();
    std::string referenceHost() const {
        return std::string(T10_GRADE_SOURCE_DIR) + "/" + info_.stage + "/Tutorial10.cpp";
    }
    std::vector<std::string> caseArgs(const CaseSpec& spec) const {
        std::vector<std::string> args;
        for (std::string arg : spec.args) {
            const auto at = arg.find("{inputs}");
            if (at != std::string::npos) arg.replace(at, 8, inputsDir_);
            args.push_back(arg);
        }
        return args;
    }
    std::vector<std::string> renderCommand(const std::string& binary, const CaseSpec& spec, const std::string& shaderDir,
                                           const std::string& out) const {
        std::vector<std::string> argv{binary, "--headless", "--backend", "egl", "--frames", "1"};
        for (const std::string& a : caseArgs(spec)) argv.push_back(a);
        if (!shaderDir.empty()) argv.insert(argv.end(), {"--shader-dir", shaderDir});
        argv.insert(argv.end(), {"--dump", out, "--output", out + "/frame.png"});
        return argv;
    }
    // Builds Tutorial10.cpp; returns the program, or "" with the compiler's message in `log`.
    std::string build(const std::string& source, std::string& log) const;
    Check flipCheck(const CaseSpec& spec, const std::string& studentFrame, const std::string& reportDir,
                    const std::vector<Check>& caseChecks) const;

    Config config_;
    PartInfo info_;
    HostKit kit_;
    std::string referenceBinary_;
    std::string inputsDir_;
    std::string referenceDir_;
};

void Grader::prepareInputs() {
    inputsDir_ = (fs::absolute(config_.cacheDir) / "inputs").string();
    if (fs::exists(inputsDir_ + "/ramp.exr") && fs::exists(inputsDir_ + "/hot.exr")) return;
    const std::string temporary = inputsDir_ + uniqueSuffix();
    fs::create_directories(temporary);
    const RunResult result = runLimited({std::string(T10_GRADE_BIN_DIR) + "/make_test_images", temporary},
                                        Limits{}, temporary + ".log");
    if (!result.ok()) throw Error("make_test_images " + result.describe() + ":\n" + result.output);
    fs::remove(temporary + ".log");
    publishDirectory(temporary, inputsDir_);
}

void Grader::prepareReference() {
    // The reference renders are kept until the reference program or its shaders change.
    std::string stamp = referenceBinary_;
    stamp += std::to_string(fs::last_write_time(referenceBinary_).time_since_epoch().count());
    for (const std::string& shader : info_.shaders)
        stamp += readFile(std::string(T10_GRADE_SOURCE_DIR) + "/" + info_.stage + "/" + shader);
    referenceDir_ = (fs::absolute(config_.cacheDir) / ("reference-" + std::string(info_.stage) + "-" + hashOf(stamp))).string();
    if (fs::exists(referenceDir_)) return;
    const std::string temporary = referenceDir_ + uniqueSuffix();
    for (const CaseSpec& spec : cases(config_.part)) {
        const std::string out = temporary + "/" + spec.id;
        fs::create_directories(out);
        const RunResult result = runLimited(renderCommand(referenceBinary_, spec, "", out), Limits{}, out + "/run.log");
        if (!result.ok()) throw Error("the reference " + std::string(info_.stage) + " (" + spec.id + ") " + result.describe() + ":\n" + result.output);
    }
    publishDirectory(temporary, referenceDir_);
}

std::string Grader::build(const std::string& source, std::string& log) const {
    // The key: the code, the recipe, and when each library was last built (a rebuilt common/ must
    // not leave stale programs in the cache).
    // Part 3 programs carry the blur pass capture (pass_capture.cpp): the submission's call of
    // t10::runStage() is renamed to the capture's t10::gradeRunStage().
    const std::string capture = std::string(T10_GRADE_SOURCE_DIR) + "/tools/grade/pass_capture.cpp";
    const bool captures = config_.part == 3;
    std::string key = kit_.text + info_.stage + readFile(source) + (captures ? readFile(capture) : "");
    for (const std::string& lib : kit_.libs) {
        std::error_code error;
        const auto time = fs::last_write_time(lib, error);
        if (!error) key += lib + std::to_string(time.time_since_epoch().count());
    }
    const fs::path dir = fs::absolute(config_.cacheDir) / "builds" / hashOf(key);
    const std::string program = (dir / "student").string();
    if (fs::exists(program)) {
        log = readFile((dir / "build.log").string());
        return program;
    }
    const fs::path temporary = dir.string() + uniqueSuffix();
    fs::create_directories(temporary);
    std::vector<std::string> argv{kit_.compiler};
    argv.insert(argv.end(), kit_.flags.begin(), kit_.flags.end());
    for (const std::string& include : kit_.includes) argv.push_back("-I" + include);
    for (const std::string& define : kit_.defines) argv.push_back("-D" + define);
    argv.push_back(std::string("-DT10_STAGE_NAME=\"") + info_.stage + "\"");
    argv.push_back(std::string("-DT10_STAGE_SHADER_DIR=\"") + T10_GRADE_SOURCE_DIR + "/" + info_.stage + "\"");
    // The submission's own file, so that the compiler's messages name it.
    if (captures) argv.insert(argv.end(), {"-DrunStage=gradeRunStage", capture});
    argv.insert(argv.end(), {source, "-o", (temporary / "student").string()});
    argv.insert(argv.end(), kit_.libs.begin(), kit_.libs.end());
    {
        // The command, so that an instructor can rebuild it by hand.
        std::ofstream script(temporary / "build.sh");
        script << "#!/bin/sh\n";
        for (const std::string& a : argv) script << "'" << a << "' ";
        script << "\n";
    }
    const Limits limits{300.0, 300, 4096};
    const RunResult result = runLimited(argv, limits, (temporary / "build.log").string());
    log = result.output;
    if (!result.ok()) {
        if (!result.timedOut && result.signal == 0 && log.empty()) log = "the compiler " + result.describe();
        if (result.timedOut) log += "\nthe build " + result.describe();
        fs::remove_all(temporary);
        return "";
    }
    publishDirectory(temporary, dir);
    return program;
}

Check Grader::flipCheck(const CaseSpec& spec, const std::string& studentFrame, const std::string& reportDir,
                        const std::vector<Check>& caseChecks) const {
    Check check;
    check.id = spec.id + ".flip";
    check.steps = partSteps(config_.part);
    const std::string referenceFrame = referenceDir_ + "/" + spec.id + "/frame.png";
    const fs::path images = fs::path(reportDir) / "images";
    fs::create_directories(images);
    const std::string base = check.id + ".flip";
    const RunResult result = runLimited({T10_GRADE_FLIP, "-r", referenceFrame, "-t", studentFrame, "-v", "1", "-d",
                                         images.string(), "-b", base},
                                        Limits{120.0, 120, 4096}, (images / (base + ".log")).string());
    const auto at = result.output.find("Mean:");
    if (!result.ok() || at == std::string::npos) {
        throw Error("FLIP " + result.describe() + " on " + studentFrame + ":\n" + result.output);
    }
    const double mean = std::strtod(result.output.c_str() + at + 5, nullptr);
    // The reference program renders the same frame on the same driver bit for bit (mean 0). An
    // equivalent rewrite of the operator (the test submission "equivalent") moves a few pixels by one
    // 8-bit step and measures below 1e-6; the subtlest mistakes of the catalogue measure 0.03 (a tap
    // at 0.424 sigma, a threshold of 2.5 Yw at 160x90) and the others 0.1 to 0.75.
    constexpr double kBound = 0.005;
    check.passed = mean <= kBound;
    std::ostringstream measured;
    measured << "mean FLIP " << mean << " against the reference stage (" << spec.description << ")";
    check.measured = measured.str();
    check.tolerance = "mean FLIP <= 0.005: the reference renders identically on the same driver (0), an "
                      "equivalent rewrite measures below 1e-6, the subtlest known mistake 0.03";
    fs::remove(images / (base + ".log"));
    if (check.passed) {
        fs::remove(images / (base + ".png"));
        return check;
    }
    fs::copy_file(studentFrame, images / (check.id + ".student.png"), fs::copy_options::overwrite_existing);
    fs::copy_file(referenceFrame, images / (check.id + ".reference.png"), fs::copy_options::overwrite_existing);
    check.studentImage = "images/" + check.id + ".student.png";
    check.referenceImage = "images/" + check.id + ".reference.png";
    check.heatMap = "images/" + base + ".png";
    for (const Check& c : caseChecks) {
        if (!c.passed && !c.diagnosis.empty() && !c.followsFrom) {
            check.diagnosis += (check.diagnosis.empty() ? "" : "; ") + c.id + ": " + c.diagnosis;
        }
    }
    if (check.diagnosis.empty()) {
        check.diagnosis = "every buffer matches the CPU reference, but the frame differs from the reference stage: "
                          "look at the heat-map (for example the scene or the view, not the post-process)";
    }
    return check;
}

Report Grader::grade(const std::string& submission, const std::string& name) const {
    const auto start = std::chrono::steady_clock::now();
    Report report;
    report.submission = name;
    report.path = submission;
    report.part = config_.part;
    report.rubric = loadRubric(config_.part); // a faulty rubric stops before any build or render
    const fs::path out = fs::absolute(config_.reportDir) / report.submission;
    fs::remove_all(out);
    fs::create_directories(out);
    auto finish = [&](Report& r) {
        r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        writeReportJson(r, (out / "report.json").string());
        writeReportHtml(r, (out / "report.html").string());
        return r;
    };

    const std::string sourceDir = fs::absolute(submission).string();
    std::string binary = referenceBinary_;
    // Part 3 always runs a program built here, so that its blur passes are captured: a
    // shaders-only submission gets the reference host code (built once, then cached).
    const std::string host = fs::exists(sourceDir + "/Tutorial10.cpp") ? sourceDir + "/Tutorial10.cpp"
                             : config_.part == 3                         ? referenceHost()
                                                                         : "";
    if (!host.empty()) {
        std::string log;
        binary = build(host, log);
        std::ofstream(out / "build.log") << log;
        if (binary.empty()) {
            report.status = "build-failed";
            report.message = "Tutorial10.cpp does not build against common/:\n" + tail(log, 40);
            return finish(report);
        }
    }

    const Limits limits{config_.timeout, static_cast<int>(config_.timeout * 2) + 5, 4096};
    std::vector<CaseRun> runs;
    for (const CaseSpec& spec : cases(config_.part)) {
        const std::string dir = (out / "runs" / spec.id).string();
        fs::create_directories(dir);
        std::string shaderDir = sourceDir;
        if (spec.id == "extremes") {
            const std::string probe = writeNanProbe(sourceDir, std::string(T10_GRADE_SOURCE_DIR) + "/" + info_.stage,
                                                    (out / "runs" / "nan-probe-shaders").string());
            if (!probe.empty()) shaderDir = probe;
        }
        const RunResult result = runLimited(renderCommand(binary, spec, shaderDir, dir), limits, dir + "/run.log");
        if (!result.ok()) {
            const std::string& o = result.output;
            if (result.timedOut || result.signal == SIGXCPU) {
                report.status = "timeout";
            } else if (result.signal == 0 && (o.find("shader compilation failed") != std::string::npos ||
                                              o.find("program link failed") != std::string::npos ||
                                              o.find("shader not found") != std::string::npos)) {
                report.status = "shader-error";
            } else {
                report.status = "crashed";
            }
            report.message = "case " + spec.id + " (" + spec.description + "): the program " + result.describe() +
                             (result.timedOut ? " (limit " + std::to_string(int(config_.timeout)) + " s)" : "") +
                             ". Its last output:\n" + tail(o, 30);
            return finish(report);
        }
        runs.push_back(CaseRun{spec.id, spec.description, spec.camera, t10::test::Dump{}});
        try {
            runs.back().dump = loadDumpDir(dir);
        } catch (const Error& error) {
            report.status = "crashed";
            report.message = "case " + spec.id + ": the program exited 0 but wrote no readable output: " + error.what();
            return finish(report);
        }
    }

    report.status = "graded";
    const std::vector<CaseSpec> specs = cases(config_.part);
    for (std::size_t i = 0; i < runs.size(); ++i) {
        std::vector<Check> checks;
        try {
            checks = bufferChecks(config_.part, runs[i], out.string(), (out / "images").string());
        } catch (const Error& error) {
            // A buffer the part must write is missing or malformed: one failed check says which.
            Check check;
            check.id = runs[i].id + ".buffers";
            check.steps = partSteps(config_.part);
            check.measured = error.what();
            check.tolerance = "every texture of the part is on its unit (15, 16, 17) with its full size and levels";
            check.diagnosis = "the stage does not write the buffers of this part where the tutorial puts them";
            checks.push_back(check);
        }
        if (specs[i].camera) {
            Check flip = flipCheck(specs[i], (out / "runs" / specs[i].id / "frame.png").string(), out.string(), checks);
            // FLIP sees what a buffer check of the same case already blamed: it costs nothing more. Alone,
            // every buffer is right and the frame is not: it costs the steps that make the frame.
            const bool buffersFailed = std::any_of(checks.begin(), checks.end(), [](const Check& c) { return !c.passed; });
            if (!flip.passed && buffersFailed) {
                flip.followsFrom = true;
                std::string ids;
                for (const Check& c : checks)
                    if (!c.passed) ids += (ids.empty() ? "" : ", ") + c.id;
                flip.diagnosis = "follows from " + ids + " (the frame shows what they diagnose)";
            }
            else if (!flip.passed) flip.blame = frameSteps(config_.part);
            checks.push_back(flip);
        }
        report.checks.insert(report.checks.end(), checks.begin(), checks.end());
    }
    crossCheckCases(config_.part, runs, report.checks);
    return finish(report);
}

} // namespace

int main(int argc, char** argv) {
    Config config;
    try {
        config = parse(argc, argv);
    } catch (const UsageError& error) {
        std::cerr << "t10-grade: error: " << error.what() << "\n" << kUsage;
        return 2;
    }
    try {
        const Grader grader(config);
        std::vector<Report> reports(config.submissions.size());
        std::atomic<std::size_t> next{0};
        std::atomic<bool> failed{false};
        std::mutex printing;
        auto worker = [&]() {
            for (std::size_t i = next++; i < config.submissions.size(); i = next++) {
                try {
                    reports[i] = grader.grade(config.submissions[i], config.names[i]);
                    const std::lock_guard<std::mutex> lock(printing);
                    std::cout << reports[i].submission << ": " << reports[i].status << ", score " << reports[i].score()
                              << " (" << reports[i].passedCount() << "/" << reports[i].checks.size() << " checks) in "
                              << static_cast<int>(reports[i].seconds + 0.5) << " s\n";
                } catch (const std::exception& error) {
                    const std::lock_guard<std::mutex> lock(printing);
                    std::cerr << "t10-grade: error: grading " << config.submissions[i] << ": " << error.what() << "\n";
                    reports[i].submission = config.names[i];
                    reports[i].path = config.submissions[i];
                    reports[i].part = config.part;
                    reports[i].status = "grader-error";
                    reports[i].message = std::string("the grader failed: ") + error.what();
                    failed = true;
                }
                try {
                    writeFormats(reports[i], config.formats, (fs::path(config.reportDir) / config.names[i]).string());
                } catch (const std::exception& error) {
                    const std::lock_guard<std::mutex> lock(printing);
                    std::cerr << "t10-grade: error: writing the results of " << config.submissions[i] << ": " << error.what() << "\n";
                    failed = true;
                }
            }
        };
        std::vector<std::thread> threads;
        for (int j = 0; j < std::min<int>(config.jobs, static_cast<int>(config.submissions.size())); ++j) threads.emplace_back(worker);
        for (std::thread& t : threads) t.join();
        const std::string gradebook = (fs::path(config.reportDir) / "gradebook.csv").string();
        writeGradebook(reports, gradebook);
        writeClassIndex(reports, config.studentNames, config.reportDir);
        std::cout << "wrote " << gradebook << ", index.html, grades-lms.csv and a report per submission in " << config.reportDir << "/\n";
        // A submission the grader could not grade (status grader-error in the gradebook) is the
        // grader's failure, not the student's.
        return failed ? 1 : 0;
    } catch (const std::exception& error) {
        std::cerr << "t10-grade: error: " << error.what() << "\n";
        // The platforms still get a result for each submission: the grader's failure, not the student's.
        for (std::size_t i = 0; i < config.submissions.size() && !config.formats.empty(); ++i) {
            Report report;
            report.submission = config.names[i];
            report.path = config.submissions[i];
            report.part = config.part;
            report.status = "grader-error";
            report.message = std::string("the grader failed: ") + error.what();
            try {
                writeFormats(report, config.formats, (fs::path(config.reportDir) / config.names[i]).string());
            } catch (const std::exception& again) {
                std::cerr << "t10-grade: error: " << again.what() << "\n";
            }
        }
        return 1;
    }
}
