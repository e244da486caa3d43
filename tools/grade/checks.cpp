// The buffer checks of t10-grade and the mistake catalogue they consult; see checks.hpp.
//
// Every check compares what the submission's GPU wrote with the CPU reference of tests/numeric
// (reference.hpp), computed from the buffers the GPU itself produced one pass earlier, so that a
// mistake shows in the check of the step that makes it and not in every later one. When a check
// fails, each known mistake of that check is modelled on the CPU (the reference chain with the
// mistake made) and measured the same way; the one that matches names the diagnosis.
//
// Adding a known mistake: add a Mistake below with the text a student reads, then a model to the
// list of the check it breaks (keyModels, frameModels, thresholdModels, blurModels, the pass models
// of blur-passes), and a submission that makes it to tools/grade/tests.cmake.
#include "checks.hpp"

#include "compare.hpp"
#include "reference.hpp"
#include "t10/contract.hpp"
#include "t10/error.hpp"
#include "t10/image_io.hpp"
#include "t10/outputs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numeric>
#include <sstream>

namespace t10::grade {

namespace {

namespace ref = t10::ref;
using t10::Image8;
using t10::ImageF;

// --- The mistake catalogue. -----------------------------------------------------------------------
struct Mistake {
    const char* id;
    const char* text;
};

const Mistake kRec601{"rec601", "Rec. 601 luminance weights (0.299, 0.587, 0.114) instead of Rec. 709 "
                                "(0.2126, 0.7152, 0.0722)"};
const Mistake kWhitePoint{"white-point", "wrong white point Yw (0.25 instead of 0.22)"};
const Mistake kMiddleGrey{"middle-grey", "middle grey with 1.0 instead of 1.03 in 1.03 - 2 / (2 + log10(Ya + 1))"};
const Mistake kNoUnmap{"missing-unmapping", "missing range un-mapping: the key is exp() of the [0, 1] mapped value, "
                                            "not of log(Ya)"};
const Mistake kLog2Exp{"log2-exp-mismatch", "log2 / exp mismatch: the log luminance and its inverse use different "
                                            "bases (log2 with exp, or log with exp2)"};
const Mistake kLog2Pass{"log2-exp-mismatch", "log2 / exp mismatch: log2(Y + epsilon) in the luminance pass, mapped "
                                             "with natural-log bounds log(epsilon) and log(Yw)"};
const Mistake kCeilLevels{"ceil-log2-levels", "ceil(log2(max(w, h))) mip levels: one level short at a power-of-two "
                                              "size, the smallest level is 2x1, not the 1x1 scene key"};
const Mistake kBlackNan{"black-0-over-0", "0/0 on black pixels: Y' / Y with Y = 0 gives NaN; guard it (fY > 0)"};
const Mistake kThreshold{"bloom-threshold", "wrong bloom threshold (2.5 x Yw instead of 2.95 x Yw)"};
const Mistake kThresholdYw{"bloom-threshold", "bloom threshold at Yw instead of 2.95 x Yw"};
const Mistake kBloomWeight{"bloom-weight", "wrong bloom weight (0.5 instead of 0.98)"};
const Mistake kBloomAfter{"bloom-after-tonemap", "bloom added after the tone map instead of before it"};
const Mistake kNoBloom{"bloom-missing", "the bloom is not added to the colour (step 20)"};
const Mistake kNoMipmap{"bloom-level1-missing", "bloom level 1 holds nothing: glGenerateMipmap on the bloom texture "
                                                "(step 24) or the blur into level 1 is missing"};
const Mistake kTap{"blur-tap", "wrong inner tap offset (0.424 instead of 0.524 sigma)"};
const Mistake kSigma{"blur-sigma", "wrong sigma (2.0 instead of 2.5)"};
const Mistake kFullRes{"blur-full-resolution-offsets", "blur offsets in full-resolution texels: the UBO or the offsets "
                                                       "still use the full size, not the half-size target"};
const Mistake kOneAxis{"swapped-subroutines", "swapped or repeated subroutine indices: both passes of a pair blur "
                                              "along the same axis"};
const Mistake kPassCount{"pass-count", "wrong number of blur pass pairs"};
const Mistake kViewport{"viewport-reset", "missing viewport reset after the blur (step 35): only the lower-left "
                                          "quarter of the frame is drawn"};
const Mistake kUboReset{"ubo-reset", "missing InvResolution UBO reset after the blur (step 35): the final pass reads "
                                     "with the half-size inverse resolution"};

constexpr ref::Rgb kRec709Weights{t10::contract::kLumaRed, t10::contract::kLumaGreen, t10::contract::kLumaBlue};
constexpr int kLuminanceUnit = static_cast<int>(t10::contract::kLuminanceKeyUnit);
constexpr int kBloomUnit = static_cast<int>(t10::contract::kBloomUnit);
constexpr ref::Rgb kRec601Weights{0.299, 0.587, 0.114};

double dot(const ref::Rgb& w, const ref::Rgb& c) { return w[0] * c[0] + w[1] * c[1] + w[2] * c[2]; }
ref::Rgb texel(const ImageF& image, int x, int y) { return {image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2)}; }

std::string format(double value, int precision = 4) {
    std::ostringstream text;
    text.precision(precision);
    text << value;
    return text.str();
}

// Names the models that explain a failed measurement: every one within the check's tolerance (a
// scene may not tell two mistakes apart), or failing that the closest one if its error is under a
// quarter of the correct chain's (a clearly better fit).
template <typename Model>
std::string diagnose(const std::vector<Model>& models, const std::function<double(const Model&)>& error,
                     const std::function<bool(double)>& withinTolerance, double correctError,
                     const std::string& fallback) {
    std::string matches;
    std::vector<std::string> named;
    const Model* best = nullptr;
    double bestError = 0.0;
    for (const Model& model : models) {
        const double e = error(model);
        if (withinTolerance(e) && std::find(named.begin(), named.end(), model.mistake->id) == named.end()) {
            named.push_back(model.mistake->id);
            matches += std::string(matches.empty() ? "" : "; or ") + "[" + model.mistake->id + "]: " + model.mistake->text;
        }
        if (best == nullptr || e < bestError) {
            best = &model;
            bestError = e;
        }
    }
    if (!matches.empty()) return "likely mistake " + matches;
    if (best != nullptr && bestError < 0.25 * correctError) {
        return std::string("likely mistake [") + best->mistake->id + "]: " + best->mistake->text +
               " (closest known mistake, not an exact match)";
    }
    return fallback;
}

// --- Luminance levels and the scene key (steps 2-5, 13, 15). -------------------------------------
struct KeyModel {
    const Mistake* mistake;
    ref::Rgb weights = kRec709Weights;
    double yw = ref::kYwhite;
    bool log2Pass = false;
};

// One pixel's range-mapped log luminance as GL_R16 stores it, with the model's mistake made.
double modelMapped(const ref::Rgb& colour, const KeyModel& model) {
    const double logEps = std::log(ref::kEpsilon);
    const double lum = dot(model.weights, colour);
    const double l = model.log2Pass ? std::log2(lum + ref::kEpsilon) : std::log(lum + ref::kEpsilon);
    return ref::toUnorm16((l - logEps) / (std::log(model.yw) - logEps));
}

double modelMappedKey(const ImageF& accumulation, const KeyModel& model) {
    double sum = 0.0;
    for (int y = 0; y < accumulation.height; ++y)
        for (int x = 0; x < accumulation.width; ++x) sum += modelMapped(texel(accumulation, x, y), model);
    return sum / (double(accumulation.width) * double(accumulation.height));
}

// Largest difference, in R16 steps, between luminance level 0 and a model of it.
double worstLuminanceSteps(const ImageF& level0, const ImageF& accumulation,
                           const std::function<double(const ref::Rgb&)>& mapped) {
    if (level0.width != accumulation.width || level0.height != accumulation.height) return 1e9;
    double worst = 0.0;
    for (int y = 0; y < accumulation.height; ++y)
        for (int x = 0; x < accumulation.width; ++x)
            worst = std::max(worst, std::abs(level0.at(x, y, 0) - mapped(texel(accumulation, x, y))) * 65535.0);
    return worst;
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
enum class Unmap { Correct, None, Log2ThenExp, LnThenExp2 };
enum class Region { Whole, LowerLeftQuarter };

struct FrameModel {
    const Mistake* mistake;
    double yw = ref::kYwhite;
    double grey = 1.03;
    Unmap unmap = Unmap::Correct;
    ref::Rgb weights = kRec709Weights;
    double bloomWeight = ref::kBloomWeight;
    bool bloomAfter = false;
    bool useBloom = true;
    Region region = Region::Whole;
    bool halfInvResolution = false; // the final pass samples at twice the texture coordinate
};

double keyFor(double mapped, const FrameModel& model) {
    const double lnEps = std::log(ref::kEpsilon);
    const double lnYw = std::log(model.yw);
    switch (model.unmap) {
    case Unmap::None: return std::exp(mapped);
    case Unmap::Log2ThenExp: return std::exp(mapped * (std::log2(model.yw) - std::log2(ref::kEpsilon)) + std::log2(ref::kEpsilon));
    case Unmap::LnThenExp2: return std::exp2(mapped * (lnYw - lnEps) + lnEps);
    case Unmap::Correct: break;
    }
    return std::exp(mapped * (lnYw - lnEps) + lnEps);
}

Image8 modelFrame(const ImageF& accumulation, double mappedKey, const ImageF* bloom, const FrameModel& model) {
    const double key = keyFor(mappedKey, model);
    const int w = accumulation.width;
    const int h = accumulation.height;
    Image8 frame(w, h, 3);
    const double scale = model.halfInvResolution ? 2.0 : 1.0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (model.region == Region::LowerLeftQuarter && (x >= w / 2 || y >= h / 2)) continue; // cleared black
            const double u = (x + 0.5) / w * scale;
            const double v = (y + 0.5) / h * scale;
            ref::Rgb c = model.halfInvResolution ? ref::sampleBilinear(accumulation, std::min(u, 1.0), std::min(v, 1.0))
                                                 : texel(accumulation, x, y);
            ref::Rgb b{0.0, 0.0, 0.0};
            if (bloom != nullptr && model.useBloom) b = ref::sampleBilinear(*bloom, std::min(u, 1.0), std::min(v, 1.0));
            if (!model.bloomAfter)
                for (int k = 0; k < 3; ++k) c[k] += model.bloomWeight * b[k];
            const double lum = dot(model.weights, c);
            ref::Rgb out{0.0, 0.0, 0.0};
            if (lum > 0.0) {
                const double dg = model.grey - 2.0 / (2.0 + std::log10(key + 1.0));
                const double yr = dg * lum / key;
                const double yNew = yr * (1.0 + yr / (model.yw * model.yw)) / (1.0 + yr);
                for (int k = 0; k < 3; ++k) out[k] = c[k] * yNew / lum;
            }
            if (model.bloomAfter)
                for (int k = 0; k < 3; ++k) out[k] += model.bloomWeight * b[k];
            for (int k = 0; k < 3; ++k) frame.at(x, y, k) = ref::toUnorm8(out[k]);
        }
    }
    return frame;
}

