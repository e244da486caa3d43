// One check of a submission as the reports show it: what it measured against which bound, whether it
// passed, and on a failure the steps it costs and the mistakes that explain it.
#pragma once
#include "diagnosis/catalogue.hpp"

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

// The steps a failed check costs (see Check::blame); empty for a passed check.
std::vector<int> failedSteps(const Check& check);

} // namespace t10::grade
