// The mistake models' shared pieces; see model.hpp.
#include "diagnosis/model.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace t10::grade {

std::string format(double value, int precision) {
    std::ostringstream text;
    text.precision(precision);
    text << value;
    return text.str();
}

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

} // namespace t10::grade
