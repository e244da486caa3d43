// Implementation of the sandbox; see sandbox.hpp. Everything the child needs (arguments, environment)
// is prepared before fork(): the grader is multithreaded, so the child only makes system calls.
//
// Memory: there is no cgroup here (the grading machines run cgroup v1 or a read-only cgroup v2), so
// memory is bounded per process by RLIMIT_AS and across the job by RLIMIT_NPROC times that and the
// wall clock.
#include "isolation/sandbox.hpp"

#include "t10/error.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <fstream>
#include <grp.h>
#include <pwd.h>
#include <sstream>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace t10::grade {

namespace {

constexpr const char* kBwrap = "/usr/bin/bwrap";
constexpr uid_t kInsideUid = 1000; // the uid the step sees inside the namespaces (never 0)

struct TaskInfo {
    pid_t pid = 0;
    uid_t uid = 0;
    pid_t parent = 0;
    int threads = 0;
    char state = '?';
};

// The processes of the machine, read from /proc.
std::vector<TaskInfo> listTasks() {
    std::vector<TaskInfo> tasks;
    DIR* proc = ::opendir("/proc");
    if (proc == nullptr) return tasks;
    while (const dirent* entry = ::readdir(proc)) {
        if (entry->d_name[0] < '0' || entry->d_name[0] > '9') continue;
        std::ifstream status(std::string("/proc/") + entry->d_name + "/status");
        TaskInfo task;
        task.pid = static_cast<pid_t>(std::atol(entry->d_name));
        bool haveUid = false;
        for (std::string line; std::getline(status, line);) {
            if (line.rfind("State:", 0) == 0 && line.size() > 7) task.state = line[line.find_first_not_of(" \t", 6)];
            else if (line.rfind("PPid:", 0) == 0) task.parent = static_cast<pid_t>(std::atol(line.c_str() + 5));
            else if (line.rfind("Threads:", 0) == 0) task.threads = std::atoi(line.c_str() + 8);
            else if (line.rfind("Uid:", 0) == 0) {
                task.uid = static_cast<uid_t>(std::strtoul(line.c_str() + 4, nullptr, 10));
                haveUid = true;
            }
        }
        if (haveUid) tasks.push_back(task);
    }
    ::closedir(proc);
    return tasks;
}

int countTasksOf(uid_t uid) {
    int count = 0;
    for (const TaskInfo& task : listTasks())
        if (task.uid == uid) count += std::max(task.threads, 1);
    return count;
}

void setLimit(int resource, rlim_t value) {
    const rlimit limit{value, value};
    ::setrlimit(resource, &limit);
}

// The system folders every step sees read-only; on a merged-/usr system /bin, /lib... are links.
std::vector<std::string> systemMountArgs() {
    std::vector<std::string> args{"--ro-bind", "/usr", "/usr"};
    for (const char* top : {"/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32"}) {
        struct stat info {};
        if (::lstat(top, &info) != 0) continue;
        if (S_ISLNK(info.st_mode)) {
            char target[4096];
            const ssize_t n = ::readlink(top, target, sizeof target - 1);
            if (n <= 0) continue;
            args.insert(args.end(), {"--symlink", std::string(target, static_cast<std::size_t>(n)), top});
        } else if (S_ISDIR(info.st_mode)) {
            args.insert(args.end(), {"--ro-bind", top, top});
        }
    }
    // The dynamic linker's cache (it names the multiarch library folders); nothing else of /etc.
    if (::access("/etc/ld.so.cache", R_OK) == 0) args.insert(args.end(), {"--ro-bind", "/etc/ld.so.cache", "/etc/ld.so.cache"});
    // Debian's alternatives (c++, cc, ld...): public links into /usr.
    if (::access("/etc/alternatives", R_OK) == 0) args.insert(args.end(), {"--ro-bind", "/etc/alternatives", "/etc/alternatives"});
    return args;
}

std::vector<std::string> bwrapOptions(const SandboxRun& run) {
    std::vector<std::string> args{"--unshare-all", "--die-with-parent", "--new-session", "--cap-drop", "ALL",
                                  "--clearenv", "--uid", std::to_string(kInsideUid), "--gid", std::to_string(kInsideUid),
                                  "--hostname", "t10-sandbox"};
    const std::vector<std::string> system = systemMountArgs();
    args.insert(args.end(), system.begin(), system.end());
    args.insert(args.end(), {"--proc", "/proc", "--dev", "/dev", "--size",
                             std::to_string(run.limits.tmpMiB * 1024 * 1024), "--tmpfs", "/tmp"});
    for (const Mount& mount : run.mounts)
        args.insert(args.end(), {mount.writable ? "--bind" : "--ro-bind", mount.host, mount.inside});
    for (const std::string& variable : run.env) {
        const auto equals = variable.find('=');
        args.insert(args.end(), {"--setenv", variable.substr(0, equals), variable.substr(equals + 1)});
    }
    if (!run.workingDirectory.empty()) args.insert(args.end(), {"--chdir", run.workingDirectory});
    args.insert(args.end(), {"--info-fd", "4"});
    return args;
}

// A file descriptor at 10 or above, so that dup2() onto 3 and 4 in the child cannot clobber it.
int highDescriptor(int fd) {
    const int high = ::fcntl(fd, F_DUPFD_CLOEXEC, 10);
    ::close(fd);
    if (high < 0) throw Error(std::string("fcntl(F_DUPFD_CLOEXEC): ") + std::strerror(errno));
    return high;
}

pid_t childPidFromInfo(int fd) {
    std::string text;
    char buffer[512];
    for (ssize_t n; (n = ::read(fd, buffer, sizeof buffer)) > 0;) text.append(buffer, static_cast<std::size_t>(n));
    const auto at = text.find("\"child-pid\"");
    if (at == std::string::npos) return 0;
    const auto colon = text.find(':', at);
    return colon == std::string::npos ? 0 : static_cast<pid_t>(std::atol(text.c_str() + colon + 1));
}

} // namespace

