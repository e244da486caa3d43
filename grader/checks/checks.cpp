// The buffer checks of t10-grade and how they explain a failure; see checks.hpp.
//
// Every check compares what the submission's GPU wrote with the CPU reference (common/reference,
// reference.hpp), computed from the buffers the GPU itself produced one pass earlier, so that a
// mistake shows in the check of the step that makes it and not in every later one. That is also
// why a mistake found by one check agrees with every check that passed: each model starts from the
// GPU's own input buffer and changes only what its own step computes.
//
// When a check fails, each catalogue mistake of that check is a model: the reference with one
// setting changed (ref::Settings) or written the mistake's way (the reference's variants:
// ref::MappedLog, ref::Unmap, ref::FrameVariant), fitted to the buffer (fits.hpp) or, for a
// mistake without a value, taken as it is. A mistake is named only when its model explains the
// buffer within the check's own tolerance; otherwise the diagnosis describes the error's shape (a
// constant factor, a shift, nothing written, NaN, the region that differs). No closest guesses.
//
// Adding a known mistake: a row of mistakes.tsv, its variant in common/reference when it changes
// the tutorial's math, a model in the check of the step it breaks, and a submission that makes it
// (tests/make_submissions.py).
#include "checks/checks.hpp"

#include "t10/compare.hpp"
#include "diagnosis/fits.hpp"
#include "reference.hpp"
#include "t10/contract.hpp"
#include "t10/error.hpp"
#include "t10/image_io.hpp"
#include "t10/outputs.hpp"

#include <algorithm>
#include <cstring>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numeric>
#include <memory>
#include <optional>
#include <set>
#include <sstream>

namespace t10::grade {

namespace {

namespace ref = t10::ref;
using t10::Image8;
using t10::ImageF;

constexpr int kLuminanceUnit = static_cast<int>(t10::contract::kLuminanceKeyUnit);
constexpr int kBloomUnit = static_cast<int>(t10::contract::kBloomUnit);
constexpr ref::Rgb kRec601Weights{0.299, 0.587, 0.114};

ref::Rgb texel(const ImageF& image, int x, int y) { return {image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2)}; }

std::string format(double value, int precision = 4) {
    std::ostringstream text;
    text.precision(precision);
    text << value;
    return text.str();
}

// The student's value to the precision the tutorial writes its own with ("0.2126" -> 4 decimals; a
// value written with an exponent, "1e-8", keeps its significant digits), or 3 significant digits.
std::string likeWritten(double value, const std::string& written) {
    if (written.find_first_of("eE") != std::string::npos || written.empty()) return format(value, 3);
    const std::size_t dot = written.find('.');
    const int decimals = dot == std::string::npos ? 0 : static_cast<int>(written.size() - dot - 1);
    std::ostringstream text;
    text.setf(std::ios::fixed);
    text.precision(decimals);
    text << value;
    return text.str();
}

std::string listed(const std::vector<std::string>& values) {
    if (values.size() == 1) return values[0];
    std::string out = "(";
    for (std::size_t i = 0; i < values.size(); ++i) out += (i ? ", " : "") + values[i];
    return out + ")";
}

// "your luminance weights measure (0.2130, 0.7150, 0.0720); the tutorial's are (0.2126, 0.7152, 0.0722)":
// the tutorial's values as mistakes.tsv writes them, the student's to the same decimals.
std::string estimateText(const Mistake& m, const std::vector<double>& value) {
    std::string words = m.parameter;
    std::replace(words.begin(), words.end(), '_', ' ');
    const bool plural = words.size() > 1 && words.back() == 's' && words[words.size() - 2] != 's';
    std::vector<std::string> student;
    for (std::size_t i = 0; i < value.size(); ++i)
        student.push_back(likeWritten(value[i], i < m.tutorialText.size() && value.size() == m.tutorialText.size()
                                                    ? m.tutorialText[i] : std::string()));
    return "your " + words + (plural ? " measure " : " measures ") + listed(student) + "; the tutorial's " +
           (plural ? "are " : "is ") + listed(m.tutorialText);
}

std::vector<int> range(int first, int last) {
    std::vector<int> steps(static_cast<std::size_t>(last - first + 1));
    std::iota(steps.begin(), steps.end(), first);
    return steps;
}

std::string stepRange(const std::vector<int>& steps) {
    if (steps.size() == 1) return "step " + std::to_string(steps[0]);
    const bool contiguous = steps.back() - steps.front() + 1 == int(steps.size());
    if (contiguous) return "steps " + std::to_string(steps.front()) + "\u2013" + std::to_string(steps.back());
    std::string out = "steps ";
    for (std::size_t i = 0; i < steps.size(); ++i) out += (i ? ", " : "") + std::to_string(steps[i]);
    return out;
}

// Names a catalogue mistake on a check: the finding, the steps it costs and the sentence a student
// reads ("your blur sigma measures 1.0; the tutorial's is 2.5 (step 27)").
std::string findingText(const std::string& id, const std::vector<int>& steps, const std::vector<double>& value,
                        const std::string& note) {
    const Mistake& m = mistake(id);
    std::string text = "[" + id + "] ";
    if (!m.parameter.empty() && !value.empty()) {
        text += estimateText(m, value);
    } else if (id.size() > 8 && id.compare(id.size() - 8, 8, "-missing") == 0 && steps.size() > 1) {
        text += stepRange(steps) + " not implemented: " + m.text;
    } else {
        text += m.text;
    }
    if (!note.empty()) text += " (" + note + ")";
    return text + " (" + stepRange(steps) + ")";
}

void name(Check& check, const std::string& id, const std::vector<int>& steps, const std::vector<double>& value = {},
          const std::string& note = "", bool loose = false) {
    const Mistake& m = mistake(id);
    for (int step : steps)
        if (std::find(check.blame.begin(), check.blame.end(), step) == check.blame.end()) check.blame.push_back(step);
    std::sort(check.blame.begin(), check.blame.end());
    const std::string text = findingText(id, steps, value, note);
    check.mistakes.push_back(Finding{id, m.parameter, value, m.tutorial, steps, text, loose});
    check.diagnosis += (check.diagnosis.empty() ? "" : "; or ") + text;
}

// Rewrites the diagnosis and the blamed steps from the findings (or the unexplained text).
void rebuildDiagnosis(Check& check) {
    check.blame.clear();
    if (check.mistakes.empty()) {
        check.diagnosis = check.unexplained;
        check.blame = check.unexplainedBlame;
        return;
    }
    check.diagnosis = check.mistakes.size() > 1 ? "one of: " : "";
    for (std::size_t i = 0; i < check.mistakes.size(); ++i) {
        check.diagnosis += (i ? "; or " : "") + check.mistakes[i].text;
        for (int step : check.mistakes[i].steps)
            if (std::find(check.blame.begin(), check.blame.end(), step) == check.blame.end()) check.blame.push_back(step);
    }
    std::sort(check.blame.begin(), check.blame.end());
}

// A failure no catalogue mistake explains (no findings, or crossCheckCases dropped them) is one
// mistake the grader cannot place among the check's steps: it costs one step, `step` (the one whose
// arithmetic makes the buffer), not all of them, so that one wrong constant nobody modelled costs less
// than steps not done (issue 38). Steps not done show as such (nothing written, or `lookMissing`: the
// steps of a "-missing" model the buffer is nearer to than to the tutorial's) and keep their cost.
void chargeOneStep(Check& check, const std::string& what, int step, const std::vector<int>& lookMissing = {}) {
    std::set<int> charged(lookMissing.begin(), lookMissing.end());
    charged.insert(step);
    check.unexplainedBlame.assign(charged.begin(), charged.end());
    check.unexplained = what + "; it costs " +
                        (lookMissing.empty() ? "one step, step " + std::to_string(step) + ": one mistake that no model places among " +
                                                   stepRange(check.steps)
                                             : stepRange(check.unexplainedBlame) + ": it is nearer to " + stepRange(lookMissing) +
                                                   " not done than to the tutorial's, and step " + std::to_string(step) +
                                                   " for what else is wrong");
    rebuildDiagnosis(check);
}

// Keeps only the findings `keep` accepts (all of them if it accepts none) and rewrites the
// diagnosis and the blamed steps from them.
void keepFindings(Check& check, const std::function<bool(const Finding&)>& keep) {
    std::vector<Finding> kept;
    for (const Finding& f : check.mistakes)
        if (keep(f)) kept.push_back(f);
    if (kept.empty() || kept.size() == check.mistakes.size()) return;
    check.mistakes = kept;
    check.blame.clear();
    check.diagnosis = kept.size() > 1 ? "one of: " : "";
    for (std::size_t i = 0; i < kept.size(); ++i) {
        check.diagnosis += (i ? "; or " : "") + kept[i].text;
        for (int step : kept[i].steps)
            if (std::find(check.blame.begin(), check.blame.end(), step) == check.blame.end()) check.blame.push_back(step);
    }
    std::sort(check.blame.begin(), check.blame.end());
}

// Least-squares factor k and offset d of got ~ k * expected and got ~ expected + d over paired
// values, with the mean residual of each; says which shape the error has, or "".
std::string errorShape(const std::vector<double>& expected, const std::vector<double>& got, double unit,
                       const std::string& unitName) {
    if (expected.empty()) return "";
    const bool nothing = std::all_of(got.begin(), got.end(), [](double v) { return v == 0.0; });
    if (nothing) return "nothing written: every value is 0";
    std::size_t nans = 0;
    for (double v : got) nans += std::isfinite(v) ? 0 : 1;
    if (nans > 0) return std::to_string(nans) + " values are NaN or Inf";
    double se = 0.0, ee = 0.0, shift = 0.0;
    for (std::size_t i = 0; i < got.size(); ++i) {
        se += got[i] * expected[i];
        ee += expected[i] * expected[i];
        shift += got[i] - expected[i];
    }
    const double k = ee > 0.0 ? se / ee : 0.0;
    shift /= double(got.size());
    double factorResidual = 0.0, shiftResidual = 0.0;
    for (std::size_t i = 0; i < got.size(); ++i) {
        factorResidual += std::abs(got[i] - k * expected[i]);
        shiftResidual += std::abs(got[i] - expected[i] - shift);
    }
    factorResidual /= double(got.size());
    shiftResidual /= double(got.size());
    if (factorResidual <= 1.5 * unit && std::abs(k - 1.0) > 0.01)
        return "a constant factor: the values are " + format(k, 3) + " x the expected ones";
    if (shiftResidual <= 1.5 * unit && std::abs(shift) > unit)
        return "a shift: the values are the expected ones " + std::string(shift > 0 ? "+ " : "- ") +
               format(std::abs(shift) / unit, 3) + " " + unitName;
    return "";
}

// A catalogue mistake that is one tutorial constant set to another value: its id, the constant,
// the range a fit searches (log-spaced) and the steps it costs; named from `firstPart` on.
struct ModelParameter {
    const char* id;
    double ref::Settings::*field;
    double low, high;
    std::vector<int> steps;
    int firstPart;
};

// --- Luminance levels and the scene key (steps 3-5, 13, 15). -------------------------------------
// Luminance level 0's one-constant mistakes (step 4's epsilon, step 5's white point), each fitted
// to level 0 by nameLogLuminanceMistakes.
const ModelParameter kLogLuminanceParameters[] = {{"epsilon", &ref::Settings::epsilon, 1e-20, 1e-1, {4}, 1},
                                                  {"white-point", &ref::Settings::whitePoint, 0.02, 20.0, {5}, 1}};

// A model of luminance level 0: the reference's mapping with other settings or the other log.
struct KeyModel {
    ref::Settings settings;
    ref::MappedLog log = ref::MappedLog::Natural;
};

// One pixel's range-mapped log luminance as GL_R16 stores it, with the model's setting.
double modelMapped(const ref::Rgb& colour, const KeyModel& model) {
    const ref::Settings& s = model.settings;
    return ref::toUnorm16(ref::rangeMappedLogLuminance(ref::luminance(colour, s), s, model.log));
}

// Largest difference, in R16 steps, between luminance level 0 and a model of it.
double worstLuminanceSteps(const ImageF& level0, const ImageF& accumulation, const KeyModel& model) {
    if (level0.width != accumulation.width || level0.height != accumulation.height) return 1e9;
    double worst = 0.0;
    for (int y = 0; y < accumulation.height; ++y)
        for (int x = 0; x < accumulation.width; ++x) {
            const double d = std::abs(level0.at(x, y, 0) - modelMapped(texel(accumulation, x, y), model)) * 65535.0;
            worst = std::max(worst, std::isfinite(d) ? d : 1e9);
        }
    return worst;
}

// The luminance weights that explain level 0: the mapped values un-mapped to Y, then least squares
// of Y on the colour over the pixels the R16 store did not clamp. Empty when the input cannot tell
// the weights apart (grey pixels only).
std::optional<ref::Rgb> fitWeights(const ImageF& level0, const ImageF& accumulation) {
    if (level0.width != accumulation.width || level0.height != accumulation.height) return std::nullopt;
    double a[3][3] = {};
    double b[3] = {};
    for (int y = 0; y < accumulation.height; ++y)
        for (int x = 0; x < accumulation.width; ++x) {
            const double m = level0.at(x, y, 0);
            if (!(m > 0.3 && m < 0.999)) continue; // far from epsilon, below the white point
            const double lum = ref::keyFromMapped(m) - ref::kEpsilon;
            const ref::Rgb c = texel(accumulation, x, y);
            for (int i = 0; i < 3; ++i) {
                for (int j = 0; j < 3; ++j) a[i][j] += c[i] * c[j];
                b[i] += c[i] * lum;
            }
        }
    const auto det = [](const double m[3][3]) {
        return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    };
    const double d = det(a);
    const double scale = a[0][0] * a[1][1] * a[2][2];
    if (!(scale > 0.0) || std::abs(d) < 1e-9 * scale) return std::nullopt;
    ref::Rgb w{};
    for (int k = 0; k < 3; ++k) {
        double m[3][3];
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) m[i][j] = j == k ? b[i] : a[i][j];
        w[k] = det(m) / d;
    }
    return w;
}

