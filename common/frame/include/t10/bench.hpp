// The bench driver (--bench N, --bench-csv FILE): any stage renders warm-up frames, then N timed
// frames, and prints the median of each GPU pass it times (Stage::timers) and of the whole frame.
#pragma once
#include "t10/gpu_timers.hpp"

#include <iosfwd>
#include <string>
#include <vector>

namespace t10 {

class App;
struct Stage;

// Untimed frames before the measured ones (shader compilation, first-touch allocations).
constexpr int kBenchWarmUpFrames = 3;

// Collects the pass times of the benchmark's frames and reports the median of each.
class BenchTable {
public:
    // One frame: its passes (from PassTimers::latest()) and its wall-clock time.
    void add(const std::vector<PassTime>& passes, double frameWallMs);
    // Prints the table: one row per pass, then "post-process" (every pass but the scene, summed
    // per frame) and "frame" (wall clock, render + glFinish).
    void print(std::ostream& out) const;
    // The same rows as CSV: pass,median_ms,min_ms,max_ms,frames. Throws t10::Error on failure.
    void writeCsv(const std::string& path) const;

private:
    struct Row {
        std::string name;
        std::vector<double> samples;
    };
    std::vector<Row> rows() const;
    std::vector<Row> passes_;
    std::vector<double> post_;
    std::vector<double> frame_;
};

// Renders kBenchWarmUpFrames + `frames` frames of the stage through app.renderFrame(), each
// followed by glFinish, and prints the table (and writes it as CSV to `csvPath` unless empty).
void runBench(App& app, const Stage& stage, int frames, const std::string& csvPath);

} // namespace t10
