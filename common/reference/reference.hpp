// CPU reference of Tutorial 10's post-processing chain in double precision: luminance, the range
// mapped log luminance and scene key, the tone map operator, the bloom threshold, the 2x2
// downsample and the five-tap importance-sampled Gaussian passes, every constant a field of
// Settings (defaults from contract.hpp). GL-free (library t10_reference_math): the numeric tests run
// it on buffers read back from the GPU, and t10-grade's mistake models are its variants (the end of
// this file): other Settings, and the final pass written with one of the mistakes the grader names.
#pragma once
#include "t10/contract.hpp"
#include "t10/image.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace t10::ref {

constexpr double kEpsilon = contract::kEpsilon;
constexpr double kYwhite = contract::kWhitePoint;
constexpr double kBloomThresholdFactor = contract::kBloomThresholdFactor;
constexpr double kBloomThreshold = kBloomThresholdFactor * kYwhite;
constexpr double kBloomWeight = contract::kBloomWeight;
constexpr double kSigma = contract::kGaussSigma;
constexpr double kTap1 = contract::kInnerTap; // inner taps at +-0.524 sigma
constexpr double kTap2 = contract::kOuterTap; // outer taps at +-1.282 sigma
constexpr int kBlurPasses = contract::kBlurPasses;

using Rgb = std::array<double, 3>;

// Every constant of the chain. extras/ makes the white point and the bloom weight variable (steps
// 37-38); t10-grade's mistake models are other values of the rest. The defaults are the tutorial's.
struct Settings {
    double whitePoint = kYwhite;
    double bloomWeight = kBloomWeight;
    Rgb lumaWeights{contract::kLumaRed, contract::kLumaGreen, contract::kLumaBlue};
    double epsilon = kEpsilon;
    double middleGrey = 1.03; // the constant of 1.03 - 2 / (2 + log10(Ya + 1)), step 9
    double bloomThresholdFactor = kBloomThresholdFactor;
    double sigma = kSigma;    // in target texels
    double tapInner = kTap1;  // in sigma
    double tapOuter = kTap2;
    int blurPasses = kBlurPasses;
};

double luminance(const Rgb& c);
double luminance(const Rgb& c, const Settings& settings);
// With other weights: the bloom threshold's classification under a student's weights (t10-grade).
double luminance(const Rgb& c, const Rgb& weights);
// (log(Y + eps) - log(eps)) / (log(Yw) - log(eps)), not clamped.
double rangeMappedLogLuminance(double y, const Settings& settings = {});
// Inverse of the range mapping followed by exp: the key Ya from a mapped value.
double keyFromMapped(double mapped, const Settings& settings = {});
// Stores v into a GL_R16 texel: clamp to [0, 1], round to the nearest 1/65535.
double toUnorm16(double v);
// Mean of the range-mapped log luminance of every pixel; with `asR16`, each value is clamped and
// quantised as the GL_R16 luminance texture stores it (so pixels above Yw saturate at 1).
double meanMappedLogLuminance(const ImageF& accumulation, bool asR16, const Settings& settings = {});
// The unclamped log-average, mean(ln(Y + epsilon)): the tutorial's formula for ln Ya.
double meanLogLuminance(const ImageF& accumulation);
// Middle grey dg of step 9 from the scene key Ya: middleGrey - 2 / (2 + log10(Ya + 1)).
double middleGrey(double sceneKey, const Settings& settings = {});
// The tone map of steps 8-9 for a linear HDR colour and the key Ya (black, or a NaN luminance, gives black).
Rgb toneMap(const Rgb& colour, double sceneKey, const Settings& settings = {});
// The tone map of a luminance alone: the new luminance Y' of step 9 (0 for y <= 0).
double toneMapLuminance(double y, double sceneKey, const Settings& settings = {});
// How GL converts a float to an 8-bit normalised channel: clamp, scale, round to nearest.
std::uint8_t toUnorm8(double v);
// How the renderer that drew a frame stores a float in its 8-bit channels. Llvmpipe (natively, as
// t10-grade and every golden render it): it scales before it clamps, through a 32-bit integer, so a
// channel at or past 2^31 / 255 (8.4e6, which a tone map can reach when its key is tiny) stores 0.
// Clamped: clamp, then scale, as GL ES 3.0 specifies; what the browsers' WebGL 2 stores, on Mesa
// llvmpipe as on SwiftShader (measured: a Part 1 with epsilon 5e-2 in step 4, whose key is 3.7e-6,
// writes 255 in the page for the 51 pixels of its 128x128 frame that llvmpipe writes 0). NaN stores 0
// in both. Below the overflow both are toUnorm8.
enum class Unorm8Store { Llvmpipe, Clamped };
std::uint8_t storeUnorm8(double v, Unorm8Store store = Unorm8Store::Llvmpipe);
inline constexpr double kUnorm8Overflow = 2147483648.0 / 255.0;
// The level storeUnorm8 rounds, in [0, 255]: what a fit's residual compares without the rounding.
double unorm8Level(double v, Unorm8Store store = Unorm8Store::Llvmpipe);

