// TGA loader used for the scene's textures and by the tga2png tool: true-colour and grey images,
// raw and run-length encoded (types 2, 3, 10, 11), 8/24/32 bits per pixel, either vertical origin.
// Everything in the header is validated before a single pixel is allocated, every read is
// bounds-checked, and an RLE image grows as its packets decode, so a malformed file gives
// "<name>: <fault>" instead of a crash or a huge allocation. Right-to-left files (descriptor bit 4)
// are rejected: no common writer produces them.
#include "t10/tga.hpp"

#include "t10/error.hpp"

#include "t10/file.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace t10 {
namespace {

constexpr std::size_t kHeaderSize = 18;
constexpr std::size_t kMaxRlePacketPixels = 128;
// What the RLE decoder reserves before the first packet; it grows from there as packets decode.
constexpr std::size_t kRleInitialBytes = std::size_t{1} << 20;

// Image types (TGA 2.0 specification, field 3).
constexpr int kTypeNoImage = 0;
constexpr int kTypeColourMapped = 1;
constexpr int kTypeTrueColour = 2;
constexpr int kTypeGrey = 3;
constexpr int kTypeColourMappedRle = 9;
constexpr int kTypeTrueColourRle = 10;
constexpr int kTypeGreyRle = 11;

constexpr std::uint8_t kDescriptorRightToLeft = 0x10;
constexpr std::uint8_t kDescriptorTopToBottom = 0x20;

// Little-endian 16-bit field; the bytes are unsigned so sizes above 127 come out right.
int readU16(const std::uint8_t* p) { return static_cast<int>(p[0]) | (static_cast<int>(p[1]) << 8); }

[[noreturn]] void fail(const std::string& name, const std::string& fault) { throw Error(name + ": " + fault); }

// Decodes the RLE stream starting at `pos` into `out` (pixelCount pixels of `bpp` bytes, file
// order). Packets may cross scan lines: TGA 1.0 writers did that, and it costs nothing to allow.
// `out` grows as packets decode, so a stream that goes wrong early never costs the declared size:
// a 10 MB file may declare 16384 x 16384 x 4 bytes (1 GiB) and be invalid from its first packet.
std::string decodeRle(const std::uint8_t* bytes, std::size_t size, std::size_t pos, std::size_t bpp,
                      std::size_t pixelCount, std::vector<std::uint8_t>& out) {
    const std::size_t total = pixelCount * bpp;
    out.assign(std::min(total, kRleInitialBytes), 0);
    std::size_t used = 0; // bytes decoded so far; out.size() is the room for them
    std::size_t done = 0;
    while (done < pixelCount) {
        if (pos >= size) return "RLE data truncated (" + std::to_string(done) + " of " +
                                std::to_string(pixelCount) + " pixels decoded)";
        const std::uint8_t packet = bytes[pos++];
        const std::size_t count = (packet & 0x7Fu) + 1u;
        if (count > pixelCount - done) return "RLE packet runs past the end of the image";
        const bool run = (packet & 0x80u) != 0;
        if (size - pos < (run ? bpp : count * bpp))
            return run ? "RLE data truncated (run packet value missing)" : "RLE data truncated (raw packet pixels missing)";
        // Double the room when full (never past the image): at most 1.5 x the image at once.
        if (used + count * bpp > out.size()) out.resize(std::min(total, std::max(used + count * bpp, out.size() * 2)));
        std::uint8_t* dst = out.data() + used;
        if (run) { // run-length packet: one pixel value repeated
            for (std::size_t i = 0; i < count; ++i) std::memcpy(dst + i * bpp, bytes + pos, bpp);
            pos += bpp;
        } else { // raw packet: `count` literal pixels
            std::memcpy(dst, bytes + pos, count * bpp);
            pos += count * bpp;
        }
        used += count * bpp;
        done += count;
    }
    return {};
}

} // namespace

