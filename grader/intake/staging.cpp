// The grader's own files: reading them, the private folders and copies of its work tree (made for a
// job's uid), and the cache's folders, published whole with a manifest of their hashes.
#include "intake/staging.hpp"

#include "t10/error.hpp"
#include "t10/fork_lock.hpp"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <mutex>
#include <shared_mutex>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace t10::grade {

namespace fs = std::filesystem;

std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path + ": cannot open");
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// FNV-1a: names a build folder after what was built.
std::string hashOf(const std::string& text) {
    std::uint64_t hash = 1469598103934665603ull;
    for (const unsigned char c : text) {
        hash ^= c;
        hash *= 1099511628211ull;
    }
    std::ostringstream out;
    out << std::hex << hash;
    return out.str();
}

// A folder is filled under a temporary name and renamed into place, so that parallel graders (or
// jobs) sharing the cache never see half of it.
void publishDirectory(const fs::path& temporary, const fs::path& target) {
    std::error_code error;
    fs::rename(temporary, target, error);
    if (error) fs::remove_all(temporary); // another grader got there first: keep theirs
}

std::string uniqueSuffix() {
    static std::atomic<int> counter{0};
    return "." + std::to_string(::getpid()) + "." + std::to_string(counter++);
}

// The FNV-1a of a file's contents, read without following a symlink; "" when it cannot be read.
std::string fileHash(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0) return "";
    std::string data;
    char buffer[65536];
    for (ssize_t n; (n = ::read(fd, buffer, sizeof buffer)) > 0;) data.append(buffer, static_cast<std::size_t>(n));
    ::close(fd);
    return hashOf(data);
}

namespace {

// A cached folder carries the hash of every file in it, recorded when the grader published it; it is
// used only while its contents still match.
std::string manifestOf(const fs::path& dir) {
    std::vector<std::string> lines;
    for (auto it = fs::recursive_directory_iterator(dir); it != fs::recursive_directory_iterator(); ++it) {
        const fs::file_status status = it->symlink_status();
        const std::string relative = fs::relative(it->path(), dir).string();
        if (relative == kManifest) continue;
        if (fs::is_directory(status)) continue;
        lines.push_back((fs::is_regular_file(status) ? fileHash(it->path().string()) : std::string("not-a-file")) + " " + relative);
    }
    std::sort(lines.begin(), lines.end());
    std::string text;
    for (const std::string& line : lines) text += line + "\n";
    return text;
}

} // namespace

void writeManifest(const fs::path& dir) { std::ofstream(dir / kManifest) << manifestOf(dir); }

bool manifestHolds(const fs::path& dir) {
    std::error_code error;
    if (!fs::is_regular_file(fs::symlink_status(dir / kManifest, error))) return false;
    return readFile((dir / kManifest).string()) == manifestOf(dir);
}

// A folder of the grader's work tree: owned by the job's uid when it must write there.
void makeDir(const fs::path& dir, uid_t owner, mode_t mode) {
    if (::mkdir(dir.c_str(), mode) != 0 && errno != EEXIST) throw Error(dir.string() + ": cannot create: " + std::strerror(errno));
    if (::chmod(dir.c_str(), mode) != 0) throw Error(dir.string() + ": chmod: " + std::strerror(errno));
    if (owner != 0 && ::chown(dir.c_str(), owner, owner) != 0) throw Error(dir.string() + ": chown: " + std::strerror(errno));
}

// Copies a file the grader owns. A descriptor open for writing inherited by a process forked
// meanwhile by another job would make exec() of the copy fail with "Text file busy": the descriptors
// are close-on-exec (std::filesystem::copy_file does not set O_CLOEXEC), and no fork() happens while
// the copy is open (t10::forkLock), since a child holds what it inherited until its exec.
void copyFile(const fs::path& from, const fs::path& to, mode_t mode, uid_t owner) {
    // No fork() while the copy is open for writing: a child forked meanwhile would hold it (fork_lock.hpp).
    const std::shared_lock noFork(t10::forkLock());
    const int in = ::open(from.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
    if (in < 0) throw Error(from.string() + ": cannot open: " + std::strerror(errno));
    const int out = ::open(to.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, mode);
    if (out < 0) {
        const int error = errno;
        ::close(in);
        throw Error(to.string() + ": cannot create: " + std::strerror(error));
    }
    char buffer[65536];
    bool ok = true;
    for (ssize_t n; ok && (n = ::read(in, buffer, sizeof buffer)) != 0;) {
        ok = n > 0 && ::write(out, buffer, static_cast<std::size_t>(n)) == n;
    }
    const int error = errno;
    if (ok && owner != 0 && ::fchown(out, owner, owner) != 0) ok = false;
    ::fchmod(out, mode);
    ::close(in);
    ::close(out);
    if (!ok) throw Error(to.string() + ": cannot copy from " + from.string() + ": " + std::strerror(error));
}

// Copies a folder of regular files (the grader's own: the Mesa shader cache seed), owned by `owner`.
void copyTree(const fs::path& from, const fs::path& to, uid_t owner) {
    makeDir(to, owner, 0700);
    for (const auto& entry : fs::directory_iterator(from)) {
        const fs::file_status status = entry.symlink_status();
        if (fs::is_directory(status)) copyTree(entry.path(), to / entry.path().filename(), owner);
        else if (fs::is_regular_file(status)) copyFile(entry.path(), to / entry.path().filename(), 0600, owner);
    }
}

} // namespace t10::grade
