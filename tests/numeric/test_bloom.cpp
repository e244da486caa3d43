// Part 2 numeric checks: the bloom threshold in level 0, the 2x2 downsample in level 1, the final
// frame with the bloom added before the tone map, a frame with nothing to bloom, and the halo of
// one hot pixel.
#include "t10/dumps.hpp"
#include "reference.hpp"

#include "t10_catch.hpp"

#include <cmath>
#include <iostream>

using t10::test::loadDump;
namespace ref = t10::ref;

namespace {

// GL_R11F_G11F_B10F keeps 6 mantissa bits for red and green and 5 for blue. Whether the driver
// rounds or truncates, a stored value is within one unit in the last place: 2^-6 or 2^-5 relative.
constexpr double kRelativeStep[3] = {1.0 / 64.0, 1.0 / 64.0, 1.0 / 32.0};
// Below 2^-14 the format is denormal with a fixed spacing; nothing in these tests is that small
// except zero, but the bound must not be negative there.
constexpr double kDenormalStep = 1.0 / 16384.0 / 32.0;

struct RelativeError {
    double worst = 0.0; // largest |gpu - cpu| / (cpu * step) over all texels: <= 1 passes
    int misclassified = 0;
};

} // namespace

TEST_CASE("bloom level 0 holds exactly the pixels at or above 2.95 x Yw", "[part2]") {
    const auto dump = loadDump("part2_pot");
    const t10::ImageF gpu = dump.bloom(0);
    const t10::ImageF cpu = ref::bloomThreshold(dump.accumulation);
    REQUIRE(gpu.width == cpu.width);
    REQUIRE(gpu.height == cpu.height);
    RelativeError error;
    int bright = 0;
    for (int y = 0; y < cpu.height; ++y) {
        for (int x = 0; x < cpu.width; ++x) {
            const ref::Rgb c{dump.accumulation.at(x, y, 0), dump.accumulation.at(x, y, 1), dump.accumulation.at(x, y, 2)};
            const double luminance = ref::luminance(c);
            const bool cpuBright = luminance >= ref::kBloomThreshold;
            const bool gpuBright = gpu.at(x, y, 0) + gpu.at(x, y, 1) + gpu.at(x, y, 2) > 0.0f;
            bright += cpuBright;
            if (cpuBright != gpuBright) {
                // Only a pixel whose luminance is within float rounding of the threshold may differ.
                if (std::abs(luminance - ref::kBloomThreshold) > 1e-6) ++error.misclassified;
                continue;
            }
            for (int k = 0; k < 3; ++k) {
                const double bound = cpu.at(x, y, k) * kRelativeStep[k] + kDenormalStep;
                error.worst = std::max(error.worst, std::abs(gpu.at(x, y, k) - cpu.at(x, y, k)) / bound);
            }
        }
    }
    std::cout << "bloom level 0: " << bright << " bright pixels, " << error.misclassified
              << " misclassified, worst error " << error.worst << " of the R11G11B10F bound\n";
    CHECK(bright > 100); // the scene must actually bloom somewhere, or this test proves nothing
    CHECK(error.misclassified == 0);
    CHECK(error.worst <= 1.0);
}

TEST_CASE("bloom level 1 is the 2x2 average of level 0", "[part2]") {
    const auto dump = loadDump("part2_pot");
    const t10::ImageF level0 = dump.bloom(0);
    const t10::ImageF gpu = dump.bloom(1);
    const t10::ImageF cpu = ref::boxDownsample(level0);
    REQUIRE(gpu.width == cpu.width);
    REQUIRE(gpu.height == cpu.height);
    double worst = 0.0;
    for (int y = 0; y < cpu.height; ++y)
        for (int x = 0; x < cpu.width; ++x)
            for (int k = 0; k < 3; ++k) {
                const double bound = cpu.at(x, y, k) * kRelativeStep[k] + kDenormalStep;
                worst = std::max(worst, std::abs(gpu.at(x, y, k) - cpu.at(x, y, k)) / bound);
            }
    std::cout << "bloom level 1 vs 2x2 box of level 0: worst error " << worst << " of the R11G11B10F bound\n";
    // At 256x256 every level-1 texel averages exactly four level-0 texels (read back as stored), so
    // the only error is storing the average: one unit in the last place.
    CHECK(worst <= 1.0);
}

TEST_CASE("the final frame adds 0.98 x bilinear level-1 bloom before the tone map", "[part2]") {
    const auto dump = loadDump("part2_pot");
    const t10::ImageF level1 = dump.bloom(1);
    const t10::Image8 expected = ref::finalFrame(dump.accumulation, ref::keyFromMapped(dump.luminanceKey()), &level1);
    const auto error = t10::test::byteError(expected, dump.frame);
    std::cout << "part2 final frame vs CPU: max " << error.max << " steps, mean " << error.mean
              << ", pixels off by more than one step " << error.fractionOverOne * 100.0 << "%\n";
    // The GPU evaluates the bilinear bloom fetch, the sum and the operator in 32-bit float, the
    // reference in double from the same read-back buffers: the exact values differ by far less than
    // one 8-bit step, so a channel can only land one step away next to a rounding boundary.
    CHECK(error.max <= 1);
    CHECK(error.mean <= 0.01);
}

TEST_CASE("with nothing above the threshold Part 2 renders exactly what Part 1 renders", "[part2]") {
    const auto part1 = loadDump("part1_dim");
    const auto part2 = loadDump("part2_dim");
    const t10::ImageF bloom = part2.bloom(0);
    for (float v : bloom.data) REQUIRE(v == 0.0f);
    const auto error = t10::test::byteError(part1.frame, part2.frame);
    std::cout << "dim input, part1 vs part2: max " << error.max << " steps\n";
    // The bloom term is exactly zero, so the sums are bit-identical.
    CHECK(error.max == 0);
}

TEST_CASE("one hot pixel spreads into a bounded halo centred on it", "[part2]") {
    const auto hot = loadDump("part2_hot");
    // Background: the tone-mapped grey of the pixels far from the block.
    const int background = hot.frame.at(5, 5, 1);
    double sum = 0.0;
    double sumX = 0.0;
    double sumY = 0.0;
    int outside = 0;
    for (int y = 0; y < hot.frame.height; ++y) {
        for (int x = 0; x < hot.frame.width; ++x) {
            const int excess = hot.frame.at(x, y, 1) - background;
            if (excess <= 0) continue;
            // The block covers 64..65; level 1 holds it in texel 32, and bilinear magnification spreads
            // that texel over at most one full-resolution pixel more on each side (63..66).
            if (x < 63 || x > 66 || y < 63 || y > 66) ++outside;
            sum += excess;
            sumX += excess * (x + 0.5);
            sumY += excess * (y + 0.5);
        }
    }
    REQUIRE(sum > 0.0);
    std::cout << "part2 hot pixel: halo centroid (" << sumX / sum << ", " << sumY / sum << "), " << outside
              << " brightened pixels outside 63..66\n";
    CHECK(outside == 0);
    // The block's centre is at 65.0 in pixel coordinates; the halo is symmetric about it.
    CHECK(sumX / sum == Approx(65.0).margin(0.01));
    CHECK(sumY / sum == Approx(65.0).margin(0.01));
}
