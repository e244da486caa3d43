// The variants of the CPU reference that t10-grade's mistake models are (common/reference's
// MappedLog, Unmap, FrameVariant), each against the formula written out here on small images: the
// grader names a mistake only when its variant explains a buffer, so a variant that computes
// something else would name the wrong mistake.
#include "reference.hpp"

#include "t10_catch.hpp"

#include <cmath>
#include <limits>
#include <vector>

namespace {

namespace ref = t10::ref;

// Relative bound for doubles computed by the same formula in another order (a few ulps).
constexpr double kUlps = 1e-12;

// A 4x2 accumulation whose colour grows along x (and differs per channel), and a 2x1 bloom level.
t10::ImageF accumulation() {
    t10::ImageF image(4, 2, 3);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x)
            for (int k = 0; k < 3; ++k) image.at(x, y, k) = static_cast<float>(0.05 * (x + 1) * (k + 1) + 0.01 * y);
    return image;
}

t10::ImageF bloomLevel() {
    t10::ImageF image(2, 1, 3);
    for (int x = 0; x < 2; ++x)
        for (int k = 0; k < 3; ++k) image.at(x, 0, k) = static_cast<float>(0.5 + x + 0.25 * k);
    return image;
}

ref::Rgb at(const t10::ImageF& image, int x, int y) { return {image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2)}; }

// Pixel (x, y) of a frame the variant computed, in the row-by-row order frameColours gives.
ref::Rgb pixel(const std::vector<ref::Rgb>& colours, const t10::ImageF& image, int x, int y) {
    return colours[static_cast<std::size_t>(y * image.width + x)];
}

void checkNear(const ref::Rgb& got, const ref::Rgb& want) {
    for (int k = 0; k < 3; ++k) CHECK(got[k] == Approx(want[k]).epsilon(kUlps).margin(1e-15));
}

// The tutorial's final pass at one pixel, written out: bloom level 1 read at the pixel's centre,
// weighted and added, then the tone map with the key Ya.
ref::Rgb tutorialPixel(const t10::ImageF& acc, const t10::ImageF* bloom, int x, int y, double key, const ref::Settings& s) {
    ref::Rgb c = at(acc, x, y);
    if (bloom != nullptr) {
        const ref::Rgb b = ref::sampleBilinear(*bloom, (x + 0.5) / acc.width, (y + 0.5) / acc.height);
        for (int k = 0; k < 3; ++k) c[k] += s.bloomWeight * b[k];
    }
    const double lum = s.lumaWeights[0] * c[0] + s.lumaWeights[1] * c[1] + s.lumaWeights[2] * c[2];
    const double relative = (s.middleGrey - 2.0 / (2.0 + std::log10(key + 1.0))) * lum / key;
    const double mapped = relative * (1.0 + relative / (s.whitePoint * s.whitePoint)) / (1.0 + relative);
    return {c[0] * mapped / lum, c[1] * mapped / lum, c[2] * mapped / lum};
}

} // namespace

TEST_CASE("the mapping with log2 of the luminance is log2 against the natural-log bounds", "[reference]") {
    const ref::Settings s;
    for (double y : {1e-4, 0.05, 0.7, 3.0}) {
        const double natural = (std::log(y + s.epsilon) - std::log(s.epsilon)) / (std::log(s.whitePoint) - std::log(s.epsilon));
        const double log2 = (std::log2(y + s.epsilon) - std::log(s.epsilon)) / (std::log(s.whitePoint) - std::log(s.epsilon));
        CHECK(ref::rangeMappedLogLuminance(y, s, ref::MappedLog::Natural) == Approx(natural).epsilon(kUlps));
        CHECK(ref::rangeMappedLogLuminance(y, s, ref::MappedLog::Log2Luminance) == Approx(log2).epsilon(kUlps));
    }
}

