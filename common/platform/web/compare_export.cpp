// The golden comparison as C functions for the browser's compare page; see compare_export.hpp.
#include "t10/compare_export.hpp"

#include "t10/compare.hpp"
#include "t10/error.hpp"
#include "t10/file.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <exception>
#include <string>
#include <vector>

#ifdef __EMSCRIPTEN__
#include <emscripten/emscripten.h>
#define T10_EXPORT EMSCRIPTEN_KEEPALIVE
#else
#define T10_EXPORT
#endif

namespace {

constexpr int kSlots = 4;
constexpr int kLargestImage = 8192 * 8192 * 4; // bytes; a canvas larger than this is not compared

std::array<std::vector<std::uint8_t>, kSlots>& buffers() {
    static std::array<std::vector<std::uint8_t>, kSlots> slots;
    return slots;
}

std::string& result() {
    static std::string text;
    return text;
}

// The RGB channels of an RGBA buffer: the golden PNGs are RGB.
t10::Image8 rgbOf(const std::vector<std::uint8_t>& rgba, int width, int height) {
    t10::Image8 image(width, height, 3);
    const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    for (std::size_t p = 0; p < pixels; ++p)
        for (std::size_t c = 0; c < 3; ++c) image.data[p * 3 + c] = rgba[p * 4 + c];
    return image;
}

std::string textOf(const std::vector<std::uint8_t>& bytes) {
    return std::string(bytes.begin(), bytes.end());
}

nlohmann::json compare(int width, int height, const std::string& tolerancePath) {
    auto& slots = buffers();
    const std::size_t bytes = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4;
    if (width <= 0 || height <= 0 || static_cast<double>(width) * height * 4 > kLargestImage) {
        throw t10::Error("t10_compare_rgba: size " + std::to_string(width) + "x" + std::to_string(height) +
                         " is not a canvas size this page compares");
    }
    for (int slot = 0; slot < 2; ++slot) {
        if (slots[slot].size() != bytes) {
            throw t10::Error("t10_compare_rgba: buffer " + std::to_string(slot) + " holds " +
                             std::to_string(slots[slot].size()) + " bytes, not " + std::to_string(bytes));
        }
    }
    const t10::test::Tolerance tolerance = t10::test::readTolerance(tolerancePath);
    const t10::Image8 expected = rgbOf(slots[0], width, height);
    const t10::Image8 actual = rgbOf(slots[1], width, height);
    const t10::test::Comparison comparison = t10::test::compareImages(expected, actual, tolerance);
    if (slots[2].size() >= bytes) {
        const t10::Image8 heat = t10::test::differenceHeatMap(expected, actual);
        for (std::size_t p = 0; p < bytes / 4; ++p) {
            for (std::size_t c = 0; c < 3; ++c) slots[2][p * 4 + c] = heat.data[p * 3 + c];
            slots[2][p * 4 + 3] = 255;
        }
    }
    return {{"passed", comparison.passed},
            {"sizeMatches", comparison.sizeMatches},
            {"failingFraction", comparison.failingFraction},
            {"meanError", comparison.meanError},
            {"maxError", comparison.maxError},
            {"summary", comparison.summary},
            {"tolerance",
             {{"threshold", tolerance.threshold},
              {"maxFraction", tolerance.maxFraction},
              {"maxMean", tolerance.maxMean},
              {"file", textOf(t10::readFile(tolerancePath))}}}};
}

} // namespace

extern "C" {

T10_EXPORT std::uint8_t* t10_compare_buffer(int slot, int bytes) {
    if (slot < 0 || slot >= kSlots || bytes <= 0 || bytes > kLargestImage) return nullptr;
    auto& buffer = buffers()[static_cast<std::size_t>(slot)];
    buffer.assign(static_cast<std::size_t>(bytes), 0);
    return buffer.data();
}

T10_EXPORT const char* t10_compare_rgba(int width, int height, const char* tolerancePath) {
    try {
        result() = compare(width, height, tolerancePath ? tolerancePath : "")
                       .dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    } catch (const std::exception& error) {
        result() = nlohmann::json{{"error", error.what()}}.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    }
    return result().c_str();
}

}
