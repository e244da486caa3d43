// The models of luminance level 0; see key_model.hpp.
#include "diagnosis/key_model.hpp"

#include <algorithm>
#include <cmath>

namespace t10::grade {

double modelMapped(const ref::Rgb& colour, const KeyModel& model) {
    const ref::Settings& s = model.settings;
    return ref::toUnorm16(ref::rangeMappedLogLuminance(ref::luminance(colour, s), s, model.log));
}

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

double logLuminanceTolerance(const KeyModel& model) {
    const auto range = [](const ref::Settings& s) { return std::log(s.whitePoint) - std::log(s.epsilon); };
    const double own = range(model.settings);
    if (!(own > 0.0)) return kLogLuminanceSteps;
    return kLogLuminanceSteps * std::max(1.0, range(ref::Settings{}) / own);
}

} // namespace t10::grade
