// Runs a submission's program on one case in the job's sandbox, and examines what it left as hostile
// files: its output folder, the frame's PNG header. The NaN probe makes NaN outputs of the tone map
// visible in the 8-bit frame.
#include "capture/capture.hpp"

#include "capture/cases.hpp"
#include "intake/staging.hpp"
#include "t10/contract.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <unistd.h>

namespace t10::grade {

namespace fs = std::filesystem;

namespace {

// A linear scan of shader text (no backtracking regex over student input): the position of `words`
// at or after `from`, where each word is a whole identifier or one punctuation character, separated
// by optional whitespace; a word of "*" is any identifier (its text is put in `captured`).
bool isWordChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

std::size_t findTokens(const std::string& text, const std::vector<std::string>& words, std::size_t& end,
                       std::vector<std::string>& captured) {
    for (std::size_t start = 0; start < text.size(); ++start) {
        if (start > 0 && isWordChar(text[start - 1])) continue;
        std::size_t at = start;
        captured.clear();
        bool matched = true;
        for (std::size_t w = 0; w < words.size() && matched; ++w) {
            if (w > 0) {
                while (at < text.size() && std::isspace(static_cast<unsigned char>(text[at]))) ++at;
            }
            const std::string& word = words[w];
            if (word == "*") {
                const std::size_t first = at;
                while (at < text.size() && isWordChar(text[at])) ++at;
                matched = at > first;
                if (matched) captured.push_back(text.substr(first, at - first));
            } else if (text.compare(at, word.size(), word) == 0) {
                at += word.size();
                matched = !isWordChar(word.back()) || at >= text.size() || !isWordChar(text[at]);
            } else {
                matched = false;
            }
            // Whitespace is skipped once per word and a failed attempt stops at the first mismatch, so
            // a start position costs at most the whitespace after it: linear in the text overall.
        }
        if (matched) {
            end = at;
            return start;
        }
    }
    return std::string::npos;
}

} // namespace

// The NaN probe: a copy of the submission's shaders whose PostProcess.frag paints every NaN output
// magenta. GL leaves the 8-bit conversion of NaN to the driver and Mesa writes 0, so without the probe
// a tone map that divides 0 by 0 on black pixels renders exactly like a guarded one. Returns "" when
// the shader's main() or its vec3/vec4 output cannot be found (the case then runs unprobed).
// `shaderDir` is the private copy, complete (the sources are size-capped by the copy-in).
std::string writeNanProbe(const std::string& shaderDir, const std::string& probeDir) {
    fs::create_directories(probeDir);
    for (const auto& entry : fs::directory_iterator(shaderDir)) {
        if (entry.is_regular_file()) fs::copy_file(entry.path(), fs::path(probeDir) / entry.path().filename(), fs::copy_options::overwrite_existing);
    }
    const fs::path own = fs::path(shaderDir) / "PostProcess.frag";
    if (!fs::exists(own)) return "";
    const std::string source = readFile(own.string());
    std::size_t mainEnd = 0, outEnd = 0;
    std::vector<std::string> unused, output;
    std::size_t mainAt = findTokens(source, {"void", "main", "(", ")"}, mainEnd, unused);
    if (mainAt == std::string::npos) mainAt = findTokens(source, {"void", "main", "(", "void", ")"}, mainEnd, unused);
    // The first vec3 or vec4 output, whichever comes first.
    std::size_t outAt = findTokens(source, {"out", "vec3", "*", ";"}, outEnd, output);
    std::string type = "vec3";
    std::vector<std::string> output4;
    const std::size_t out4At = findTokens(source, {"out", "vec4", "*", ";"}, outEnd, output4);
    if (out4At < outAt) {
        outAt = out4At;
        output = output4;
        type = "vec4";
    }
    if (mainAt == std::string::npos || outAt == std::string::npos) return "";
    const std::string name = output[0];
    const std::string magenta = type == "vec3" ? "vec3(1.0, 0.0, 1.0)" : "vec4(1.0, 0.0, 1.0, 1.0)";
    const fs::path probe = fs::path(probeDir) / "PostProcess.frag";
    fs::remove(probe);
    std::ofstream(probe) << source.substr(0, mainAt) << "void t10gradeStudentMain()" << source.substr(mainEnd)
                         << "\n// Added by t10-grade: NaN outputs are painted magenta so that the 8-bit frame shows them.\n"
                         << "void main() {\n    t10gradeStudentMain();\n    if (any(isnan(" << name << "))) " << name
                         << " = " << magenta << ";\n}\n";
    return probeDir;
}

namespace {

// A case's arguments for the program: the case's own, the shader folder, where its outputs go.
std::vector<std::string> caseArgv(const SandboxRun& run, const CaseRender& render, const std::string& shaderDir,
                                  const std::string& outDir, bool capturePasses) {
    std::vector<std::string> argv{"--headless", "--backend", "egl", "--frames", "1"};
    for (const std::string& a : caseArgs(render.args, run.path("/t10/inputs"))) argv.push_back(a);
    argv.insert(argv.end(), {"--shader-dir", run.path(shaderDir), "--dump", run.path(outDir), "--output",
                             run.path(outDir + "/frame.png")});
    // Part 3: each blur pass as it is drawn (checks/table.cpp's blur-passes and blur-pass-count).
    if (capturePasses) argv.insert(argv.end(), {"--capture-passes", run.path(outDir)});
    return argv;
}

} // namespace

RunResult runCases(const SandboxRun& base, const fs::path& program, const fs::path& inputs, const fs::path& work,
                   const std::vector<CaseRender>& renders, bool capturePasses, const std::string& logFile) {
    const bool namespaces = base.isolation == Isolation::Namespaces;
    const std::string tmp = (work / "tmp").string();
    SandboxRun run = base;
    run.mounts.push_back({program.string(), "/t10/bin/student", false});
    run.mounts.push_back({inputs.string(), "/t10/inputs", false});
    run.mounts.push_back({(work / "mesa-cache").string(), "/mesa-cache", true});
    // One case: its output folder is /out and its shaders /submission. Several: each case's folder is
    // /out/<id>, and a shader folder other than the first case's (the NaN probe's) is /<its name>.
    const bool one = renders.size() == 1;
    std::vector<std::string> shaderDirs;
    for (const CaseRender& render : renders) {
        std::string inside = "/submission";
        if (render.shaderDir != renders.front().shaderDir) inside = "/" + fs::path(render.shaderDir).filename().string();
        if (std::find(shaderDirs.begin(), shaderDirs.end(), inside) == shaderDirs.end())
            run.mounts.push_back({render.shaderDir, inside, false});
        shaderDirs.push_back(inside);
        run.mounts.push_back({render.dir.string(), one ? "/out" : "/out/" + render.id, true});
    }
    run.workingDirectory = one ? "/out" : "/out/" + renders.front().id;
    // llvmpipe draws in the program's thread (kLlvmpipeSmallRenders): no threads of its own to count.
    run.env = {"PATH=/usr/bin:/bin", "LC_ALL=C", "MESA_SHADER_CACHE_DIR=" + run.path("/mesa-cache"),
               "HOME=" + (namespaces ? std::string("/tmp") : tmp),
               "TMPDIR=" + (namespaces ? std::string("/tmp") : tmp)};
    run.env.insert(run.env.end(), kLlvmpipeSmallRenders.begin(), kLlvmpipeSmallRenders.end());
    std::vector<std::string> argv{run.path("/t10/bin/student")};
    for (std::size_t i = 0; i < renders.size(); ++i) {
        if (i > 0) argv.push_back(contract::kThenOption);
        const std::vector<std::string> args =
            caseArgv(run, renders[i], shaderDirs[i], one ? "/out" : "/out/" + renders[i].id, capturePasses);
        argv.insert(argv.end(), args.begin(), args.end());
    }
    return runSandboxed(run, argv, logFile);
}

std::vector<std::string> splitRunLog(const std::string& logFile, std::size_t runs) {
    std::vector<std::string> parts(1);
    std::ifstream in(logFile, std::ios::binary);
    const std::string marker = contract::kThenMarker;
    for (std::string line; std::getline(in, line);) {
        // "t10: run N of M", N the next run's number: a line the program itself printed otherwise.
        if (parts.size() < runs && line == marker + std::to_string(parts.size() + 1) + " of " + std::to_string(runs)) {
            parts.emplace_back();
            continue;
        }
        parts.back() += line;
        if (!in.eof()) parts.back() += '\n';
    }
    return parts;
}

// What a render left in its output folder, examined after every process of it is dead: "" when it is
// regular files and folders within the caps, else what is wrong (the submission's fault).
std::string checkOutputs(const fs::path& dir) {
    int files = 0;
    std::uintmax_t bytes = 0;
    std::error_code error;
    for (auto it = fs::recursive_directory_iterator(dir, error); !error && it != fs::recursive_directory_iterator(); it.increment(error)) {
        const fs::file_status status = it->symlink_status();
        const std::string name = fs::relative(it->path(), dir).string();
        if (fs::is_symlink(status)) return "it left a symlink in its output folder (" + name + "): outputs must be regular files";
        if (fs::is_directory(status)) continue;
        if (!fs::is_regular_file(status)) return "it left something that is not a regular file in its output folder (" + name + ")";
        bytes += fs::file_size(it->path());
        if (++files > kMaxOutputFiles) return "it wrote more than " + std::to_string(kMaxOutputFiles) + " files";
        if (bytes > kMaxOutputBytes) return "it wrote more than " + std::to_string(kMaxOutputBytes >> 20) + " MiB";
    }
    if (error) return "its output folder cannot be listed: " + error.message();
    return "";
}

// The frame's PNG header, read before any decoder or FLIP sees the file: "" when it is a PNG of the
// expected size.
std::string checkFrame(const std::string& path, int width, int height) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0) return std::string("frame.png cannot be opened: ") + std::strerror(errno);
    unsigned char header[24] = {};
    const ssize_t n = ::read(fd, header, sizeof header);
    ::close(fd);
    static const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (n != 24 || std::memcmp(header, kSignature, 8) != 0 || std::memcmp(header + 12, "IHDR", 4) != 0) {
        return "frame.png is not a PNG file";
    }
    auto big = [&](int at) { return (int(header[at]) << 24) | (int(header[at + 1]) << 16) | (int(header[at + 2]) << 8) | int(header[at + 3]); };
    if (big(16) != width || big(20) != height) {
        return "frame.png is " + std::to_string(big(16)) + "x" + std::to_string(big(20)) + ", the case renders " +
               std::to_string(width) + "x" + std::to_string(height);
    }
    return "";
}

} // namespace t10::grade
