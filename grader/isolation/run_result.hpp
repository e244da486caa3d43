// What a process run by the grader's one runner (runSandboxed, sandbox.hpp; runLimited,
// run_limited.hpp) ended with. Its own header so that the two runners' headers need not include
// each other (describe() is defined in run_limited.cpp).
#pragma once
#include <cstddef>
#include <string>

namespace t10::grade {

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

// The last `lines` lines of a process's output (all of it when it has fewer), for messages that quote it.
std::string lastLines(const std::string& text, std::size_t lines);

} // namespace t10::grade
