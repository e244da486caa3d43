// The models of the bloom; see bloom_model.hpp.
#include "diagnosis/bloom_model.hpp"

#include "t10/dumps.hpp"

#include <algorithm>
#include <cmath>

namespace t10::grade {

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

PeakError peakError(const ImageF& gpu, const ImageF& cpu) {
    if (gpu.width != cpu.width || gpu.height != cpu.height) return {1e9, 1e9};
    const t10::test::LevelError error = t10::test::compareLevels(gpu, cpu);
    return {error.worstRelativeToPeak, error.meanRelativeToPeak};
}

bool allZero(const ImageF& image) {
    return std::all_of(image.data.begin(), image.data.end(), [](float v) { return v == 0.0f; });
}

double worstStoreError(const ImageF& gpu, const ImageF& cpu, const ImageF* classifiedBy) {
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

bool blurWithin(const PeakError& e) { return e.worst <= kBlurWorst && e.mean <= kBlurMean; }

ImageF modelPass(const ImageF& source, int w, int h, bool horizontal, const ref::Settings& s, ref::FloatStore store) {
    ImageF out = ref::gaussianPass(source, w, h, horizontal, s);
    ref::storeR11G11B10F(out, store);
    return out;
}

ref::FloatStore passStore(const ImageF& source, const ImageF& firstPass, int w, int h, ref::FloatStore detected) {
    if (detected != ref::FloatStore::Truncate || firstPass.width != w || firstPass.height != h) return detected;
    // Texels that are not black and that a rule reproduces exactly; a wrong blur is reproduced by neither.
    std::size_t lit = 0;
    const auto matches = [&](ref::FloatStore store) {
        const ImageF model = modelPass(source, w, h, true, ref::Settings{}, store);
        std::size_t same = 0;
        lit = 0;
        for (std::size_t i = 0; i < model.data.size() && i < firstPass.data.size(); ++i) {
            if (firstPass.data[i] == 0.0f) continue;
            ++lit;
            same += model.data[i] == firstPass.data[i];
        }
        return same;
    };
    const std::size_t half = matches(ref::FloatStore::HalfThenTruncate);
    const std::size_t truncated = matches(ref::FloatStore::Truncate);
    return half > truncated && 2 * half > lit ? ref::FloatStore::HalfThenTruncate : detected;
}

PeakError chainError(const ImageF& level1, const ImageF& level0, int passes, ref::FloatStore store, const ref::Settings& s) {
    PeakError best = peakError(level1, ref::gaussianBloom(level0, passes, store, s));
    if (store == ref::FloatStore::Truncate || store == ref::FloatStore::HalfThenTruncate) {
        const ref::FloatStore other =
            store == ref::FloatStore::Truncate ? ref::FloatStore::HalfThenTruncate : ref::FloatStore::Truncate;
        const PeakError e = peakError(level1, ref::gaussianBloom(level0, passes, other, s));
        if (e.mean < best.mean) best = e;
    }
    return best;
}

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

} // namespace t10::grade
