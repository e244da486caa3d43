// Implementation of the copy-in; see submission_files.hpp. Entries are examined with lstat and opened
// with O_NOFOLLOW | O_NONBLOCK relative to the folder's descriptor, then checked again with fstat, so
// that a symlink, a FIFO or a file swapped in between is refused, never followed or waited on.
#include "intake/submission_files.hpp"

#include "t10/error.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace t10::grade {

namespace {

std::string lower(std::string text) {
    for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

bool contains(const std::vector<std::string>& list, const std::string& item) {
    return std::find(list.begin(), list.end(), item) != list.end();
}

// Reads at most `limit` + 1 bytes of an open file.
std::string readCapped(int fd, std::uintmax_t limit) {
    std::string data;
    char buffer[16384];
    while (data.size() <= limit) {
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        data.append(buffer, static_cast<std::size_t>(n));
    }
    return data;
}

void writeFile(const std::string& path, const std::string& data) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd < 0) throw Error(path + ": cannot create: " + std::strerror(errno));
    const bool written = ::write(fd, data.data(), data.size()) == static_cast<ssize_t>(data.size());
    const int error = errno;
    ::close(fd);
    if (!written) throw Error(path + ": cannot write: " + std::strerror(error));
}

std::string kindOf(mode_t mode) {
    if (S_ISLNK(mode)) return "a symlink (never followed)";
    if (S_ISDIR(mode)) return "a folder (only the files at the top are graded)";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

} // namespace

const char* fillPolicyName(FillPolicy policy) {
    switch (policy) {
    case FillPolicy::All: return "all";
    case FillPolicy::None: return "none";
    default: return "unchanged";
    }
}

CopiedSubmission copySubmission(const std::string& submission, const PartFiles& part, const std::string& referenceDir,
                                FillPolicy policy, const std::string& destination) {
    CopiedSubmission copied;
    if (::mkdir(destination.c_str(), 0755) != 0) throw Error(destination + ": cannot create: " + std::strerror(errno));
    // The folder itself is not followed either: a submission that is a link to another folder (the
    // reference stage, another student's) has no files of its own.
    std::string path = submission;
    while (path.size() > 1 && path.back() == '/') path.pop_back();
    const int folder = ::open(path.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (folder < 0 && (errno == ELOOP || errno == ENOTDIR)) {
        copied.files.push_back({".", "ignored", "the submission folder is a symlink (never followed)", 0});
        return copied;
    }
    if (folder < 0) throw Error(submission + ": cannot open the submission folder: " + std::strerror(errno));
    DIR* dir = ::fdopendir(folder);
    if (dir == nullptr) {
        ::close(folder);
        throw Error(submission + ": cannot list: " + std::strerror(errno));
    }
    std::vector<std::string> names;
    while (const dirent* entry = ::readdir(dir)) {
        const std::string name = entry->d_name;
        if (name != "." && name != "..") names.push_back(name);
    }
    std::sort(names.begin(), names.end());
    std::vector<std::string> taken;
    int unlisted = 0;
    for (const std::string& name : names) {
        SubmissionFile file{name, "ignored", "", 0};
        struct stat info {};
        const bool exact = contains(part.expected, name);
        auto nearMatch = std::find_if(part.expected.begin(), part.expected.end(),
                                      [&](const std::string& e) { return lower(e) == lower(name); });
        if (::fstatat(folder, name.c_str(), &info, AT_SYMLINK_NOFOLLOW) != 0) {
            file.reason = std::string("cannot be examined: ") + std::strerror(errno);
        } else if (!exact && nearMatch != part.expected.end()) {
            file.reason = "wrong case, did you mean " + *nearMatch;
        } else if (!exact) {
            file.reason = "not a file of this part (it expects " + [&] {
                std::string list;
                for (const std::string& e : part.expected) list += (list.empty() ? "" : ", ") + e;
                return list;
            }() + ")";
        } else if (!S_ISREG(info.st_mode)) {
            file.reason = kindOf(info.st_mode);
        } else {
            const int fd = ::openat(folder, name.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
            struct stat opened {};
            if (fd < 0) {
                file.reason = std::string("cannot be opened: ") + std::strerror(errno);
            } else if (::fstat(fd, &opened) != 0 || !S_ISREG(opened.st_mode)) {
                file.reason = "not a regular file";
            } else {
                const std::string data = readCapped(fd, kMaxSourceBytes);
                file.bytes = data.size();
                if (data.size() > kMaxSourceBytes) {
                    file.reason = "too large (over " + std::to_string(kMaxSourceBytes / 1024) + " KiB)";
                } else {
                    writeFile(destination + "/" + name, data);
                    file.source = "submission";
                    taken.push_back(name);
                    copied.empty = false;
                }
            }
            if (fd >= 0) ::close(fd);
        }
        // A folder with thousands of entries is listed by count beyond the first ones.
        if (file.source == "submission" || static_cast<int>(copied.files.size()) < kMaxListedEntries) {
            copied.files.push_back(file);
        } else {
            ++unlisted;
        }
    }
    ::closedir(dir);
    if (unlisted > 0) copied.files.push_back({"(" + std::to_string(unlisted) + " more entries)", "ignored", "not listed one by one", 0});

    for (const std::string& name : part.expected) {
        if (contains(taken, name)) continue;
        const bool fill = policy == FillPolicy::All || (policy == FillPolicy::Unchanged && !contains(part.asked, name));
        if (!fill) {
            copied.files.push_back({name, "missing", "this part asks you to write it (not taken from the reference: "
                                                     "--fill-from-reference " + std::string(fillPolicyName(policy)) + ")", 0});
            copied.missing.push_back(name);
            continue;
        }
        const std::string from = referenceDir + "/" + name;
        const int fd = ::open(from.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
        if (fd < 0) throw Error(from + ": cannot open the reference file: " + std::strerror(errno));
        const std::string data = readCapped(fd, 16 * kMaxSourceBytes);
        ::close(fd);
        writeFile(destination + "/" + name, data);
        copied.files.push_back({name, "reference", "", data.size()});
    }
    return copied;
}

} // namespace t10::grade
