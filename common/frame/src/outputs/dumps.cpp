// Loading the numeric-test dumps and measuring 8-bit differences; see dumps.hpp.
#include "t10/dumps.hpp"

#include "t10/compare.hpp"

#include "t10/error.hpp"
#include "t10/image_io.hpp"
#include "t10/outputs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

namespace t10::test {

ImageF Dump::level(int unit, int levelIndex) const {
    const std::string file = path(dumpFileName(static_cast<unsigned>(unit), levelIndex));
    if (!std::filesystem::exists(file)) throw Error(file + ": not written by the stage (is the texture bound to unit " + std::to_string(unit) + "?)");
    return readPfm(file);
}

int Dump::levelCount(int unit) const {
    int count = 0;
    while (std::filesystem::exists(path(dumpFileName(static_cast<unsigned>(unit), count)))) ++count;
    return count;
}

double Dump::luminanceKey() const {
    const int levels = luminanceLevels();
    if (levels == 0) throw Error(dir + ": no luminance texture (unit 16) was written");
    const ImageF last = level(contract::kLuminanceKeyUnit, levels - 1);
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
    dump.accumulation = readPfm(dump.path(dumpFileName(contract::kAccumulationUnit, 0)));
    dump.frame = readPng(dump.path("frame.png"));
    return dump;
}

ByteError byteError(const Image8& a, const Image8& b) {
    if (a.width != b.width || a.height != b.height || a.channels != b.channels) {
        throw Error("byteError: images differ in size");
    }
    const ImageDifference difference = imageDifference(a, b, 1);
    ByteError error;
    error.max = difference.maxError;
    error.mean = difference.meanError;
    error.fractionOverOne = difference.fractionOverThreshold;
    return error;
}

LevelError compareLevels(const ImageF& gpu, const ImageF& cpu) {
    if (gpu.width != cpu.width || gpu.height != cpu.height || gpu.channels < 3 || cpu.channels < 3) {
        throw Error("compareLevels: levels differ in size");
    }
    LevelError error;
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
                error.worstRelativeToPeak = std::max(error.worstRelativeToPeak, e);
                sum += e;
            }
    error.meanRelativeToPeak = sum / (3.0 * cpu.width * cpu.height);
    return error;
}

} // namespace t10::test
