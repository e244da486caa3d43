// The median of measurements; see stats.hpp.
#include "t10/stats.hpp"

#include <algorithm>

namespace t10 {

double median(std::vector<double> samples) {
    if (samples.empty()) return 0.0;
    const std::size_t n = samples.size();
    // Only the middle one or two values need to be in place.
    std::nth_element(samples.begin(), samples.begin() + static_cast<std::ptrdiff_t>(n / 2), samples.end());
    const double upper = samples[n / 2];
    if (n % 2 == 1) return upper;
    const double lower = *std::max_element(samples.begin(), samples.begin() + static_cast<std::ptrdiff_t>(n / 2));
    return 0.5 * (lower + upper);
}

} // namespace t10
