// One-parameter fits of t10-grade: the value of one tutorial constant that makes the CPU reference
// (reference.hpp, with that one setting changed) closest to what a submission's GPU wrote.
#pragma once
#include <functional>

namespace t10::grade {

struct Fit {
    double value = 0.0;
    double error = 1e300;
};

// Minimises `error` over [low, high]: a grid of `grid` points (evenly spaced in log when logScale),
// then `steps` steps of a golden-section search between the best point's neighbours (each narrows
// the bracket by 0.618: 12 leave 0.3 % of it, 22 leave 0.001 %). Assumes one minimum near the best
// grid point, which holds for the chain's constants on inputs that spread across them.
Fit fitParameter(const std::function<double(double)>& error, double low, double high, bool logScale, int grid = 40,
                 int steps = 22);

} // namespace t10::grade
