// Implementation of the CPU reference; see reference.hpp. Everything is double precision and
// follows the tutorial's formulas directly, not the shaders' code.
#include "reference.hpp"

#include <algorithm>
#include <cmath>

namespace t10::ref {

double luminance(const Rgb& c) {
    return contract::kLumaRed * c[0] + contract::kLumaGreen * c[1] + contract::kLumaBlue * c[2];
}

double luminance(const Rgb& c, const Settings& settings) { return luminance(c, settings.lumaWeights); }

double luminance(const Rgb& c, const Rgb& w) { return w[0] * c[0] + w[1] * c[1] + w[2] * c[2]; }

double rangeMappedLogLuminance(double y, const Settings& settings) {
    const double e = settings.epsilon;
    return (std::log(y + e) - std::log(e)) / (std::log(settings.whitePoint) - std::log(e));
}

double keyFromMapped(double mapped, const Settings& settings) {
    const double e = settings.epsilon;
    return std::exp(mapped * (std::log(settings.whitePoint) - std::log(e)) + std::log(e));
}

double toUnorm16(double v) { return std::round(std::clamp(v, 0.0, 1.0) * 65535.0) / 65535.0; }

double meanMappedLogLuminance(const ImageF& accumulation, bool asR16, const Settings& settings) {
    double sum = 0.0;
    for (int y = 0; y < accumulation.height; ++y) {
        for (int x = 0; x < accumulation.width; ++x) {
            const Rgb c{accumulation.at(x, y, 0), accumulation.at(x, y, 1), accumulation.at(x, y, 2)};
            const double mapped = rangeMappedLogLuminance(luminance(c, settings), settings);
            sum += asR16 ? toUnorm16(mapped) : mapped;
        }
    }
    return sum / (double(accumulation.width) * double(accumulation.height));
}

double meanLogLuminance(const ImageF& accumulation) {
    double sum = 0.0;
    for (int y = 0; y < accumulation.height; ++y) {
        for (int x = 0; x < accumulation.width; ++x) {
            const Rgb c{accumulation.at(x, y, 0), accumulation.at(x, y, 1), accumulation.at(x, y, 2)};
            sum += std::log(luminance(c) + kEpsilon);
        }
    }
    return sum / (double(accumulation.width) * accumulation.height);
}

double middleGrey(double sceneKey, const Settings& settings) {
    return settings.middleGrey - 2.0 / (2.0 + std::log10(sceneKey + 1.0));
}

namespace {

// The tone map with dg already computed: a frame's pixels share one key, and log10 per pixel was the
// largest part of the grader's frame fits. The same operations in the same order as without it.
double toneMapLuminance(double y, double sceneKey, double grey, const Settings& settings) {
    if (!(y > 0.0)) return 0.0;
    const double relative = grey * y / sceneKey;
    const double yw = settings.whitePoint;
    return relative * (1.0 + relative / (yw * yw)) / (1.0 + relative);
}

Rgb toneMap(const Rgb& colour, double sceneKey, double grey, const Settings& settings) {
    const double y = luminance(colour, settings);
    if (!(y > 0.0)) return {0.0, 0.0, 0.0};
    const double mapped = toneMapLuminance(y, sceneKey, grey, settings);
    return {colour[0] * mapped / y, colour[1] * mapped / y, colour[2] * mapped / y};
}

} // namespace

double toneMapLuminance(double y, double sceneKey, const Settings& settings) {
    return toneMapLuminance(y, sceneKey, middleGrey(sceneKey, settings), settings);
}

Rgb toneMap(const Rgb& colour, double sceneKey, const Settings& settings) {
    return toneMap(colour, sceneKey, middleGrey(sceneKey, settings), settings);
}

std::uint8_t toUnorm8(double v) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
}

double unorm8Level(double v, Unorm8Store store) {
    // Measured on Mesa 22.3: a Part 1 whose key is 1e-6 writes 0 for all 1186 channels at or
    // past 2^31 / 255 of its extremes case and 255 for the 8030 between 1 and that. Debian 13's Mesa
    // stores the same (the fitted batch's white point 0.03 is named there).
    if (std::isnan(v) || (store == Unorm8Store::Llvmpipe && v >= kUnorm8Overflow)) return 0.0;
    return std::clamp(v, 0.0, 1.0) * 255.0;
}

std::uint8_t storeUnorm8(double v, Unorm8Store store) {
    return static_cast<std::uint8_t>(std::lround(unorm8Level(v, store)));
}

