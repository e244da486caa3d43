// Summaries of repeated measurements (frame times, pass times): one median for the whole project,
// so every table and log line agrees on what "median" means.
#pragma once
#include <vector>

namespace t10 {

// The median of `samples`: the middle value for an odd count, the mean of the two middle values for
// an even count; 0 for no samples (a table row that was never measured).
double median(std::vector<double> samples);

} // namespace t10