const char* isolationName(Isolation isolation) {
    switch (isolation) {
    case Isolation::Namespaces: return "namespaces";
    case Isolation::Uid: return "uid";
    default: return "none";
    }
}

std::string SandboxRun::path(const std::string& inside) const {
    if (isolation == Isolation::Namespaces) return inside;
    const Mount* best = nullptr;
    for (const Mount& mount : mounts) {
        const std::string& prefix = mount.inside;
        const bool under = inside == prefix || (inside.rfind(prefix, 0) == 0 && inside[prefix.size()] == '/');
        if (under && (best == nullptr || prefix.size() > best->inside.size())) best = &mount;
    }
    return best == nullptr ? inside : best->host + inside.substr(best->inside.size());
}

std::vector<uid_t> pickJobUids(int count) {
    // Far above any account's uid; the grader's pid spreads parallel graders apart.
    std::vector<uid_t> uids;
    std::vector<TaskInfo> tasks = listTasks();
    uid_t candidate = 1600000000u + static_cast<uid_t>(::getpid() % 100000) * 64u;
    while (static_cast<int>(uids.size()) < count) {
        const bool used = ::getpwuid(candidate) != nullptr || ::getgrgid(candidate) != nullptr ||
                          std::any_of(tasks.begin(), tasks.end(), [&](const TaskInfo& t) { return t.uid == candidate; });
        if (!used) uids.push_back(candidate);
        ++candidate;
    }
    return uids;
}