// --- The bloom threshold (steps 17-18). -----------------------------------------------------------
struct ThresholdModel {
    const Mistake* mistake;
    double threshold = ref::kBloomThreshold;
    ref::Rgb weights = kRec709Weights;
};

int misclassified(const ImageF& accumulation, const ImageF& gpu, const ThresholdModel& model) {
    int count = 0;
    for (int y = 0; y < accumulation.height; ++y)
        for (int x = 0; x < accumulation.width; ++x) {
            const double lum = dot(model.weights, texel(accumulation, x, y));
            const bool modelBright = lum >= model.threshold;
            const bool gpuBright = gpu.at(x, y, 0) + gpu.at(x, y, 1) + gpu.at(x, y, 2) > 0.0f;
            // Only a pixel within float rounding of the threshold may land on either side.
            if (modelBright != gpuBright && std::abs(lum - model.threshold) > 1e-6) ++count;
        }
    return count;
}

// --- The Gaussian blur (steps 27-34). -------------------------------------------------------------
enum class Axes { Both, HorizontalOnly, VerticalOnly };

struct BlurModel {
    const Mistake* mistake;
    int passes = ref::kBlurPasses;
    double sigma = ref::kSigma;
    double tap1 = ref::kTap1;
    double offsetScale = 1.0;
    Axes axes = Axes::Both;
};

