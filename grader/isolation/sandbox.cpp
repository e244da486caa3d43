// Implementation of the sandbox; see sandbox.hpp. Everything the child needs (arguments, environment)
// is prepared before fork(): the grader is multithreaded, so the child only makes system calls.
//
// Memory: there is no cgroup here (the grading machines run cgroup v1 or a read-only cgroup v2), so
// memory is bounded per process by RLIMIT_AS and across the job by RLIMIT_NPROC times that and the
// wall clock.
#include "isolation/sandbox.hpp"

#include "t10/error.hpp"
#include "t10/fork_lock.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <chrono>
#include <csignal>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <grp.h>
#include <pwd.h>
#include <shared_mutex>
#include <ostream>
#include <sstream>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <time.h>
#include <unistd.h>

namespace t10::grade {

namespace {

// fork() while no program file is open for writing (copyFile holds t10::forkLock shared while it
// writes): the child inherits no descriptor that would make another job's exec fail with ETXTBSY.
// The child's copy of the lock stays locked; it only execs or exits.
pid_t forkAlone() {
    std::shared_mutex& lock = t10::forkLock();
    lock.lock();
    const pid_t pid = ::fork();
    if (pid != 0) lock.unlock();
    return pid;
}

constexpr const char* kBwrap = "/usr/bin/bwrap";
constexpr const char* kPrlimit = "/usr/bin/prlimit"; // util-linux (Essential in Debian)
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

// The step's environment: run.env, and in an AddressSanitizer build, where the address-space limit
// cannot be set (see execChild), the memory limit as the sanitizer's own: an allocation over it
// returns null and a process whose resident memory passes it is stopped, as RLIMIT_AS would. Only
// sanitized programs (a submission built by the sanitized kit) read ASAN_OPTIONS.
std::vector<std::string> stepEnvironment(const SandboxRun& run) {
    std::vector<std::string> env = run.env;
#ifdef __SANITIZE_ADDRESS__
    const std::string mib = std::to_string(run.limits.memoryMiB);
    env.push_back("ASAN_OPTIONS=allocator_may_return_null=1:max_allocation_size_mb=" + mib + ":hard_rss_limit_mb=" + mib);
#endif
    return env;
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
    for (const std::string& variable : stepEnvironment(run)) {
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
        const pid_t killer = forkAlone();
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

namespace {

// Runs argv as `run` says, its output collected in a temporary file (removed after), into `result`;
// returns why it could not run at all ("" when it ran, whatever its exit).
std::string probeRun(const SandboxRun& run, const std::vector<std::string>& argv, RunResult& result) {
    char name[] = "/tmp/t10-grade-probe.XXXXXX";
    const int fd = ::mkstemp(name);
    if (fd < 0) return std::string("mkstemp: ") + std::strerror(errno);
    ::close(fd);
    std::string error;
    try {
        result = runSandboxed(run, argv, name);
    } catch (const Error& e) {
        error = e.what();
    }
    ::unlink(name);
    return error;
}

// The first line of bwrap --version ("bubblewrap 0.6.1"), or "bubblewrap (its version unknown)".
std::string bwrapVersion() {
    SandboxRun run; // isolation none: bwrap itself, asked only its version
    run.limits.wallSeconds = 10;
    RunResult result;
    const bool ran = probeRun(run, {kBwrap, "--version"}, result).empty() && result.ok();
    const std::string version = ran ? result.output.substr(0, result.output.find('\n')) : "";
    return version.empty() ? "bubblewrap (its version unknown)" : version;
}

} // namespace

std::string probeNamespaces(uid_t uid) {
    if (::access(kBwrap, X_OK) != 0) return std::string(kBwrap) + ": " + std::strerror(errno) + " (install bubblewrap)";
    SandboxRun run;
    run.isolation = Isolation::Namespaces;
    run.uid = uid;
    run.limits.wallSeconds = 10;
    RunResult result;
    if (const std::string error = probeRun(run, {"/usr/bin/true"}, result); !error.empty()) return error;
    if (result.ok()) return "";
    // bubblewrap before 0.8 knows no --size (0.4 no --clearenv either): the namespaces are there, the
    // program is too old for the sandbox's options. Say so rather than blame the kernel.
    const std::size_t unknown = result.output.find("Unknown option");
    if (unknown != std::string::npos) {
        const std::string what = result.output.substr(unknown, result.output.find('\n', unknown) - unknown);
        return bwrapVersion() + " is too old for the sandbox (bwrap: " + what +
               "): namespaces isolation needs bubblewrap 0.8 or later";
    }
    return "bwrap " + result.describe() + ": " + result.output;
}

std::string probeOwnProcessLimit() {
    if (::access(kPrlimit, X_OK) != 0) return std::string(kPrlimit) + ": " + std::strerror(errno) + " (install util-linux)";
    SandboxRun run;
    run.isolation = Isolation::Namespaces;
    run.ownProcessLimit = true;
    run.limits.processes = 2; // the shell and its child; bwrap's pid 1 is added
    run.limits.wallSeconds = 10;
    RunResult result;
    // Counted with the user's processes outside the namespace (the grader, bwrap), the fork fails.
    if (const std::string error = probeRun(run, {"/bin/sh", "-c", "/usr/bin/true & wait"}, result); !error.empty())
        return error;
    if (result.ok()) return "";
    std::string output = result.output.substr(0, result.output.find('\n'));
    return "this kernel counts the user's processes together across its user namespaces (Linux before 5.14): a "
           "sandbox allowed 3 processes could not start its third (" + result.describe() + (output.empty() ? "" : ": " + output) + ")";
}

namespace {

// What the child of runSandboxed needs, all of it made before fork(): the grader is multithreaded,
// so the child only makes system calls.
struct ChildPlan {
    std::vector<std::string> command;
    std::vector<char*> args;
    std::vector<std::string> envCopy;
    std::vector<char*> env;
    std::string program;
    std::string directory;                 // the uid and none isolations change into it here
    std::string options;                   // bwrap's, NUL-separated (namespaces)
    rlim_t processes = RLIM_INFINITY;
    int log = -1;
    int optionsPipe[2] = {-1, -1};
    int infoPipe[2] = {-1, -1};
};

void planChild(const SandboxRun& run, const std::vector<std::string>& argv, const std::string& logFile, ChildPlan& plan) {
    const bool namespaces = run.isolation == Isolation::Namespaces;
    if (namespaces) {
        for (const std::string& option : bwrapOptions(run)) plan.options += option + '\0';
        plan.command = {"bwrap", "--args", "3", "--"};
        if (run.ownProcessLimit) {
            // Soft and hard limit at once, inside the namespace; bwrap's pid 1 there counts too.
            plan.command.insert(plan.command.end(), {kPrlimit, "--nproc=" + std::to_string(run.limits.processes + 1), "--"});
        }
        plan.command.insert(plan.command.end(), argv.begin(), argv.end());
    } else {
        for (const std::string& arg : argv) plan.command.push_back(run.path(arg));
    }
    for (std::string& arg : plan.command) plan.args.push_back(arg.data());
    plan.args.push_back(nullptr);
    plan.envCopy = stepEnvironment(run);
    for (std::string& variable : plan.envCopy) plan.env.push_back(variable.data());
    plan.env.push_back(nullptr);
    plan.program = namespaces ? kBwrap : plan.command.front();
    // bwrap changes into the working directory inside (--chdir); the other isolations here.
    if (!run.workingDirectory.empty() && !namespaces) plan.directory = run.path(run.workingDirectory);
    // A non-root grader keeps its own uid: RLIMIT_NPROC then counts its other processes too, unless the
    // limit is set inside the sandbox's own user namespace (bwrap keeps the grader's limit: the user's
    // count outside, which every namespace of it adds to, is checked against the limit of the
    // namespace's creator).
    if (run.uid != 0) plan.processes = static_cast<rlim_t>(run.limits.processes);
    else if (run.ownProcessLimit && namespaces) plan.processes = RLIM_INFINITY;
    else if (::geteuid() != 0) plan.processes = static_cast<rlim_t>(countTasksOf(::geteuid()) + run.limits.processes);

    plan.log = ::open(logFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, 0600);
    if (plan.log < 0) throw Error(logFile + ": cannot create log file: " + std::strerror(errno));
    if (!namespaces) return;
    if (::pipe2(plan.optionsPipe, O_CLOEXEC) != 0 || ::pipe2(plan.infoPipe, O_CLOEXEC) != 0) {
        ::close(plan.log);
        throw Error(std::string("pipe: ") + std::strerror(errno));
    }
    for (int& fd : plan.optionsPipe) fd = highDescriptor(fd);
    for (int& fd : plan.infoPipe) fd = highDescriptor(fd);
    // Small (a few KiB): fits the pipe's buffer, so the write does not wait for bwrap.
    if (::write(plan.optionsPipe[1], plan.options.data(), plan.options.size()) != static_cast<ssize_t>(plan.options.size())) {
        throw Error(std::string("writing bwrap's options: ") + std::strerror(errno));
    }
    ::close(plan.optionsPipe[1]);
    ::fcntl(plan.infoPipe[0], F_SETFL, O_NONBLOCK);
}

// The child: limits, its own session, the log as output, the job's uid, then exec. Never returns.
[[noreturn]] void execChild(const SandboxRun& run, ChildPlan& plan) {
    ::setsid(); // its own session and process group: no terminal, killed as a group
    setLimit(RLIMIT_CPU, static_cast<rlim_t>(run.limits.cpuSeconds));
#ifndef __SANITIZE_ADDRESS__
    // Not in an AddressSanitizer build: sanitized programs reserve terabytes of shadow memory (the
    // limit reaches them through ASAN_OPTIONS instead: stepEnvironment).
    setLimit(RLIMIT_AS, static_cast<rlim_t>(run.limits.memoryMiB) * 1024 * 1024);
#endif
    setLimit(RLIMIT_CORE, 0);
    setLimit(RLIMIT_FSIZE, static_cast<rlim_t>(run.limits.fileMiB) * 1024 * 1024);
    setLimit(RLIMIT_NOFILE, static_cast<rlim_t>(run.limits.openFiles));
    if (plan.processes != RLIM_INFINITY) setLimit(RLIMIT_NPROC, plan.processes);
    ::dup2(plan.log, STDOUT_FILENO);
    ::dup2(plan.log, STDERR_FILENO);
    const int null = ::open("/dev/null", O_RDONLY);
    if (null >= 0) ::dup2(null, STDIN_FILENO);
    if (run.isolation == Isolation::Namespaces) {
        ::dup2(plan.optionsPipe[0], 3);
        ::dup2(plan.infoPipe[1], 4);
    }
    if (run.uid != 0) {
        if (::setgroups(0, nullptr) != 0 || ::setresgid(run.uid, run.uid, run.uid) != 0 || ::setresuid(run.uid, run.uid, run.uid) != 0) {
            static const char kNoUid[] = "t10-grade: cannot switch to the job's uid\n";
            [[maybe_unused]] auto written = ::write(STDERR_FILENO, kNoUid, sizeof kNoUid - 1);
            _exit(126);
        }
    }
    ::prctl(PR_SET_PDEATHSIG, SIGKILL); // dies with the grader
    if (!plan.directory.empty() && ::chdir(plan.directory.c_str()) != 0) _exit(126);
    // ETXTBSY: another job's child, forked while the grader was writing this program's copy, holds
    // that descriptor until its own exec (O_CLOEXEC closes it only then). It passes within
    // microseconds: retry for up to a second.
    for (int attempt = 0; attempt < 100; ++attempt) {
        ::execve(plan.program.c_str(), plan.args.data(), plan.env.data());
        if (errno != ETXTBSY) break;
        const timespec pause{0, 10 * 1000 * 1000};
        ::nanosleep(&pause, nullptr);
    }
    static const char kFailed[] = "cannot run the command: ";
    const char* reason = ::strerror(errno);
    [[maybe_unused]] auto written = ::write(STDERR_FILENO, kFailed, sizeof kFailed - 1);
    written = ::write(STDERR_FILENO, plan.program.c_str(), plan.program.size());
    written = ::write(STDERR_FILENO, ": ", 2);
    written = ::write(STDERR_FILENO, reason, std::strlen(reason));
    _exit(127);
}

// Waits for `pid` until the wall limit, then kills its process group; `status` is its wait status.
void waitWithLimit(pid_t pid, double wallSeconds, std::chrono::steady_clock::time_point start, int& status, RunResult& result) {
    for (;;) {
        const pid_t done = ::waitpid(pid, &status, WNOHANG);
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (done == pid) {
            result.wallSeconds = elapsed;
            return;
        }
        if (done < 0 && errno != EINTR) throw Error(std::string("waitpid: ") + std::strerror(errno));
        if (elapsed > wallSeconds) {
            ::kill(-pid, SIGKILL);
            ::waitpid(pid, &status, 0);
            result.timedOut = true;
            result.wallSeconds = elapsed;
            return;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
}

// The sandbox's pid 1: when bwrap was killed it came back to the grader (subreaper) and died of its
// parent-death signal; it is reaped only after every process of its namespace is gone.
void reapSandbox(int infoFd) {
    const pid_t inner = childPidFromInfo(infoFd);
    ::close(infoFd);
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

// The log is the grader's own file; at most its last 64 KiB.
std::string logTail(const std::string& logFile) {
    std::string text;
    const int in = ::open(logFile.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
    if (in < 0) return text;
    constexpr off_t kKeep = 64 * 1024;
    const off_t size = ::lseek(in, 0, SEEK_END);
    ::lseek(in, size > kKeep ? size - kKeep : 0, SEEK_SET);
    char buffer[8192];
    for (ssize_t n; (n = ::read(in, buffer, sizeof buffer)) > 0;) text.append(buffer, static_cast<std::size_t>(n));
    ::close(in);
    return text;
}

} // namespace

RunResult runSandboxed(const SandboxRun& run, const std::vector<std::string>& argv, const std::string& logFile) {
    if (argv.empty()) throw Error("runSandboxed: no command");
    // Orphans of a killed sandbox (its pid 1) come back to the grader, which waits for them.
    ::prctl(PR_SET_CHILD_SUBREAPER, 1);
    const bool namespaces = run.isolation == Isolation::Namespaces;
    ChildPlan plan;
    planChild(run, argv, logFile, plan);

    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = forkAlone();
    if (pid < 0) {
        ::close(plan.log);
        throw Error(std::string("fork: ") + std::strerror(errno));
    }
    if (pid == 0) execChild(run, plan);
    ::close(plan.log);
    if (namespaces) {
        ::close(plan.optionsPipe[0]);
        ::close(plan.infoPipe[1]);
    }
    RunResult result;
    int status = 0;
    waitWithLimit(pid, run.limits.wallSeconds, start, status, result);
    ::kill(-pid, SIGKILL);
    if (namespaces) reapSandbox(plan.infoPipe[0]);
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
    result.output = logTail(logFile);
    return result;
}

Isolation chooseIsolation(const std::string& asked, uid_t uid, const std::string& program, std::ostream& log) {
    if (asked == "none") {
        log << program << ": warning: --no-sandbox: student code runs as this user with only time and size limits\n";
        return Isolation::None;
    }
    const bool root = ::geteuid() == 0;
    if (asked == "uid") {
        if (!root) throw Error("--isolation uid: the grader must run as root to run each job as its own uid");
        return Isolation::Uid;
    }
    const std::string why = probeNamespaces(root ? uid : 0);
    if (why.empty()) return Isolation::Namespaces;
    if (asked == "namespaces") throw Error("--isolation namespaces: bubblewrap cannot start a sandbox here: " + why);
    if (!root) {
        throw Error("no sandbox can be had here: bubblewrap fails (" + why + ") and the uid fallback needs root. "
                    "Refusing to run student code; --no-sandbox runs it unprotected (unsafe)");
    }
    log << program << ": warning: no namespaces sandbox here (" << why << "): falling back to one uid per job\n";
    return Isolation::Uid;
}

Unreachable firstUnreachable(uid_t uid, const std::vector<std::string>& paths) {
    if (uid == 0 || paths.empty()) return {};
    // A child switched to the uid tries each path: the kernel's own answer (modes, ACLs, mounts).
    std::vector<std::vector<char>> copies;
    for (const std::string& path : paths) copies.emplace_back(path.c_str(), path.c_str() + path.size() + 1);
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0) throw Error(std::string("pipe: ") + std::strerror(errno));
    const pid_t child = forkAlone();
    if (child == 0) {
        if (::setgroups(0, nullptr) != 0 || ::setresgid(uid, uid, uid) != 0 || ::setresuid(uid, uid, uid) != 0) _exit(126);
        for (std::uint32_t i = 0; i < copies.size(); ++i) {
            char* path = copies[i].data();
            if (::access(path, R_OK) == 0) continue;
            // The first folder on the way that the uid cannot enter, else the path itself.
            std::size_t stop = std::strlen(path);
            for (char* slash = std::strchr(path + 1, '/'); slash != nullptr; slash = std::strchr(slash + 1, '/')) {
                *slash = '\0';
                const bool enters = ::access(path, X_OK) == 0;
                *slash = '/';
                if (!enters) {
                    stop = static_cast<std::size_t>(slash - path);
                    break;
                }
            }
            [[maybe_unused]] auto written = ::write(fds[1], &i, sizeof i);
            written = ::write(fds[1], path, stop);
            _exit(1);
        }
        _exit(0);
    }
    ::close(fds[1]);
    if (child < 0) {
        ::close(fds[0]);
        throw Error(std::string("fork: ") + std::strerror(errno));
    }
    std::string answer;
    char buffer[4096];
    for (ssize_t n; (n = ::read(fds[0], buffer, sizeof buffer)) > 0;) answer.append(buffer, static_cast<std::size_t>(n));
    ::close(fds[0]);
    int status = 0;
    ::waitpid(child, &status, 0);
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return {};
    std::uint32_t index = 0;
    if (answer.size() < sizeof index) throw Error("cannot test what uid " + std::to_string(uid) + " may read");
    std::memcpy(&index, answer.data(), sizeof index);
    if (index >= paths.size()) throw Error("cannot test what uid " + std::to_string(uid) + " may read");
    return {paths[index], answer.substr(sizeof index)};
}

std::string Unreachable::explain() const {
    std::ostringstream text;
    text << "the job uids cannot read " << path;
    struct stat info {};
    if (folder != path && ::stat(folder.c_str(), &info) == 0) {
        text << ": " << folder << " lets no one else in (mode 0" << std::oct << (info.st_mode & 07777) << std::dec << ")";
    }
    return text.str();
}

void stageUnreachableMounts(std::vector<Mount>& mounts, const std::string& staging, uid_t uid, Isolation isolation) {
    namespace fs = std::filesystem;
    if (uid == 0 || isolation == Isolation::None) return;
    for (std::size_t i = 0; i < mounts.size(); ++i) {
        Mount& mount = mounts[i];
        if (mount.writable) continue;
        const Unreachable blocked = firstUnreachable(uid, {mount.host});
        if (blocked.path.empty()) continue;
        if (isolation == Isolation::Uid && mount.inside == mount.host) {
            throw Error(blocked.explain() + ". Under --isolation uid student code sees the host's files at their paths: "
                        "move the checkout to a folder others may enter, let them pass (chmod o+x " + blocked.folder +
                        "), or grade with --isolation namespaces");
        }
        if (!fs::exists(staging)) {
            fs::create_directories(staging);
            fs::permissions(staging, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                                         fs::perms::others_read | fs::perms::others_exec);
        }
        // Hard links where the staging folder is on the same file system (no copy), else a copy.
        const fs::path to = fs::path(staging) / std::to_string(i);
        std::error_code linked;
        fs::copy(mount.host, to, fs::copy_options::recursive | fs::copy_options::create_hard_links, linked);
        if (linked) {
            fs::remove_all(to);
            fs::copy(mount.host, to, fs::copy_options::recursive);
        }
        const Unreachable still = firstUnreachable(uid, {to.string()});
        if (!still.path.empty()) throw Error(blocked.explain() + ", nor its copy: " + still.explain());
        mount.host = to.string();
    }
}

} // namespace t10::grade
