// The mistake models of the bloom (steps 17-34): the threshold's luminance interval, the store of
// GL_R11F_G11F_B10F, and the Gaussian passes with another sigma, tap or axis, fitted to a pass.
#pragma once
#include "diagnosis/fits.hpp"
#include "diagnosis/model.hpp"

#include <string>
#include <vector>

namespace t10::grade {

// The pixels the GPU's bloom level 0 puts on the other side of `threshold` than the luminance (with
// `weights`) of the accumulation texture does.
int misclassified(const ImageF& accumulation, const ImageF& gpu, double threshold, const ref::Rgb& weights);

// The luminances between which the GPU's threshold lies: the brightest pixel left dark and the
// dimmest pixel kept. Consistent with a threshold when low < high.
struct ThresholdInterval {
    double low = 0.0;
    double high = 1e300;
};

ThresholdInterval thresholdInterval(const ImageF& accumulation, const ImageF& gpu, const ref::Rgb& weights);

// A blur's error relative to the CPU level's peak in each channel: the worst texel's and the mean.
struct PeakError {
    double worst = 0.0;
    double mean = 0.0;
};

// `gpu` against `cpu` (1e9 when their sizes differ).
PeakError peakError(const ImageF& gpu, const ImageF& cpu);

// Nothing written: every value is 0.
bool allZero(const ImageF& image);

// GL_R11F_G11F_B10F keeps 6 mantissa bits for red and green and 5 for blue: one unit in the last
// place is 2^-6 or 2^-5 of the value, whether the driver rounds or truncates.
constexpr double kRelativeStep[3] = {1.0 / 64.0, 1.0 / 64.0, 1.0 / 32.0};

constexpr double kDenormalStep = 1.0 / 16384.0 / 32.0;

// The largest difference in units of the store's last place (kRelativeStep); with `classifiedBy`, texels
// that it and `gpu` classify differently (one black, one not) are left to the threshold's count.
double worstStoreError(const ImageF& gpu, const ImageF& cpu, const ImageF* classifiedBy = nullptr);

// The blur's tolerance, for the whole chain and for each pass: with the driver's store rule
// emulated what is left is float vs double and the bilinear weights, two blue steps of the peak at
// worst and 1e-4 of the peak on average (measured 2e-6 to 7e-7). A wrong tap, sigma or pass count
// moves the blur by tens of percent.
constexpr double kBlurWorst = 2.0 / 32.0;

constexpr double kBlurMean = 1e-4;

bool blurWithin(const PeakError& e);

// One Gaussian pass with a model's settings, stored as the GPU's R11G11B10F target stores it.
ImageF modelPass(const ImageF& source, int w, int h, bool horizontal, const ref::Settings& s, ref::FloatStore store);

// The blur target's store rule: `detected` (ref::detectFloatStore on bloom level 0), or, when that is
// Truncate, HalfThenTruncate if it reproduces more of the first pass's texels exactly (`source` is what
// the pass read) and more than half of those that are not black. Level 0 cannot tell the two apart: the
// threshold writes it from the half-float accumulation, whose values a half float's rounding leaves alone.
ref::FloatStore passStore(const ImageF& source, const ImageF& firstPass, int w, int h, ref::FloatStore detected);

// `level1` against `passes` CPU pairs of passes from `level0` with `s`, stored by `store`, or by the other
// of Truncate and HalfThenTruncate when that explains it better: a blur with a wrong constant matches
// neither rule in its first pass (passStore keeps truncation), yet its chain is judged with the rule the
// driver used. The two rules differ by 2e-4 of the peak on average over ten passes; a wrong blur by tens
// of percent.
PeakError chainError(const ImageF& level1, const ImageF& level0, int passes, ref::FloatStore store, const ref::Settings& s);

// The blur's one-constant mistakes, fitted to a pass (fitPass) and made to agree across the cases
// (crossCheckCases).
inline const ModelParameter kBlurParameters[] = {{"blur-sigma", &ref::Settings::sigma, 0.2, 12.0, {27}, 3},
                                                 {"blur-tap-inner", &ref::Settings::tapInner, 0.02, 3.0, {27}, 3},
                                                 {"blur-tap-outer", &ref::Settings::tapOuter, 0.05, 5.0, {27}, 3}};

// A blur mistake that explains a pass: the catalogue id, the fitted value and the settings.
struct BlurFinding {
    std::string id;
    std::vector<double> value;
    ref::Settings settings;
    bool otherAxis = false;
    bool loose = false;
};

// Fits sigma, the inner and the outer tap to one pass (one at a time), and tries the other axis;
// returns every model within the blur's tolerance.
std::vector<BlurFinding> fitPass(const ImageF& source, const ImageF& gpu, int w, int h, bool horizontal,
                                 ref::FloatStore store);

// What a fitted sigma of exactly half the tutorial's means, or "".
std::string sigmaNote(const BlurFinding& f);

} // namespace t10::grade
