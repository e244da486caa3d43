// The mistake models of the final frame (steps 6-10, 19-20, 35): the reference's variants of the final
// pass (ref::FrameVariant), their fits to the 8-bit frame, and what a frame no model explains looks like.
#pragma once
#include "diagnosis/fits.hpp"
#include "diagnosis/model.hpp"

#include "t10/dumps.hpp"

namespace t10::grade {

// The frame's models are the reference's variants of the final pass (ref::FrameVariant): the tutorial's,
// another value of one constant, or the pass written with one of the catalogue's mistakes.
using FrameModel = ref::FrameVariant;

// The frame's one-constant mistakes: the frame check fits each to one case, crossCheckCases to
// every case whose frame failed at once.
inline const ModelParameter kFrameParameters[] = {{"white-point", &ref::Settings::whitePoint, 0.02, 20.0, {9}, 1},
                                                  {"middle-grey", &ref::Settings::middleGrey, 0.3, 3.0, {9}, 1},
                                                  {"epsilon", &ref::Settings::epsilon, 1e-20, 1e-1, {9}, 1},
                                                  {"bloom-weight", &ref::Settings::bloomWeight, 0.01, 10.0, {20}, 2}};

// The tutorial's final pass with one setting changed.
FrameModel withSetting(double ref::Settings::*field, double value);

// The frame's mistakes without a constant to fit: each a model of the final pass taken as it is.
struct DiscreteModel {
    const char* id;
    std::vector<int> steps;
    FrameModel model;
    std::vector<double> value;
};

// The discrete models of `part`'s frame (a key-level model for each of `luminanceLevels` but the last).
std::vector<DiscreteModel> frameDiscreteModels(int part, int luminanceLevels);

// The buffers a model of the final pass reads: the GPU's own accumulation, key and bloom.
using ref::FrameInputs;

// What the fits minimise: the mean distance, in 8-bit steps, from the model's unrounded output to
// the frame. Unlike the rounded error it changes smoothly with a constant, so the search does not
// stall on the plateaus of the 8-bit store.
// `colours` is scratch memory the fits reuse from one evaluation to the next. The rough stage reads
// every kRoughFrameStep-th pixel of every kRoughFrameStep-th row (a ninth of the frame): it looks for
// the neighbourhood of the value, which every pixel the constant touches points to alike; the second
// stage and the tolerance read every pixel. make grade-sweep gives the same table with 3 as with 2 (a
// quarter), but for the bloom weight's largest error (0.02 % instead of 0.04 %); with 4 the epsilon
// of step 9 is off by 0.07 % instead of 0.00 %, for no further saving.
constexpr int kRoughFrameStep = 3;
double frameResidual(const FrameInputs& in, const FrameModel& model, const Image8& frame, std::vector<ref::Rgb>& colours,
                     int step = 1);

// A frame fit's golden-section steps (every step renders the frame on the CPU again), each narrowing
// the bracket by 0.618. The rough stage's bracket is two cells of its log grid (a factor 1.36 for the
// middle grey's 16 points over 0.3-3). The middle grey is the constant the frame is most sensitive to:
// Part 1's extremes case, whose key is small, passes with a middle grey of 1.0 only within 5e-7 of
// it (1.0 - 2 / (2 + log10(Ya + 1)) is then about 1e-4, so 1e-6 of the constant moves it 1 %). 16
// steps left 1.4e-4 of the value, and the case was left unexplained (issue 38: "no constant factor or
// shift explains it", steps 6-10 lost); 40 steps leave 4e-9. The second stage's bracket (two cells of
// 0.2 %) 12 steps bring within 0.002 %. The reports give three significant digits.
constexpr int kRoughFrameFitSteps = 40;
constexpr int kFrameFitSteps = 12;

// Basins the rough stage searches, best first, until one is within kFrameResidualCeiling: a middle
// grey below about 0.98 makes the operator's scale negative, which gives a frame of its own (not a
// black one), so the grid's best point can sit in the wrong basin.
constexpr int kFrameFitStarts = 3;

// A model whose best smooth residual is above this many 8-bit steps cannot pass the frame's
// tolerance, so its second stage is skipped: at a value that passes, every channel rounds to within
// 1 step of the frame and 99 % or more to the same step (mean <= 0.01), so the unrounded output is
// within 0.5 + 0.01 steps of the frame on average. The margin covers the rough stage's last step.
constexpr double kFrameResidualCeiling = 0.75;

// The second stage of a frame fit: the smooth residual finds the neighbourhood, the rounded 8-bit
// error (what the tolerance judges) the value within 1 % of it. Constants the frame is very
// sensitive to (the middle grey's 1.03 moves the operator's scale 30 times as much) need it.
Fit refineFrameFit(double value, const std::function<double(double)>& roundedError);

// The frame check's tolerance: float vs double rounding moves a channel one step, rarely.
bool frameWithin(const t10::test::ByteError& e);

// How the frame differs when no model explains it: its shape over the luminance of the pixels.
std::string describeFrame(const Image8& expected, const Image8& got);

// Whether every pixel off by more than a step is black in the input (the tone map's 0 / 0), and
// there is at least one.
bool onlyBlackPixelsOff(const ImageF& acc, const Image8& expected, const Image8& frame);

// The steps of the frame's "-missing" models (no tone map, no bloom) that the submission's frame is
// nearer to than to the tutorial's, up to a gain: over the channels where the two frames differ by more
// than a step, the frame is closer in direction (cosine) to the model's than to the tutorial's. Steps
// that look not done then cost their points even where something else is wrong too (no bloom and
// another mistake: no one model names it), while a wrong constant, which mostly scales the tone map's
// output, stays nearer the tutorial's frame (a darker frame is not a frame without its bloom).
std::vector<int> lookMissing(int part, const Image8& got, const FrameInputs& inputs, const Image8& expected);

} // namespace t10::grade
