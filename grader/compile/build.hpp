// Builds a submission's host code (Tutorial10.cpp) against common/ in the job's sandbox, by the one
// compiler call the project's build wrote down for submissions (grader/CMakeLists.txt, host_kit.txt),
// and keeps each program in the grader's cache.
#pragma once
#include "isolation/sandbox.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace t10::grade {

// The compile and link recipe the build wrote for submissions (grader/CMakeLists.txt).
struct HostKit {
    std::string compiler;
    std::vector<std::string> flags, includes, defines, libs;
    // The folder of the precompiled t10/app.hpp (t10/app.hpp.gch); empty where the kit names none.
    std::string pch;
    std::string text;
};

// Reads T10_GRADE_HOST_KIT; throws t10::Error when it cannot be read or names no compiler.
HostKit loadHostKit();

// The project's files the kit names, read-only, for a sandbox: include folders at /t10/include/N, the
// precompiled header's folder at kPchInside and the project's libraries at /t10/lib/N-NAME (host paths
// do not show inside); the common shaders and assets at their host paths, which the project's
// libraries have compiled in.
std::vector<Mount> projectMounts(const HostKit& kit);
// Where the kit's precompiled header folder is inside a sandbox; a build searches it first.
inline constexpr const char* kPchInside = "/t10/pch";

// The limits of one build: a compiler call of a stage takes seconds, never minutes.
constexpr SandboxLimits kBuildLimits{300.0, 300, 4096, 256, 256, 64, 512};

// Builds Tutorial10.cpp (`source`, a host path) of `stage` with `kit` in `sandbox` (the job's, with
// kBuildLimits; the project's folders mounted at /t10) and a build folder under `work`. Returns the
// program in `cacheDir`/builds (a host path only the grader can read), or "" with the compiler's
// message in `log`. A program already built from the same code, recipe, layout and libraries is
// taken from the cache while its manifest holds.
std::string buildProgram(const HostKit& kit, const std::string& stage, const std::string& cacheDir, const SandboxRun& sandbox,
                         const std::string& source, const std::filesystem::path& work, std::string& log);

} // namespace t10::grade
