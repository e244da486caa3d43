// What the mistake models of t10-grade share: a tutorial constant a fit searches (ModelParameter),
// a pixel's colour as the reference reads it, a run of steps, the figures' formatting and the shape of
// an error no model explains.
#pragma once
#include "reference.hpp"

#include "t10/image.hpp"

#include <numeric>
#include <string>
#include <vector>

namespace t10::grade {

namespace ref = t10::ref;
using t10::Image8;
using t10::ImageF;

constexpr ref::Rgb kRec601Weights{0.299, 0.587, 0.114};

// A pixel's colour, as the reference's functions take it.
inline ref::Rgb texel(const ImageF& image, int x, int y) { return {image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2)}; }

// `value` to `precision` significant digits, as the diagnoses write figures.
std::string format(double value, int precision = 4);

inline bool endsWith(const std::string& text, const std::string& suffix) {
    return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// The steps first to last.
inline std::vector<int> range(int first, int last) {
    std::vector<int> steps(static_cast<std::size_t>(last - first + 1));
    std::iota(steps.begin(), steps.end(), first);
    return steps;
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

// Least-squares factor k and offset d of got ~ k * expected and got ~ expected + d over paired
// values, with the mean residual of each; says which shape the error has, or "".
std::string errorShape(const std::vector<double>& expected, const std::vector<double>& got, double unit,
                       const std::string& unitName);

} // namespace t10::grade
