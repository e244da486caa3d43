// The one-parameter search; see fits.hpp.
#include "diagnosis/fits.hpp"

#include <cmath>

namespace t10::grade {

Fit fitParameter(const std::function<double(double)>& error, double low, double high, bool logScale, int grid, int steps) {
    // Searched in t: the value itself, or its log.
    const auto value = [&](double t) { return logScale ? std::exp(t) : t; };
    const double t0 = logScale ? std::log(low) : low;
    const double t1 = logScale ? std::log(high) : high;
    const double dt = (t1 - t0) / (grid - 1);
    Fit best;
    int bestIndex = 0;
    for (int i = 0; i < grid; ++i) {
        const double e = error(value(t0 + dt * i));
        if (e < best.error) {
            best = {value(t0 + dt * i), e};
            bestIndex = i;
        }
    }
    double a = t0 + dt * std::max(0, bestIndex - 1);
    double b = t0 + dt * std::min(grid - 1, bestIndex + 1);
    const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
    double c = b - ratio * (b - a);
    double d = a + ratio * (b - a);
    double ec = error(value(c));
    double ed = error(value(d));
    for (int i = 0; i < steps; ++i) {
        if (ec < ed) {
            b = d;
            d = c;
            ed = ec;
            c = b - ratio * (b - a);
            ec = error(value(c));
        } else {
            a = c;
            c = d;
            ec = ed;
            d = a + ratio * (b - a);
            ed = error(value(d));
        }
    }
    if (ec < best.error) best = {value(c), ec};
    if (ed < best.error) best = {value(d), ed};
    return best;
}

} // namespace t10::grade