// The value the final pass reads with its huge bias: the average of the smallest level written.
double gpuMappedKey(const t10::test::Dump& dump) {
    const int levels = dump.luminanceLevels();
    if (levels == 0) throw Error(dump.dir + ": no luminance texture on unit 16 (steps 12-13)");
    const ImageF last = dump.level(kLuminanceUnit, levels - 1);
    double sum = 0.0;
    for (int y = 0; y < last.height; ++y)
        for (int x = 0; x < last.width; ++x) sum += last.at(x, y, 0);
    return sum / (double(last.width) * double(last.height));
}

// --- The final frame (steps 6-10, 19-20, 35). -----------------------------------------------------
// Its models are the reference's variants of the final pass (ref::FrameVariant): the tutorial's,
// another value of one constant, or the pass written with one of the catalogue's mistakes.
using FrameModel = ref::FrameVariant;

// The frame's one-constant mistakes: the frame check fits each to one case, crossCheckCases to
// every case whose frame failed at once.
const ModelParameter kFrameParameters[] = {{"white-point", &ref::Settings::whitePoint, 0.02, 20.0, {9}, 1},
                                               {"middle-grey", &ref::Settings::middleGrey, 0.3, 3.0, {9}, 1},
                                               {"epsilon", &ref::Settings::epsilon, 1e-20, 1e-1, {9}, 1},
                                               {"bloom-weight", &ref::Settings::bloomWeight, 0.01, 10.0, {20}, 2}};

FrameModel withSetting(double ref::Settings::*field, double value) {
    FrameModel model;
    model.settings.*field = value;
    return model;
}

// The frame's mistakes without a constant to fit: each a model of the final pass taken as it is.
struct DiscreteModel {
    const char* id;
    std::vector<int> steps;
    FrameModel model;
    std::vector<double> value;
};

std::vector<DiscreteModel> frameDiscreteModels(int part, int luminanceLevels) {
    std::vector<DiscreteModel> models;
    FrameModel m;
    m.toneMap = false;
    models.push_back({"tone-map-missing", range(6, 10), m, {}});
    for (ref::Unmap unmap : {ref::Unmap::None, ref::Unmap::Log2ThenExp, ref::Unmap::LnThenExp2}) {
        m = FrameModel{};
        m.unmap = unmap;
        models.push_back({unmap == ref::Unmap::None ? "missing-unmapping" : "log2-exp-mismatch", {9}, m, {}});
    }
    m = FrameModel{};
    m.settings.lumaWeights = kRec601Weights;
    models.push_back({"luminance-weights", {9}, m, {kRec601Weights[0], kRec601Weights[1], kRec601Weights[2]}});
    for (int l = 0; l + 1 < luminanceLevels; ++l) {
        m = FrameModel{};
        m.keyLevel = l;
        models.push_back({"key-level", {8}, m, {double(l)}});
    }
    if (part >= 2) {
        m = FrameModel{};
        m.addBloom = false;
        models.push_back({"bloom-missing", {19, 20}, m, {}});
        m = FrameModel{};
        m.bloomAfterToneMap = true;
        models.push_back({"bloom-after-tonemap", {20}, m, {}});
    }
    if (part >= 3) {
        m = FrameModel{};
        m.lowerLeftQuarter = true;
        models.push_back({"viewport-reset", {35}, m, {}});
        m = FrameModel{};
        m.doubledUv = true;
        models.push_back({"ubo-reset", {35}, m, {}});
    }
    return models;
}

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
                     int step = 1) {
    ref::frameColours(in, model, colours, step);
    const int w = in.accumulation.width;
    double sum = 0.0;
    std::size_t count = 0;
    for (int y = 0; y < in.accumulation.height; y += step)
        for (int x = 0; x < w; x += step, ++count)
            for (int k = 0; k < 3; ++k) {
                // The level llvmpipe stores, unrounded, so that the residual varies smoothly with the value.
                sum += std::abs(ref::unorm8Level(colours[std::size_t(y) * w + x][k]) - frame.at(x, y, k));
            }
    return sum / (3.0 * double(count));
}

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
Fit refineFrameFit(double value, const std::function<double(double)>& roundedError) {
    return fitParameter(roundedError, value * 0.99, value * 1.01, false, 11, kFrameFitSteps);
}