TEST_CASE("each way of un-mapping the key gives the Ya its formula gives", "[reference]") {
    ref::Settings s;
    s.whitePoint = 0.5; // not the default, so a variant that ignores the settings fails
    const double e = s.epsilon;
    for (double y : {0.001, 0.04, 0.4}) {
        const double mapped = ref::rangeMappedLogLuminance(y, s);
        // The tutorial's inverse gives the luminance back.
        CHECK(ref::keyFromMapped(mapped, s, ref::Unmap::Correct) == Approx(y + e).epsilon(1e-9));
        CHECK(ref::keyFromMapped(mapped, s, ref::Unmap::None) == Approx(std::exp(mapped)).epsilon(kUlps));
        // Mapped with log2, un-mapped with exp: exp(log2(Y + eps)). Mapped with ln, un-mapped with exp2.
        const double mappedLog2 = (std::log2(y + e) - std::log2(e)) / (std::log2(s.whitePoint) - std::log2(e));
        CHECK(ref::keyFromMapped(mappedLog2, s, ref::Unmap::Log2ThenExp) == Approx(std::exp(std::log2(y + e))).epsilon(1e-9));
        CHECK(ref::keyFromMapped(mapped, s, ref::Unmap::LnThenExp2) == Approx(std::exp2(std::log(y + e))).epsilon(1e-9));
    }
}

TEST_CASE("the default frame variant is the tutorial's final pass, and finalFrame's", "[reference]") {
    const t10::ImageF acc = accumulation();
    const t10::ImageF bloom = bloomLevel();
    const double mappedKey = 0.62;
    ref::FrameVariant variant;
    variant.settings.bloomWeight = 0.3;
    const double key = ref::keyFromMapped(mappedKey, variant.settings);
    const ref::FrameInputs inputs(acc, mappedKey, &bloom);
    const std::vector<ref::Rgb> colours = ref::frameColours(inputs, variant);
    REQUIRE(colours.size() == 8u);
    for (int y = 0; y < acc.height; ++y)
        for (int x = 0; x < acc.width; ++x) checkNear(pixel(colours, acc, x, y), tutorialPixel(acc, &bloom, x, y, key, variant.settings));
    const t10::Image8 frame = ref::finalFrame(inputs, variant);
    const t10::Image8 plain = ref::finalFrame(acc, key, &bloom, variant.settings);
    CHECK(frame.data == plain.data);
    CHECK(frame.at(3, 1, 2) == ref::toUnorm8(tutorialPixel(acc, &bloom, 3, 1, key, variant.settings)[2]));
}

TEST_CASE("the frame variants change only what their mistake changes", "[reference]") {
    const t10::ImageF acc = accumulation();
    const t10::ImageF bloom = bloomLevel();
    const double mappedKey = 0.62;
    const ref::FrameInputs inputs(acc, mappedKey, &bloom);
    const ref::Settings s;
    const double key = ref::keyFromMapped(mappedKey, s);
    const auto run = [&](auto&& change) {
        ref::FrameVariant v;
        change(v);
        return ref::frameColours(inputs, v);
    };
    const ref::Rgb b = ref::sampleBilinear(bloom, 2.5 / 4.0, 1.5 / 2.0);
    SECTION("no tone map: the accumulation plus the weighted bloom") {
        const auto c = run([](ref::FrameVariant& v) { v.toneMap = false; });
        const ref::Rgb a = at(acc, 2, 1);
        checkNear(pixel(c, acc, 2, 1), {a[0] + s.bloomWeight * b[0], a[1] + s.bloomWeight * b[1], a[2] + s.bloomWeight * b[2]});
    }
    SECTION("no bloom: the tone map of the accumulation alone") {
        const auto c = run([](ref::FrameVariant& v) { v.addBloom = false; });
        checkNear(pixel(c, acc, 2, 1), tutorialPixel(acc, nullptr, 2, 1, key, s));
    }
    SECTION("bloom after the tone map: added to the mapped colour") {
        const auto c = run([](ref::FrameVariant& v) { v.bloomAfterToneMap = true; });
        const ref::Rgb m = tutorialPixel(acc, nullptr, 2, 1, key, s);
        checkNear(pixel(c, acc, 2, 1), {m[0] + s.bloomWeight * b[0], m[1] + s.bloomWeight * b[1], m[2] + s.bloomWeight * b[2]});
    }
    SECTION("the viewport left at half size: the lower-left quarter drawn, the rest black") {
        const auto c = run([](ref::FrameVariant& v) { v.lowerLeftQuarter = true; });
        checkNear(pixel(c, acc, 1, 0), tutorialPixel(acc, &bloom, 1, 0, key, s));
        checkNear(pixel(c, acc, 2, 0), {0.0, 0.0, 0.0});
        checkNear(pixel(c, acc, 0, 1), {0.0, 0.0, 0.0});
    }
    SECTION("twice the texture coordinate: pixel x reads between texels 2x and 2x + 1, then the edge") {
        const auto c = run([](ref::FrameVariant& v) {
            v.doubledUv = true;
            v.toneMap = false;
            v.addBloom = false;
        });
        // Pixel 0's centre u = 0.125 doubled is 0.25, half-way between texels 0 and 1 (centres 0.125,
        // 0.375); row 0's v = 0.25 doubled is 0.5, half-way between the rows.
        for (int k = 0; k < 3; ++k) {
            const double rows = 0.5 * (acc.at(0, 0, k) + acc.at(0, 1, k)) + 0.5 * (acc.at(1, 0, k) + acc.at(1, 1, k));
            CHECK(pixel(c, acc, 0, 0)[k] == Approx(0.5 * rows).epsilon(1e-6));
            CHECK(pixel(c, acc, 3, 1)[k] == Approx(acc.at(3, 1, k)).epsilon(1e-6)); // clamped to the corner
        }
    }
    SECTION("the key read per pixel from a luminance level, un-mapped the variant's way") {
        t10::ImageF level(4, 2, 1);
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 4; ++x) level.at(x, y, 0) = 0.3f;
        const std::vector<t10::ImageF> levels{level};
        const ref::FrameInputs withLevels(acc, mappedKey, &bloom, &levels);
        ref::FrameVariant v;
        v.keyLevel = 0;
        v.unmap = ref::Unmap::None;
        const auto c = ref::frameColours(withLevels, v);
        checkNear(pixel(c, acc, 2, 1), tutorialPixel(acc, &bloom, 2, 1, std::exp(double(0.3f)), s));
    }
    SECTION("a constant of the settings: another white point") {
        const auto c = run([](ref::FrameVariant& v) { v.settings.whitePoint = 0.5; });
        ref::Settings other;
        other.whitePoint = 0.5;
        checkNear(pixel(c, acc, 2, 1), tutorialPixel(acc, &bloom, 2, 1, ref::keyFromMapped(mappedKey, other), other));
    }
}

