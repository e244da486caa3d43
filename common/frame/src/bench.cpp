// The bench driver and its table; see bench.hpp.
#include "t10/bench.hpp"

#include "t10/app.hpp"
#include "t10/error.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <ostream>

namespace t10 {

namespace {
struct Stats {
    double median = 0.0;
    double min = 0.0;
    double max = 0.0;
};

Stats stats(std::vector<double> samples) {
    Stats s;
    if (samples.empty()) return s;
    std::sort(samples.begin(), samples.end());
    const std::size_t n = samples.size();
    s.median = n % 2 == 1 ? samples[n / 2] : 0.5 * (samples[n / 2 - 1] + samples[n / 2]);
    s.min = samples.front();
    s.max = samples.back();
    return s;
}
} // namespace

void BenchTable::add(const std::vector<PassTime>& passes, double frameWallMs) {
    double post = 0.0;
    for (const PassTime& pass : passes) {
        auto row = std::find_if(passes_.begin(), passes_.end(), [&](const Row& r) { return r.name == pass.name; });
        if (row == passes_.end()) row = passes_.insert(passes_.end(), Row{pass.name, {}});
        row->samples.push_back(pass.ms);
        if (pass.name != "scene") post += pass.ms;
    }
    post_.push_back(post);
    frame_.push_back(frameWallMs);
}

std::vector<BenchTable::Row> BenchTable::rows() const {
    std::vector<Row> all = passes_;
    // A stage without pass timers has only the frame's wall clock.
    if (!passes_.empty()) all.push_back(Row{"post-process", post_});
    all.push_back(Row{"frame", frame_});
    return all;
}

void BenchTable::print(std::ostream& out) const {
    const std::ios::fmtflags flags = out.flags();
    out << std::left << std::setw(14) << "pass" << std::right << std::setw(11) << "median ms" << std::setw(11) << "min ms"
        << std::setw(11) << "max ms" << "\n";
    out << std::fixed << std::setprecision(3);
    for (const Row& row : rows()) {
        const Stats s = stats(row.samples);
        if (row.name == "post-process") out << std::string(47, '-') << "\n";
        out << std::left << std::setw(14) << row.name << std::right << std::setw(11) << s.median << std::setw(11) << s.min
            << std::setw(11) << s.max << "\n";
    }
    out << "(GPU times from GL_TIME_ELAPSED queries; post-process = every pass but the scene, summed per frame;\n"
           " frame = wall clock of render + glFinish)\n";
    out.flags(flags);
}

void BenchTable::writeCsv(const std::string& path) const {
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    std::error_code error;
    if (!parent.empty()) std::filesystem::create_directories(parent, error);
    std::ofstream file(path);
    if (!file) throw t10::Error(path + ": cannot write the benchmark CSV");
    file << "pass,median_ms,min_ms,max_ms,frames\n" << std::fixed << std::setprecision(4);
    for (const Row& row : rows()) {
        const Stats s = stats(row.samples);
        file << row.name << "," << s.median << "," << s.min << "," << s.max << "," << row.samples.size() << "\n";
    }
    if (!file) throw t10::Error(path + ": cannot write the benchmark CSV");
}

void runBench(App& app, const Stage& stage, int frames, const std::string& csvPath) {
    BenchTable table;
    for (int i = 0; i < kBenchWarmUpFrames + frames; ++i) {
        const auto start = std::chrono::steady_clock::now();
        app.renderFrame();
        glFinish();
        const double wallMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        std::vector<PassTime> passes;
        if (stage.timers != nullptr) {
            stage.timers->collect(true);
            passes = stage.timers->latest();
        }
        if (i >= kBenchWarmUpFrames) table.add(passes, wallMs);
    }
    std::cout << stage.name << " benchmark: " << app.width() << "x" << app.height();
    if (stage.benchSettings != nullptr) std::cout << ", " << stage.benchSettings();
    std::cout << "; median of " << frames << " frames after " << kBenchWarmUpFrames << " warm-up frames\n";
    table.print(std::cout);
    if (!csvPath.empty()) {
        table.writeCsv(csvPath);
        std::cout << "wrote " << csvPath << "\n";
    }
}

} // namespace t10
