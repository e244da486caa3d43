// Runs a program as a child process under limits (t10-grade runs its trusted tools with it, the
// reference and FLIP; student code, a stage's or a TGA loader's, goes through sandbox.hpp): wall time (the whole
// process group is killed when it runs out, so a hanging shader cannot stall the grader), CPU
// time and address space (setrlimit), with stdout and stderr captured into one log file.
#pragma once
#include <string>
#include <vector>

namespace t10::grade {

struct Limits {
    double wallSeconds = 60.0;
    int cpuSeconds = 120;
    long memoryMiB = 4096; // address space; Mesa's llvmpipe maps about 1 GiB for a small frame
};

struct RunResult {
    int exitCode = -1;   // valid when neither signalled nor timedOut
    int signal = 0;      // the signal that ended the process, 0 if it exited
    bool timedOut = false;
    double wallSeconds = 0.0;
    std::string output;  // stdout and stderr, interleaved (the last 64 KiB)
    bool ok() const { return !timedOut && signal == 0 && exitCode == 0; }
    // "exit 1", "killed by signal 11 (Segmentation fault)", "timed out after 20 s"
    std::string describe() const;
};

// Runs argv[0] with argv (PATH is searched); throws t10::Error if the process cannot be started.
// `environment` ("NAME=value") is added to the grader's own.
RunResult runLimited(const std::vector<std::string>& argv, const Limits& limits, const std::string& logFile,
                     const std::string& workingDirectory = "", const std::vector<std::string>& environment = {});

} // namespace t10::grade