double storeUnsignedFloat(double v, int mantissaBits, FloatStore mode) {
    if (mode == FloatStore::Exact) return v;
    if (!(v > 0.0)) return 0.0; // negative values and NaN have no unsigned-float encoding
    if (mode == FloatStore::HalfThenTruncate) {
        constexpr int kHalfMantissa = 10; // a half float's exponent range is the target's: one rule serves both
        return storeUnsignedFloat(storeUnsignedFloat(v, kHalfMantissa, FloatStore::RoundToNearest), mantissaBits,
                                  FloatStore::Truncate);
    }
    constexpr int kMinExponent = -14; // exponent bias 15: below 2^-14 the format is denormal
    const double largest = (2.0 - std::ldexp(1.0, -mantissaBits)) * std::ldexp(1.0, 15);
    if (v >= largest) return largest;
    const int exponent = std::max(static_cast<int>(std::floor(std::log2(v))), kMinExponent);
    const double step = std::ldexp(1.0, exponent - mantissaBits);
    const double steps = v / step;
    return (mode == FloatStore::Truncate ? std::floor(steps) : std::nearbyint(steps)) * step;
}

void storeR11G11B10F(ImageF& image, FloatStore mode) {
    constexpr int kMantissa[3] = {6, 6, 5};
    for (std::size_t i = 0; i < image.data.size(); ++i) {
        const int c = static_cast<int>(i % static_cast<std::size_t>(image.channels));
        if (c < 3) image.data[i] = static_cast<float>(storeUnsignedFloat(image.data[i], kMantissa[c], mode));
    }
}

FloatStore detectFloatStore(const ImageF& stored, const ImageF& exact) {
    // Rounding puts about half of the inexact values above the exact one (by up to half a step,
    // 2^-7 of the value) and truncation none. Counting, rather than taking the first value above,
    // keeps sampling noise from deciding: a texture coordinate a hair off a texel centre mixes in a
    // little of the neighbour, which next to a 100:1 edge (a lamp of luminance 80 on a wall of 0.5)
    // moves a value by more than 2^-12 at a few texels along the edge. Texels that are zero on one
    // side only are pixels at the threshold, classified differently by float and double arithmetic:
    // they say nothing about the store rule.
    std::size_t above = 0;
    std::size_t below = 0;
    for (std::size_t i = 0; i < stored.data.size() && i < exact.data.size(); ++i) {
        if (!(exact.data[i] > 0.0f && stored.data[i] > 0.0f)) continue;
        if (stored.data[i] > exact.data[i] * (1.0 + 1.0 / 4096.0)) ++above;
        if (stored.data[i] < exact.data[i] * (1.0 - 1.0 / 4096.0)) ++below;
    }
    // Rounding: above is close to below. Truncation: above is a handful of edge texels.
    return above * 4 > above + below ? FloatStore::RoundToNearest : FloatStore::Truncate;
}

namespace {

// Where a bilinear sample reads and how it weighs the four texels, shared by its channels (the
// grader's blur fits sample millions of times).
struct BilinearTaps {
    std::size_t texel[4];
    double weight[4];
};

BilinearTaps bilinearTaps(const ImageF& image, double u, double v) {
    // Texel centres sit at (i + 0.5) / size, as in GL.
    const double x = u * image.width - 0.5;
    const double y = v * image.height - 0.5;
    const double fx = std::floor(x);
    const double fy = std::floor(y);
    const double ax = x - fx;
    const double ay = y - fy;
    const auto column = [&](double t) { return std::clamp(static_cast<int>(t), 0, image.width - 1); };
    const auto row = [&](double t) { return std::clamp(static_cast<int>(t), 0, image.height - 1); };
    const auto at = [&](int ix, int iy) { return (static_cast<std::size_t>(iy) * image.width + ix) * image.channels; };
    const int x0 = column(fx), x1 = column(fx + 1), y0 = row(fy), y1 = row(fy + 1);
    return {{at(x0, y0), at(x1, y0), at(x0, y1), at(x1, y1)},
            {(1 - ax) * (1 - ay), ax * (1 - ay), (1 - ax) * ay, ax * ay}};
}

double sampleChannel(const ImageF& image, const BilinearTaps& taps, int c) {
    const auto texel = [&](int k) { return double(image.data[taps.texel[k] + static_cast<std::size_t>(c)]); };
    return taps.weight[0] * texel(0) + taps.weight[1] * texel(1) + taps.weight[2] * texel(2) + taps.weight[3] * texel(3);
}

} // namespace

