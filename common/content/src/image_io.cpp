// Image files for the stages, tools and tests: 8-bit PNG through stb (the final frame, golden
// images) and little-endian PFM (exact float dumps for the numeric tests); RGBA half-float OpenEXR
// (the HDR accumulation buffer) is the platform's: exr_io.cpp, or exr_io_web.cpp in the browser build.
// In memory row 0 is the bottom row; PNG stores the top row first, so it is flipped here, while PFM
// stores the bottom row first like we do. Every failure throws t10::Error with a message that starts
// with the file's path.
#include "t10/image_io.hpp"
#include "t10/stb_guard.hpp"

#include "t10/file.hpp"

#include "t10/error.hpp"
#include "image_file.hpp"

#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <limits>
#include <locale>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace t10 {
namespace {

// Little-endian float I/O that does not depend on the host's byte order.
void putFloatLe(float value, std::uint8_t* out) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    for (int i = 0; i < 4; ++i) out[i] = static_cast<std::uint8_t>(bits >> (8 * i));
}

float getFloat(const std::uint8_t* in, bool littleEndian) {
    std::uint32_t bits = 0;
    for (int i = 0; i < 4; ++i) bits |= static_cast<std::uint32_t>(in[littleEndian ? i : 3 - i]) << (8 * i);
    float value = 0.0f;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}


// A top-row-first copy, as PNG and JPEG store rows; stb's global flip flag would be shared state
// between callers.
std::vector<std::uint8_t> topRowFirst(const Image8& image) {
    const std::size_t rowBytes = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.channels);
    std::vector<std::uint8_t> topFirst(image.data.size());
    for (int y = 0; y < image.height; ++y)
        std::memcpy(topFirst.data() + static_cast<std::size_t>(y) * rowBytes,
                    image.data.data() + static_cast<std::size_t>(image.height - 1 - y) * rowBytes, rowBytes);
    return topFirst;
}

void appendBytes(void* context, void* data, int size) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(context);
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    out->insert(out->end(), bytes, bytes + size);
}

} // namespace

void writePng(const std::string& path, const Image8& image) {
    image_file::checkImage(path, image, true);
    const std::vector<std::uint8_t> topFirst = topRowFirst(image);
    const int rowBytes = image.width * image.channels;
    // Encoded in memory, then written all or nothing: stb's own file writer ignores fwrite's result.
    std::vector<std::uint8_t> encoded;
    if (!stbi_write_png_to_func(appendBytes, &encoded, image.width, image.height, image.channels, topFirst.data(), rowBytes))
        image_file::fail(path, "cannot encode PNG");
    writeFileAtomically(path, encoded.data(), encoded.size(), "PNG");
}

std::vector<std::uint8_t> encodeJpeg(const Image8& image, int quality, const std::string& name) {
    image_file::checkImage(name, image, true);
    const std::vector<std::uint8_t> topFirst = topRowFirst(image);
    std::vector<std::uint8_t> encoded;
    if (!stbi_write_jpg_to_func(appendBytes, &encoded, image.width, image.height, image.channels, topFirst.data(), quality))
        image_file::fail(name, "cannot encode JPEG");
    return encoded;
}

Image8 readPng(const std::string& path) {
    const std::vector<std::uint8_t> bytes = readFile(path);
    if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max())) image_file::fail(path, "file too large");
    const int length = static_cast<int>(bytes.size());
    // The same checks as the glTF loader's images: a JPEG named .png must not reach stb unchecked.
    if (const auto fault = stbInputFault(bytes.data(), bytes.size())) image_file::fail(path, "cannot read PNG: " + *fault);
    int w = 0, h = 0, fileChannels = 0;
    if (!stbi_info_from_memory(bytes.data(), length, &w, &h, &fileChannels))
        image_file::fail(path, std::string("cannot read PNG: ") + stbi_failure_reason());
    // Grey + alpha has no place in Image8's grey/RGB/RGBA: expand it to RGBA.
    const int channels = fileChannels == 2 ? 4 : fileChannels;
    std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
        stbi_load_from_memory(bytes.data(), length, &w, &h, &fileChannels, channels), &stbi_image_free);
    if (!pixels) image_file::fail(path, std::string("cannot read PNG: ") + stbi_failure_reason());

    Image8 image(w, h, channels);
    const std::size_t rowBytes = static_cast<std::size_t>(w) * static_cast<std::size_t>(channels);
    for (int y = 0; y < h; ++y)
        std::memcpy(image.data.data() + static_cast<std::size_t>(h - 1 - y) * rowBytes,
                    pixels.get() + static_cast<std::size_t>(y) * rowBytes, rowBytes);
    return image;
}


