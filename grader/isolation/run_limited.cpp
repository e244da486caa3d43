// Implementation of the trusted tools' runs; see run_limited.hpp. The process itself is started by
// the one process runner, runSandboxed (sandbox.cpp), with no isolation.
#include "isolation/run_limited.hpp"

#include "isolation/sandbox.hpp"
#include "t10/error.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <unistd.h>

namespace t10::grade {

std::string lastLines(const std::string& text, std::size_t lines) {
    std::size_t pos = text.size();
    for (std::size_t n = 0; n <= lines; ++n) {
        if (pos == 0) return text;
        pos = text.rfind('\n', pos - 1);
        if (pos == std::string::npos) return text;
    }
    return text.substr(pos + 1);
}

std::string RunResult::describe() const {
    std::ostringstream text;
    if (timedOut) {
        text << "timed out after " << static_cast<int>(wallSeconds + 0.5) << " s and was killed";
    } else if (signal != 0) {
        text << "was killed by signal " << signal << " (" << strsignal(signal) << ")";
    } else {
        text << "ended with exit code " << exitCode;
    }
    return text.str();
}

namespace {

// argv[0] as execvp would find it: a name without '/' is looked up on PATH.
std::string onPath(const std::string& program) {
    if (program.find('/') != std::string::npos) return program;
    const char* path = std::getenv("PATH");
    std::string folders = path != nullptr ? path : "/usr/bin:/bin";
    for (std::size_t start = 0; start <= folders.size();) {
        const std::size_t end = std::min(folders.find(':', start), folders.size());
        const std::string candidate = (end == start ? std::string(".") : folders.substr(start, end - start)) + "/" + program;
        if (::access(candidate.c_str(), X_OK) == 0) return candidate;
        start = end + 1;
    }
    return program;
}

} // namespace

RunResult runLimited(const std::vector<std::string>& argv, const Limits& limits, const std::string& logFile,
                     const std::string& workingDirectory, const std::vector<std::string>& environment) {
    if (argv.empty()) throw Error("runLimited: no command");
    // The one process runner (sandbox.hpp) with no isolation: the grader's own user and environment,
    // which `environment` extends or overrides.
    SandboxRun run;
    run.isolation = Isolation::None;
    run.limits.wallSeconds = limits.wallSeconds;
    run.limits.cpuSeconds = limits.cpuSeconds;
    run.limits.memoryMiB = limits.memoryMiB;
    // Trusted tools: no caps on files or processes beyond the system's.
    run.limits.fileMiB = 1 << 20;
    run.limits.openFiles = 4096;
    run.limits.processes = 1 << 20;
    run.workingDirectory = workingDirectory;
    run.env = environment;
    for (char** e = environ; *e != nullptr; ++e) {
        const std::string variable = *e;
        const std::string name = variable.substr(0, variable.find('=') + 1);
        const bool overridden = std::any_of(environment.begin(), environment.end(),
                                            [&](const std::string& v) { return v.rfind(name, 0) == 0; });
        if (!overridden) run.env.push_back(variable);
    }
    std::vector<std::string> command = argv;
    command.front() = onPath(argv.front());
    return runSandboxed(run, command, logFile);
}

} // namespace t10::grade