double sampleBilinear(const ImageF& image, int c, double u, double v) {
    return sampleChannel(image, bilinearTaps(image, u, v), c);
}

Rgb sampleBilinear(const ImageF& image, double u, double v) {
    const BilinearTaps taps = bilinearTaps(image, u, v);
    return {sampleChannel(image, taps, 0), sampleChannel(image, taps, 1), sampleChannel(image, taps, 2)};
}

ImageF bloomThreshold(const ImageF& accumulation, double threshold) {
    ImageF bloom(accumulation.width, accumulation.height, 3);
    for (int y = 0; y < accumulation.height; ++y) {
        for (int x = 0; x < accumulation.width; ++x) {
            const Rgb c{accumulation.at(x, y, 0), accumulation.at(x, y, 1), accumulation.at(x, y, 2)};
            const bool bright = luminance(c) >= threshold;
            for (int k = 0; k < 3; ++k) bloom.at(x, y, k) = bright ? static_cast<float>(c[k]) : 0.0f;
        }
    }
    return bloom;
}

ImageF boxDownsample(const ImageF& level0) {
    ImageF level1(std::max(1, level0.width / 2), std::max(1, level0.height / 2), level0.channels);
    for (int y = 0; y < level1.height; ++y) {
        for (int x = 0; x < level1.width; ++x) {
            for (int c = 0; c < level0.channels; ++c) {
                double sum = 0.0;
                for (int dy = 0; dy < 2; ++dy)
                    for (int dx = 0; dx < 2; ++dx)
                        sum += level0.at(std::min(2 * x + dx, level0.width - 1), std::min(2 * y + dy, level0.height - 1), c);
                level1.at(x, y, c) = static_cast<float>(sum / 4.0);
            }
        }
    }
    return level1;
}

ImageF gaussianPass(const ImageF& source, int dstWidth, int dstHeight, bool horizontal, const Settings& settings) {
    ImageF out(dstWidth, dstHeight, 3);
    const double step1 = settings.tapInner * settings.sigma / (horizontal ? dstWidth : dstHeight);
    const double step2 = settings.tapOuter * settings.sigma / (horizontal ? dstWidth : dstHeight);
    const double offsets[5] = {-step2, -step1, 0.0, step1, step2};
    for (int y = 0; y < dstHeight; ++y) {
        for (int x = 0; x < dstWidth; ++x) {
            const double u = (x + 0.5) / dstWidth;
            const double v = (y + 0.5) / dstHeight;
            Rgb sum{0.0, 0.0, 0.0};
            for (double offset : offsets) {
                const Rgb s = horizontal ? sampleBilinear(source, u + offset, v) : sampleBilinear(source, u, v + offset);
                for (int c = 0; c < 3; ++c) sum[c] += s[c];
            }
            for (int c = 0; c < 3; ++c) out.at(x, y, c) = static_cast<float>(sum[c] / 5.0);
        }
    }
    return out;
}

ImageF gaussianBloom(const ImageF& level0, int passes, FloatStore store, const Settings& settings) {
    const int halfWidth = std::max(1, level0.width / 2);
    const int halfHeight = std::max(1, level0.height / 2);
    ImageF level1 = level0;
    for (int pass = 0; pass < passes; ++pass) {
        ImageF blur = gaussianPass(level1, halfWidth, halfHeight, true, settings);
        storeR11G11B10F(blur, store);
        level1 = gaussianPass(blur, halfWidth, halfHeight, false, settings);
        storeR11G11B10F(level1, store);
    }
    return level1;
}

double rangeMappedLogLuminance(double y, const Settings& settings, MappedLog log) {
    if (log == MappedLog::Natural) return rangeMappedLogLuminance(y, settings);
    const double logEps = std::log(settings.epsilon);
    return (std::log2(y + settings.epsilon) - logEps) / (std::log(settings.whitePoint) - logEps);
}

double keyFromMapped(double mapped, const Settings& settings, Unmap unmap) {
    const double e = settings.epsilon;
    const double yw = settings.whitePoint;
    switch (unmap) {
    case Unmap::None: return std::exp(mapped);
    case Unmap::Log2ThenExp: return std::exp(mapped * (std::log2(yw) - std::log2(e)) + std::log2(e));
    case Unmap::LnThenExp2: return std::exp2(mapped * (std::log(yw) - std::log(e)) + std::log(e));
    case Unmap::Correct: break;
    }
    return keyFromMapped(mapped, settings);
}

