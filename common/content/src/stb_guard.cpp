// The checks before stb_image; see stb_guard.hpp.
#include "t10/stb_guard.hpp"

#include <algorithm>
#include <cstring>

namespace t10 {

namespace {

// Walks the JPEG's segments, entropy-coded data included, and checks every Huffman table's counts.
bool jpegHuffmanTablesValid(const std::uint8_t* bytes, std::size_t size) {
    std::size_t i = 2; // after SOI
    while (i + 1 < size) {
        if (bytes[i] != 0xFF) {
            ++i; // entropy-coded data: skip to the next marker
            continue;
        }
        const std::uint8_t marker = bytes[i + 1];
        if (marker == 0xFF) { // fill byte
            ++i;
            continue;
        }
        i += 2;
        // Stuffed zero, restart markers, SOI, EOI and TEM have no length.
        if (marker == 0x00 || (marker >= 0xD0 && marker <= 0xD9) || marker == 0x01) continue;
        if (i + 2 > size) return true; // truncated: stb reports it
        const std::size_t length = (std::size_t(bytes[i]) << 8) | bytes[i + 1];
        if (length < 2) return false;
        if (marker == 0xC4) {
            std::size_t at = i + 2;
            const std::size_t end = std::min(size, i + length);
            while (at + 17 <= end) {
                std::size_t count = 0;
                for (std::size_t k = 1; k <= 16; ++k) count += bytes[at + k];
                if (count > 256) return false;
                at += 17 + count;
            }
        }
        i += length;
    }
    return true;
}

} // namespace

std::optional<std::string> stbInputFault(const std::uint8_t* bytes, std::size_t size) {
    const bool png = size >= 8 && std::memcmp(bytes, "\x89PNG\r\n\x1a\n", 8) == 0;
    const bool jpeg = size >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF;
    if (!png && !jpeg) return std::string("not a PNG or JPEG file");
    if (jpeg && !jpegHuffmanTablesValid(bytes, size)) return std::string("corrupt JPEG (a Huffman table with more than 256 codes)");
    return std::nullopt;
}

} // namespace t10