ImageF modelPass(const ImageF& source, int w, int h, bool horizontal, const BlurModel& model) {
    ImageF out(w, h, 3);
    const double texelSize = model.offsetScale / (horizontal ? w : h);
    const double step1 = model.tap1 * model.sigma * texelSize;
    const double step2 = ref::kTap2 * model.sigma * texelSize;
    const double offsets[5] = {-step2, -step1, 0.0, step1, step2};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double u = (x + 0.5) / w;
            const double v = (y + 0.5) / h;
            ref::Rgb sum{0.0, 0.0, 0.0};
            for (double offset : offsets) {
                const ref::Rgb s = horizontal ? ref::sampleBilinear(source, u + offset, v) : ref::sampleBilinear(source, u, v + offset);
                for (int c = 0; c < 3; ++c) sum[c] += s[c];
            }
            for (int c = 0; c < 3; ++c) out.at(x, y, c) = static_cast<float>(sum[c] / 5.0);
        }
    return out;
}

ImageF modelBlur(const ImageF& level0, const BlurModel& model, ref::FloatStore store) {
    const int w = std::max(1, level0.width / 2);
    const int h = std::max(1, level0.height / 2);
    ImageF level1 = level0;
    for (int pass = 0; pass < model.passes; ++pass) {
        ImageF blur = modelPass(level1, w, h, model.axes != Axes::VerticalOnly, model);
        ref::storeR11G11B10F(blur, store);
        level1 = modelPass(blur, w, h, model.axes == Axes::HorizontalOnly, model);
        ref::storeR11G11B10F(level1, store);
    }
    return level1;
}