FrameInputs::FrameInputs(const ImageF& acc, double key, const ImageF* bloomLevel, const std::vector<ImageF>* luminanceLevels,
                         Unorm8Store frameStore)
    : accumulation(acc), mappedKey(key), bloom(bloomLevel), levels(luminanceLevels), store(frameStore) {
    if (bloom == nullptr) return;
    bloomAt.reserve(std::size_t(acc.width) * acc.height);
    for (int y = 0; y < acc.height; ++y)
        for (int x = 0; x < acc.width; ++x)
            bloomAt.push_back(sampleBilinear(*bloom, (x + 0.5) / acc.width, (y + 0.5) / acc.height));
}

namespace {

// One pixel of the final pass under a variant; `sceneKey` is the Ya of the smallest level.
Rgb frameColour(const FrameInputs& in, const FrameVariant& variant, double sceneKey, double sceneGrey, int x, int y) {
    const ImageF& acc = in.accumulation;
    const int w = acc.width;
    const int h = acc.height;
    if (variant.lowerLeftQuarter && (x >= w / 2 || y >= h / 2)) return {0.0, 0.0, 0.0}; // cleared black
    const Settings& s = variant.settings;
    const double scale = variant.doubledUv ? 2.0 : 1.0;
    const double u = std::min((x + 0.5) / w * scale, 1.0);
    const double v = std::min((y + 0.5) / h * scale, 1.0);
    Rgb c = variant.doubledUv ? sampleBilinear(acc, u, v) : Rgb{acc.at(x, y, 0), acc.at(x, y, 1), acc.at(x, y, 2)};
    Rgb b{0.0, 0.0, 0.0};
    if (in.bloom != nullptr && variant.addBloom)
        b = variant.doubledUv ? sampleBilinear(*in.bloom, u, v) : in.bloomAt[std::size_t(y) * w + x];
    if (!variant.bloomAfterToneMap)
        for (int k = 0; k < 3; ++k) c[k] += s.bloomWeight * b[k];
    Rgb out = c;
    if (variant.toneMap) {
        if (variant.keyLevel >= 0) {
            const double key = keyFromMapped(sampleBilinear((*in.levels)[std::size_t(variant.keyLevel)], 0, u, v), s, variant.unmap);
            out = toneMap(c, key, s);
        } else {
            out = toneMap(c, sceneKey, sceneGrey, s);
        }
    }
    if (variant.bloomAfterToneMap)
        for (int k = 0; k < 3; ++k) out[k] += s.bloomWeight * b[k];
    return out;
}

void colours(const FrameInputs& in, const FrameVariant& variant, double sceneKey, std::vector<Rgb>& out, int step = 1) {
    const int w = in.accumulation.width;
    out.resize(std::size_t(w) * in.accumulation.height);
    const double sceneGrey = middleGrey(sceneKey, variant.settings);
    for (int y = 0; y < in.accumulation.height; y += step)
        for (int x = 0; x < w; x += step) out[std::size_t(y) * w + x] = frameColour(in, variant, sceneKey, sceneGrey, x, y);
}

std::vector<Rgb> colours(const FrameInputs& in, const FrameVariant& variant, double sceneKey) {
    std::vector<Rgb> out;
    colours(in, variant, sceneKey, out);
    return out;
}

Image8 toImage8(const std::vector<Rgb>& colours, int width, int height, Unorm8Store store) {
    Image8 frame(width, height, 3);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int k = 0; k < 3; ++k) frame.at(x, y, k) = storeUnorm8(colours[std::size_t(y) * width + x][k], store);
    return frame;
}

} // namespace

std::vector<Rgb> frameColours(const FrameInputs& inputs, const FrameVariant& variant) {
    return colours(inputs, variant, keyFromMapped(inputs.mappedKey, variant.settings, variant.unmap));
}

void frameColours(const FrameInputs& inputs, const FrameVariant& variant, std::vector<Rgb>& out, int step) {
    colours(inputs, variant, keyFromMapped(inputs.mappedKey, variant.settings, variant.unmap), out, std::max(1, step));
}

Image8 finalFrame(const FrameInputs& inputs, const FrameVariant& variant) {
    return toImage8(frameColours(inputs, variant), inputs.accumulation.width, inputs.accumulation.height, inputs.store);
}

Image8 finalFrame(const ImageF& accumulation, double sceneKey, const ImageF* bloomLevel, const Settings& settings) {
    FrameVariant variant;
    variant.settings = settings;
    const FrameInputs inputs(accumulation, 0.0, bloomLevel);
    return toImage8(colours(inputs, variant, sceneKey), accumulation.width, accumulation.height, inputs.store);
}

} // namespace t10::ref
