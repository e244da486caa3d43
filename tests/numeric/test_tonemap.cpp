// Part 1 numeric checks: the scene key in the smallest luminance mip against a CPU log-average of
// the read-back accumulation buffer, and every pixel of the final frame against the CPU operator.
// The key's bounds are relative errors of Ya, the exposure a user sees, not of the range-mapped
// value: one R16 step of the mapped range is a factor exp(16.9 / 65535) in Ya, and 2 % of the
// range would be a factor 1.4.
#include "t10/dumps.hpp"
#include "reference.hpp"

#include "t10_catch.hpp"

#include <cmath>
#include <iostream>

using t10::test::loadDump;
namespace ref = t10::ref;

namespace {

// ln(Yw) - ln(eps): a range-mapped difference d is a factor exp(d * kRange) in Ya.
const double kRange = std::log(ref::kYwhite) - std::log(ref::kEpsilon);

double relativeKeyError(double gpuMapped, double cpuMapped) {
    return std::abs(ref::keyFromMapped(gpuMapped) / ref::keyFromMapped(cpuMapped) - 1.0);
}

void reportKey(const char* label, double gpuMapped, double cpuMapped) {
    const double gpuKey = ref::keyFromMapped(gpuMapped);
    const double cpuKey = ref::keyFromMapped(cpuMapped);
    std::cout << label << ": mapped key GPU " << gpuMapped << " CPU " << cpuMapped << " (difference "
              << std::abs(gpuMapped - cpuMapped) * 65535.0 << " R16 steps); Ya GPU " << gpuKey << " CPU " << cpuKey
              << " (relative error " << std::abs(gpuKey - cpuKey) / cpuKey << ")\n";
}

// Measured (see the test case that uses it), plus a margin.
constexpr double kMesaNpotKeyError = 0.055;

} // namespace

TEST_CASE("the luminance chain ends in one texel: floor(log2(max)) + 1 levels", "[part1]") {
    for (const char* name : {"part1_pot", "part1_npot"}) {
        const auto dump = loadDump(name);
        const int size = std::max(dump.accumulation.width, dump.accumulation.height);
        CHECK(dump.luminanceLevels() == int(std::floor(std::log2(size))) + 1);
    }
}

TEST_CASE("scene key at a power-of-two size equals the CPU log-average", "[part1]") {
    const auto dump = loadDump("part1_pot");
    const double gpu = dump.luminanceKey();
    const double cpu = ref::meanMappedLogLuminance(dump.accumulation, true);
    reportKey("256x256", gpu, cpu);
    // At a power-of-two size every 2x2 average is exact, but each of the levels below level 0 stores
    // its average in GL_R16 again, rounding by up to half a step: half a step per level (8 levels:
    // 0.1 % of Ya at most).
    const int roundings = dump.luminanceLevels() - 1;
    const double relative = relativeKeyError(gpu, cpu);
    const double bound = std::exp(kRange * (0.5 * roundings + 0.01) / 65535.0) - 1.0;
    CHECK(relative <= bound);
}

TEST_CASE("scene key at a non-power-of-two size: the error Mesa's mip chain gives", "[part1]") {
    const auto dump = loadDump("part1_npot");
    const double gpu = dump.luminanceKey();
    const double cpu = ref::meanMappedLogLuminance(dump.accumulation, true);
    reportKey("320x180", gpu, cpu);
    // At odd sizes (180: 45 -> 22, 11 -> 5, 5 -> 2) glGenerateMipmap's filter is implementation-
    // defined. Mesa (llvmpipe, what CI runs) blits each level with a bilinear sample at the centre
    // of each destination texel; for an odd source the samples no longer fall between texel pairs,
    // so some rows get more weight than others (3 -> 1 reads only the middle one). That is not the
    // image's mean: measured at 320x180 with the default camera, Ya comes out 4.4 % above the exact
    // log-average (`make bench` measures every size; the site's notes page, #npot-key, has the
    // table: far worse at 1920x1080). The bound is that error plus a margin of about a quarter of
    // it, for another Mesa version; a GPU may filter differently (extras' --key exact is the fix).
    // A range mapping with another white point (the mutant "range_white_point_0_30_npot", about
    // 20 % off) or a wrong formula exceeds it.
    const double relative = relativeKeyError(gpu, cpu);
    const double bound = kMesaNpotKeyError;
    CHECK(relative <= bound);
}

TEST_CASE("every pixel of the final frame matches the CPU tone map", "[part1]") {
    for (const char* name : {"part1_pot", "part1_npot"}) {
        const auto dump = loadDump(name);
        const double key = ref::keyFromMapped(dump.luminanceKey());
        const t10::Image8 expected = ref::finalFrame(dump.accumulation, key);
        const auto error = t10::test::byteError(expected, dump.frame);
        std::cout << name << " final frame vs CPU tone map: max " << error.max << " steps, mean " << error.mean
                  << ", pixels off by more than one step " << error.fractionOverOne * 100.0 << "%\n";
        // The GPU evaluates the operator in 32-bit float, the reference in double: the results differ
        // by far less than one 8-bit step, so a channel can only land one step away when its exact
        // value is near a rounding boundary. Hence at most 1 step anywhere, and rarely.
        CHECK(error.max <= 1);
        CHECK(error.mean <= 0.01);
    }
}
