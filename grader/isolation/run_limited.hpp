// Runs a trusted program (t10-grade's reference renders, FLIP, make_test_images) as a child process
// under limits: wall time (its whole process group is killed when it runs out), CPU time and address
// space, with stdout and stderr captured into one log file. It goes through the one process runner,
// runSandboxed (sandbox.hpp), with no isolation: the grader's own user, its environment extended by
// the caller's. Student code, a stage's or a TGA loader's, runs through runSandboxed with isolation.
#pragma once
#include "isolation/run_result.hpp"

#include <string>
#include <vector>

namespace t10::grade {

struct Limits {
    double wallSeconds = 60.0;
    int cpuSeconds = 120;
    long memoryMiB = 4096; // address space; Mesa's llvmpipe maps about 1 GiB for a small frame
};

// Runs argv[0] with argv (PATH is searched); throws t10::Error if the process cannot be started.
// `environment` ("NAME=value") is added to the grader's own.
RunResult runLimited(const std::vector<std::string>& argv, const Limits& limits, const std::string& logFile,
                     const std::string& workingDirectory = "", const std::vector<std::string>& environment = {});

} // namespace t10::grade
