// The bench driver and its table; see bench.hpp.
#include "t10/bench.hpp"

#include "t10/cli_range.hpp"
#include "t10/error.hpp"
#include "t10/file.hpp"
#include "t10/gl.hpp"
#include "t10/stats.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <ostream>
#include <sstream>

namespace t10 {

namespace {
struct Stats {
    double median = 0.0;
    double min = 0.0;
    double max = 0.0;
};

Stats stats(const std::vector<double>& samples) {
    Stats s;
    if (samples.empty()) return s;
    s.median = median(samples);
    const auto [lo, hi] = std::minmax_element(samples.begin(), samples.end());
    s.min = *lo;
    s.max = *hi;
    return s;
}
} // namespace

void addBenchOptions(CLI::App& cli, BenchSettings& settings) {
    CLI::Option_group* group = cli.add_option_group("Benchmark", "Timing the stage's frames");
    CLI::Option* bench = group->add_option("--bench", settings.frames,
                                           "Render N frames after " + std::to_string(kBenchWarmUpFrames) +
                                               " warm-up frames and print the median time of the frame and of each "
                                               "pass the stage times (use with --headless)")
                             ->check(inRange(1, 100000, true));
    group->add_option("--bench-csv", settings.csv, "Also write the --bench table as CSV "
                                                   "(pass,median_ms,min_ms,max_ms,frames)")
        ->needs(bench);
}

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
    std::ostringstream text;
    text << "pass,median_ms,min_ms,max_ms,frames\n" << std::fixed << std::setprecision(4);
    for (const Row& row : rows()) {
        const Stats s = stats(row.samples);
        text << row.name << "," << s.median << "," << s.min << "," << s.max << "," << row.samples.size() << "\n";
    }
    const std::string csv = text.str();
    writeFileAtomically(path, csv.data(), csv.size(), "the benchmark CSV");
}

void runBench(const BenchSettings& settings, const BenchTarget& target) {
    BenchTable table;
    for (int i = 0; i < kBenchWarmUpFrames + settings.frames; ++i) {
        const auto start = std::chrono::steady_clock::now();
        target.renderFrame();
        glFinish();
        const double wallMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        std::vector<PassTime> passes;
        if (target.timers != nullptr) {
            target.timers->collect(true);
            passes = target.timers->latest();
        }
        if (i >= kBenchWarmUpFrames) table.add(passes, wallMs);
    }
    std::cout << target.name << " benchmark: " << target.width << "x" << target.height;
    if (!target.settings.empty()) std::cout << ", " << target.settings;
    std::cout << "; median of " << settings.frames << " frames after " << kBenchWarmUpFrames << " warm-up frames\n";
    table.print(std::cout);
    if (!settings.csv.empty()) {
        table.writeCsv(settings.csv);
        std::cout << "wrote " << settings.csv << "\n";
    }
}

} // namespace t10
