// Loading the numeric-test dumps and measuring 8-bit differences; see dumps.hpp.
#include "dumps.hpp"

#include "t10/error.hpp"
#include "t10/image_io.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

namespace t10::test {

ImageF Dump::level(int unit, int levelIndex) const {
    const std::string file = path("unit" + std::to_string(unit) + "_level" + std::to_string(levelIndex) + ".pfm");
    if (!std::filesystem::exists(file)) throw Error(file + ": not written by the stage (is the texture bound to unit " + std::to_string(unit) + "?)");
    return readPfm(file);
}

int Dump::levelCount(int unit) const {
    int count = 0;
    while (std::filesystem::exists(path("unit" + std::to_string(unit) + "_level" + std::to_string(count) + ".pfm"))) ++count;
    return count;
}

double Dump::luminanceKey() const {
    const int levels = levelCount(16);
    if (levels == 0) throw Error(dir + ": no luminance texture (unit 16) was written");
    const ImageF last = level(16, levels - 1);
    if (last.width != 1 || last.height != 1) {
        throw Error(dir + ": the last luminance level is " + std::to_string(last.width) + "x" +
                    std::to_string(last.height) + ", not 1x1");
    }
    return last.data[0];
}

Dump loadDump(const std::string& name) {
    const char* root = std::getenv("T10_DUMP_DIR");
    if (root == nullptr || *root == '\0') throw Error("T10_DUMP_DIR is not set: run these tests through ctest");
    Dump dump;
    dump.dir = std::string(root) + "/" + name;
    dump.accumulation = readPfm(dump.path("unit15_level0.pfm"));
    dump.frame = readPng(dump.path("frame.png"));
    return dump;
}

ByteError byteError(const Image8& a, const Image8& b) {
    if (a.width != b.width || a.height != b.height || a.channels != b.channels) {
        throw Error("byteError: images differ in size");
    }
    ByteError error;
    double sum = 0.0;
    std::size_t overOne = 0;
    const std::size_t pixels = static_cast<std::size_t>(a.width) * static_cast<std::size_t>(a.height);
    for (std::size_t p = 0; p < pixels; ++p) {
        int worst = 0;
        for (int c = 0; c < a.channels; ++c) {
            const std::size_t i = p * static_cast<std::size_t>(a.channels) + static_cast<std::size_t>(c);
            const int d = std::abs(int(a.data[i]) - int(b.data[i]));
            worst = std::max(worst, d);
            sum += d;
        }
        error.max = std::max(error.max, worst);
        if (worst > 1) ++overOne;
    }
    error.mean = sum / double(pixels * static_cast<std::size_t>(a.channels));
    error.fractionOverOne = double(overOne) / double(pixels);
    return error;
}

PeakError peakRelativeError(const ImageF& gpu, const ImageF& cpu) {
    if (gpu.width != cpu.width || gpu.height != cpu.height) throw Error("peakRelativeError: images differ in size");
    PeakError error;
    double peak[3] = {0.0, 0.0, 0.0};
    for (int y = 0; y < cpu.height; ++y)
        for (int x = 0; x < cpu.width; ++x)
            for (int c = 0; c < 3; ++c) peak[c] = std::max(peak[c], double(cpu.at(x, y, c)));
    double sum = 0.0;
    for (int y = 0; y < cpu.height; ++y)
        for (int x = 0; x < cpu.width; ++x)
            for (int c = 0; c < 3; ++c) {
                if (peak[c] == 0.0) continue;
                const double e = std::abs(double(gpu.at(x, y, c)) - double(cpu.at(x, y, c))) / peak[c];
                error.worst = std::max(error.worst, e);
                sum += e;
            }
    error.mean = sum / (3.0 * cpu.width * cpu.height);
    return error;
}

} // namespace t10::test
