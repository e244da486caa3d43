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
// then `steps` steps of a golden-section search between the best local minimum's neighbours (each
// narrows the bracket by 0.618: 12 leave 0.3 % of it, 22 leave 0.001 %, 40 leave 4e-9). Where the
// error has more than one basin (the frame's middle grey below 1 turns the operator's scale
// negative, which is not black), `starts` > 1 searches the next local minima of the grid too, best
// first, until one ends at or below `goodEnough`.
Fit fitParameter(const std::function<double(double)>& error, double low, double high, bool logScale, int grid = 40,
                 int steps = 22, int starts = 1, double goodEnough = 0.0);

} // namespace t10::grade