std::size_t clampNonFinite(ImageF& image, float maximum) {
    const std::size_t channels = static_cast<std::size_t>(std::max(image.channels, 1));
    std::size_t pixels = 0;
    for (std::size_t i = 0; i < image.data.size(); i += channels) {
        bool changed = false;
        for (std::size_t c = i; c < i + channels && c < image.data.size(); ++c) {
            float& v = image.data[c];
            if (std::isfinite(v)) continue;
            v = v > 0.0f ? maximum : 0.0f; // NaN compares false: 0 like -infinity
            changed = true;
        }
        pixels += changed ? 1 : 0;
    }
    return pixels;
}

// A 4-channel image is written as "PF" (RGB): PFM has no alpha, so alpha is dropped.
void writePfm(const std::string& path, const ImageF& image) {
    image_file::checkImage(path, image, true);
    const int fileChannels = image.channels == 1 ? 1 : 3;
    const std::string header = std::string(fileChannels == 1 ? "Pf" : "PF") + "\n" + std::to_string(image.width) +
                               " " + std::to_string(image.height) + "\n-1.0\n"; // negative scale: little-endian
    const std::size_t pixelCount = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
    std::vector<std::uint8_t> bytes(header.begin(), header.end());
    bytes.resize(header.size() + pixelCount * static_cast<std::size_t>(fileChannels) * 4u);
    std::uint8_t* out = bytes.data() + header.size();
    // Rows bottom to top, as PFM specifies and as the image is held.
    for (std::size_t i = 0; i < pixelCount; ++i)
        for (int c = 0; c < fileChannels; ++c, out += 4)
            putFloatLe(image.data[i * static_cast<std::size_t>(image.channels) + static_cast<std::size_t>(c)], out);

    writeFileAtomically(path, bytes.data(), bytes.size(), "PFM");
}

ImageF readPfm(const std::string& path) {
    const std::vector<std::uint8_t> bytes = readFile(path);
    std::size_t pos = 0;
    auto isSpace = [](std::uint8_t b) { return b == ' ' || b == '\t' || b == '\n' || b == '\r'; };
    // Header: three whitespace-separated tokens after the magic; one whitespace byte ends it.
    auto token = [&](const char* what) {
        while (pos < bytes.size() && isSpace(bytes[pos])) ++pos;
        const std::size_t start = pos;
        while (pos < bytes.size() && !isSpace(bytes[pos]) && pos - start < 64) ++pos;
        if (pos == start || pos >= bytes.size())
            image_file::fail(path, std::string("PFM header truncated or malformed at ") + what);
        return std::string(reinterpret_cast<const char*>(bytes.data()) + start, pos - start);
    };
    if (bytes.size() < 2 || bytes[0] != 'P' || (bytes[1] != 'F' && bytes[1] != 'f') ||
        (bytes.size() > 2 && !isSpace(bytes[2])))
        image_file::fail(path, "not a PFM file (expected \"PF\" or \"Pf\")");
    const int channels = bytes[1] == 'F' ? 3 : 1;
    pos = 2;
    auto parseSide = [&](const std::string& text, const char* what) {
        long long value = 0;
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (ec != std::errc() || end != text.data() + text.size())
            image_file::fail(path, std::string("PFM ") + what + " \"" + text + "\" is not a number");
        if (value <= 0 || value > image_file::kMaxReadSide)
            image_file::fail(path, std::string("PFM ") + what + " " + text + " is out of range (1 to " +
                           std::to_string(image_file::kMaxReadSide) + ")");
        return static_cast<int>(value);
    };
    const int width = parseSide(token("width"), "width");
    const int height = parseSide(token("height"), "height");
    const std::string scaleText = token("scale");
    // A C-locale stream, not std::from_chars: g++ 10's library has no floating-point from_chars.
    std::istringstream scaleIn(scaleText);
    scaleIn.imbue(std::locale::classic());
    double scale = 0.0;
    scaleIn >> scale;
    if (scaleIn.fail() || scaleIn.peek() != std::char_traits<char>::eof() || scale == 0.0 || !std::isfinite(scale))
        image_file::fail(path, "PFM scale \"" + scaleText + "\" is not a non-zero number");
    ++pos; // the single whitespace byte that token() stopped at

    const std::size_t values = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) *
                               static_cast<std::size_t>(channels);
    if (bytes.size() - pos < values * 4u)
        image_file::fail(path, "PFM pixel data truncated (" + std::to_string(bytes.size() - pos) + " of " +
                       std::to_string(values * 4u) + " bytes)");
    ImageF image(width, height, channels);
    const bool littleEndian = scale < 0.0;
    for (std::size_t i = 0; i < values; ++i) image.data[i] = getFloat(bytes.data() + pos + i * 4u, littleEndian);
    return image;
}

} // namespace t10