Image8 decodeTga(const std::uint8_t* bytes, std::size_t size, const std::string& name) {
    if (bytes == nullptr) size = 0;
    if (size < kHeaderSize)
        fail(name, "truncated header (" + std::to_string(size) + " of 18 bytes)");

    const std::uint8_t* h = bytes;
    const std::size_t idLength = h[0];
    const int colourMapType = h[1];
    const int imageType = h[2];
    const int colourMapLength = readU16(h + 5);
    const int colourMapEntryBits = h[7];
    const int width = readU16(h + 12);
    const int height = readU16(h + 14);
    const int depth = h[16];
    const std::uint8_t descriptor = h[17];

    // Image type first: it decides what every other field means.
    bool grey = false;
    bool rle = false;
    switch (imageType) {
    case kTypeTrueColour: break;
    case kTypeGrey: grey = true; break;
    case kTypeTrueColourRle: rle = true; break;
    case kTypeGreyRle: grey = true; rle = true; break;
    case kTypeNoImage: fail(name, "image type 0 (no image data)");
    case kTypeColourMapped:
    case kTypeColourMappedRle:
        fail(name, "unsupported image type " + std::to_string(imageType) +
                              " (colour-mapped); save the texture as true-colour or grey");
    default:
        fail(name, "unsupported image type " + std::to_string(imageType) +
                              " (expected 2, 3, 10 or 11)");
    }
    if (colourMapType > 1) fail(name, "invalid colour-map type " + std::to_string(colourMapType));

    if (width == 0 || height == 0)
        fail(name, "zero width or height (" + std::to_string(width) + "x" + std::to_string(height) + ")");
    if (width > kTgaMaxSide)
        fail(name, "width " + std::to_string(width) + " exceeds " + std::to_string(kTgaMaxSide));
    if (height > kTgaMaxSide)
        fail(name, "height " + std::to_string(height) + " exceeds " + std::to_string(kTgaMaxSide));

    if (grey && depth != 8)
        fail(name, "unsupported pixel depth " + std::to_string(depth) + " for grey (expected 8)");
    if (!grey && depth != 24 && depth != 32)
        fail(name, "unsupported pixel depth " + std::to_string(depth) +
                              " for true-colour (expected 24 or 32)");
    if (descriptor & kDescriptorRightToLeft)
        fail(name, "unsupported right-to-left pixel order (descriptor bit 4)");

    // Skip the image-ID field and, for a true-colour or grey image, any colour map (allowed by the
    // specification and ignored): both by their declared lengths.
    std::size_t pos = kHeaderSize;
    if (size - pos < idLength) fail(name, "image-ID field truncated");
    pos += idLength;
    if (colourMapType == 1) {
        const std::size_t mapBytes =
            static_cast<std::size_t>(colourMapLength) * ((static_cast<std::size_t>(colourMapEntryBits) + 7u) / 8u);
        if (size - pos < mapBytes) fail(name, "colour map truncated");
        pos += mapBytes;
    }

    // Check that the data can cover the image before allocating it. The bound for RLE is the
    // smallest possible stream: packets of 128 pixels, each a header byte plus one pixel.
    const std::size_t bpp = static_cast<std::size_t>(depth) / 8u;
    const std::size_t pixelCount = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    const std::size_t available = size - pos;
    if (!rle && available < pixelCount * bpp)
        fail(name, "pixel data truncated (" + std::to_string(available) + " of " +
                              std::to_string(pixelCount * bpp) + " bytes)");
    const std::size_t minRleBytes = (pixelCount + kMaxRlePacketPixels - 1) / kMaxRlePacketPixels * (1 + bpp);
    if (rle && available < minRleBytes)
        fail(name, "RLE data truncated (" + std::to_string(available) + " bytes cannot hold " +
                              std::to_string(pixelCount) + " pixels)");

    // Decode in file order (BGR(A) or grey), then reorder channels and rows in place.
    Image8 image;
    if (rle) {
        std::vector<std::uint8_t> decoded;
        std::string fault = decodeRle(bytes, size, pos, bpp, pixelCount, decoded);
        if (!fault.empty()) fail(name, fault);
        image.width = width;
        image.height = height;
        image.channels = static_cast<int>(bpp);
        image.data = std::move(decoded);
    } else {
        image = Image8(width, height, static_cast<int>(bpp));
        std::memcpy(image.data.data(), bytes + pos, pixelCount * bpp);
    }
    std::uint8_t* out = image.data.data();
    if (bpp >= 3)
        for (std::size_t i = 0; i < pixelCount; ++i) std::swap(out[i * bpp], out[i * bpp + 2]); // BGR -> RGB
    if (descriptor & kDescriptorTopToBottom) { // top-left origin: make row 0 the bottom row
        const std::size_t rowBytes = static_cast<std::size_t>(width) * bpp;
        for (int y = 0; y < height / 2; ++y) {
            std::uint8_t* a = out + static_cast<std::size_t>(y) * rowBytes;
            std::uint8_t* b = out + static_cast<std::size_t>(height - 1 - y) * rowBytes;
            std::swap_ranges(a, a + rowBytes, b);
        }
    }
    return image;
}

Image8 loadTga(const std::string& path) {
    const std::vector<std::uint8_t> bytes = readFile(path);
    return decodeTga(bytes.data(), bytes.size(), path);
}

} // namespace t10
