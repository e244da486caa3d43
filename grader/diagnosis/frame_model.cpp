// The models of the final frame; see frame_model.hpp.
#include "diagnosis/frame_model.hpp"

#include <algorithm>
#include <cmath>
#include <set>

namespace t10::grade {

FrameModel withSetting(double ref::Settings::*field, double value) {
    FrameModel model;
    model.settings.*field = value;
    return model;
}

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

double frameResidual(const FrameInputs& in, const FrameModel& model, const Image8& frame, std::vector<ref::Rgb>& colours,
                     int step) {
    ref::frameColours(in, model, colours, step);
    const int w = in.accumulation.width;
    double sum = 0.0;
    std::size_t count = 0;
    for (int y = 0; y < in.accumulation.height; y += step)
        for (int x = 0; x < w; x += step, ++count)
            for (int k = 0; k < 3; ++k) {
                // The level the renderer stores, unrounded, so that the residual varies smoothly with the value.
                sum += std::abs(ref::unorm8Level(colours[std::size_t(y) * w + x][k], in.store) - frame.at(x, y, k));
            }
    return sum / (3.0 * double(count));
}

Fit refineFrameFit(double value, const std::function<double(double)>& roundedError) {
    return fitParameter(roundedError, value * 0.99, value * 1.01, false, 11, kFrameFitSteps);
}

bool frameWithin(const t10::test::ByteError& e) { return e.max <= 1 && e.mean <= 0.01; }

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

std::vector<int> lookMissing(int part, const Image8& got, const FrameInputs& inputs, const Image8& expected) {
    std::set<int> steps;
    for (const DiscreteModel& d : frameDiscreteModels(part, 0)) {
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

} // namespace t10::grade
