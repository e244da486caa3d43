// The image check of a scene case: the submission's frame against the reference stage's frame of the
// same case, measured with FLIP (the flip-evaluator in the grader's venv, run as a limited process).
// The buffer checks (checks.hpp) say which pass is wrong; this one says whether the picture is.
#pragma once
#include "checks/buffers.hpp"
#include "checks/check.hpp"

#include <string>
#include <vector>

namespace t10::grade {

// Compares `studentFrame` with `referenceFrame` (both PNGs of the case's size). On a failure the
// frames and FLIP's heat-map are copied into <reportDir>/images and the diagnosis gathers what the
// case's own buffer checks (`caseChecks`) named. Throws t10::Error when FLIP itself cannot start: the
// grader's failure, never the student's.
Check flipCheck(int part, const CaseRun& run, const std::string& referenceFrame, const std::string& studentFrame,
                const std::string& reportDir, const std::vector<Check>& caseChecks);

} // namespace t10::grade
