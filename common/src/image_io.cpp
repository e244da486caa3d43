// Image files for the stages, tools and tests: 8-bit PNG through stb (the final frame, golden
// images), RGBA half-float OpenEXR (the HDR accumulation buffer) and little-endian PFM (exact
// float dumps for the numeric tests). In memory row 0 is the bottom row; PNG and EXR store the top
// row first, so they are flipped here, while PFM stores the bottom row first like we do. Every
// failure throws t10::Error with a message that starts with the file's path.
#include "t10/image_io.hpp"

#include "t10/file.hpp"

#include "t10/error.hpp"

// OpenEXR's and Imath's headers trip -Wshadow and -Wconversion when they are not on a system
// include path (as with plain pkg-config flags); CMake's imported target marks them SYSTEM.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wconversion"
#include <ImfArray.h>
#include <ImfRgbaFile.h>
#pragma GCC diagnostic pop
#include <stb_image.h>
#include <stb_image_write.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace t10 {
namespace {

// The largest side accepted when reading EXR or PFM: far beyond any render here, small enough that
// width * height * channels cannot overflow.
constexpr long long kMaxReadSide = 65536;

[[noreturn]] void fail(const std::string& path, const std::string& fault) { throw Error(path + ": " + fault); }

using FilePtr = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

FilePtr openFile(const std::string& path, const char* mode) {
    errno = 0;
    FilePtr file(std::fopen(path.c_str(), mode), &std::fclose);
    if (!file) fail(path, std::string("cannot open file: ") + std::strerror(errno));
    return file;
}

template <typename T>
void checkImage(const std::string& path, const ImageT<T>& image, bool allowGrey) {
    const bool channelsOk = image.channels == 3 || image.channels == 4 || (allowGrey && image.channels == 1);
    if (image.width <= 0 || image.height <= 0 || !channelsOk)
        fail(path, "cannot write a " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                       " image with " + std::to_string(image.channels) + " channels");
    const std::size_t expected = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) *
                                 static_cast<std::size_t>(image.channels);
    if (image.data.size() != expected)
        fail(path, "image data holds " + std::to_string(image.data.size()) + " values, expected " +
                       std::to_string(expected));
}

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

} // namespace

void writePng(const std::string& path, const Image8& image) {
    checkImage(path, image, true);
    // Flip into a top-row-first copy; stb's global flip flag would be shared state between callers.
    const std::size_t rowBytes = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.channels);
    std::vector<std::uint8_t> topFirst(image.data.size());
    for (int y = 0; y < image.height; ++y)
        std::memcpy(topFirst.data() + static_cast<std::size_t>(y) * rowBytes,
                    image.data.data() + static_cast<std::size_t>(image.height - 1 - y) * rowBytes, rowBytes);
    if (!stbi_write_png(path.c_str(), image.width, image.height, image.channels, topFirst.data(),
                        static_cast<int>(rowBytes)))
        fail(path, "cannot write PNG (is the directory there and writable?)");
}

Image8 readPng(const std::string& path) {
    const std::vector<std::uint8_t> bytes = readFile(path);
    if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max())) fail(path, "file too large");
    const int length = static_cast<int>(bytes.size());
    int w = 0, h = 0, fileChannels = 0;
    if (!stbi_info_from_memory(bytes.data(), length, &w, &h, &fileChannels))
        fail(path, std::string("cannot read PNG: ") + stbi_failure_reason());
    // Grey + alpha has no place in Image8's grey/RGB/RGBA: expand it to RGBA.
    const int channels = fileChannels == 2 ? 4 : fileChannels;
    std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
        stbi_load_from_memory(bytes.data(), length, &w, &h, &fileChannels, channels), &stbi_image_free);
    if (!pixels) fail(path, std::string("cannot read PNG: ") + stbi_failure_reason());

    Image8 image(w, h, channels);
    const std::size_t rowBytes = static_cast<std::size_t>(w) * static_cast<std::size_t>(channels);
    for (int y = 0; y < h; ++y)
        std::memcpy(image.data.data() + static_cast<std::size_t>(h - 1 - y) * rowBytes,
                    pixels.get() + static_cast<std::size_t>(y) * rowBytes, rowBytes);
    return image;
}

void writeExr(const std::string& path, const ImageF& image) {
    checkImage(path, image, true);
    const int w = image.width, h = image.height, c = image.channels;
    Imf::Array2D<Imf::Rgba> pixels(h, w); // [row][column], row 0 at the top
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const int src = h - 1 - y;
            Imf::Rgba& p = pixels[y][x];
            // A grey image is written as equal R, G and B.
            p.r = image.at(x, src, 0);
            p.g = image.at(x, src, c >= 3 ? 1 : 0);
            p.b = image.at(x, src, c >= 3 ? 2 : 0);
            p.a = c == 4 ? image.at(x, src, 3) : 1.0f;
        }
    }
    try {
        Imf::RgbaOutputFile file(path.c_str(), w, h, Imf::WRITE_RGBA);
        file.setFrameBuffer(&pixels[0][0], 1, static_cast<std::size_t>(w));
        file.writePixels(h);
    } catch (const std::exception& e) {
        fail(path, std::string("cannot write EXR: ") + e.what());
    }
}