void killAllOfUid(uid_t uid) {
    if (uid == 0) return;
    const auto start = std::chrono::steady_clock::now();
    for (;;) {
        // kill(-1) as the uid reaches every process of it, wherever it moved (setsid, double fork),
        // with no race on recycled pids.
        const pid_t killer = ::fork();
        if (killer == 0) {
            if (::setgroups(0, nullptr) != 0 || ::setresgid(uid, uid, uid) != 0 || ::setresuid(uid, uid, uid) != 0) _exit(1);
            ::kill(-1, SIGKILL);
            _exit(0);
        }
        if (killer > 0) ::waitpid(killer, nullptr, 0);
        bool alive = false;
        for (const TaskInfo& task : listTasks()) {
            if (task.uid != uid) continue;
            // The grader is the subreaper of orphans: it reaps the ones that were the uid's.
            if (task.state == 'Z' && task.parent == ::getpid()) ::waitpid(task.pid, nullptr, WNOHANG);
            else if (task.state != 'Z') alive = true;
        }
        if (!alive) return;
        if (std::chrono::steady_clock::now() - start > std::chrono::seconds(5)) {
            throw Error("processes of uid " + std::to_string(uid) + " survive SIGKILL for 5 s");
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
}

std::string probeNamespaces(uid_t uid) {
    if (::access(kBwrap, X_OK) != 0) return std::string(kBwrap) + ": " + std::strerror(errno) + " (install bubblewrap)";
    SandboxRun run;
    run.isolation = Isolation::Namespaces;
    run.uid = uid;
    run.limits.wallSeconds = 10;
    char name[] = "/tmp/t10-grade-probe.XXXXXX";
    const int fd = ::mkstemp(name);
    if (fd < 0) return std::string("mkstemp: ") + std::strerror(errno);
    ::close(fd);
    RunResult result;
    try {
        result = runSandboxed(run, {"/usr/bin/true"}, name);
    } catch (const Error& error) {
        ::unlink(name);
        return error.what();
    }
    ::unlink(name);
    if (result.ok()) return "";
    return "bwrap " + result.describe() + ": " + result.output;
}

RunResult runSandboxed(const SandboxRun& run, const std::vector<std::string>& argv, const std::string& logFile) {
    if (argv.empty()) throw Error("runSandboxed: no command");
    // Orphans of a killed sandbox (its pid 1) come back to the grader, which waits for them.
    ::prctl(PR_SET_CHILD_SUBREAPER, 1);
    const bool namespaces = run.isolation == Isolation::Namespaces;

    // Everything the child uses, built now.
    std::vector<std::string> command;
    std::string options;
    if (namespaces) {
        for (const std::string& option : bwrapOptions(run)) options += option + '\0';
        command = {"bwrap", "--args", "3", "--"};
        command.insert(command.end(), argv.begin(), argv.end());
    } else {
        for (const std::string& arg : argv) command.push_back(run.path(arg));
    }
    std::vector<char*> args;
    for (std::string& arg : command) args.push_back(arg.data());
    args.push_back(nullptr);
    std::vector<std::string> envCopy = run.env;
    std::vector<char*> env;
    for (std::string& variable : envCopy) env.push_back(variable.data());
    env.push_back(nullptr);
    const std::string program = namespaces ? kBwrap : command.front();
    // bwrap changes into the working directory inside (--chdir); the other isolations here.
    const std::string directory = run.workingDirectory.empty() || namespaces ? "" : run.path(run.workingDirectory);

    // A non-root grader keeps its own uid: RLIMIT_NPROC then counts its other processes too.
    rlim_t processes = RLIM_INFINITY;
    if (run.uid != 0) processes = static_cast<rlim_t>(run.limits.processes);
    else if (::geteuid() != 0) processes = static_cast<rlim_t>(countTasksOf(::geteuid()) + run.limits.processes);

    const int log = ::open(logFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, 0600);
    if (log < 0) throw Error(logFile + ": cannot create log file: " + std::strerror(errno));
    int optionsPipe[2] = {-1, -1}, infoPipe[2] = {-1, -1};
    if (namespaces) {
        if (::pipe2(optionsPipe, O_CLOEXEC) != 0 || ::pipe2(infoPipe, O_CLOEXEC) != 0) {
            ::close(log);
            throw Error(std::string("pipe: ") + std::strerror(errno));
        }
        for (int& fd : optionsPipe) fd = highDescriptor(fd);
        for (int& fd : infoPipe) fd = highDescriptor(fd);
        // Small (a few KiB): fits the pipe's buffer, so the write does not wait for bwrap.
        if (::write(optionsPipe[1], options.data(), options.size()) != static_cast<ssize_t>(options.size())) {
            throw Error(std::string("writing bwrap's options: ") + std::strerror(errno));
        }
        ::close(optionsPipe[1]);
        ::fcntl(infoPipe[0], F_SETFL, O_NONBLOCK);
    }

    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = ::fork();
    if (pid < 0) {
        ::close(log);
        throw Error(std::string("fork: ") + std::strerror(errno));
    }
    if (pid == 0) {
        ::setsid(); // its own session and process group: no terminal, killed as a group
        setLimit(RLIMIT_CPU, static_cast<rlim_t>(run.limits.cpuSeconds));
#ifndef __SANITIZE_ADDRESS__
        // Not in an AddressSanitizer build: sanitized programs reserve terabytes of shadow memory.
        setLimit(RLIMIT_AS, static_cast<rlim_t>(run.limits.memoryMiB) * 1024 * 1024);
#endif
        setLimit(RLIMIT_CORE, 0);
        setLimit(RLIMIT_FSIZE, static_cast<rlim_t>(run.limits.fileMiB) * 1024 * 1024);
        setLimit(RLIMIT_NOFILE, static_cast<rlim_t>(run.limits.openFiles));
        if (processes != RLIM_INFINITY) setLimit(RLIMIT_NPROC, processes);
        ::dup2(log, STDOUT_FILENO);
        ::dup2(log, STDERR_FILENO);
        const int null = ::open("/dev/null", O_RDONLY);
        if (null >= 0) ::dup2(null, STDIN_FILENO);
        if (namespaces) {
            ::dup2(optionsPipe[0], 3);
            ::dup2(infoPipe[1], 4);
        }
        if (run.uid != 0) {
            if (::setgroups(0, nullptr) != 0 || ::setresgid(run.uid, run.uid, run.uid) != 0 ||
                ::setresuid(run.uid, run.uid, run.uid) != 0) {
                static const char kNoUid[] = "t10-grade: cannot switch to the job's uid\n";
                [[maybe_unused]] auto written = ::write(STDERR_FILENO, kNoUid, sizeof kNoUid - 1);
                _exit(126);
            }
        }
        ::prctl(PR_SET_PDEATHSIG, SIGKILL); // dies with the grader
        if (!directory.empty() && ::chdir(directory.c_str()) != 0) _exit(126);
        ::execve(program.c_str(), args.data(), env.data());
        static const char kFailed[] = "cannot run the command: ";
        const char* reason = ::strerror(errno);
        [[maybe_unused]] auto written = ::write(STDERR_FILENO, kFailed, sizeof kFailed - 1);
        written = ::write(STDERR_FILENO, program.c_str(), program.size());
        written = ::write(STDERR_FILENO, ": ", 2);
        written = ::write(STDERR_FILENO, reason, std::strlen(reason));
        _exit(127);
    }
    ::close(log);
    if (namespaces) {
        ::close(optionsPipe[0]);
        ::close(infoPipe[1]);
    }

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
        if (elapsed > run.limits.wallSeconds) {
            ::kill(-pid, SIGKILL);
            ::waitpid(pid, &status, 0);
            result.timedOut = true;
            result.wallSeconds = elapsed;
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    ::kill(-pid, SIGKILL);
    if (namespaces) {
        // The sandbox's pid 1: when bwrap was killed it came back to the grader (subreaper) and died
        // of its parent-death signal; it is reaped only after every process of its namespace is gone.
        const pid_t inner = childPidFromInfo(infoPipe[0]);
        ::close(infoPipe[0]);
        const auto waitStart = std::chrono::steady_clock::now();
        while (inner > 0) {
            const pid_t reaped = ::waitpid(inner, nullptr, WNOHANG);
            if (reaped == inner || (reaped < 0 && errno == ECHILD)) break; // reaped, or bwrap reaped it
            if (std::chrono::steady_clock::now() - waitStart > std::chrono::seconds(5)) {
                throw Error("the sandbox's pid namespace survives SIGKILL for 5 s");
            }
            ::kill(inner, SIGKILL);
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
    }
    killAllOfUid(run.uid);
    if (!result.timedOut) {
        if (WIFSIGNALED(status)) result.signal = WTERMSIG(status);
        else if (WIFEXITED(status)) result.exitCode = WEXITSTATUS(status);
        // bwrap exits 128 + N when its command was killed by signal N.
        if (namespaces && result.exitCode > 128 && result.exitCode < 128 + NSIG) {
            result.signal = result.exitCode - 128;
            result.exitCode = -1;
        }
    }
    // The log is the grader's own file; read at most its last 64 KiB.
    const int in = ::open(logFile.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
    if (in >= 0) {
        constexpr off_t kKeep = 64 * 1024;
        const off_t size = ::lseek(in, 0, SEEK_END);
        const off_t from = size > kKeep ? size - kKeep : 0;
        ::lseek(in, from, SEEK_SET);
        char buffer[8192];
        for (ssize_t n; (n = ::read(in, buffer, sizeof buffer)) > 0;) result.output.append(buffer, static_cast<std::size_t>(n));
        ::close(in);
    }
    return result;
}

} // namespace t10::grade
