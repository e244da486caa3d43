// OpenEXR files (image_io.hpp): RGBA half float, the top row first in the file (flipped here, as
// PNG is). The headers are checked by hand before OpenEXR parses them, so that a hostile file is
// refused before a large allocation. The browser build compiles exr_io_web.cpp instead
// (common/CMakeLists.txt): OpenEXR has no WebAssembly build.
#include "t10/image_io.hpp"

#include "t10/file.hpp"
#include "image_file.hpp"

// OpenEXR's and Imath's headers trip -Wshadow and -Wconversion when they are not on a system
// include path (as with plain pkg-config flags); CMake's imported target marks them SYSTEM.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wconversion"
#include <Iex.h>
#include <ImfArray.h>
#include <ImfChannelList.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfRgbaFile.h>
#include <ImfStdIO.h>
#pragma GCC diagnostic pop

#include <cstdint>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

namespace t10 {
namespace {

// An OpenEXR input stream over bytes already in memory (the file, read by readFile, or fuzz data).
class MemoryIStream final : public Imf::IStream {
public:
    MemoryIStream(const std::uint8_t* bytes, std::size_t size, const std::string& name)
        : Imf::IStream(name.c_str()), bytes_(bytes), size_(size) {}
    bool read(char c[], int n) override {
        if (n < 0 || static_cast<std::uint64_t>(n) > size_ - pos_) throw Iex::InputExc("unexpected end of file");
        if (n > 0) std::memcpy(c, bytes_ + pos_, static_cast<std::size_t>(n));
        pos_ += static_cast<std::size_t>(n);
        return pos_ < size_;
    }
    std::uint64_t tellg() override { return pos_; }
    void seekg(std::uint64_t pos) override {
        if (pos > size_) throw Iex::InputExc("seek past the end of file");
        pos_ = static_cast<std::size_t>(pos);
    }

private:
    const std::uint8_t* bytes_;
    std::size_t size_;
    std::size_t pos_ = 0;
};

// What checkHeaders() learns from an EXR's first header.
struct ExrShape {
    long long width = 0;
    long long height = 0;
};

std::uint32_t getU32Le(const std::uint8_t* p) {
    return static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
           static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24;
}

std::int32_t getI32Le(const std::uint8_t* p) {
    const std::uint32_t bits = getU32Le(p);
    std::int32_t value = 0;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}

// The size a fixed-size EXR attribute type must declare, or 0 for the variable-size ones.
std::size_t fixedAttributeSize(const std::string& type) {
    static const std::pair<const char*, std::size_t> kSizes[] = {
        {"box2i", 16}, {"box2f", 16}, {"v2i", 8}, {"v2f", 8}, {"v2d", 16}, {"v3i", 12}, {"v3f", 12},
        {"v3d", 24}, {"int", 4}, {"float", 4}, {"double", 8}, {"compression", 1}, {"lineOrder", 1},
        {"envmap", 1}, {"deepImageState", 1}, {"tiledesc", 9}, {"chromaticities", 32}, {"keycode", 28},
        {"timecode", 8}, {"rational", 8}, {"m33f", 36}, {"m33d", 72}, {"m44f", 64}, {"m44d", 128}};
    for (const auto& [name, size] : kSizes)
        if (type == name) return size;
    return 0;
}

// Whether a variable-size attribute's value fills exactly its declared `size` bytes at `p`, the
// way OpenEXR will parse it (it parses by type, not by the declared size).
bool variableAttributeFits(const std::string& type, const std::uint8_t* p, std::size_t size) {
    if (type == "chlist") { // (name, 0, int32 type, uint8 linear, 3 reserved, int32 xs, int32 ys)..., 0
        std::size_t pos = 0;
        while (pos < size && p[pos] != 0) {
            while (pos < size && p[pos] != 0) ++pos;
            pos += 1 + 16;
        }
        return pos + 1 == size;
    }
    if (type == "preview") { // uint32 width, uint32 height, width x height RGBA bytes
        if (size < 8) return false;
        return static_cast<std::uint64_t>(getU32Le(p)) * getU32Le(p + 4) * 4u == size - 8;
    }
    if (type == "stringvector") { // (int32 length, bytes)...
        std::size_t pos = 0;
        while (pos < size) {
            if (size - pos < 4) return false;
            const std::uint32_t length = getU32Le(p + pos);
            pos += 4;
            if (length > size - pos) return false;
            pos += length;
        }
        return true;
    }
    return true; // string, floatvector and unknown types are read by their declared size
}

// Walks the EXR headers before OpenEXR sees them, because OpenEXR trusts what they declare: it
// allocates an attribute of unknown type by its declared size (2 GB from a 300-byte file, found by
// the fuzz target), parses known types by type whatever size they declare (then reads the rest of
// the header out of step: another 2 GB, also found by the fuzz target), sizes a preview image by its
// declared width and height, and a tile offset table by the declared tile count. Refuses an
// attribute larger than the rest of the file or not of its type's size, more tiles than the file
// has room for offsets, deep data, and a data window beyond `limits`; returns the first header's
// data window size.
ExrShape checkHeaders(const std::uint8_t* bytes, std::size_t size, const std::string& name, const ExrLimits& limits) {
    constexpr std::uint32_t kMagic = 20000630;
    constexpr std::uint32_t kLongNames = 0x400, kDeep = 0x800, kMultiPart = 0x1000;
    if (size < 8 || getU32Le(bytes) != kMagic) image_file::fail(name, "not an OpenEXR file");
    const std::uint32_t flags = getU32Le(bytes + 4);
    if (flags & kDeep) image_file::fail(name, "deep EXR data is not supported");
    const std::size_t maxName = (flags & kLongNames) ? 256 : 32;
    std::size_t pos = 8;
    auto cString = [&](const char* what) {
        const std::size_t start = pos;
        while (pos < size && bytes[pos] != 0 && pos - start < maxName) ++pos;
        if (pos >= size || bytes[pos] != 0) image_file::fail(name, std::string("EXR header truncated or malformed (") + what + ")");
        std::string text(reinterpret_cast<const char*>(bytes) + start, pos++ - start);
        for (char& c : text) c = (c >= 0x20 && c < 0x7F) ? c : '?'; // it may end up in a message
        return text;
    };
    ExrShape shape;
    bool first = true;
    for (;;) { // one header, or several (multi-part) ended by an empty one
        if (pos >= size) image_file::fail(name, "EXR header truncated");
        if (bytes[pos] == 0) { ++pos; break; }
        long long tileW = 0, tileH = 0;
        while (pos < size && bytes[pos] != 0) {
            const std::string attribute = cString("attribute name");
            const std::string type = cString("attribute type");
            if (size - pos < 4) image_file::fail(name, "EXR header truncated (attribute " + attribute + ")");
            const std::int32_t length = getI32Le(bytes + pos);
            pos += 4;
            if (length < 0 || static_cast<std::size_t>(length) > size - pos)
                image_file::fail(name, "EXR attribute " + attribute + " declares " + std::to_string(length) +
                               " bytes, more than the file holds");
            const std::size_t fixed = fixedAttributeSize(type);
            if ((fixed != 0 && static_cast<std::size_t>(length) != fixed) ||
                (fixed == 0 && !variableAttributeFits(type, bytes + pos, static_cast<std::size_t>(length))))
                image_file::fail(name, "EXR attribute " + attribute + " of type " + type + " is malformed (" +
                               std::to_string(length) + " bytes)");
            if (first && attribute == "dataWindow" && type == "box2i" && length == 16) {
                shape.width = static_cast<long long>(getI32Le(bytes + pos + 8)) - getI32Le(bytes + pos) + 1;
                shape.height = static_cast<long long>(getI32Le(bytes + pos + 12)) - getI32Le(bytes + pos + 4) + 1;
            }
            if (attribute == "tiles" && type == "tiledesc" && length >= 8) {
                tileW = getU32Le(bytes + pos);
                tileH = getU32Le(bytes + pos + 4);
            }
            pos += static_cast<std::size_t>(length);
        }
        if (pos >= size) image_file::fail(name, "EXR header truncated");
        ++pos; // the empty name that ends this header
        if (first && (shape.width <= 0 || shape.height <= 0 || shape.width > image_file::kMaxReadSide || shape.height > image_file::kMaxReadSide))
            image_file::fail(name, "unsupported EXR data window " + std::to_string(shape.width) + "x" + std::to_string(shape.height));
        if (first && (shape.width > limits.maxSide || shape.height > limits.maxSide))
            image_file::fail(name, "the image is " + std::to_string(shape.width) + "x" + std::to_string(shape.height) +
                           ", larger than " + std::to_string(limits.maxSide) + " on a side (" + limits.maxSideReason + ")");
        if (first && static_cast<std::uint64_t>(shape.width) * static_cast<std::uint64_t>(shape.height) > limits.maxPixels)
            image_file::fail(name, "the image is " + std::to_string(shape.width) + "x" + std::to_string(shape.height) +
                           ", more than " + std::to_string(limits.maxPixels) + " pixels (" + limits.maxPixelsReason + ")");
        // OpenEXR allocates a buffer of one tile: a tile larger than the image it tiles is refused
        // (a 65536 x 65536 tile over a small image took 15 s of memset under ASan, found by the fuzz
        // target).
        if (first && (tileW > shape.width || tileH > shape.height) && (tileW > 64 || tileH > 64))
            image_file::fail(name, "EXR tile size " + std::to_string(tileW) + "x" + std::to_string(tileH) +
                           " is larger than the image");
        // Every tile of the first level has an 8-byte offset in the file: more tiles than that is a lie.
        if (tileW > 0 && tileH > 0 && first) {
            const std::uint64_t tiles = static_cast<std::uint64_t>((shape.width + tileW - 1) / tileW) *
                                        static_cast<std::uint64_t>((shape.height + tileH - 1) / tileH);
            if (tiles > size / 8) image_file::fail(name, "EXR declares " + std::to_string(tiles) + " tiles, more than the file holds");
        }
        first = false;
        if (!(flags & kMultiPart)) break;
    }
    if (shape.width <= 0) image_file::fail(name, "EXR header has no data window");
    return shape;
}

std::string channelNames(const Imf::Header& header) {
    std::string names;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it)
        names += (names.empty() ? "" : ", ") + std::string(it.name());
    return names.empty() ? "none" : names;
}

} // namespace

