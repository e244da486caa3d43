// Whole-file reading and all-or-nothing writing, shared by the TGA loader, the image readers and
// the image writers.
#include "t10/file.hpp"

#include "t10/error.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <random>

namespace t10 {

std::vector<std::uint8_t> readFile(const std::string& path) {
    // std::fopen sets errno reliably, so the message can say why the file did not open.
    errno = 0;
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
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
    auto fail = [&](const std::string& step, int error) {
        throw Error(path + ": cannot write " + what + " (" + step + "): " + std::strerror(error));
    };
    // A name no other writer picks: O_EXCL refuses an existing one, so a clash just tries again.
    // open() with mode 0666 lets the umask decide the permissions, as for any new file.
    std::random_device random;
    std::string temporary;
    int fd = -1;
    for (int attempt = 0; fd < 0; ++attempt) {
        temporary = path + ".tmp" + std::to_string(random() % 1000000u);
        fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd < 0 && (errno != EEXIST || attempt == 100)) fail("create " + temporary, errno);
    }
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    std::size_t done = 0;
    while (done < size) {
        const ssize_t wrote = ::write(fd, bytes + done, size - done);
        if (wrote < 0 && errno == EINTR) continue;
        if (wrote <= 0) {
            const int error = wrote < 0 ? errno : ENOSPC; // write() returning 0 for a file: no room
            ::close(fd);
            ::unlink(temporary.c_str());
            fail("write", error);
        }
        done += static_cast<std::size_t>(wrote);
    }
    // Some file systems (NFS, quotas) only report a full disk when the file is closed.
    if (::close(fd) != 0) {
        const int error = errno;
        ::unlink(temporary.c_str());
        fail("close", error);
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0) {
        const int error = errno;
        ::unlink(temporary.c_str());
        fail("rename " + temporary, error);
    }
}

} // namespace t10