struct PeakError {
    double worst = 0.0; // of the channel's peak
    double mean = 0.0;
};

// Blur results of a model against the GPU's; a level of the wrong size is as far off as can be.
PeakError peakError(const ImageF& gpu, const ImageF& cpu) {
    if (gpu.width != cpu.width || gpu.height != cpu.height) return {1e9, 1e9};
    const t10::test::LevelError error = t10::test::compareLevels(gpu, cpu);
    return {error.worstRelativeToPeak, error.meanRelativeToPeak};
}

bool allZero(const ImageF& image) {
    return std::all_of(image.data.begin(), image.data.end(), [](float v) { return v == 0.0f; });
}

std::vector<int> range(int first, int last) {
    std::vector<int> steps(static_cast<std::size_t>(last - first + 1));
    std::iota(steps.begin(), steps.end(), first);
    return steps;
}

std::vector<int> frameSteps(int part) {
    std::vector<int> steps = range(6, 10);
    if (part >= 2) steps.insert(steps.end(), {19, 20});
    if (part >= 3) steps.push_back(35);
    return steps;
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

// --- Each blur pass (steps 27, 32-34), captured by pass_capture.cpp. --------------------------------
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

// A mistake made in one pass: the model's offsets, along the pass's axis or the other one.
struct PassModel {
    const Mistake* mistake;
    BlurModel blur;
    bool otherAxis = false;
};

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

std::vector<int> partSteps(int part) { return range(1, part == 1 ? 16 : part == 2 ? 25 : 36); }

t10::test::Dump loadDumpDir(const std::string& dir) {
    t10::test::Dump dump;
    dump.dir = dir;
    dump.accumulation = t10::readPfm(dump.path(t10::dumpFileName(t10::contract::kAccumulationUnit, 0)));
    dump.frame = t10::readPng(dump.path("frame.png"));
    return dump;
}

std::vector<Check> bufferChecks(int part, const CaseRun& run, const std::string& reportDir, const std::string& imageDir) {
    const t10::test::Dump& dump = run.dump;
    const ImageF& acc = dump.accumulation;
    const CheckWriter writer(run, reportDir, imageDir);
    std::vector<Check> checks;

    // Luminance mip chain (step 13): floor(log2(max)) + 1 levels reach the 1x1 key.
    {
        Check check = writer.make("luminance-levels", {13, 15});
        const int side = std::max(acc.width, acc.height);
        const int expected = int(std::floor(std::log2(side))) + 1;
        const int levels = dump.luminanceLevels();
        check.passed = levels == expected;
        check.measured = std::to_string(levels) + " levels on unit 16 at " + std::to_string(acc.width) + "x" +
                         std::to_string(acc.height);
        check.tolerance = "exactly floor(log2(" + std::to_string(side) + ")) + 1 = " + std::to_string(expected) +
                          ": fewer levels never reach the 1x1 average, more cannot be allocated";
        if (!check.passed) {
            check.diagnosis = levels == int(std::ceil(std::log2(side)))
                                  ? std::string("likely mistake [") + kCeilLevels.id + "]: " + kCeilLevels.text
                                  : levels == 0 ? "no luminance texture on unit 16 (steps 12-13)"
                                                : "the luminance texture does not have the full mip chain";
        }
        checks.push_back(check);
    }

    // Luminance level 0 (steps 3-5): every pixel's range-mapped log luminance.
    {
        Check check = writer.make("log-luminance", {3, 4, 5});
        const ImageF level0 = dump.level(kLuminanceUnit, 0);
        const double worst = worstLuminanceSteps(level0, acc, [](const ref::Rgb& c) {
            return ref::toUnorm16(ref::rangeMappedLogLuminance(ref::luminance(c)));
        });
        // The GPU's float log differs from the double one by about 1e-7 of the mapped range, far below
        // one R16 step (1.5e-5), so a texel rounds at most to the neighbouring step. At sizes that are
        // not a power of two gl_FragCoord x 1 / size lands a hair off the texel centre, and beside a
        // lamp 1e-6 of its light moves a dark texel's log: 2 steps measured at 160x90. A wrong weight,
        // base or bound moves texels by hundreds of steps.
        constexpr double kSteps = 4.0;
        check.passed = worst <= kSteps;
        check.measured = "largest difference " + format(worst) + " R16 steps over " + std::to_string(acc.width) + "x" +
                         std::to_string(acc.height) + " pixels";
        check.tolerance = "<= 4 R16 steps: float vs double rounding, and off-centre sampling beside bright "
                          "pixels (2 measured); a wrong weight or base is hundreds of steps off";
        if (!check.passed) {
            const std::vector<KeyModel> models{{&kRec601, kRec601Weights}, {&kWhitePoint, kRec709Weights, 0.25},
                                               {&kLog2Pass, kRec709Weights, ref::kYwhite, true}};
            check.diagnosis = diagnose<KeyModel>(
                models,
                [&](const KeyModel& m) {
                    return worstLuminanceSteps(level0, acc, [&](const ref::Rgb& c) { return modelMapped(c, m); });
                },
                [&](double e) { return e <= kSteps; }, worst,
                "no known mistake matches: check the luminance, log and range mapping of PostProcessInit.frag");
        }
        checks.push_back(check);
    }

    // The scene key (steps 2-5, 15): the smallest level against the CPU log-average.
    const double gpuKey = gpuMappedKey(dump);
    {
        Check check = writer.make("key", {3, 4, 5, 15});
        const double cpu = ref::meanMappedLogLuminance(acc, true);
        const int roundings = std::max(0, dump.luminanceLevels() - 1);
        const bool exactChain = (acc.width & (acc.width - 1)) == 0 && (acc.height & (acc.height - 1)) == 0;
        // Power-of-two sizes: every 2x2 average is exact and each level rounds to R16 once, half a step
        // per level. Other sizes: glGenerateMipmap's filter is implementation-defined for odd levels, so
        // 2% of the mapped range (0.34 in log luminance); a wrong formula is far beyond either.
        const double bound = exactChain ? (0.5 * roundings + 0.01) / 65535.0 : 0.02;
        check.passed = std::abs(gpuKey - cpu) <= bound;
        check.measured = "mapped key " + format(gpuKey, 6) + ", CPU " + format(cpu, 6) + " (difference " +
                         format(std::abs(gpuKey - cpu) * 65535.0) + " R16 steps)";
        check.tolerance = exactChain ? "<= " + format(bound * 65535.0) + " R16 steps: half a step of rounding per mip level"
                                     : "<= 0.02 of the mapped range: glGenerateMipmap filters odd sizes as the driver likes";
        if (!check.passed) {
            const std::vector<KeyModel> models{{&kRec601, kRec601Weights}, {&kWhitePoint, kRec709Weights, 0.25},
                                               {&kLog2Pass, kRec709Weights, ref::kYwhite, true}};
            check.diagnosis = diagnose<KeyModel>(
                models, [&](const KeyModel& m) { return std::abs(gpuKey - modelMappedKey(acc, m)); },
                [&](double e) { return e <= bound; }, std::abs(gpuKey - cpu),
                dump.luminanceLevels() > 0 && dump.level(kLuminanceUnit, dump.luminanceLevels() - 1).width > 1
                    ? std::string("likely mistake [") + kCeilLevels.id + "]: " + kCeilLevels.text
                    : "no known mistake matches: check the luminance, log and range mapping of PostProcessInit.frag");
        }
        checks.push_back(check);
    }

    ImageF bloom0;
    ImageF bloom1;
    if (part >= 2) {
        // Bloom level 0 (steps 17-18): exactly the pixels at or above 2.95 x Yw, with their colour.
        Check check = writer.make("bloom-threshold", {17, 18});
        if (dump.levelCount(kBloomUnit) < 2) {
            check.measured = std::to_string(dump.levelCount(kBloomUnit)) + " levels on unit 17";
            check.tolerance = "the bloom texture has 2 levels (step 22)";
            check.diagnosis = "no two-level bloom texture on unit 17 (steps 21-23)";
            checks.push_back(check);
            return checks;
        }
        bloom0 = dump.bloom(0);
        bloom1 = dump.bloom(1);
        const ImageF cpu = ref::bloomThreshold(acc);
        const int wrong = misclassified(acc, bloom0, ThresholdModel{nullptr});
        const double worst = wrong == 0 ? worstStoreError(bloom0, cpu, &cpu) : 0.0;
        check.passed = wrong == 0 && worst <= 1.0;
        check.measured = std::to_string(wrong) + " pixels on the wrong side of the threshold; worst colour error " +
                         format(worst) + " R11G11B10F steps";
        check.tolerance = "0 misclassified (pixels within 1e-6 of the threshold excepted: float vs double), colour "
                          "within 1 step of GL_R11F_G11F_B10F (6/5 mantissa bits)";
        if (!check.passed) {
            const std::vector<ThresholdModel> models{{&kThreshold, 2.5 * ref::kYwhite},
                                                     {&kThresholdYw, ref::kYwhite},
                                                     {&kRec601, ref::kBloomThreshold, kRec601Weights}};
            check.diagnosis = diagnose<ThresholdModel>(
                models, [&](const ThresholdModel& m) { return double(misclassified(acc, bloom0, m)); },
                [](double e) { return e == 0.0; }, double(wrong),
                "no known mistake matches: check the threshold test and the colour written to location 1");
        }
        checks.push_back(check);
    }

    if (part == 2) {
        // Bloom level 1 (steps 22, 24): the 2x2 average glGenerateMipmap writes (exact for even sizes).
        Check check = writer.make("bloom-downsample", {22, 24});
        const ImageF cpu = ref::boxDownsample(bloom0);
        const bool even = acc.width % 2 == 0 && acc.height % 2 == 0;
        const double worst = bloom1.width == cpu.width && bloom1.height == cpu.height ? worstStoreError(bloom1, cpu) : 1e9;
        check.passed = worst <= (even ? 1.0 : 64.0);
        check.measured = "worst error " + format(worst) + " R11G11B10F steps against the 2x2 average of level 0";
        check.tolerance = even ? "<= 1 step: each texel averages exactly four level-0 texels and is stored once"
                               : "<= 64 steps: odd sizes are filtered as the driver likes";
        if (!check.passed) {
            check.diagnosis = allZero(bloom1) && !allZero(bloom0)
                                  ? std::string("likely mistake [") + kNoMipmap.id + "]: " + kNoMipmap.text
                                  : "no known mistake matches: check glGenerateMipmap on unit 17 (step 24)";
        }
        checks.push_back(check);
    }

    if (part >= 3) {
        // Bloom level 1 after the blur (steps 27-34): five CPU pass pairs from the GPU's level 0.
        Check check = writer.make("blur", {27, 30, 31, 32, 33, 34});
        const ref::FloatStore store = ref::detectFloatStore(bloom0, ref::bloomThreshold(acc));
        const ImageF cpu = ref::gaussianBloom(bloom0, ref::kBlurPasses, store);
        const PeakError error = peakError(bloom1, cpu);
        // With the driver's store rule emulated what is left is float vs double and the bilinear
        // weights: two blue steps of the peak at worst, 1e-4 of the peak on average (measured 2e-6 to
        // 7e-7). A wrong tap, sigma or pass count moves the blur by tens of percent.
        constexpr double kWorst = 2.0 / 32.0;
        constexpr double kMean = 1e-4;
        check.passed = error.worst <= kWorst && error.mean <= kMean;
        check.measured = "worst " + format(error.worst) + " of the peak, mean " + format(error.mean) + " of the peak";
        check.tolerance = "worst <= 2/32 of the peak (two R11G11B10F blue steps), mean <= 1e-4 of the peak";
        if (!check.passed && allZero(bloom1)) {
            check.diagnosis = std::string("likely mistake [") + kNoMipmap.id + "]: " + kNoMipmap.text;
        } else if (!check.passed) {
            std::vector<BlurModel> models{{&kSigma, 5, 2.0}, {&kTap, 5, ref::kSigma, 0.424},
                                          {&kFullRes, 5, ref::kSigma, ref::kTap1, 0.5},
                                          {&kOneAxis, 5, ref::kSigma, ref::kTap1, 1.0, Axes::HorizontalOnly},
                                          {&kOneAxis, 5, ref::kSigma, ref::kTap1, 1.0, Axes::VerticalOnly}};
            for (int passes : {1, 2, 3, 4, 6, 7, 8, 10}) models.push_back({&kPassCount, passes});
            const auto measure = [&](const BlurModel& m) { return peakError(bloom1, modelBlur(bloom0, m, store)).mean; };
            std::string text = diagnose<BlurModel>(models, measure, [&](double e) { return e <= kMean; }, error.mean,
                                                   "no known mistake matches: check Gauss.frag's offsets and the passes");
            // Name the pass count found.
            for (const BlurModel& m : models) {
                if (m.mistake == &kPassCount && text.find(kPassCount.id) != std::string::npos && measure(m) <= kMean) {
                    text += " (" + std::to_string(m.passes) + " pairs instead of 5)";
                    break;
                }
            }
            check.diagnosis = text;
        }
        checks.push_back(check);
    }

    if (part >= 3) {
        // Every blur pass (steps 27, 32-34): each captured pass against one CPU Gaussian pass of the
        // texture the GPU wrote one pass earlier (bloom level 0 for the first), so the first pass that
        // goes wrong is named, whatever the passes after it do. Same bound as the blur check: with
        // the store rule emulated what is left is float vs double and the bilinear weights.
        std::vector<CapturedPass> passes;
        const bool captured = loadPasses(dump.dir, passes);
        const ref::FloatStore store = ref::detectFloatStore(bloom0, ref::bloomThreshold(acc));
        const int w = std::max(1, bloom0.width / 2);
        const int h = std::max(1, bloom0.height / 2);
        constexpr double kWorst = 2.0 / 32.0;
        constexpr double kMean = 1e-4;
        Check check = writer.make("blur-passes", {27, 32, 33, 34});
        check.tolerance = "each pass: worst <= 2/32 of the peak (two R11G11B10F blue steps), mean <= 1e-4 of the "
                          "peak, against one CPU pass of the GPU's previous pass";
        std::string worstText;
        double worstMean = -1.0;
        check.passed = captured && !passes.empty();
        if (!captured) {
            check.measured = "no pass was captured (the grader's capture did not run)";
            check.diagnosis = "the program was not built with t10-grade's pass capture";
        } else if (passes.empty()) {
            check.measured = "the blur program drew no pass into a texture";
            check.diagnosis = "no blur pass: check the blur framebuffers and draws (steps 30, 32-34)";
        }
        for (std::size_t k = 0; k < passes.size() && check.passed; ++k) {
            const ImageF& source = k == 0 ? bloom0 : passes[k - 1].image;
            const bool horizontal = k % 2 == 0;
            ImageF expected = ref::gaussianPass(source, w, h, horizontal);
            ref::storeR11G11B10F(expected, store);
            const PeakError error = peakError(passes[k].image, expected);
            const std::string figures = passName(k) + " (subroutine " + passes[k].subroutine + "): worst " +
                                        format(error.worst) + " of the peak, mean " + format(error.mean) + " of the peak";
            if (error.worst <= kWorst && error.mean <= kMean) {
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
            const std::vector<PassModel> models{{&kOneAxis, {nullptr}, true},
                                                {&kFullRes, {nullptr, 5, ref::kSigma, ref::kTap1, 0.5}},
                                                {&kSigma, {nullptr, 5, 2.0}},
                                                {&kTap, {nullptr, 5, ref::kSigma, 0.424}}};
            const auto measure = [&](const PassModel& m) {
                ImageF model = modelPass(source, w, h, horizontal != m.otherAxis, m.blur);
                ref::storeR11G11B10F(model, store);
                return peakError(passes[k].image, model).mean;
            };
            check.diagnosis = passName(k) + ": " +
                              diagnose<PassModel>(models, measure, [&](double e) { return e <= kMean; }, error.mean,
                                                  "no known mistake matches: check Gauss.frag's offsets and the "
                                                  "subroutine and texture of this pass");
        }
        if (check.passed) check.measured = std::to_string(passes.size()) + " passes within tolerance; the farthest: " + worstText;
        checks.push_back(check);

        // The number of passes (step 34): five pairs, counted from the captured draws.
        Check count = writer.make("blur-pass-count", {34});
        const int expectedPasses = 2 * ref::kBlurPasses;
        count.passed = captured && int(passes.size()) == expectedPasses;
        count.measured = std::to_string(passes.size()) + " blur passes drawn into textures";
        count.tolerance = "exactly " + std::to_string(expectedPasses) + " (" + std::to_string(ref::kBlurPasses) +
                          " horizontal + vertical pairs): the count is exact";
        if (!count.passed && captured) {
            count.diagnosis = std::string("likely mistake [") + kPassCount.id + "]: " + kPassCount.text + " (" +
                              (passes.size() % 2 == 0 ? std::to_string(passes.size() / 2) + " pairs"
                                                      : std::to_string(passes.size()) + " passes, not whole pairs") +
                              " instead of " + std::to_string(ref::kBlurPasses) + ")";
        } else if (!count.passed) {
            count.diagnosis = check.diagnosis;
        }
        checks.push_back(count);
    }

    // The final frame (steps 6-10, 19-20, 35): the CPU tone map of the GPU's own buffers.
    const bool levelsShort = !checks.front().passed;
    {
        Check check = writer.make("frame", frameSteps(part));
        const ImageF* bloom = part >= 2 ? &bloom1 : nullptr;
        const Image8 expected = ref::finalFrame(acc, ref::keyFromMapped(gpuKey), bloom);
        const auto error = t10::test::byteError(expected, dump.frame);
        // The GPU evaluates in float, the reference in double from the same read-back buffers: a
        // channel lands one step away only next to a rounding boundary, so at most 1 step and rarely.
        check.passed = error.max <= 1 && error.mean <= 0.01;
        check.measured = "largest error " + std::to_string(error.max) + " 8-bit steps, mean " + format(error.mean) +
                         ", " + format(error.fractionOverOne * 100.0) + "% of pixels off by more than 1";
        check.tolerance = "largest <= 1 step and mean <= 0.01 steps: float vs double rounding only";
        if (!check.passed) {
            writer.attachImages(check, expected);
            // Black pixels first: if every pixel off by more than a step is black in the input, the
            // tone map divides 0 by 0 there.
            bool onlyBlack = true;
            bool anyBlack = false;
            for (int y = 0; y < acc.height && onlyBlack; ++y)
                for (int x = 0; x < acc.width; ++x) {
                    int worst = 0;
                    for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(int(expected.at(x, y, k)) - int(dump.frame.at(x, y, k))));
                    if (worst <= 1) continue;
                    const ref::Rgb c = texel(acc, x, y);
                    if (c[0] == 0.0 && c[1] == 0.0 && c[2] == 0.0) {
                        anyBlack = true;
                    } else {
                        onlyBlack = false;
                        break;
                    }
                }
            if (onlyBlack && anyBlack) {
                check.diagnosis = std::string("likely mistake [") + kBlackNan.id + "]: " + kBlackNan.text +
                                  " (the NaN pixels are painted magenta by the grader's probe)";
            } else if (levelsShort) {
                check.diagnosis = "follows from " + checks.front().id + ": the final pass reads the key from a level "
                                  "that is not 1x1 (" + checks.front().diagnosis + ")";
            } else {
                std::vector<FrameModel> models{{&kWhitePoint, 0.25}, {&kMiddleGrey, ref::kYwhite, 1.0},
                                               {&kNoUnmap, ref::kYwhite, 1.03, Unmap::None},
                                               {&kLog2Exp, ref::kYwhite, 1.03, Unmap::Log2ThenExp},
                                               {&kLog2Exp, ref::kYwhite, 1.03, Unmap::LnThenExp2},
                                               {&kRec601, ref::kYwhite, 1.03, Unmap::Correct, kRec601Weights}};
                if (part >= 2) {
                    FrameModel weight{&kBloomWeight};
                    weight.bloomWeight = 0.5;
                    FrameModel after{&kBloomAfter};
                    after.bloomAfter = true;
                    FrameModel none{&kNoBloom};
                    none.useBloom = false;
                    models.insert(models.end(), {weight, after, none});
                }
                if (part >= 3) {
                    FrameModel quarter{&kViewport};
                    quarter.region = Region::LowerLeftQuarter;
                    FrameModel ubo{&kUboReset};
                    ubo.halfInvResolution = true;
                    models.insert(models.end(), {quarter, ubo});
                }
                check.diagnosis = diagnose<FrameModel>(
                    models,
                    [&](const FrameModel& m) { return t10::test::byteError(modelFrame(acc, gpuKey, bloom, m), dump.frame).mean; },
                    [](double mean) { return mean <= 0.01; }, error.mean,
                    "no known mistake matches: check the tone map and bloom of PostProcess.frag");
            }
        }
        checks.push_back(check);
    }
    return checks;
}

} // namespace t10::grade
