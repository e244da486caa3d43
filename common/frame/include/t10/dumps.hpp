// Access to the buffers a stage wrote with --dump/--output, for the numeric tests (the ctest fixtures
// render them first; T10_DUMP_DIR points at their folder) and for the grader, which reads each
// submission's dumps the same way.
#pragma once
#include "t10/contract.hpp"
#include "t10/image.hpp"

#include <string>

namespace t10::test {

struct Dump {
    std::string dir;
    ImageF accumulation;   // the accumulation unit (15), level 0 (RGB)
    Image8 frame;          // the final frame (--output)
    std::string path(const std::string& file) const { return dir + "/" + file; }
    // Level `level` of the texture that was on `unit`; throws t10::Error if the stage did not write it.
    ImageF level(int unit, int level) const;
    // Number of levels written for `unit`.
    int levelCount(int unit) const;
    // The bloom texture's level (unit 17) and the luminance texture's level count (unit 16).
    ImageF bloom(int level) const { return this->level(contract::kBloomUnit, level); }
    int luminanceLevels() const { return levelCount(contract::kLuminanceKeyUnit); }
    // The value in the last (1x1) level of the luminance texture on unit 16: the range-mapped scene
    // key (GL_R16) or the log key itself (GL_R16F). Throws t10::Error if that level is not 1x1.
    double luminanceKey() const;
};

// Loads T10_DUMP_DIR/<name>; throws t10::Error naming what is missing.
Dump loadDump(const std::string& name);

// Max and mean absolute difference between two 8-bit RGB images of the same size, in 8-bit steps
// (t10/compare.hpp's imageDifference, the golden tests' metric); throws t10::Error if the sizes differ.
struct ByteError {
    int max = 0;
    double mean = 0.0;
    double fractionOverOne = 0.0; // pixels with some channel off by more than one step
};
ByteError byteError(const Image8& a, const Image8& b);

// Difference of two float RGB levels (GPU against CPU), relative to the CPU level's largest value
// in each channel; throws t10::Error if the sizes differ.
struct LevelError {
    double worstRelativeToPeak = 0.0; // largest |gpu - cpu| / (largest cpu value of the channel)
    double meanRelativeToPeak = 0.0;
};
LevelError compareLevels(const ImageF& gpu, const ImageF& cpu);

} // namespace t10::test