// The frame check's tolerance: float vs double rounding moves a channel one step, rarely.
bool frameWithin(const t10::test::ByteError& e) { return e.max <= 1 && e.mean <= 0.01; }

// How the frame differs when no model explains it: its shape over the luminance of the pixels.
std::string describeFrame(const Image8& expected, const Image8& got) {
    std::vector<double> e, g;
    int x0 = got.width, y0 = got.height, x1 = -1, y1 = -1, off = 0, magenta = 0;
    for (int y = 0; y < got.height; ++y)
        for (int x = 0; x < got.width; ++x) {
            int worst = 0;
            for (int k = 0; k < 3; ++k) {
                e.push_back(expected.at(x, y, k));
                g.push_back(got.at(x, y, k));
                worst = std::max(worst, std::abs(int(expected.at(x, y, k)) - int(got.at(x, y, k))));
            }
            if (got.at(x, y, 0) == 255 && got.at(x, y, 1) == 0 && got.at(x, y, 2) == 255) ++magenta;
            if (worst <= 1) continue;
            ++off;
            x0 = std::min(x0, x);
            y0 = std::min(y0, y);
            x1 = std::max(x1, x);
            y1 = std::max(y1, y);
        }
    std::string shape = magenta > 0 ? std::to_string(magenta) + " pixels are NaN (painted magenta by the grader's probe)"
                                    : errorShape(e, g, 1.0, "8-bit steps");
    if (shape.empty()) shape = "no constant factor or shift explains it";
    return "the frame first goes wrong here, and no catalogue mistake explains it: " + shape + "; " +
           format(100.0 * off / (double(got.width) * got.height), 3) + "% of pixels differ by more than 1 step, within x " +
           std::to_string(x0) + "-" + std::to_string(x1) + ", y " + std::to_string(y0) + "-" + std::to_string(y1) +
           " (y up); look at the heat-map";
}

// --- The bloom threshold (steps 17-18). -----------------------------------------------------------
int misclassified(const ImageF& accumulation, const ImageF& gpu, double threshold, const ref::Rgb& weights) {
    int count = 0;
    for (int y = 0; y < accumulation.height; ++y)
        for (int x = 0; x < accumulation.width; ++x) {
            const double lum = ref::luminance(texel(accumulation, x, y), weights);
            const bool modelBright = lum >= threshold;
            const bool gpuBright = gpu.at(x, y, 0) + gpu.at(x, y, 1) + gpu.at(x, y, 2) > 0.0f;
            // Only a pixel within float rounding of the threshold may land on either side.
            if (modelBright != gpuBright && std::abs(lum - threshold) > 1e-6) ++count;
        }
    return count;
}

// The luminances between which the GPU's threshold lies: the brightest pixel left dark and the
// dimmest pixel kept. Consistent with a threshold when low < high.
struct ThresholdInterval {
    double low = 0.0;
    double high = 1e300;
};

ThresholdInterval thresholdInterval(const ImageF& accumulation, const ImageF& gpu, const ref::Rgb& weights) {
    ThresholdInterval interval;
    for (int y = 0; y < accumulation.height; ++y)
        for (int x = 0; x < accumulation.width; ++x) {
            const double lum = ref::luminance(texel(accumulation, x, y), weights);
            const bool gpuBright = gpu.at(x, y, 0) + gpu.at(x, y, 1) + gpu.at(x, y, 2) > 0.0f;
            if (gpuBright) interval.high = std::min(interval.high, lum);
            else interval.low = std::max(interval.low, lum);
        }
    return interval;
}

// --- The Gaussian blur (steps 27-34). -------------------------------------------------------------
struct PeakError {
    double worst = 0.0;
    double mean = 0.0;
};

PeakError peakError(const ImageF& gpu, const ImageF& cpu) {
    if (gpu.width != cpu.width || gpu.height != cpu.height) return {1e9, 1e9};
    const t10::test::LevelError error = t10::test::compareLevels(gpu, cpu);
    return {error.worstRelativeToPeak, error.meanRelativeToPeak};
}

bool allZero(const ImageF& image) {
    return std::all_of(image.data.begin(), image.data.end(), [](float v) { return v == 0.0f; });
}

// GL_R11F_G11F_B10F keeps 6 mantissa bits for red and green and 5 for blue: one unit in the last
// place is 2^-6 or 2^-5 of the value, whether the driver rounds or truncates.
constexpr double kRelativeStep[3] = {1.0 / 64.0, 1.0 / 64.0, 1.0 / 32.0};
constexpr double kDenormalStep = 1.0 / 16384.0 / 32.0;

double worstStoreError(const ImageF& gpu, const ImageF& cpu, const ImageF* classifiedBy = nullptr) {
    double worst = 0.0;
    for (int y = 0; y < cpu.height; ++y)
        for (int x = 0; x < cpu.width; ++x) {
            if (classifiedBy != nullptr) {
                // Texels the threshold classified differently are counted by the classification.
                const bool a = cpu.at(x, y, 0) + cpu.at(x, y, 1) + cpu.at(x, y, 2) > 0.0f;
                const bool b = gpu.at(x, y, 0) + gpu.at(x, y, 1) + gpu.at(x, y, 2) > 0.0f;
                if (a != b) continue;
            }
            for (int k = 0; k < 3; ++k) {
                const double bound = cpu.at(x, y, k) * kRelativeStep[k] + kDenormalStep;
                worst = std::max(worst, std::abs(gpu.at(x, y, k) - cpu.at(x, y, k)) / bound);
            }
        }
    return worst;
}

// --- Each blur pass (steps 27, 32-34), captured by --capture-passes. -------------------------------
struct CapturedPass {
    std::string subroutine; // the subroutine the pass ran with
    ImageF image;           // the texture level it drew into
};

// <dump>/blur_passes.txt and its blur_passNN.pfm; false when the program did not capture (no file).
bool loadPasses(const std::string& dir, std::vector<CapturedPass>& passes) {
    std::ifstream list(dir + "/blur_passes.txt");
    if (!list) return false;
    for (std::string line; std::getline(list, line);) {
        std::istringstream fields(line);
        int index = 0;
        CapturedPass pass;
        fields >> index >> pass.subroutine;
        char file[32];
        std::snprintf(file, sizeof(file), "blur_pass%02d.pfm", index);
        pass.image = t10::readPfm(dir + "/" + file);
        passes.push_back(std::move(pass));
    }
    return true;
}

std::string passName(std::size_t k) {
    return "pass " + std::to_string(k / 2 + 1) + (k % 2 == 0 ? " horizontal" : " vertical");
}

// The blur's tolerance, for the whole chain and for each pass: with the driver's store rule
// emulated what is left is float vs double and the bilinear weights, two blue steps of the peak at
// worst and 1e-4 of the peak on average (measured 2e-6 to 7e-7). A wrong tap, sigma or pass count
// moves the blur by tens of percent.
constexpr double kBlurWorst = 2.0 / 32.0;
constexpr double kBlurMean = 1e-4;
bool blurWithin(const PeakError& e) { return e.worst <= kBlurWorst && e.mean <= kBlurMean; }

// One Gaussian pass with a model's settings, stored as the GPU's R11G11B10F target stores it.
ImageF modelPass(const ImageF& source, int w, int h, bool horizontal, const ref::Settings& s, ref::FloatStore store) {
    ImageF out = ref::gaussianPass(source, w, h, horizontal, s);
    ref::storeR11G11B10F(out, store);
    return out;
}

