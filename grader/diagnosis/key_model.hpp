// The mistake models of luminance level 0 and the scene key (steps 3-5, 13, 15): the reference's
// range-mapped log luminance with another setting or the other log, and the fit of the luminance
// weights.
#pragma once
#include "diagnosis/model.hpp"

#include <optional>

namespace t10::grade {

// Luminance level 0's one-constant mistakes (step 4's epsilon, step 5's white point), each fitted
// to level 0 by nameLogLuminanceMistakes.
inline const ModelParameter kLogLuminanceParameters[] = {{"epsilon", &ref::Settings::epsilon, 1e-20, 1e-1, {4}, 1},
                                                         {"white-point", &ref::Settings::whitePoint, 0.02, 20.0, {5}, 1}};

// A model of luminance level 0: the reference's mapping with other settings or the other log.
struct KeyModel {
    ref::Settings settings;
    ref::MappedLog log = ref::MappedLog::Natural;
};

// One pixel's range-mapped log luminance as GL_R16 stores it, with the model's setting.
double modelMapped(const ref::Rgb& colour, const KeyModel& model);

// Largest difference, in R16 steps, between luminance level 0 and a model of it.
double worstLuminanceSteps(const ImageF& level0, const ImageF& accumulation, const KeyModel& model);

// The luminance weights that explain level 0: the mapped values un-mapped to Y, then least squares
// of Y on the colour over the pixels the R16 store did not clamp. Empty when the input cannot tell
// the weights apart (grey pixels only).
std::optional<ref::Rgb> fitWeights(const ImageF& level0, const ImageF& accumulation);

// The luminance level 0 tolerance, in R16 steps. The GPU's float log differs from the double one by
// about 1e-7 of the mapped range, far below one R16 step (1.5e-5), so a texel rounds at most to the
// neighbouring step. At sizes that are not a power of two gl_FragCoord x 1 / size lands a hair off
// the texel centre, and beside a lamp 1e-6 of its light moves a dark texel's log: 2 steps measured
// at 160x90. A wrong weight, base or bound moves texels by hundreds of steps.
constexpr double kLogLuminanceSteps = 4.0;

// The tolerance for a model of level 0 with another epsilon or white point. Both sources above are
// errors in the log luminance, and the mapping divides the log by its range, ln(white / epsilon): a
// model with a narrower range (a larger epsilon) shows the same log error as more R16 steps (epsilon
// 1e-4: 7.7 against the tutorial's 20.9, so the lamp's 2 steps at 160x90 become 5). So the tolerance
// holds in log luminance: kLogLuminanceSteps of the tutorial's range (1.3e-3), and never fewer than
// kLogLuminanceSteps of the model's own (where the range is wider, R16's rounding still costs a step).
double logLuminanceTolerance(const KeyModel& model);

} // namespace t10::grade
