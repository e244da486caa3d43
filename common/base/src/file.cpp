// Whole-file reading and all-or-nothing writing, shared by the TGA loader, the image readers and
// the image writers. POSIX and Windows differ in three places, each kept to a small function below:
// creating the temporary file (Windows: binary mode, or every "\n" byte of a PNG gains a "\r"),
// writing to it, and renaming it into place (Windows: std::rename refuses to replace a file, so
// MoveFileExW with MOVEFILE_REPLACE_EXISTING). Paths are UTF-8; Windows gets them as UTF-16.
#include "t10/file.hpp"

#include "t10/error.hpp"

#ifdef _WIN32
#include <windows.h>

#include <fcntl.h>
#include <io.h>
#include <sys/stat.h>
#else
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#endif

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <random>

namespace t10 {

namespace {

#ifdef _WIN32
std::wstring widen(const std::string& path) {
    if (path.empty()) return std::wstring();
    const int length = MultiByteToWideChar(CP_UTF8, 0, path.data(), static_cast<int>(path.size()), nullptr, 0);
    std::wstring wide(static_cast<std::size_t>(length), L'\0');
    MultiByteToWideChar(CP_UTF8, 0, path.data(), static_cast<int>(path.size()), wide.data(), length);
    return wide;
}

std::FILE* openForReading(const std::string& path) { return _wfopen(widen(path).c_str(), L"rb"); }

int createExclusive(const std::string& path) {
    return _wopen(widen(path).c_str(), _O_WRONLY | _O_CREAT | _O_EXCL | _O_BINARY | _O_NOINHERIT, _S_IREAD | _S_IWRITE);
}

long long writeSome(int fd, const std::uint8_t* bytes, std::size_t size) {
    const unsigned chunk = size > (1u << 30) ? (1u << 30) : static_cast<unsigned>(size);
    return _write(fd, bytes, chunk);
}

int closeFile(int fd) { return _close(fd); }

void removeFile(const std::string& path) { _wunlink(widen(path).c_str()); }

// Replaces `to` by `from`; on failure returns the reason. A folder in the way is named as POSIX names
// it ("Is a directory"), not as "Access is denied", which Windows says for it and for much else.
bool replaceFile(const std::string& from, const std::string& to, std::string& reason) {
    const std::wstring target = widen(to);
    if (MoveFileExW(widen(from).c_str(), target.c_str(), MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH) != 0) {
        return true;
    }
    const DWORD error = GetLastError();
    const DWORD attributes = GetFileAttributesW(target.c_str());
    if (attributes != INVALID_FILE_ATTRIBUTES && (attributes & FILE_ATTRIBUTE_DIRECTORY) != 0) {
        reason = std::strerror(EISDIR);
        return false;
    }
    char* text = nullptr;
    FormatMessageA(FORMAT_MESSAGE_ALLOCATE_BUFFER | FORMAT_MESSAGE_FROM_SYSTEM | FORMAT_MESSAGE_IGNORE_INSERTS, nullptr,
                   error, 0, reinterpret_cast<char*>(&text), 0, nullptr);
    reason = text != nullptr ? text : "Windows error " + std::to_string(error);
    if (text != nullptr) LocalFree(text);
    while (!reason.empty() && (reason.back() == '\n' || reason.back() == '\r' || reason.back() == '.')) reason.pop_back();
    return false;
}
#else
std::FILE* openForReading(const std::string& path) { return std::fopen(path.c_str(), "rb"); }

// open() with mode 0666 lets the umask decide the permissions, as for any new file.
int createExclusive(const std::string& path) { return ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666); }

long long writeSome(int fd, const std::uint8_t* bytes, std::size_t size) { return ::write(fd, bytes, size); }

int closeFile(int fd) { return ::close(fd); }

void removeFile(const std::string& path) { ::unlink(path.c_str()); }

bool replaceFile(const std::string& from, const std::string& to, std::string& reason) {
    if (std::rename(from.c_str(), to.c_str()) == 0) return true;
    reason = std::strerror(errno);
    return false;
}
#endif

} // namespace

std::vector<std::uint8_t> readFile(const std::string& path) {
    // std::fopen sets errno reliably, so the message can say why the file did not open.
    errno = 0;
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(openForReading(path), &std::fclose);
    if (!file) throw Error(path + ": cannot open file: " + std::strerror(errno));
    std::vector<std::uint8_t> bytes;
    std::uint8_t chunk[16384];
    for (;;) {
        const std::size_t got = std::fread(chunk, 1, sizeof chunk, file.get());
        bytes.insert(bytes.end(), chunk, chunk + got);
        if (got < sizeof chunk) break;
    }
    if (std::ferror(file.get())) {
        const int error = errno;
        throw Error(path + ": cannot read file: " + (error != 0 ? std::strerror(error) : "read error"));
    }
    return bytes;
}

void writeFileAtomically(const std::string& path, const void* data, std::size_t size, const std::string& what) {
    auto failWith = [&](const std::string& step, const std::string& reason) {
        throw Error(path + ": cannot write " + what + " (" + step + "): " + reason);
    };
    auto fail = [&](const std::string& step, int error) { failWith(step, std::strerror(error)); };
    // A name no other writer picks: O_EXCL refuses an existing one, so a clash just tries again.
    std::random_device random;
    std::string temporary;
    int fd = -1;
    for (int attempt = 0; fd < 0; ++attempt) {
        temporary = path + ".tmp" + std::to_string(random() % 1000000u);
        fd = createExclusive(temporary);
        if (fd < 0 && (errno != EEXIST || attempt == 100)) fail("create " + temporary, errno);
    }
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    std::size_t done = 0;
    while (done < size) {
        const long long wrote = writeSome(fd, bytes + done, size - done);
        if (wrote < 0 && errno == EINTR) continue;
        if (wrote <= 0) {
            const int error = wrote < 0 ? errno : ENOSPC; // write() returning 0 for a file: no room
            closeFile(fd);
            removeFile(temporary);
            fail("write", error);
        }
        done += static_cast<std::size_t>(wrote);
    }
    // Some file systems (NFS, quotas) only report a full disk when the file is closed.
    if (closeFile(fd) != 0) {
        const int error = errno;
        removeFile(temporary);
        fail("close", error);
    }
    std::string reason;
    if (!replaceFile(temporary, path, reason)) {
        removeFile(temporary);
        failWith("rename " + temporary, reason);
    }
}

} // namespace t10