// The blur's one-constant mistakes, fitted to a pass (fitPass) and made to agree across the cases
// (crossCheckCases).
const ModelParameter kBlurParameters[] = {{"blur-sigma", &ref::Settings::sigma, 0.2, 12.0, {27}, 3},
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
                                 ref::FloatStore store) {
    std::vector<BlurFinding> found;
    const auto error = [&](const ref::Settings& s, bool axis) { return peakError(gpu, modelPass(source, w, h, axis, s, store)); };
    for (const ModelParameter& p : kBlurParameters) {
        const Fit fit = fitParameter(
            [&](double v) {
                ref::Settings s;
                s.*(p.field) = v;
                return error(s, horizontal).mean;
            },
            p.low, p.high, true, 30);
        ref::Settings s;
        s.*(p.field) = fit.value;
        if (!blurWithin(error(s, horizontal))) continue;
        bool loose = true;
        for (double factor : {0.93, 1.07}) {
            ref::Settings off;
            off.*(p.field) = fit.value * factor;
            loose = loose && blurWithin(error(off, horizontal));
        }
        found.push_back({p.id, {fit.value}, s, false, loose});
    }
    if (blurWithin(error(ref::Settings{}, !horizontal))) found.push_back({"swapped-subroutines", {}, {}, true});
    return found;
}

std::string sigmaNote(const BlurFinding& f) {
    if (f.id == "blur-sigma" && std::abs(f.value[0] / ref::kSigma - 0.5) < 0.02)
        return "exactly half: offsets in full-resolution texels, not the half-size target's, do this";
    return "";
}

class CheckWriter {
public:
    CheckWriter(const CaseRun& run, std::string reportDir, std::string imageDir)
        : run_(run), reportDir_(std::move(reportDir)), imageDir_(std::move(imageDir)) {}

    Check make(const std::string& what, std::vector<int> steps) const {
        Check check;
        check.id = run_.id + "." + what;
        check.steps = std::move(steps);
        return check;
    }

    // Writes the student's frame, the expected frame and their difference heat-map.
    void attachImages(Check& check, const Image8& expected) const {
        std::filesystem::create_directories(imageDir_);
        const std::string base = (std::filesystem::path(imageDir_) / check.id).string();
        t10::writePng(base + ".student.png", run_.dump.frame);
        t10::writePng(base + ".expected.png", expected);
        t10::writePng(base + ".diff.png", t10::test::differenceHeatMap(expected, run_.dump.frame));
        check.studentImage = relative(base + ".student.png");
        check.referenceImage = relative(base + ".expected.png");
        check.heatMap = relative(base + ".diff.png");
    }

private:
    std::string relative(const std::string& path) const {
        return std::filesystem::relative(path, reportDir_).generic_string();
    }
    const CaseRun& run_;
    std::string reportDir_;
    std::string imageDir_;
};

} // namespace

