// The checks t10-grade runs on one rendered case of a submission: every intermediate buffer that
// the part writes (luminance levels and key, bloom levels, each blur pass as --capture-passes
// recorded it, the blurred bloom) against the CPU reference (common/reference), the final frame
// against the CPU tone map of the buffers the GPU produced, and the frame against the reference
// stage with FLIP. The buffer checks are one table in checks.cpp (checkTable: id, steps, the checks
// each follows from, its function). A failed check fits the tutorial's constants to the buffers
// (fits.hpp) and names a mistake of the catalogue (catalogue.hpp) only when its fitted model
// explains them within the check's tolerance, in every case (crossCheckCases); otherwise it says
// how the buffer is wrong.
#pragma once
#include "diagnosis/catalogue.hpp"
#include "t10/dumps.hpp"

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
    std::vector<Finding> mistakes; // the catalogue's mistakes whose fitted model explains the failure
    // The steps a failure costs: the steps of the mistakes found, else `unexplainedBlame` where the
    // check sets it, else `steps`. A check that fails only because an earlier check's buffer is wrong
    // (followsFrom) costs nothing of its own.
    std::vector<int> blame;
    bool followsFrom = false;
    // What the diagnosis says when no mistake explains the failure (kept for crossCheckCases), and
    // the steps it then costs: one step of the check (one mistake is in one of its steps, and the
    // grader cannot say which), with the steps of a "-missing" model the buffer looks like beside it
    // (the frame of Part 2 without its tone map and bloom, steps 6-10 and 19-20 lost); empty: `steps`.
    std::string unexplained;
    std::vector<int> unexplainedBlame;
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

// Makes the cases agree: a constant the student wrote is the same in every render, so the frame's
// constants are fitted once to every case whose frame failed (kept only when one value explains
// them all), the bloom threshold is the one luminance interval every case allows, and of several
// mistakes that explain one case only those the other cases' same check also names are kept.
// Rewrites the diagnoses and blamed steps of the checks it changes.
void crossCheckCases(int part, const std::vector<CaseRun>& runs, std::vector<Check>& checks);

// The tutorial steps of a part (1-16, 1-25, 1-36).
std::vector<int> partSteps(int part);
// The steps whose result is the final frame (6-10, 19-20 from Part 2, 35 in Part 3).
std::vector<int> frameSteps(int part);
// The steps a failed check costs (see Check::blame); empty for a passed check.
std::vector<int> failedSteps(const Check& check);

} // namespace t10::grade
