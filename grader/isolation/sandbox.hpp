// Runs a student-controlled step (the compiler, a render) in a sandbox. Three isolations:
//   namespaces: bubblewrap with every namespace unshared, no capabilities, a cleared environment, a
//               fixed view of the file system (the mounts below at neutral paths such as /submission,
//               /out, /t10), a size-capped /tmp; killed with the grader, and at the wall limit the
//               whole pid namespace dies. As root, bwrap itself runs as the job's unprivileged uid so
//               that the process and file limits hold; as another user, the process limit is set
//               inside the sandbox's user namespace, which counts the job's processes alone.
//   uid:        where user namespaces cannot be had: the step runs as the job's unprivileged uid (the
//               grader must be root), with the same limits and environment; it sees the host's file
//               system with that uid's rights, and every process of the uid is killed after the run.
//   none:       only the limits (--no-sandbox; unsafe for untrusted code).
// Paths given to a step are written as they are inside (Mount::inside); SandboxRun::path() turns them
// into host paths for the isolations that have no mount namespace.
#pragma once
#include "isolation/run_result.hpp"

#include <iosfwd>
#include <string>
#include <sys/types.h>
#include <vector>

namespace t10::grade {

enum class Isolation { Namespaces, Uid, None };
const char* isolationName(Isolation isolation);

struct Mount {
    std::string host;
    std::string inside; // absolute, e.g. /submission
    bool writable = false;
};

struct SandboxLimits {
    double wallSeconds = 60.0;
    int cpuSeconds = 120;
    long memoryMiB = 4096;       // address space per process (no cgroup: see sandbox.cpp)
    long fileMiB = 64;           // the largest file a process may write (RLIMIT_FSIZE)
    int openFiles = 256;         // RLIMIT_NOFILE
    int processes = 64;          // tasks (threads count) of the job: llvmpipe's threads fit
    long tmpMiB = 64;            // the tmpfs /tmp
};

struct SandboxRun {
    Isolation isolation = Isolation::None;
    uid_t uid = 0;                 // the job's uid (0: stay as the grader's user)
    std::vector<Mount> mounts;     // besides the system folders (read-only /usr)
    std::vector<std::string> env;  // "NAME=value", the whole environment of the step
    std::string workingDirectory;  // inside path
    SandboxLimits limits;
    // A grader other than root (uid 0 here) under namespaces: the process limit is set inside the
    // sandbox's user namespace, where the kernel counts the job's processes alone (probeOwnProcessLimit).
    // Otherwise such a grader's jobs share one count: the limit is what the user runs plus `processes`.
    bool ownProcessLimit = false;
    // The host path of an inside path for isolations without a mount namespace.
    std::string path(const std::string& inside) const;
};

// Probes whether bwrap can start a sandbox here (as `uid` when not 0). "" when it can, else why not.
std::string probeNamespaces(uid_t uid);
// Whether a grader other than root can give each namespaces sandbox a process limit of its own: the
// kernel counts a user's processes per user namespace (Linux 5.14 and later), so a limit set inside
// the sandbox (with util-linux's prlimit) counts that job's processes only, whatever the user's other
// jobs run. "" when it can (a sandbox with room for 3 processes starts 3 while the grader and bwrap
// run outside it), else why not. Call it where bwrap works (probeNamespaces).
std::string probeOwnProcessLimit();
// Picks `count` uids no account and no process uses (the grader must be root to use them).
std::vector<uid_t> pickJobUids(int count);
// Kills every process of `uid` and returns once none is left (or after 5 s).
void killAllOfUid(uid_t uid);

// The isolation to run student code with: `asked` is auto (namespaces where bwrap starts, as `uid`
// when not 0, else the uid fallback as root), namespaces, uid or none. Throws t10::Error when the one
// asked for cannot be had, or when auto finds none (never runs student code unprotected unasked).
// Warnings go to `log`, prefixed with `program`.
Isolation chooseIsolation(const std::string& asked, uid_t uid, const std::string& program, std::ostream& log);

// A path a uid cannot read, and the folder on its way that stops it (a home made 0700).
struct Unreachable {
    std::string path;   // empty: every path is readable
    std::string folder; // the first folder of `path` the uid cannot enter, else `path` itself
    std::string explain() const; // "the job uids cannot read P: F lets no one else in (mode 0700)"
};
// Asks the kernel, from a child switched to `uid`, whether it can read each of `paths`.
Unreachable firstUnreachable(uid_t uid, const std::vector<std::string>& paths);
// Makes each read-only mount readable by `uid` (the grader's environment is never the student's
// fault): one it cannot reach, such as a checkout inside a 0700 home, is linked or copied under
// `staging` and mounted from there. Under the uid isolation a mount seen at its host path (the common
// shaders and assets, whose paths are compiled into the project's libraries) cannot move: throws
// t10::Error naming the folder that stops the uid and what to do.
void stageUnreachableMounts(std::vector<Mount>& mounts, const std::string& staging, uid_t uid, Isolation isolation);

// Runs argv (inside paths) under the sandbox; stdout and stderr go to logFile (a host path the step
// cannot see). Throws t10::Error when the sandbox cannot be started at all.
RunResult runSandboxed(const SandboxRun& run, const std::vector<std::string>& argv, const std::string& logFile);

} // namespace t10::grade
