// Whole-file reading shared by the TGA loader and the image readers.
#include "t10/file.hpp"

#include "t10/error.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

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

} // namespace t10
