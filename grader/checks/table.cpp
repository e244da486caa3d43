// The buffer checks of one case, as a table (bufferChecks, checks.hpp); see checks.hpp.
//
// Every check compares what the submission's GPU wrote with the CPU reference (common/reference,
// reference.hpp), computed from the buffers the GPU itself produced one pass earlier, so that a
// mistake shows in the check of the step that makes it and not in every later one. That is also
// why a mistake found by one check agrees with every check that passed: each model starts from the
// GPU's own input buffer and changes only what its own step computes.
//
// When a check fails, each catalogue mistake of that check is a model (diagnosis/): the reference
// with one setting changed (ref::Settings) or written the mistake's way (the reference's variants:
// ref::MappedLog, ref::Unmap, ref::FrameVariant), fitted to the buffer (fits.hpp) or, for a
// mistake without a value, taken as it is. A mistake is named only when its model explains the
// buffer within the check's own tolerance; otherwise the diagnosis describes the error's shape (a
// constant factor, a shift, nothing written, NaN, the region that differs). No closest guesses.
//
// Adding a known mistake: a row of mistakes.tsv, its variant in common/reference when it changes
// the tutorial's math, a model in diagnosis/ and its use in the check of the step it breaks, and a
// submission that makes it (tests/make_submissions.py).
#include "checks/checks.hpp"

#include "checks/findings.hpp"
#include "diagnosis/bloom_model.hpp"
#include "diagnosis/frame_model.hpp"
#include "diagnosis/key_model.hpp"
#include "part/part.hpp"
#include "t10/contract.hpp"
#include "t10/error.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <set>

