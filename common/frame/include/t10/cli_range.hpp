// CLI11 helpers every options group uses: a check for numeric options with a range (common/'s
// --bench, extras' settings), which rejects anything else with the allowed range, e.g.
// "--white-point: must be from 0.05 to 2 (got 9)", the refusal of empty values, and the list of
// sizes of --resize-sequence.
#pragma once
#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace t10 {

// Accepts numbers from lo to hi (whole numbers only with `integer`); NaN is rejected.
CLI::Validator inRange(double lo, double hi, bool integer = false);

// Throws t10::UsageError("--output: the value is empty") for the first given option whose value is
// empty: an empty value is refused rather than read as "not given".
void refuseEmpty(std::initializer_list<const CLI::Option*> options);

// "--resize-sequence 320x200,0x0,640x360": each item through `parseSize` (0x0 is kept as a
// minimised window). An empty item (a leading, doubled or trailing comma) is refused with
// t10::UsageError rather than dropped: "640x360," is a typo, not a one-frame sequence.
std::vector<std::pair<int, int>> parseResizeSequence(
    const std::string& text, const std::function<std::pair<int, int>(const std::string&)>& parseSize);

} // namespace t10
