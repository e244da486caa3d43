// Runs a student-controlled step (the compiler, a render) in a sandbox. Three isolations:
//   namespaces: bubblewrap with every namespace unshared, no capabilities, a cleared environment, a
//               fixed view of the file system (the mounts below at neutral paths such as /submission,
//               /out, /t10), a size-capped /tmp; killed with the grader, and at the wall limit the
//               whole pid namespace dies. As root, bwrap itself runs as the job's unprivileged uid so
//               that the process and file limits hold.
//   uid:        where user namespaces cannot be had: the step runs as the job's unprivileged uid (the
//               grader must be root), with the same limits and environment; it sees the host's file
//               system with that uid's rights, and every process of the uid is killed after the run.
//   none:       only the limits (--no-sandbox; unsafe for untrusted code).
// Paths given to a step are written as they are inside (Mount::inside); SandboxRun::path() turns them
// into host paths for the isolations that have no mount namespace.
#pragma once
#include "isolation/run_limited.hpp"

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
    int processes = 64;          // tasks (threads count) of the job's uid: llvmpipe's threads fit
    long tmpMiB = 64;            // the tmpfs /tmp
};

struct SandboxRun {
    Isolation isolation = Isolation::None;
    uid_t uid = 0;                 // the job's uid (0: stay as the grader's user)
    std::vector<Mount> mounts;     // besides the system folders (read-only /usr)
    std::vector<std::string> env;  // "NAME=value", the whole environment of the step
    std::string workingDirectory;  // inside path
    SandboxLimits limits;
    // The host path of an inside path for isolations without a mount namespace.
    std::string path(const std::string& inside) const;
};

// Probes whether bwrap can start a sandbox here (as `uid` when not 0). "" when it can, else why not.
std::string probeNamespaces(uid_t uid);
// Picks `count` uids no account and no process uses (the grader must be root to use them).
std::vector<uid_t> pickJobUids(int count);
// Kills every process of `uid` and returns once none is left (or after 5 s).
void killAllOfUid(uid_t uid);

// Runs argv (inside paths) under the sandbox; stdout and stderr go to logFile (a host path the step
// cannot see). Throws t10::Error when the sandbox cannot be started at all.
RunResult runSandboxed(const SandboxRun& run, const std::vector<std::string>& argv, const std::string& logFile);

} // namespace t10::grade
