// libFuzzer target: the EXR input path of --input (decodeExr with limits, then clampNonFinite) on
// arbitrary bytes. What comes out must be RGBA within the limits and free of NaN and infinity;
// every failure must be a t10::Error naming the input (anything else escapes and is a finding).
#include "t10/error.hpp"
#include "t10/image_io.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

namespace {

// Small limits keep each run fast and make the size checks reachable: 256 on a side, 64 Kpixel.
constexpr int kFuzzMaxSide = 256;
constexpr std::uint64_t kFuzzMaxPixels = 1u << 16;

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    t10::ExrLimits limits;
    limits.maxSide = kFuzzMaxSide;
    limits.maxSideReason = "fuzz limit";
    limits.maxPixels = kFuzzMaxPixels;
    limits.maxPixelsReason = "fuzz limit";
    try {
        t10::ImageF image = t10::decodeExr(data, size, "fuzz.exr", limits);
        t10::clampNonFinite(image, t10::kHalfMax);
        if (image.channels != 4 || image.width < 1 || image.height < 1 || image.width > kFuzzMaxSide ||
            image.height > kFuzzMaxSide ||
            image.data.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4u)
            __builtin_trap();
        for (const float value : image.data)
            if (!std::isfinite(value) || std::abs(value) > t10::kHalfMax) __builtin_trap();
    } catch (const t10::Error& error) {
        if (std::string(error.what()).rfind("fuzz.exr: ", 0) != 0) __builtin_trap();
    }
    return 0;
}