namespace t10::grade {

namespace {

// One case's checks in the making: the buffers they read and what the earlier checks found.
struct CaseState {
    CaseState(int partNumber, const CaseRun& caseRun, CheckImages& checkImages)
        : part(partNumber), buffers(caseRun.buffers), acc(caseRun.buffers.accumulation), images(checkImages), passes(caseRun.buffers.passes) {}
    int part;
    const CaseBuffers& buffers;
    const ImageF& acc;
    CheckImages& images;
    std::vector<Check> checks;              // the checks made so far, in the table's order
    std::optional<ref::Rgb> studentWeights; // log-luminance: the weights that explain level 0
    double gpuKey = 0.0;                    // the mapped key the final pass reads
    ImageF bloom0, bloom1;                  // Part 2 on: the bloom texture's two levels
    // Part 3: the captured blur passes (read by blur-passes first) and what the first failing one measured.
    const std::vector<CapturedPass>& passes;
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
    const int levels = state.buffers.luminanceLevels();
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
    const ImageF level0 = state.buffers.level(kLuminanceUnit, 0);
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
    state.gpuKey = gpuMappedKey(state.buffers);
    const double cpu = ref::meanMappedLogLuminance(acc, true);
    const int roundings = std::max(0, state.buffers.luminanceLevels() - 1);
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
    if (state.buffers.levelCount(kBloomUnit) < 2) {
        check.measured = std::to_string(state.buffers.levelCount(kBloomUnit)) + " levels on unit 17";
        check.tolerance = "the bloom texture has 2 levels (step 22)";
        check.diagnosis = "no two-level bloom texture on unit 17 (steps 21-23)";
        check.blame = range(17, 25);
        return false;
    }
    state.bloom0 = state.buffers.bloom(0);
    state.bloom1 = state.buffers.bloom(1);
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

std::string passName(std::size_t k) {
    return "pass " + std::to_string(k / 2 + 1) + (k % 2 == 0 ? " horizontal" : " vertical");
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
    if (state.buffers.passesFault) std::rethrow_exception(state.buffers.passesFault);
    state.captured = state.buffers.captured;
    state.store = ref::detectFloatStore(state.bloom0, ref::bloomThreshold(state.acc));
    if (state.captured && state.passes.size() % 2 == 0) state.pairs = int(state.passes.size()) / 2;
    const int w = std::max(1, state.bloom0.width / 2);
    const int h = std::max(1, state.bloom0.height / 2);
    if (state.captured && !state.passes.empty()) state.store = passStore(state.bloom0, state.passes[0].image, w, h, state.store);
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
    const auto chain = [&](const ref::Settings& s, int n) { return chainError(state.bloom1, state.bloom0, n, state.store, s); };
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
    const PeakError error = chainError(state.bloom1, state.bloom0, ref::kBlurPasses, state.store, ref::Settings{});
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

// The frame's models (frameDiscreteModels, kFrameParameters) that explain it, named on the check.
void nameFrameMistakes(CaseState& state, const ImageF* bloom, Check& check) {
    std::vector<ImageF> levels;
    for (int l = 0; l < state.buffers.luminanceLevels(); ++l) levels.push_back(state.buffers.level(kLuminanceUnit, l));
    const FrameInputs withLevels{state.acc, state.gpuKey, bloom, &levels, state.buffers.frameStore};
    const auto frameError = [&](const FrameModel& m) { return t10::test::byteError(ref::finalFrame(withLevels, m), state.buffers.frame); };
    std::vector<ref::Rgb> scratch;
    for (const DiscreteModel& d : frameDiscreteModels(state.part, int(levels.size())))
        if (!names(check, d.id) && frameWithin(frameError(d.model))) name(check, d.id, d.steps, d.value);
    for (const ModelParameter& p : kFrameParameters) {
        if (state.part < p.firstPart) continue;
        const auto model = [&p](double v) { return withSetting(p.field, v); };
        const auto residual = [&](double v) { return frameResidual(withLevels, model(v), state.buffers.frame, scratch, kRoughFrameStep); };
        const Fit rough = fitParameter(residual, p.low, p.high, true, 16, kRoughFrameFitSteps, kFrameFitStarts, kFrameResidualCeiling);
        if (rough.error > kFrameResidualCeiling) continue;
        const Fit fit = refineFrameFit(rough.value, [&](double v) {
            const auto e = frameError(model(v));
            return e.mean + e.fractionOverOne;
        });
        if (frameWithin(frameError(model(fit.value)))) name(check, p.id, p.steps, {fit.value});
    }
}

// The final frame (steps 6-10, 19-20, 35): the CPU tone map of the GPU's own buffers. The GPU
// evaluates in float, the reference in double from the same read-back buffers: a channel lands one
// step away only next to a rounding boundary, so at most 1 step and rarely.
bool frameCheck(CaseState& state, const CheckSpec& spec, Check& check) {
    const ImageF* bloom = state.part >= 2 ? &state.bloom1 : nullptr;
    const FrameInputs inputs{state.acc, state.gpuKey, bloom, nullptr, state.buffers.frameStore};
    const Image8 expected = ref::finalFrame(inputs, FrameModel{});
    const auto error = t10::test::byteError(expected, state.buffers.frame);
    check.passed = frameWithin(error);
    check.measured = "largest error " + std::to_string(error.max) + " 8-bit steps, mean " + format(error.mean) +
                     " 8-bit steps, " + format(error.fractionOverOne * 100.0) + "% of pixels off by more than 1 step";
    check.tolerance = "largest <= 1 8-bit step and mean <= 0.01 8-bit steps: float vs double rounding only";
    if (check.passed) return true;
    state.images.attach(check, state.buffers.frame, expected);
    const Check& levels = earlier(state, spec, "luminance-levels");
    if (onlyBlackPixelsOff(state.acc, expected, state.buffers.frame)) {
        name(check, "black-0-over-0", {9}, {}, "the NaN pixels are painted magenta by the grader's probe");
    } else if (!levels.passed) {
        inherit(check, levels, "the final pass reads the key from a level that is not 1x1");
    } else {
        nameFrameMistakes(state, bloom, check);
        chargeOneStep(check, describeFrame(expected, state.buffers.frame), 9, lookMissing(state.part, state.buffers.frame, inputs, expected));
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
        {"frame", 1, 3, [](int p) { return partInfo(p).frameSteps; }, {"luminance-levels"}, frameCheck},
    };
    return table;
}

} // namespace

std::vector<Check> bufferChecks(int part, const CaseRun& run, CheckImages& images) {
    CaseState state(part, run, images);
    for (const CheckSpec& spec : checkTable()) {
        if (part < spec.firstPart || part > spec.lastPart) continue;
        Check check;
        check.id = run.id + "." + spec.what;
        check.steps = spec.steps(part);
        const bool goOn = spec.run(state, spec, check);
        state.checks.push_back(std::move(check));
        if (!goOn) break;
    }
    return state.checks;
}

std::vector<Check> caseBufferChecks(int part, const CaseRun& run, CheckImages& images) {
    try {
        return bufferChecks(part, run, images);
    } catch (const Error& error) {
        Check check;
        check.id = run.id + ".buffers";
        check.steps = partInfo(part).steps;
        check.measured = error.what();
        check.tolerance = "every texture of the part is on its unit (15, 16, 17) with its full size and levels";
        check.diagnosis = "the stage does not write the buffers of this part where the tutorial puts them";
        return {check};
    }
}

} // namespace t10::grade
