// Reading and writing images: PNG (8-bit, stb), OpenEXR (RGBA half) and PFM (32-bit float, used
// for the numeric test dumps). Every function throws t10::Error naming the file on failure. Every
// writer is all or nothing: a temporary file next to the target, renamed into place once complete.
#pragma once
#include "t10/image.hpp"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace t10 {

// 8-bit grey, RGB or RGBA. The file's top row is the image's last row (row 0 is the bottom).
void writePng(const std::string& path, const Image8& image);
Image8 readPng(const std::string& path);
// The image as a JPEG in memory (quality 1-100), for pictures that are looked at, not measured (the
// grader's images inline in a platform's result); `name` is the one its errors give.
std::vector<std::uint8_t> encodeJpeg(const Image8& image, int quality, const std::string& name);

// What an EXR may be before its pixels are allocated. The defaults accept any side up to 65536; a
// caller that renders the image passes its GL context's limits and the memory it has. The reasons
// end the message that refuses a file, e.g. "GL_MAX_TEXTURE_SIZE of this context".
struct ExrLimits {
    int maxSide = 65536;
    std::string maxSideReason = "the reader's limit";
    std::uint64_t maxPixels = std::numeric_limits<std::uint64_t>::max(); // width x height
    std::string maxPixelsReason = "the reader's limit";
};

// RGBA half-float OpenEXR; 3-channel images get alpha 1.
void writeExr(const std::string& path, const ImageF& image);
// Always returns 4 channels; a luminance-only (Y) file gives R = G = B = Y. Refuses a file with no
// colour or luminance channel (only Z, say) and one beyond `limits`, before allocating its pixels.
ImageF readExr(const std::string& path, const ExrLimits& limits = {});
// The same from bytes in memory; `name` is only used in messages (the fuzz target's entry point).
ImageF decodeExr(const std::uint8_t* bytes, std::size_t size, const std::string& name, const ExrLimits& limits = {});

// The largest finite half float: where an HDR image read from a half EXR saturates.
constexpr float kHalfMax = 65504.0f;
// Replaces +infinity by `maximum`, and NaN and -infinity by 0 (negative light has no meaning, and
// a negative luminance would make the tone map's log NaN), in every channel; returns how many
// pixels changed.
std::size_t clampNonFinite(ImageF& image, float maximum);

// Portable float map ("Pf" grey or "PF" RGB, little-endian). PFM stores the bottom row first too.
void writePfm(const std::string& path, const ImageF& image);
ImageF readPfm(const std::string& path);

} // namespace t10
