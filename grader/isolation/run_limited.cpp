// Implementation of the limited child process; see run_limited.hpp.
#include "isolation/run_limited.hpp"

#include "t10/error.hpp"

#include <chrono>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <sstream>
#include <sys/resource.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace t10::grade {

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

RunResult runLimited(const std::vector<std::string>& argv, const Limits& limits, const std::string& logFile,
                     const std::string& workingDirectory, const std::vector<std::string>& environment) {
    if (argv.empty()) throw Error("runLimited: no command");
    const int log = ::open(logFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (log < 0) throw Error(logFile + ": cannot create log file: " + std::strerror(errno));
    std::vector<char*> args;
    for (const std::string& arg : argv) args.push_back(const_cast<char*>(arg.c_str()));
    args.push_back(nullptr);
    // The environment, built before fork(): the child of a multithreaded parent must not allocate.
    std::vector<std::string> variables = environment;
    for (char** e = environ; *e != nullptr; ++e) {
        const std::string variable = *e;
        const std::string name = variable.substr(0, variable.find('='));
        bool replaced = false;
        for (const std::string& v : environment) replaced = replaced || v.rfind(name + "=", 0) == 0;
        if (!replaced) variables.push_back(variable);
    }
    std::vector<char*> env;
    for (std::string& variable : variables) env.push_back(variable.data());
    env.push_back(nullptr);

    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = ::fork();
    if (pid < 0) {
        ::close(log);
        throw Error(std::string("fork: ") + std::strerror(errno));
    }
    if (pid == 0) {
        // The child: its own process group (so the whole group can be killed), limits, log as output.
        ::setpgid(0, 0);
        const rlim_t cpu = static_cast<rlim_t>(limits.cpuSeconds);
        const rlimit cpuLimit{cpu, cpu + 1};
        ::setrlimit(RLIMIT_CPU, &cpuLimit);
#ifndef __SANITIZE_ADDRESS__
        // Not in an AddressSanitizer build: the sanitized programs it runs reserve terabytes of
        // shadow address space at start-up and abort under any RLIMIT_AS (wall and CPU limits stay).
        const rlim_t bytes = static_cast<rlim_t>(limits.memoryMiB) * 1024 * 1024;
        const rlimit memoryLimit{bytes, bytes};
        ::setrlimit(RLIMIT_AS, &memoryLimit);
#endif
        const rlimit noCore{0, 0};
        ::setrlimit(RLIMIT_CORE, &noCore);
        ::dup2(log, STDOUT_FILENO);
        ::dup2(log, STDERR_FILENO);
        const int null = ::open("/dev/null", O_RDONLY);
        if (null >= 0) ::dup2(null, STDIN_FILENO);
        if (!workingDirectory.empty() && ::chdir(workingDirectory.c_str()) != 0) _exit(126);
        ::execvpe(args[0], args.data(), env.data());
        // Only async-signal-safe calls between fork and exec: the parent may be multithreaded.
        static const char kFailed[] = "cannot run the command: ";
        const char* reason = ::strerror(errno);
        [[maybe_unused]] auto written = ::write(STDERR_FILENO, kFailed, sizeof kFailed - 1);
        written = ::write(STDERR_FILENO, args[0], std::strlen(args[0]));
        written = ::write(STDERR_FILENO, ": ", 2);
        written = ::write(STDERR_FILENO, reason, std::strlen(reason));
        _exit(127);
    }
    ::close(log);
    ::setpgid(pid, pid); // also from the parent, so the group exists before any kill

    RunResult result;
    int status = 0;
    for (;;) {
        const pid_t done = ::waitpid(pid, &status, WNOHANG);
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (done == pid) {
            result.wallSeconds = elapsed;
            break;
        }
        if (done < 0 && errno != EINTR) throw Error(std::string("waitpid: ") + std::strerror(errno));
        if (elapsed > limits.wallSeconds) {
            ::kill(-pid, SIGKILL);
            ::waitpid(pid, &status, 0);
            result.timedOut = true;
            result.wallSeconds = elapsed;
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    // Whatever the child left running in its group (it should be nothing) goes too.
    ::kill(-pid, SIGKILL);
    if (!result.timedOut) {
        if (WIFSIGNALED(status)) {
            result.signal = WTERMSIG(status);
        } else if (WIFEXITED(status)) {
            result.exitCode = WEXITSTATUS(status);
        }
    }
    std::ifstream in(logFile, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    constexpr std::size_t kKeep = 64 * 1024;
    result.output = text.size() > kKeep ? text.substr(text.size() - kKeep) : text;
    return result;
}

} // namespace t10::grade