TEST_CASE("the tone map keeps black and a NaN luminance black", "[reference]") {
    const double nan = std::nan("");
    for (const ref::Rgb& c : {ref::Rgb{0.0, 0.0, 0.0}, ref::Rgb{nan, 0.1, 0.1}}) {
        const ref::Rgb m = ref::toneMap(c, 0.18);
        CHECK(m[0] == 0.0);
        CHECK(m[1] == 0.0);
        CHECK(m[2] == 0.0);
    }
}

TEST_CASE("the 8-bit frame store is GL's below llvmpipe's integer overflow, and 0 from it on", "[reference]") {
    for (const double v : {-3.0, 0.0, 0.2, 0.5, 1.0, 7.0, 1e6, ref::kUnorm8Overflow * 0.999999})
        CHECK(ref::storeUnorm8(v) == ref::toUnorm8(v));
    CHECK(ref::storeUnorm8(1e6) == 255);
    // 2^31 / 255 and past it, and NaN: what llvmpipe writes (a Part 1 with white point 0.03, issue 38).
    for (const double v : {ref::kUnorm8Overflow, 1e7, 1e30, std::numeric_limits<double>::infinity(), std::nan("")})
        CHECK(ref::storeUnorm8(v) == 0);
    // The unrounded level the fits compare: the same rule.
    CHECK(ref::unorm8Level(0.5) == 127.5);
    CHECK(ref::unorm8Level(ref::kUnorm8Overflow) == 0.0);
    // WebGL 2 (the page's check) clamps first: 255 from there on, NaN still 0.
    for (const double v : {ref::kUnorm8Overflow, 1e30, std::numeric_limits<double>::infinity()})
        CHECK(ref::storeUnorm8(v, ref::Unorm8Store::Clamped) == 255);
    CHECK(ref::storeUnorm8(std::nan(""), ref::Unorm8Store::Clamped) == 0);
    CHECK(ref::unorm8Level(0.5, ref::Unorm8Store::Clamped) == 127.5);
    // finalFrame stores that way: a tiny key takes a bright channel past it.
    t10::ImageF acc(1, 1, 3);
    acc.at(0, 0, 0) = 8.6f;
    acc.at(0, 0, 1) = 6.4f;
    acc.at(0, 0, 2) = 14.0f; // 9.2e6 once mapped; red's 8.6 maps to 5.7e6
    const t10::Image8 frame = ref::finalFrame(acc, 9.4e-7);
    CHECK(int(frame.at(0, 0, 0)) == 255);
    CHECK(int(frame.at(0, 0, 2)) == 0);
}
