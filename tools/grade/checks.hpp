// The checks t10-grade runs on one rendered case of a submission: every intermediate buffer that
// the part writes (luminance levels and key, bloom levels, each blur pass as pass_capture.cpp
// recorded it, the blurred bloom) against the CPU
// reference of tests/numeric, the final frame against the CPU tone map of the buffers the GPU
// produced, and the frame against the reference stage with FLIP. A failed check asks the mistake
// catalogue (mistakes.hpp) which known mistake explains the measurement.
#pragma once
#include "dumps.hpp"

#include <string>
#include <vector>

namespace t10::grade {

struct Check {
    std::string id;          // "<case>.<what>", e.g. "pot.key"
    std::vector<int> steps;  // tutorial steps the check covers
    bool passed = false;
    std::string measured;    // the figures, in units a reader knows (8-bit steps, R16 steps, % of peak)
    std::string tolerance;   // the bound and why
    std::string diagnosis;   // the known mistake that explains a failure, or what to look at
    // Image checks: files relative to the submission's report folder (empty when not an image check).
    std::string studentImage;
    std::string referenceImage;
    std::string heatMap;
};

// One rendered case: what the stage wrote with --dump and --output.
struct CaseRun {
    std::string id;          // pot, npot, extremes, hot
    std::string description; // "128x128, camera default"
    bool camera = false;     // a scene render (FLIP is compared against the reference stage)
    t10::test::Dump dump;
};

// Reads <dir>/unit15_level0.pfm and <dir>/frame.png; throws t10::Error naming a missing file. The
// blur passes (<dir>/blur_passes.txt) are read by bufferChecks.
t10::test::Dump loadDumpDir(const std::string& dir);

// The buffer checks of `part` (1, 2 or 3) for one case. Images for failed image checks go into
// `imageDir` (a folder inside the report folder) and are named relative to `reportDir`.
std::vector<Check> bufferChecks(int part, const CaseRun& run, const std::string& reportDir, const std::string& imageDir);

// The tutorial steps of a part (1-16, 1-25, 1-36).
std::vector<int> partSteps(int part);

} // namespace t10::grade
