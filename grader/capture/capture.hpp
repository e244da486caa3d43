// Render and capture: runs a submission's program on one case in the job's sandbox, then examines
// what it left, as hostile files, before any decoder reads them.
#pragma once
#include "isolation/sandbox.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace t10::grade {

// Runs `program` (the job's copy) headless for one frame in `base` (the job's sandbox) with the
// shaders of `shaderDir`, the inputs of `inputs`, the job's Mesa cache and tmp under `work`, and the
// case's `args`; it writes its dump and frame.png to `dir` (made by the caller, the job's own) and,
// with `capturePasses` (Part 3), each blur pass. Its output goes to `logFile`.
RunResult runCase(const SandboxRun& base, const std::filesystem::path& program, const std::string& shaderDir,
                  const std::filesystem::path& inputs, const std::filesystem::path& work, const std::filesystem::path& dir,
                  const std::vector<std::string>& args, bool capturePasses, const std::string& logFile);

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
