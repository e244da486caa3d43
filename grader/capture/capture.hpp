// Render and capture: runs a submission's program on one case in the job's sandbox, then examines
// what it left, as hostile files, before any decoder reads them.
#pragma once
#include "isolation/sandbox.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace t10::grade {

// One case of a render: what the program is asked and where its outputs go.
struct CaseRender {
    std::string id;                 // the case's (CaseSpec::id)
    std::vector<std::string> args;  // the case's own arguments (CaseSpec::args)
    std::string shaderDir;          // the submission's shaders (the private copy), or the NaN probe's
    std::filesystem::path dir;      // its output folder, the job's own, made by the caller
};

// Runs `program` (the job's copy) headless in `base` (the job's sandbox), one frame of each of
// `renders` in one process (the stage's --then), with the inputs of `inputs` and the job's Mesa
// cache and tmp under `work`. Each case writes its dump and frame.png to its `dir` and, with
// `capturePasses` (Part 3), each blur pass. The process's output goes to `logFile`. One case runs
// exactly as a process of its own always did (its folder is /out, its shaders /submission).
RunResult runCases(const SandboxRun& base, const std::filesystem::path& program, const std::filesystem::path& inputs,
                   const std::filesystem::path& work, const std::vector<CaseRender>& renders, bool capturePasses,
                   const std::string& logFile);

// The log of a run of `runs` cases split where the program started each later case (its
// contract::kThenMarker lines): one text per case that started, at most `runs`.
std::vector<std::string> splitRunLog(const std::string& logFile, std::size_t runs);

// The folder of the job's work folder that holds the NaN probe's shaders (writeNanProbe); in a
// render of several cases it is mounted at /<this name> (runCases).
inline constexpr const char* kNanProbeFolder = "nan-probe-shaders";

// The NaN probe: a copy of the submission's shaders (`shaderDir`, the private copy) in `probeDir`
// whose PostProcess.frag paints every NaN output magenta. Returns `probeDir`, or "" when the shader's
// main() or its vec3/vec4 output cannot be found (the case then runs unprobed).
std::string writeNanProbe(const std::string& shaderDir, const std::string& probeDir);

// The caps on what one render may leave in its output folder.
constexpr int kMaxOutputFiles = 512;
constexpr std::uintmax_t kMaxOutputBytes = 64ull * 1024 * 1024;

// What a render left in `dir`, examined after every process of it is dead: "" when it is regular
// files and folders within the caps, else what is wrong (the submission's fault).
std::string checkOutputs(const std::filesystem::path& dir);
// The frame's PNG header: "" when `path` is a PNG of width x height, else what is wrong.
std::string checkFrame(const std::string& path, int width, int height);

} // namespace t10::grade