namespace {

bool endsWith(const std::string& text, const std::string& suffix) {
    return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// A case's buffers as the frame models read them.
struct CaseFrame {
    CaseFrame(int part, const CaseRun& caseRun) : run(caseRun) {
        if (part >= 2) bloom1 = run.dump.bloom(1);
        inputs = std::make_unique<FrameInputs>(run.dump.accumulation, gpuMappedKey(run.dump), part >= 2 ? &bloom1 : nullptr, nullptr);
    }
    const CaseRun& run;
    ImageF bloom1;
    std::unique_ptr<FrameInputs> inputs;
};

// The checks of every case of one submission, looked up by kind ("frame" finds pot.frame, ...).
class AllCases {
public:
    AllCases(const std::vector<CaseRun>& runs, std::vector<Check>& checks) : runs_(runs), checks_(checks) {}

    const CaseRun* runOf(const Check& c) const {
        for (const CaseRun& run : runs_)
            if (c.id.rfind(run.id + ".", 0) == 0) return &run;
        return nullptr;
    }
    // The failed checks of `kind` that fail on their own (not following from an earlier one).
    std::vector<Check*> failed(const std::string& kind) const {
        std::vector<Check*> list;
        for (Check& c : checks_)
            if (!c.passed && !c.followsFrom && endsWith(c.id, "." + kind) && runOf(c) != nullptr) list.push_back(&c);
        return list;
    }

private:
    const std::vector<CaseRun>& runs_;
    std::vector<Check>& checks_;
};

bool names(const Check& c, const std::string& id) {
    return std::any_of(c.mistakes.begin(), c.mistakes.end(), [&](const Finding& f) { return f.id == id; });
}

void drop(Check& c, const std::string& id) {
    c.mistakes.erase(std::remove_if(c.mistakes.begin(), c.mistakes.end(), [&](const Finding& f) { return f.id == id; }),
                     c.mistakes.end());
}

// The bloom threshold: named only when one luminance interval separates the pixels in every case.
void reconcileThreshold(const AllCases& cases) {
    const std::vector<Check*> thresholds = cases.failed("bloom-threshold");
    if (std::none_of(thresholds.begin(), thresholds.end(), [&](const Check* c) { return names(*c, "bloom-threshold"); })) return;
    const ref::Rgb rec709{t10::contract::kLumaRed, t10::contract::kLumaGreen, t10::contract::kLumaBlue};
    ThresholdInterval joint;
    bool readable = true;
    for (const Check* c : thresholds) {
        const CaseRun* run = cases.runOf(*c);
        if (run->dump.levelCount(kBloomUnit) < 1) {
            readable = false; // a case without a bloom texture allows no threshold at all
            continue;
        }
        const ThresholdInterval i = thresholdInterval(run->dump.accumulation, run->dump.bloom(0), rec709);
        joint.low = std::max(joint.low, i.low);
        joint.high = std::min(joint.high, i.high);
    }
    const bool consistent = readable && joint.low > 0.0 && joint.low < joint.high && joint.high < 1e300;
    for (Check* c : thresholds) {
        if (!names(*c, "bloom-threshold")) continue;
        drop(*c, "bloom-threshold");
        c->unexplained = "bloom level 0 is the first buffer that goes wrong: no one luminance threshold separates the "
                         "pixels that bloom from those that do not in every input (step 18)";
        rebuildDiagnosis(*c);
        if (c->mistakes.empty()) c->blame = {18};
        if (consistent) {
            c->diagnosis.clear();
            name(*c, "bloom-threshold", {18}, {std::sqrt(joint.low * joint.high) / ref::kYwhite},
                 "between " + format(joint.low / ref::kYwhite, 3) + " and " + format(joint.high / ref::kYwhite, 3) +
                     " x Yw over every input");
            rebuildDiagnosis(*c);
        }
    }
}

// One frame constant fitted to every case at once; the cases' own fits of it are replaced by that
// value when it explains every case within the frame's tolerance, and dropped when it does not.
void fitFrameConstantJointly(const ModelParameter& p, const std::vector<Check*>& frames,
                             const std::vector<std::unique_ptr<CaseFrame>>& cases) {
    std::vector<double> values;
    std::vector<int> steps;
    for (const Check* c : frames)
        for (const Finding& f : c->mistakes)
            if (f.id == p.id) {
                values.push_back(f.value[0]);
                steps = f.steps;
            }
    const auto model = [&p](double v) { return withSetting(p.field, v); };
    std::vector<ref::Rgb> scratch;
    const Fit rough = fitParameter(
        [&](double v) {
            double sum = 0.0;
            for (const auto& c : cases) sum += frameResidual(*c->inputs, model(v), c->run.dump.frame, scratch, kRoughFrameStep);
            return sum;
        },
        *std::min_element(values.begin(), values.end()) * 0.5, *std::max_element(values.begin(), values.end()) * 2.0, true, 12,
        kRoughFrameFitSteps, kFrameFitStarts, kFrameResidualCeiling * double(cases.size()));
    const Fit fit = refineFrameFit(rough.value, [&](double v) {
        double sum = 0.0;
        for (const auto& c : cases) {
            const auto e = t10::test::byteError(ref::finalFrame(*c->inputs, model(v)), c->run.dump.frame);
            sum += e.mean + e.fractionOverOne;
        }
        return sum;
    });
    bool everyCase = true;
    for (const auto& c : cases)
        everyCase = everyCase && frameWithin(t10::test::byteError(ref::finalFrame(*c->inputs, model(fit.value)), c->run.dump.frame));
    for (Check* c : frames) {
        drop(*c, p.id);
        rebuildDiagnosis(*c);
        if (everyCase) {
            c->diagnosis.clear();
            name(*c, p.id, steps, {fit.value});
            rebuildDiagnosis(*c);
        }
    }
}

// The frame's constants: a constant the student wrote is the same in every render.
void reconcileFrameConstants(int part, const AllCases& all) {
    std::vector<Check*> frames;
    std::vector<std::unique_ptr<CaseFrame>> cases;
    std::set<std::string> named;
    for (Check* c : all.failed("frame")) {
        // A frame check exists only where the case's buffers were read (bufferChecks got that far).
        if (part >= 2 && all.runOf(*c)->dump.levelCount(kBloomUnit) < 2) continue;
        const bool discreteOnly = !c->mistakes.empty() && std::none_of(c->mistakes.begin(), c->mistakes.end(),
                                                                          [](const Finding& f) { return f.value.size() == 1; });
        if (discreteOnly) continue;
        frames.push_back(c);
        cases.push_back(std::make_unique<CaseFrame>(part, *all.runOf(*c)));
        for (const Finding& f : c->mistakes)
            if (f.value.size() == 1 && f.id != "key-level") named.insert(f.id);
    }
    if (frames.size() < 2) return;
    for (const ModelParameter& p : kFrameParameters)
        if (named.count(p.id) != 0) fitFrameConstantJointly(p, frames, cases);
}

// The blur's constants: a case that does not pin a constant down takes the value of the cases that
// do (their median).
void reconcileBlurConstants(const AllCases& all) {
    for (const char* kind : {"blur-passes", "blur"}) {
        const std::vector<Check*> list = all.failed(kind);
        for (const ModelParameter& p : kBlurParameters) {
            std::vector<double> pinned;
            for (const Check* c : list)
                for (const Finding& f : c->mistakes)
                    if (f.id == p.id && !f.loose && f.value.size() == 1) pinned.push_back(f.value[0]);
            if (pinned.empty()) continue;
            std::sort(pinned.begin(), pinned.end());
            const double median = pinned[pinned.size() / 2];
            for (Check* c : list)
                for (Finding& f : c->mistakes)
                    if (f.id == p.id && f.loose) {
                        f.value = {median};
                        f.loose = false;
                        f.text = findingText(p.id, f.steps, f.value, "measured in the other inputs; this one does not pin it down");
                        rebuildDiagnosis(*c);
                    }
        }
    }
}

// The frame's names must explain every case: a frame check keeps a finding only when the frame
// check of every other case that fails on its own names it too (a mistake that shows as "no bloom"
// where the bloom is saturated anyway, but not elsewhere, is not that mistake). The frame is what
// every case renders whole, so a case whose frame no model explains vetoes every name. The buffer
// checks keep, of several findings, those every other case names: a case whose inputs do not pin a
// blur constant down (the extremes case's pass 1) does not veto the name the others measure.
void keepFindingsOfEveryCase(const AllCases& all) {
    const std::vector<Check*> frames = all.failed("frame");
    std::set<std::string> everywhere;
    for (const Finding& f : frames.empty() ? std::vector<Finding>{} : frames.front()->mistakes) everywhere.insert(f.id);
    for (const Check* c : frames)
        for (auto it = everywhere.begin(); it != everywhere.end();)
            it = names(*c, *it) ? std::next(it) : everywhere.erase(it);
    for (Check* c : frames) {
        const std::size_t before = c->mistakes.size();
        c->mistakes.erase(std::remove_if(c->mistakes.begin(), c->mistakes.end(),
                                         [&](const Finding& f) { return everywhere.count(f.id) == 0; }),
                          c->mistakes.end());
        if (c->mistakes.size() == before) continue;
        if (c->mistakes.empty() && c->unexplained.empty())
            c->unexplained = "no catalogue mistake explains this check in every input: compare what " + stepRange(c->steps) +
                             " write with the tutorial";
        rebuildDiagnosis(*c);
    }
    for (const char* kind : {"log-luminance", "blur-passes", "blur"}) {
        std::vector<Check*> list;
        for (Check* c : all.failed(kind))
            if (!c->mistakes.empty()) list.push_back(c);
        for (Check* c : list) {
            if (c->mistakes.size() < 2) continue;
            keepFindings(*c, [&](const Finding& f) {
                return std::all_of(list.begin(), list.end(), [&](const Check* o) { return names(*o, f.id); });
            });
        }
    }
}

} // namespace

void crossCheckCases(int part, const std::vector<CaseRun>& runs, std::vector<Check>& checks) {
    const AllCases all(runs, checks);
    reconcileThreshold(all);
    reconcileFrameConstants(part, all);
    reconcileBlurConstants(all);
    keepFindingsOfEveryCase(all);
}

std::vector<int> partSteps(int part) { return range(1, part == 1 ? 16 : part == 2 ? 25 : 36); }

std::vector<int> frameSteps(int part) {
    std::vector<int> steps = range(6, 10);
    if (part >= 2) steps.insert(steps.end(), {19, 20});
    if (part >= 3) steps.push_back(35);
    return steps;
}

std::vector<int> failedSteps(const Check& check) {
    if (check.passed || check.followsFrom) return {};
    return check.blame.empty() ? check.steps : check.blame;
}

t10::test::Dump loadDumpDir(const std::string& dir) {
    t10::test::Dump dump;
    dump.dir = dir;
    dump.accumulation = t10::readPfm(dump.path(t10::dumpFileName(t10::contract::kAccumulationUnit, 0)));
    dump.frame = t10::readPng(dump.path("frame.png"));
    return dump;
}

namespace {

// --- One case's checks, as a table. ---------------------------------------------------------------

// One case's checks in the making: the buffers they read and what the earlier checks found.
struct CaseState {
    CaseState(int partNumber, const CaseRun& caseRun, const CheckWriter& checkWriter)
        : part(partNumber), dump(caseRun.dump), acc(caseRun.dump.accumulation), writer(checkWriter) {}
    int part;
    const t10::test::Dump& dump;
    const ImageF& acc;
    const CheckWriter& writer;
    std::vector<Check> checks;              // the checks made so far, in the table's order
    std::optional<ref::Rgb> studentWeights; // log-luminance: the weights that explain level 0
    double gpuKey = 0.0;                    // the mapped key the final pass reads
    ImageF bloom0, bloom1;                  // Part 2 on: the bloom texture's two levels
    // Part 3: the captured blur passes and what the first failing one measured.
    std::vector<CapturedPass> passes;
    bool captured = false;
    ref::FloatStore store{};
    std::vector<BlurFinding> passFindings;
    int pairs = ref::kBlurPasses;
};

// A check of the table: `what` names it within the case ("pot.key"); `followsFrom` lists the
// earlier checks whose failure it may inherit (the only ones its function reads, through
// earlier()); `run` fills in the check and returns false when the checks after it cannot run.
struct CheckSpec {
    const char* what;
    int firstPart;
    int lastPart;
    std::vector<int> (*steps)(int part);
    std::vector<const char*> followsFrom;
    bool (*run)(CaseState& state, const CheckSpec& spec, Check& check);
};

// The check `what` made earlier for this case; `spec` must list it in followsFrom. `what` is a C string,
// not a std::string: g++ 14's -Wdangling-reference takes a reference returned from a call with a
// temporary string argument for a reference into that temporary.
Check& earlier(CaseState& state, const CheckSpec& spec, const char* what) {
    const bool declared = std::any_of(spec.followsFrom.begin(), spec.followsFrom.end(),
                                      [&](const char* w) { return std::strcmp(what, w) == 0; });
    for (Check& check : state.checks)
        if (declared && endsWith(check.id, std::string(".") + what)) return check;
    throw Error(std::string("grader bug: check ") + spec.what + " reads " + what + ", which it does not follow from or which did not run");
}

// The check inherits the failure of `from`: it costs nothing of its own.
void inherit(Check& check, const Check& from, const std::string& why) {
    check.followsFrom = true;
    check.diagnosis = "follows from " + from.id + (why.empty() ? " (see its diagnosis)" : ": " + why);
}

// Luminance mip chain (step 13): floor(log2(max)) + 1 levels reach the 1x1 key.
bool luminanceLevelsCheck(CaseState& state, const CheckSpec&, Check& check) {
    const int side = std::max(state.acc.width, state.acc.height);
    const int expected = int(std::floor(std::log2(side))) + 1;
    const int levels = state.dump.luminanceLevels();
    check.passed = levels == expected;
    check.measured = std::to_string(levels) + " levels on unit 16 at " + std::to_string(state.acc.width) + "x" +
                     std::to_string(state.acc.height);
    check.tolerance = "exactly floor(log2(" + std::to_string(side) + ")) + 1 = " + std::to_string(expected) +
                      ": fewer levels never reach the 1x1 average, more cannot be allocated";
    if (!check.passed) {
        if (levels == int(std::ceil(std::log2(side)))) name(check, "ceil-log2-levels", {13});
        else if (levels == 0) check.diagnosis = "no luminance texture on unit 16 (steps 12-13)";
        else chargeOneStep(check, "the luminance texture does not have the full mip chain", 13);
    }
    return true;
}

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
double logLuminanceTolerance(const KeyModel& model) {
    const auto range = [](const ref::Settings& s) { return std::log(s.whitePoint) - std::log(s.epsilon); };
    const double own = range(model.settings);
    if (!(own > 0.0)) return kLogLuminanceSteps;
    return kLogLuminanceSteps * std::max(1.0, range(ref::Settings{}) / own);
}

// The models of luminance level 0 that explain it within the tolerance, named on the check.
void nameLogLuminanceMistakes(CaseState& state, const ImageF& level0, Check& check) {
    const ImageF& acc = state.acc;
    if (const std::optional<ref::Rgb> w = fitWeights(level0, acc)) {
        KeyModel model;
        model.settings.lumaWeights = *w;
        if (worstLuminanceSteps(level0, acc, model) <= kLogLuminanceSteps) {
            state.studentWeights = *w;
            name(check, "luminance-weights", {3}, {(*w)[0], (*w)[1], (*w)[2]});
        }
    }
    for (const ModelParameter& p : kLogLuminanceParameters) {
        const auto model = [&](double v) {
            KeyModel m;
            m.settings.*(p.field) = v;
            return m;
        };
        const Fit fit = fitParameter([&](double v) { return worstLuminanceSteps(level0, acc, model(v)); }, p.low, p.high, true);
        if (fit.error <= logLuminanceTolerance(model(fit.value))) name(check, p.id, p.steps, {fit.value});
    }
    KeyModel log2Pass;
    log2Pass.log = ref::MappedLog::Log2Luminance;
    if (worstLuminanceSteps(level0, acc, log2Pass) <= kLogLuminanceSteps) name(check, "log2-exp-mismatch", {4});
}

// Luminance level 0 (steps 3-5): every pixel's range-mapped log luminance.
bool logLuminanceCheck(CaseState& state, const CheckSpec&, Check& check) {
    const ImageF& acc = state.acc;
    const ImageF level0 = state.dump.level(kLuminanceUnit, 0);
    const double worst = worstLuminanceSteps(level0, acc, KeyModel{});
    check.passed = worst <= kLogLuminanceSteps;
    check.measured = "largest difference " + format(worst) + " R16 steps (1/65535 of the mapped range) over " +
                     std::to_string(acc.width) + "x" + std::to_string(acc.height) + " pixels";
    check.tolerance = "<= 4 R16 steps: float vs double rounding, and off-centre sampling beside bright "
                      "pixels (2 measured); a wrong weight or base is hundreds of steps off";
    if (check.passed) return true;
    nameLogLuminanceMistakes(state, level0, check);
    if (check.mistakes.empty()) {
        std::vector<double> expected, got;
        for (int y = 0; y < acc.height && level0.width == acc.width; ++y)
            for (int x = 0; x < acc.width; ++x) {
                expected.push_back(modelMapped(texel(acc, x, y), KeyModel{}));
                got.push_back(level0.at(x, y, 0));
            }
        const std::string shape = errorShape(expected, got, 1.0 / 65535.0, "R16 steps");
        check.diagnosis = "luminance level 0 is the first buffer that goes wrong, and no catalogue mistake "
                          "explains it" + (shape.empty() ? std::string() : ": " + shape) +
                          "; check the luminance, log and range mapping of PostProcessInit.frag (steps 3-5)";
        // Nothing written is steps 3-5 not done; anything else is one mistake in one of them.
        if (shape.rfind("nothing written", 0) != 0) chargeOneStep(check, check.diagnosis, 5);
    }
    return true;
}

// The scene key (steps 3-5, 15): the smallest level against the CPU log-average.
bool keyCheck(CaseState& state, const CheckSpec& spec, Check& check) {
    const ImageF& acc = state.acc;
    state.gpuKey = gpuMappedKey(state.dump);
    const double cpu = ref::meanMappedLogLuminance(acc, true);
    const int roundings = std::max(0, state.dump.luminanceLevels() - 1);
    const bool exactChain = (acc.width & (acc.width - 1)) == 0 && (acc.height & (acc.height - 1)) == 0;
    // Power-of-two sizes: every 2x2 average is exact and each level rounds to R16 once, half a step
    // per level. Other sizes: glGenerateMipmap's filter is implementation-defined for odd levels, so
    // 2% of the mapped range (0.34 in log luminance); a wrong formula is far beyond either.
    const double bound = exactChain ? (0.5 * roundings + 0.01) / 65535.0 : 0.02;
    check.passed = std::abs(state.gpuKey - cpu) <= bound;
    check.measured = "mapped key " + format(state.gpuKey, 6) + ", CPU " + format(cpu, 6) + " (difference " +
                     format(std::abs(state.gpuKey - cpu) * 65535.0) + " R16 steps)";
    check.tolerance = exactChain ? "<= " + format(bound * 65535.0) + " R16 steps: half a step of rounding per mip level"
                                 : "<= 1311 R16 steps (0.02 of the mapped range): glGenerateMipmap filters odd sizes as "
                                   "the driver likes";
    if (check.passed) return true;
    const Check& level0 = earlier(state, spec, "log-luminance");
    const Check& levels = earlier(state, spec, "luminance-levels");
    if (!level0.passed) {
        inherit(check, level0, "the key averages luminance level 0");
    } else if (!levels.passed) {
        inherit(check, levels, "the smallest level written is not the 1x1 average");
    } else {
        check.diagnosis = "level 0 is right but its average through the mip chain is not: check "
                          "glGenerateMipmap on the luminance texture (step 15)";
        check.blame = {15};
    }
    return true;
}

// What a bloom level 0 with pixels on the wrong side of the threshold means.
void diagnoseThreshold(CaseState& state, const CheckSpec& spec, const ref::Rgb& rec709, Check& check) {
    if (state.studentWeights && misclassified(state.acc, state.bloom0, ref::kBloomThreshold, *state.studentWeights) == 0) {
        inherit(check, earlier(state, spec, "log-luminance"), "the threshold tests the luminance of step 3, whose weights are wrong");
        return;
    }
    const ThresholdInterval interval = thresholdInterval(state.acc, state.bloom0, rec709);
    if (interval.low < interval.high && interval.high < 1e300 && interval.low > 0.0) {
        const double factor = std::sqrt(interval.low * interval.high) / ref::kYwhite;
        name(check, "bloom-threshold", {18}, {factor},
             "between " + format(interval.low / ref::kYwhite, 3) + " and " + format(interval.high / ref::kYwhite, 3) +
                 " x Yw: the input has no luminance in between");
    } else {
        check.diagnosis = "bloom level 0 is the first buffer that goes wrong: no luminance threshold separates the "
                          "pixels that bloom from those that do not (step 18)";
    }
}

// Bloom level 0 (steps 17-18): exactly the pixels at or above 2.95 x Yw, with their colour. Without
// a two-level bloom texture nothing after it can be checked.
bool bloomThresholdCheck(CaseState& state, const CheckSpec& spec, Check& check) {
    const ImageF& acc = state.acc;
    if (state.dump.levelCount(kBloomUnit) < 2) {
        check.measured = std::to_string(state.dump.levelCount(kBloomUnit)) + " levels on unit 17";
        check.tolerance = "the bloom texture has 2 levels (step 22)";
        check.diagnosis = "no two-level bloom texture on unit 17 (steps 21-23)";
        check.blame = range(17, 25);
        return false;
    }
    state.bloom0 = state.dump.bloom(0);
    state.bloom1 = state.dump.bloom(1);
    const ImageF cpu = ref::bloomThreshold(acc);
    const ref::Rgb rec709{t10::contract::kLumaRed, t10::contract::kLumaGreen, t10::contract::kLumaBlue};
    const int wrong = misclassified(acc, state.bloom0, ref::kBloomThreshold, rec709);
    const double worst = wrong == 0 ? worstStoreError(state.bloom0, cpu, &cpu) : 0.0;
    check.passed = wrong == 0 && worst <= 1.0;
    check.measured = std::to_string(wrong) + " pixels on the wrong side of the threshold; worst colour error " +
                     format(worst) + " R11G11B10F steps";
    check.tolerance = "0 misclassified (pixels within 1e-6 of the threshold excepted: float vs double), colour "
                      "within 1 step of GL_R11F_G11F_B10F (6/5 mantissa bits)";
    if (check.passed) return true;
    if (allZero(state.bloom0) && !allZero(cpu)) {
        check.diagnosis = "step 18 not implemented: bloom level 0 is black, nothing was written to location 1";
        check.blame = {17, 18};
    } else if (wrong == 0) {
        check.diagnosis = "the right pixels bloom but with the wrong colour (" + format(worst) +
                          " R11G11B10F steps off): write the accumulation colour to location 1 (step 18)";
        check.blame = {18};
    } else {
        diagnoseThreshold(state, spec, rec709, check);
    }
    return true;
}

// Bloom level 1 in Part 2 (steps 22, 24): the 2x2 average glGenerateMipmap writes (exact for even sizes).
bool bloomDownsampleCheck(CaseState& state, const CheckSpec&, Check& check) {
    const ImageF cpu = ref::boxDownsample(state.bloom0);
    const bool even = state.acc.width % 2 == 0 && state.acc.height % 2 == 0;
    const double worst = state.bloom1.width == cpu.width && state.bloom1.height == cpu.height ? worstStoreError(state.bloom1, cpu) : 1e9;
    check.passed = worst <= (even ? 1.0 : 64.0);
    check.measured = "worst error " + format(worst) + " R11G11B10F steps against the 2x2 average of level 0";
    check.tolerance = even ? "<= 1 step: each texel averages exactly four level-0 texels and is stored once"
                           : "<= 64 steps: odd sizes are filtered as the driver likes";
    if (!check.passed) {
        if (allZero(state.bloom1) && !allZero(state.bloom0)) name(check, "bloom-level1-missing", {24});
        else chargeOneStep(check, "bloom level 1 is the first buffer that goes wrong, and it is not the 2x2 average "
                                  "of level 0: check glGenerateMipmap on unit 17", 24);
    }
    return true;
}

// The first failing blur pass: what it measured, and the sigma, tap or axis models that explain it.
void diagnosePass(CaseState& state, std::size_t k, const ImageF& source, const ImageF& expected, Check& check) {
    const bool horizontal = k % 2 == 0;
    const int w = std::max(1, state.bloom0.width / 2);
    const int h = std::max(1, state.bloom0.height / 2);
    state.passFindings = fitPass(source, state.passes[k].image, w, h, horizontal, state.store);
    // Named now; the whole blur after it keeps those its chain confirms.
    for (const BlurFinding& f : state.passFindings) {
        const std::vector<int> steps = f.id == "swapped-subroutines" ? std::vector<int>{horizontal ? 32 : 33} : std::vector<int>{27};
        name(check, f.id, steps, f.value, sigmaNote(f), f.loose);
    }
    if (!state.passFindings.empty()) return;
    std::vector<double> e, g;
    for (std::size_t i = 0; i < expected.data.size() && i < state.passes[k].image.data.size(); ++i) {
        e.push_back(expected.data[i]);
        g.push_back(state.passes[k].image.data[i]);
    }
    const std::string shape = errorShape(e, g, 1e-3, "");
    check.diagnosis = passName(k) + " is the first that goes wrong, and no sigma, tap or axis explains it" +
                      (shape.empty() ? std::string() : ": " + shape) +
                      "; check Gauss.frag's offsets and weights, and the texture this pass reads (steps 27, 32-34)";
    check.blame = {27};
}

// Every blur pass (steps 27, 32-34): each captured pass against one CPU Gaussian pass of the texture
// the GPU wrote one pass earlier (bloom level 0 for the first), so the first pass that goes wrong is
// named, whatever the passes after it do.
bool blurPassesCheck(CaseState& state, const CheckSpec&, Check& check) {
    state.captured = loadPasses(state.dump.dir, state.passes);
    state.store = ref::detectFloatStore(state.bloom0, ref::bloomThreshold(state.acc));
    if (state.captured && state.passes.size() % 2 == 0) state.pairs = int(state.passes.size()) / 2;
    const int w = std::max(1, state.bloom0.width / 2);
    const int h = std::max(1, state.bloom0.height / 2);
    check.tolerance = "each pass: worst <= 2/32 of the peak (two R11G11B10F blue steps), mean <= 1e-4 of the "
                      "peak, against one CPU pass of the GPU's previous pass";
    check.passed = state.captured && !state.passes.empty();
    if (!state.captured) {
        check.measured = "no pass was captured (the grader's capture did not run)";
        check.diagnosis = "the program did not run the frame loop's pass capture (--capture-passes)";
    } else if (state.passes.empty()) {
        check.measured = "the blur program drew no pass into a texture";
        check.diagnosis = "no blur pass: check the blur framebuffers and draws (steps 30, 32-34)";
    }
    std::string worstText;
    double worstMean = -1.0;
    for (std::size_t k = 0; k < state.passes.size() && check.passed; ++k) {
        const ImageF& source = k == 0 ? state.bloom0 : state.passes[k - 1].image;
        const ImageF expected = modelPass(source, w, h, k % 2 == 0, ref::Settings{}, state.store);
        const PeakError error = peakError(state.passes[k].image, expected);
        const std::string figures = passName(k) + " (subroutine " + state.passes[k].subroutine + "): worst " +
                                    format(error.worst) + " of the peak, mean " + format(error.mean) + " of the peak";
        if (blurWithin(error)) {
            if (error.mean > worstMean) {
                worstMean = error.mean;
                worstText = figures;
            }
            continue;
        }
        check.passed = false;
        check.measured = "first failing pass: " + figures +
                         (k == 0 ? "" : k == 1 ? " (the pass before it is within tolerance)"
                                               : " (the " + std::to_string(k) + " passes before it are within tolerance)");
        diagnosePass(state, k, source, expected, check);
    }
    if (check.passed) check.measured = std::to_string(state.passes.size()) + " passes within tolerance; the farthest: " + worstText;
    return true;
}

// The number of passes (step 34): five pairs, counted from the captured draws.
bool blurPassCountCheck(CaseState& state, const CheckSpec& spec, Check& check) {
    const std::size_t drawn = state.passes.size();
    const int expectedPasses = 2 * ref::kBlurPasses;
    check.passed = state.captured && int(drawn) == expectedPasses;
    check.measured = std::to_string(drawn) + " blur passes drawn into textures";
    check.tolerance = "exactly " + std::to_string(expectedPasses) + " (" + std::to_string(ref::kBlurPasses) +
                      " horizontal + vertical pairs): the count is exact";
    if (check.passed) return true;
    if (state.captured && drawn == 0) name(check, "blur-missing", range(27, 34));
    else if (state.captured && drawn % 2 == 0) name(check, "blur-passes", {34}, {double(state.pairs)});
    else if (state.captured) check.diagnosis = std::to_string(drawn) + " passes, not whole horizontal + vertical pairs (step 34)";
    else check.diagnosis = earlier(state, spec, "blur-passes").diagnosis;
    return true;
}

// What a bloom level 1 that is not the blur of level 0 means, given what the passes measured.
void diagnoseBlur(CaseState& state, const CheckSpec& spec, Check& check) {
    Check& passCheck = earlier(state, spec, "blur-passes");
    // The chain with what the passes measured: the counted pairs and each fitted constant.
    const auto chain = [&](const ref::Settings& s, int n) { return peakError(state.bloom1, ref::gaussianBloom(state.bloom0, n, state.store, s)); };
    bool named = false;
    for (const BlurFinding& f : state.passFindings) {
        if (f.otherAxis) continue;
        if (blurWithin(chain(f.settings, state.pairs))) {
            name(check, f.id, {27}, f.value, sigmaNote(f), f.loose);
            named = true;
        }
    }
    // A constant that explains the first pass but not the chain of passes is not the student's.
    if (named) {
        keepFindings(passCheck, [&](const Finding& f) { return names(check, f.id); });
        return;
    }
    const bool swapped = std::any_of(state.passFindings.begin(), state.passFindings.end(), [](const BlurFinding& f) { return f.otherAxis; });
    if (swapped) {
        inherit(check, passCheck, "");
    } else if (state.pairs != ref::kBlurPasses && blurWithin(chain(ref::Settings{}, state.pairs))) {
        name(check, "blur-passes", {34}, {double(state.pairs)});
    } else if (blurWithin(peakError(state.bloom1, ref::boxDownsample(state.bloom0)))) {
        name(check, "blur-missing", range(27, 34));
    } else if (!passCheck.passed) {
        inherit(check, passCheck, "");
    } else {
        check.diagnosis = "every captured pass is right but level 1 is not their result: check which texture the "
                          "last pass draws into (steps 32-34)";
        check.blame = {32, 33, 34};
    }
}

// Bloom level 1 after the blur (steps 27-34): the CPU passes from the GPU's level 0.
bool blurCheck(CaseState& state, const CheckSpec& spec, Check& check) {
    const ImageF cpu = ref::gaussianBloom(state.bloom0, ref::kBlurPasses, state.store);
    const PeakError error = peakError(state.bloom1, cpu);
    check.passed = blurWithin(error);
    check.measured = "worst " + format(error.worst) + " of the peak, mean " + format(error.mean) + " of the peak";
    check.tolerance = "worst <= 2/32 of the peak (two R11G11B10F blue steps), mean <= 1e-4 of the peak";
    if (check.passed) return true;
    // Level 1 holds nothing because nothing drew into it, not because the passes drawn into it wrote
    // black (then it follows from blur-passes: the UV or the input of the passes is wrong).
    const bool passesWroteBlack = state.captured && !state.passes.empty() && allZero(state.passes.back().image);
    if (allZero(state.bloom1) && !passesWroteBlack) name(check, "bloom-level1-missing", {24});
    else diagnoseBlur(state, spec, check);
    return true;
}

// Whether every pixel off by more than a step is black in the input (the tone map's 0 / 0), and
// there is at least one.
bool onlyBlackPixelsOff(const ImageF& acc, const Image8& expected, const Image8& frame) {
    bool anyBlack = false;
    for (int y = 0; y < acc.height; ++y)
        for (int x = 0; x < acc.width; ++x) {
            int worst = 0;
            for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(int(expected.at(x, y, k)) - int(frame.at(x, y, k))));
            if (worst <= 1) continue;
            const ref::Rgb c = texel(acc, x, y);
            if (c[0] != 0.0 || c[1] != 0.0 || c[2] != 0.0) return false;
            anyBlack = true;
        }
    return anyBlack;
}

// The frame's models (frameDiscreteModels, kFrameParameters) that explain it, named on the check.
void nameFrameMistakes(CaseState& state, const ImageF* bloom, Check& check) {
    std::vector<ImageF> levels;
    for (int l = 0; l < state.dump.luminanceLevels(); ++l) levels.push_back(state.dump.level(kLuminanceUnit, l));
    const FrameInputs withLevels{state.acc, state.gpuKey, bloom, &levels};
    const auto frameError = [&](const FrameModel& m) { return t10::test::byteError(ref::finalFrame(withLevels, m), state.dump.frame); };
    std::vector<ref::Rgb> scratch;
    for (const DiscreteModel& d : frameDiscreteModels(state.part, int(levels.size())))
        if (!names(check, d.id) && frameWithin(frameError(d.model))) name(check, d.id, d.steps, d.value);
    for (const ModelParameter& p : kFrameParameters) {
        if (state.part < p.firstPart) continue;
        const auto model = [&p](double v) { return withSetting(p.field, v); };
        const auto residual = [&](double v) { return frameResidual(withLevels, model(v), state.dump.frame, scratch, kRoughFrameStep); };
        const Fit rough = fitParameter(residual, p.low, p.high, true, 16, kRoughFrameFitSteps, kFrameFitStarts, kFrameResidualCeiling);
        if (rough.error > kFrameResidualCeiling) continue;
        const Fit fit = refineFrameFit(rough.value, [&](double v) {
            const auto e = frameError(model(v));
            return e.mean + e.fractionOverOne;
        });
        if (frameWithin(frameError(model(fit.value)))) name(check, p.id, p.steps, {fit.value});
    }
}

// The steps of the frame's "-missing" models (no tone map, no bloom) that the submission's frame is
// nearer to than to the tutorial's, up to a gain: over the channels where the two frames differ by more
// than a step, the frame is closer in direction (cosine) to the model's than to the tutorial's. Steps
// that look not done then cost their points even where something else is wrong too (no bloom and
// another mistake: no one model names it), while a wrong constant, which mostly scales the tone map's
// output, stays nearer the tutorial's frame (a darker frame is not a frame without its bloom).
std::vector<int> lookMissing(const CaseState& state, const FrameInputs& inputs, const Image8& expected) {
    const Image8& got = state.dump.frame;
    std::set<int> steps;
    for (const DiscreteModel& d : frameDiscreteModels(state.part, 0)) {
        if (!endsWith(d.id, "-missing")) continue;
        const Image8 missing = ref::finalFrame(inputs, d.model);
        double gt = 0.0, tt = 0.0, gm = 0.0, mm = 0.0;
        for (int y = 0; y < got.height; ++y)
            for (int x = 0; x < got.width; ++x)
                for (int k = 0; k < 3; ++k) {
                    const double e = expected.at(x, y, k), m = missing.at(x, y, k), g = got.at(x, y, k);
                    if (std::abs(e - m) <= 1.0) continue;
                    gt += g * e;
                    tt += e * e;
                    gm += g * m;
                    mm += m * m;
                }
        // cos(got, missing) > cos(got, tutorial), both >= 0 for 8-bit values; a black model is no match.
        if (mm > 0.0 && tt > 0.0 && gm * gm * tt > gt * gt * mm) steps.insert(d.steps.begin(), d.steps.end());
    }
    return {steps.begin(), steps.end()};
}

// The final frame (steps 6-10, 19-20, 35): the CPU tone map of the GPU's own buffers. The GPU
// evaluates in float, the reference in double from the same read-back buffers: a channel lands one
// step away only next to a rounding boundary, so at most 1 step and rarely.
bool frameCheck(CaseState& state, const CheckSpec& spec, Check& check) {
    const ImageF* bloom = state.part >= 2 ? &state.bloom1 : nullptr;
    const FrameInputs inputs{state.acc, state.gpuKey, bloom, nullptr};
    const Image8 expected = ref::finalFrame(inputs, FrameModel{});
    const auto error = t10::test::byteError(expected, state.dump.frame);
    check.passed = frameWithin(error);
    check.measured = "largest error " + std::to_string(error.max) + " 8-bit steps, mean " + format(error.mean) +
                     " 8-bit steps, " + format(error.fractionOverOne * 100.0) + "% of pixels off by more than 1 step";
    check.tolerance = "largest <= 1 8-bit step and mean <= 0.01 8-bit steps: float vs double rounding only";
    if (check.passed) return true;
    state.writer.attachImages(check, expected);
    const Check& levels = earlier(state, spec, "luminance-levels");
    if (onlyBlackPixelsOff(state.acc, expected, state.dump.frame)) {
        name(check, "black-0-over-0", {9}, {}, "the NaN pixels are painted magenta by the grader's probe");
    } else if (!levels.passed) {
        inherit(check, levels, "the final pass reads the key from a level that is not 1x1");
    } else {
        nameFrameMistakes(state, bloom, check);
        chargeOneStep(check, describeFrame(expected, state.dump.frame), 9, lookMissing(state, inputs, expected));
    }
    return true;
}

std::vector<int> stepsOf(std::initializer_list<int> steps) { return steps; }

// The checks of one case in the order the chain computes them: a check reads only the buffers of
// its own steps and the checks it follows from, which come before it.
const std::vector<CheckSpec>& checkTable() {
    static const std::vector<CheckSpec> table{
        {"luminance-levels", 1, 3, [](int) { return stepsOf({13, 15}); }, {}, luminanceLevelsCheck},
        {"log-luminance", 1, 3, [](int) { return stepsOf({3, 4, 5}); }, {}, logLuminanceCheck},
        {"key", 1, 3, [](int) { return stepsOf({3, 4, 5, 15}); }, {"log-luminance", "luminance-levels"}, keyCheck},
        {"bloom-threshold", 2, 3, [](int) { return stepsOf({17, 18}); }, {"log-luminance"}, bloomThresholdCheck},
        {"bloom-downsample", 2, 2, [](int) { return stepsOf({22, 24}); }, {}, bloomDownsampleCheck},
        {"blur-passes", 3, 3, [](int) { return stepsOf({27, 32, 33, 34}); }, {}, blurPassesCheck},
        {"blur-pass-count", 3, 3, [](int) { return stepsOf({34}); }, {"blur-passes"}, blurPassCountCheck},
        {"blur", 3, 3, [](int) { return stepsOf({27, 30, 31, 32, 33, 34}); }, {"blur-passes"}, blurCheck},
        {"frame", 1, 3, frameSteps, {"luminance-levels"}, frameCheck},
    };
    return table;
}

} // namespace

std::vector<Check> bufferChecks(int part, const CaseRun& run, const std::string& reportDir, const std::string& imageDir) {
    const CheckWriter writer(run, reportDir, imageDir);
    CaseState state(part, run, writer);
    for (const CheckSpec& spec : checkTable()) {
        if (part < spec.firstPart || part > spec.lastPart) continue;
        Check check = writer.make(spec.what, spec.steps(part));
        const bool goOn = spec.run(state, spec, check);
        state.checks.push_back(std::move(check));
        if (!goOn) break;
    }
    return state.checks;
}

} // namespace t10::grade