void writeExr(const std::string& path, const ImageF& image) {
    image_file::checkImage(path, image, true);
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
    // Encoded in memory, then written all or nothing (OpenEXR's file writer leaves a partial file).
    std::string encoded;
    try {
        Imf::StdOSStream stream;
        {
            Imf::RgbaOutputFile file(stream, Imf::Header(w, h), Imf::WRITE_RGBA);
            file.setFrameBuffer(&pixels[0][0], 1, static_cast<std::size_t>(w));
            file.writePixels(h);
        } // the destructor writes the line offset table
        encoded = stream.str();
    } catch (const std::exception& e) {
        image_file::fail(path, std::string("cannot encode EXR: ") + e.what());
    }
    writeFileAtomically(path, encoded.data(), encoded.size(), "EXR");
}

ImageF readExr(const std::string& path, const ExrLimits& limits) {
    const std::vector<std::uint8_t> bytes = readFile(path);
    return decodeExr(bytes.data(), bytes.size(), path, limits);
}

ImageF decodeExr(const std::uint8_t* bytes, std::size_t size, const std::string& name, const ExrLimits& limits) {
    if (bytes == nullptr) size = 0;
    try {
        // OpenEXR allocates its chunk offset table from the header before we see the size: its own
        // limit (process-wide, the same for every call) keeps that table small for a hostile header.
        Imf::Header::setMaxImageSize(static_cast<int>(image_file::kMaxReadSide), static_cast<int>(image_file::kMaxReadSide));
        Imf::Header::setMaxTileSize(static_cast<int>(image_file::kMaxReadSide), static_cast<int>(image_file::kMaxReadSide));
        // Every check comes before OpenEXR allocates anything, and before the pixels are allocated.
        const ExrShape shape = checkHeaders(bytes, size, name, limits);
        MemoryIStream stream(bytes, size, name);
        Imf::RgbaInputFile file(stream, 1);
        const Imath::Box2i window = file.dataWindow();
        const long long w = static_cast<long long>(window.max.x) - window.min.x + 1;
        const long long h = static_cast<long long>(window.max.y) - window.min.y + 1;
        if (w != shape.width || h != shape.height)
            image_file::fail(name, "EXR data window " + std::to_string(w) + "x" + std::to_string(h) + " is not the header's");
        // A file with only depth, alpha or layered channels would render black without a word.
        if ((file.channels() & (Imf::WRITE_RGB | Imf::WRITE_Y)) == 0)
            image_file::fail(name, "the EXR has no colour (R, G, B) or luminance (Y) channel (its channels: " +
                           channelNames(file.header()) + ")");
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
        image_file::fail(name, std::string("cannot read EXR: ") + e.what());
    }
}

} // namespace t10