ImageF readExr(const std::string& path) {
    // OpenEXR's message for a missing file is long-winded; say it the way the other readers do.
    openFile(path, "rb");
    try {
        Imf::RgbaInputFile file(path.c_str());
        const Imath::Box2i window = file.dataWindow();
        const long long w = static_cast<long long>(window.max.x) - window.min.x + 1;
        const long long h = static_cast<long long>(window.max.y) - window.min.y + 1;
        if (w <= 0 || h <= 0 || w > kMaxReadSide || h > kMaxReadSide)
            fail(path, "unsupported EXR data window " + std::to_string(w) + "x" + std::to_string(h));
        const int width = static_cast<int>(w), height = static_cast<int>(h);
        Imf::Array2D<Imf::Rgba> pixels(height, width);
        // OpenEXR addresses the buffer by file coordinates: hand it the address of pixel (0, 0),
        // which lies outside our array when the data window does not start there. Computed on
        // integers, because pointer arithmetic outside an array is undefined.
        const std::ptrdiff_t originOffset =
            -(static_cast<std::ptrdiff_t>(window.min.x) + static_cast<std::ptrdiff_t>(window.min.y) * width);
        const std::intptr_t origin = reinterpret_cast<std::intptr_t>(&pixels[0][0]) +
                                     originOffset * static_cast<std::ptrdiff_t>(sizeof(Imf::Rgba));
        file.setFrameBuffer(reinterpret_cast<Imf::Rgba*>(origin), 1, static_cast<std::size_t>(width));
        file.readPixels(window.min.y, window.max.y);

        ImageF image(width, height, 4);
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x) {
                const Imf::Rgba& p = pixels[height - 1 - y][x];
                image.at(x, y, 0) = p.r;
                image.at(x, y, 1) = p.g;
                image.at(x, y, 2) = p.b;
                image.at(x, y, 3) = p.a;
            }
        }
        return image;
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        fail(path, std::string("cannot read EXR: ") + e.what());
    }
}

// A 4-channel image is written as "PF" (RGB): PFM has no alpha, so alpha is dropped.
void writePfm(const std::string& path, const ImageF& image) {
    checkImage(path, image, true);
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

    FilePtr file = openFile(path, "wb");
    const bool written = std::fwrite(bytes.data(), 1, bytes.size(), file.get()) == bytes.size();
    const bool closed = std::fclose(file.release()) == 0;
    if (!written || !closed) fail(path, std::string("cannot write PFM: ") + std::strerror(errno));
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
            fail(path, std::string("PFM header truncated or malformed at ") + what);
        return std::string(reinterpret_cast<const char*>(bytes.data()) + start, pos - start);
    };
    if (bytes.size() < 2 || bytes[0] != 'P' || (bytes[1] != 'F' && bytes[1] != 'f') ||
        (bytes.size() > 2 && !isSpace(bytes[2])))
        fail(path, "not a PFM file (expected \"PF\" or \"Pf\")");
    const int channels = bytes[1] == 'F' ? 3 : 1;
    pos = 2;
    auto parseSide = [&](const std::string& text, const char* what) {
        long long value = 0;
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (ec != std::errc() || end != text.data() + text.size())
            fail(path, std::string("PFM ") + what + " \"" + text + "\" is not a number");
        if (value <= 0 || value > kMaxReadSide)
            fail(path, std::string("PFM ") + what + " " + text + " is out of range (1 to " +
                           std::to_string(kMaxReadSide) + ")");
        return static_cast<int>(value);
    };
    const int width = parseSide(token("width"), "width");
    const int height = parseSide(token("height"), "height");
    const std::string scaleText = token("scale");
    double scale = 0.0;
    const auto [scaleEnd, scaleEc] = std::from_chars(scaleText.data(), scaleText.data() + scaleText.size(), scale);
    if (scaleEc != std::errc() || scaleEnd != scaleText.data() + scaleText.size() || scale == 0.0 ||
        !std::isfinite(scale))
        fail(path, "PFM scale \"" + scaleText + "\" is not a non-zero number");
    ++pos; // the single whitespace byte that token() stopped at

    const std::size_t values = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) *
                               static_cast<std::size_t>(channels);
    if (bytes.size() - pos < values * 4u)
        fail(path, "PFM pixel data truncated (" + std::to_string(bytes.size() - pos) + " of " +
                       std::to_string(values * 4u) + " bytes)");
    ImageF image(width, height, channels);
    const bool littleEndian = scale < 0.0;
    for (std::size_t i = 0; i < values; ++i) image.data[i] = getFloat(bytes.data() + pos + i * 4u, littleEndian);
    return image;
}

} // namespace t10
