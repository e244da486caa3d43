// A CLI11 check for numeric options with a range (common/'s --bench, extras' settings): anything
// else is rejected with the allowed range, e.g. "--white-point: must be from 0.05 to 2 (got 9)".
#pragma once
#include <CLI/CLI.hpp>

namespace t10 {

// Accepts numbers from lo to hi (whole numbers only with `integer`); NaN is rejected.
CLI::Validator inRange(double lo, double hi, bool integer = false);

} // namespace t10
