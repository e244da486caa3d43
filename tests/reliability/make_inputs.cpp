// make_inputs: writes the EXR files the reliability tests and the EXR fuzz target start from, with
// OpenEXR directly (not t10::writeExr), so they can hold what our writer never produces:
//   z_only.exr        8x8, a single Z channel (no colour, no luminance: must be refused)
//   alpha_only.exr    8x8, only A
//   y_only.exr        8x8, luminance Y only (readable: R = G = B = Y)
//   one_1x1.exr, one_1x50.exr, one_50x1.exr   a side of 1 (refused: sides start at 2)
//   tiled.exr         16x16 in 4x4 tiles, ZIP, data window starting at (3, 5)
//   inf_nan.exr       8x8 RGBA with +inf, -inf and NaN in different channels
//   huge.exr          20000 x 20000, every pixel the same (ZIP): under 1 MB on disk, 3.2 GB of half
//                     RGBA once read (left out with --small)
// usage: make_inputs OUT_DIR [--small]
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wconversion"
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <ImfRgbaFile.h>
#include <ImfStdIO.h>
#include <ImfTiledRgbaFile.h>
#pragma GCC diagnostic pop

#include <cstdint>
#include <exception>
#include <fstream>
#include <stdexcept>
#include <filesystem>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace {

// One float channel named `name`, every value `value`.
void writeSingleChannel(const std::string& path, const char* name, int w, int h, float value) {
    Imf::Header header(w, h);
    header.channels().insert(name, Imf::Channel(Imf::FLOAT));
    std::vector<float> pixels(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), value);
    Imf::FrameBuffer buffer;
    buffer.insert(name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(pixels.data()), sizeof(float),
                                   sizeof(float) * static_cast<std::size_t>(w)));
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(buffer);
    file.writePixels(h);
}

void writeGrey(const std::string& path, int w, int h, float value) {
    std::vector<Imf::Rgba> pixels(static_cast<std::size_t>(w) * static_cast<std::size_t>(h),
                                  Imf::Rgba(value, value, value, 1.0f));
    Imf::RgbaOutputFile file(path.c_str(), w, h, Imf::WRITE_RGBA);
    file.setFrameBuffer(pixels.data(), 1, static_cast<std::size_t>(w));
    file.writePixels(h);
}

void writeTiled(const std::string& path) {
    const Imath::Box2i window(Imath::V2i(3, 5), Imath::V2i(18, 20));
    std::vector<Imf::Rgba> pixels(16 * 16);
    for (int i = 0; i < 256; ++i) pixels[static_cast<std::size_t>(i)] = Imf::Rgba(0.01f * float(i), 0.5f, 2.0f, 1.0f);
    Imf::Header header(window, window);
    header.compression() = Imf::ZIP_COMPRESSION;
    Imf::TiledRgbaOutputFile file(path.c_str(), header, Imf::WRITE_RGBA, 4, 4, Imf::ONE_LEVEL);
    // Addressed by file coordinates: the buffer's origin is pixel (0, 0), outside the vector.
    file.setFrameBuffer(pixels.data() - (3 + 5 * 16), 1, 16);
    file.writeTiles(0, file.numXTiles() - 1, 0, file.numYTiles() - 1);
}

void writeInfNan(const std::string& path) {
    const float inf = std::numeric_limits<float>::infinity();
    std::vector<Imf::Rgba> pixels(64, Imf::Rgba(0.2f, 0.2f, 0.2f, 1.0f));
    pixels[9] = Imf::Rgba(inf, 0.2f, 0.2f, 1.0f);
    pixels[18] = Imf::Rgba(0.2f, -inf, 0.2f, 1.0f);
    pixels[27] = Imf::Rgba(0.2f, 0.2f, std::numeric_limits<float>::quiet_NaN(), 1.0f);
    Imf::RgbaOutputFile file(path.c_str(), 8, 8, Imf::WRITE_RGBA);
    file.setFrameBuffer(pixels.data(), 1, 8);
    file.writePixels(8);
}

// A valid 20000 x 20000 file in milliseconds: OpenEXR writes one ZIP chunk of 16 identical rows,
// then the header's windows are stretched to `side` rows and that chunk is repeated with each
// chunk's first row, behind a table of their offsets. The file is a few hundred kB; reading it
// would take 3.2 GB of half RGBA.
void putLe(std::string& out, std::uint64_t value, int bytes) {
    for (int i = 0; i < bytes; ++i) out += static_cast<char>((value >> (8 * i)) & 0xFFu);
}