// How a float is stored in GL_R11F_G11F_B10F: unsigned floats with 5 exponent bits and 6 (red,
// green) or 5 (blue) mantissa bits. GL leaves the rounding to the implementation; Mesa truncates.
// SwiftShader (Chromium's WebGL without a GPU) converts through a half float: the value is rounded to
// 10 mantissa bits (to nearest), then truncated to 6 or 5, so a value within 1/32 of a step of the next
// one (1/64 in blue) is stored one step higher than truncation stores it (measured on Chromium 120's
// blur passes: every texel that differs from truncation does so, by one step, and no other).
enum class FloatStore { Exact, Truncate, RoundToNearest, HalfThenTruncate };
double storeUnsignedFloat(double v, int mantissaBits, FloatStore mode);
// Applies storeUnsignedFloat to every texel with the R11G11B10F mantissa widths.
void storeR11G11B10F(ImageF& image, FloatStore mode);
// Which rule a driver used, judged from a texture it wrote and the exact values it was given:
// RoundToNearest if a quarter or more of the inexact values lie above their exact value, else Truncate.
FloatStore detectFloatStore(const ImageF& stored, const ImageF& exact);

// Bilinear sample of channel c at texture coordinate (u, v) in [0, 1] with clamp-to-edge.
double sampleBilinear(const ImageF& image, int c, double u, double v);
Rgb sampleBilinear(const ImageF& image, double u, double v);

// Step 18: the accumulation colour where its luminance reaches the threshold, else black.
ImageF bloomThreshold(const ImageF& accumulation, double threshold = kBloomThreshold);
// The next mipmap level by 2x2 averaging (sizes floor(n / 2), at least 1); exact for even sizes.
ImageF boxDownsample(const ImageF& level0);
// One Gaussian pass (steps 27, 32-34): each output pixel of a dstWidth x dstHeight target averages
// five bilinear samples of `source` at its centre and +-kTap1, +-kTap2 sigma target texels along one axis.
ImageF gaussianPass(const ImageF& source, int dstWidth, int dstHeight, bool horizontal, const Settings& settings = {});
// The whole Part 3 blur: `passes` horizontal + vertical pairs at half resolution from bloom level 0,
// each pass's result stored as the R11G11B10F targets store it.
ImageF gaussianBloom(const ImageF& level0, int passes = kBlurPasses, FloatStore store = FloatStore::Exact,
                     const Settings& settings = {});

// The final frame: optionally add the bloom weight x bloom (bilinear from the given level) to each
// accumulation texel, tone map with Ya, convert to 8 bits.
Image8 finalFrame(const ImageF& accumulation, double sceneKey, const ImageF* bloomLevel = nullptr,
                  const Settings& settings = {});

// --- The variants t10-grade models (grader/diagnosis/mistakes.tsv names them). -------------------
// Each is the tutorial's formula with one thing written another way; the defaults are the
// tutorial's, so a default variant gives what the functions above give.

// How step 4's log is taken: the natural log (the tutorial's), or log2 of the luminance against the
// natural-log bounds (the mapping's two logs in different bases).
enum class MappedLog { Natural, Log2Luminance };
double rangeMappedLogLuminance(double y, const Settings& settings, MappedLog log);

// How the final pass turns the stored key back into Ya: the tutorial's inverse of the range mapping,
// no inverse at all (exp of the stored value), or the inverse in the other base than the mapping's
// (log2 to map and exp to undo it, ln to map and exp2 to undo it).
enum class Unmap { Correct, None, Log2ThenExp, LnThenExp2 };
double keyFromMapped(double mapped, const Settings& settings, Unmap unmap);

// The final pass (steps 6-10, 19-20, 35) written the tutorial's way (the defaults) or with one of
// the mistakes t10-grade models.
struct FrameVariant {
    Settings settings;
    Unmap unmap = Unmap::Correct;
    bool toneMap = true;          // false: the colour written without the tone map
    bool addBloom = true;         // false: the bloom never added (Part 2 on)
    bool bloomAfterToneMap = false;
    bool lowerLeftQuarter = false; // the viewport left at half size: only the lower-left quarter drawn, the rest black
    bool doubledUv = false;        // every texture read at twice its coordinate (half the inverse resolution)
    int keyLevel = -1;             // >= 0: Ya read per pixel from this luminance level, not the smallest
};

// What the final pass reads: the accumulation, the stored (range-mapped) key of the smallest
// luminance level, bloom level 1 (null without bloom) and, for a variant with a key level, the
// luminance levels. Bloom level 1 at each pixel's centre is sampled once here: a fit evaluates the
// frame hundreds of times. The images must outlive the inputs. `store` is how the renderer whose
// frame is compared stores 8 bits.
struct FrameInputs {
    explicit FrameInputs(const ImageF& accumulation, double mappedKey, const ImageF* bloomLevel = nullptr,
                const std::vector<ImageF>* luminanceLevels = nullptr, Unorm8Store frameStore = Unorm8Store::Llvmpipe);
    const ImageF& accumulation;
    double mappedKey;
    const ImageF* bloom;
    const std::vector<ImageF>* levels;
    Unorm8Store store;
    std::vector<Rgb> bloomAt;
};

// Every pixel's colour under the variant before the 8-bit store, row by row (x fastest).
std::vector<Rgb> frameColours(const FrameInputs& inputs, const FrameVariant& variant);
// The same into `out`, whose memory is reused: for fits that evaluate hundreds of variants. With
// `step` > 1 only the pixels of every step-th row and column (x % step == 0, y % step == 0) are
// computed, the others left as they were: a fit's rough search, which looks for a neighbourhood.
void frameColours(const FrameInputs& inputs, const FrameVariant& variant, std::vector<Rgb>& out, int step = 1);
// The frame under the variant, converted to 8 bits: finalFrame's result for the default variant.
Image8 finalFrame(const FrameInputs& inputs, const FrameVariant& variant);

} // namespace t10::ref
