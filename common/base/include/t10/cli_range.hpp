// CLI11 helpers every options group uses: a check for numeric options with a range (common/'s
// --bench, extras' settings), which rejects anything else with the allowed range, e.g.
// "--white-point: must be from 0.05 to 2 (got 9)", and the refusal of empty values.
#pragma once
#include <CLI/CLI.hpp>

namespace t10 {

// Accepts numbers from lo to hi (whole numbers only with `integer`); NaN is rejected.
CLI::Validator inRange(double lo, double hi, bool integer = false);

// Throws t10::UsageError("--output: the value is empty") for the first given option whose value is
// empty: an empty value is refused rather than read as "not given".
void refuseEmpty(std::initializer_list<const CLI::Option*> options);

} // namespace t10
