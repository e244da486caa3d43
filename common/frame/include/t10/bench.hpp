// The bench driver (--bench N, --bench-csv FILE): any stage renders warm-up frames, then N timed
// frames, and prints the median of each GPU pass it times (Stage::timers) and of the whole frame.
// The driver knows nothing of the frame loop: it is handed one frame to render as a callback.
#pragma once
#include "t10/gpu_timers.hpp"

#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace t10 {

// Untimed frames before the measured ones (shader compilation, first-touch allocations).
constexpr int kBenchWarmUpFrames = 3;

struct BenchSettings {
    int frames = 0;  // --bench N: timed frames before the ordinary ones (0: no benchmark)
    std::string csv; // --bench-csv FILE
};

// Adds the "Benchmark" group to `cli`.
void addBenchOptions(CLI::App& cli, BenchSettings& settings);

// What one benchmark measures.
struct BenchTarget {
    std::string name;                 // the stage, for the heading
    int width = 0;                    // the framebuffer size, for the heading
    int height = 0;
    std::string settings;             // the stage's settings for the heading ("5 blur passes"); may be empty
    std::function<void()> renderFrame; // one frame, without input, UI, outputs or swap
    PassTimers* timers = nullptr;      // the stage's pass timers, if it times its passes
};

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

// Renders kBenchWarmUpFrames + settings.frames frames through target.renderFrame(), each followed
// by glFinish, and prints the table (and writes it as CSV to settings.csv unless empty).
void runBench(const BenchSettings& settings, const BenchTarget& target);

} // namespace t10