std::uint32_t getLe32(const std::string& in, std::size_t pos) {
    std::uint32_t value = 0;
    for (int i = 0; i < 4; ++i) value |= static_cast<std::uint32_t>(static_cast<unsigned char>(in[pos + i])) << (8 * i);
    return value;
}

void writeHuge(const std::string& path, int side) {
    constexpr int kRowsPerChunk = 16; // ZIP_COMPRESSION's block
    const std::vector<Imf::Rgba> row(static_cast<std::size_t>(side), Imf::Rgba(0.5f, 0.25f, 0.125f, 1.0f));
    Imf::StdOSStream stream;
    {
        Imf::Header header(side, kRowsPerChunk);
        header.compression() = Imf::ZIP_COMPRESSION;
        Imf::RgbaOutputFile file(stream, header, Imf::WRITE_RGBA);
        file.setFrameBuffer(row.data(), 1, 0); // a y stride of 0: every row is `row`
        file.writePixels(kRowsPerChunk);
    }
    std::string small = stream.str();
    // Header: magic and version, then attributes (name, type, int32 size, value) up to an empty name.
    std::size_t pos = 8;
    while (small.at(pos) != '\0') {
        const std::string name = small.c_str() + pos;
        pos += name.size() + 1;
        pos += std::string(small.c_str() + pos).size() + 1;
        const std::uint32_t size = getLe32(small, pos);
        pos += 4;
        if (name == "dataWindow" || name == "displayWindow") { // box2i: xMin yMin xMax yMax
            std::string yMax;
            putLe(yMax, static_cast<std::uint64_t>(side - 1), 4);
            small.replace(pos + 12, 4, yMax);
        }
        pos += size;
    }
    const std::string header = small.substr(0, pos + 1);
    const std::size_t chunkStart = header.size() + 8; // one offset in the small file
    const std::string chunkData = small.substr(chunkStart + 8, getLe32(small, chunkStart + 4));
    const int chunks = (side + kRowsPerChunk - 1) / kRowsPerChunk;
    std::string out = header;
    const std::uint64_t chunkBytes = 8 + chunkData.size();
    for (int i = 0; i < chunks; ++i)
        putLe(out, header.size() + 8u * static_cast<std::uint64_t>(chunks) + chunkBytes * static_cast<std::uint64_t>(i), 8);
    for (int i = 0; i < chunks; ++i) {
        putLe(out, static_cast<std::uint64_t>(i * kRowsPerChunk), 4);
        putLe(out, chunkData.size(), 4);
        out += chunkData;
    }
    std::ofstream file(path, std::ios::binary);
    file.write(out.data(), static_cast<std::streamsize>(out.size()));
    if (!file) throw std::runtime_error(path + ": cannot write");
    file.close();
    // Proof that the file is valid: OpenEXR reads its first and last chunks back (rows into `back`).
    std::vector<Imf::Rgba> back(static_cast<std::size_t>(side));
    Imf::RgbaInputFile check(path.c_str());
    check.setFrameBuffer(back.data(), 1, 0);
    check.readPixels(0, kRowsPerChunk - 1);
    check.readPixels(side - kRowsPerChunk, side - 1);
    if (float(back.back().g) != 0.25f) throw std::runtime_error(path + ": reads back wrong");
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2 || argc > 3 || (argc == 3 && std::string(argv[2]) != "--small")) {
        std::cerr << "usage: make_inputs OUT_DIR [--small]\n";
        return 2;
    }
    try {
        const std::string dir = argv[1];
        std::filesystem::create_directories(dir);
        writeSingleChannel(dir + "/z_only.exr", "Z", 8, 8, 3.0f);
        writeSingleChannel(dir + "/alpha_only.exr", "A", 8, 8, 1.0f);
        writeSingleChannel(dir + "/y_only.exr", "Y", 8, 8, 0.5f);
        writeGrey(dir + "/one_1x1.exr", 1, 1, 0.5f);
        writeGrey(dir + "/one_1x50.exr", 1, 50, 0.5f);
        writeGrey(dir + "/one_50x1.exr", 50, 1, 0.5f);
        writeTiled(dir + "/tiled.exr");
        writeInfNan(dir + "/inf_nan.exr");
        if (argc == 2) writeHuge(dir + "/huge.exr", 20000);
        std::cout << "wrote the reliability inputs into " << dir << "\n";
        return 0;
    } catch (const std::exception& error) {
        std::cerr << "make_inputs: error: " << error.what() << "\n";
        return 1;
    }
}
