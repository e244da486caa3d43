// The result files of the platforms courses grade on, written from a Report beside its report.json:
// Gradescope's results.json (gradescope-results.json), PrairieLearn's external grader results
// (prairielearn-results.json) and the JSON GitHub Classroom's grading reporter reads
// (classroom-result.json, and classroom-result.b64, its base64 as the reporter takes it from a step
// output). Every platform test is one tutorial step (plus one for the whole frame): stepResults() is
// the one place that groups the checks and gives each step its points.
#pragma once
#include "report.hpp"

#include <string>
#include <vector>

namespace t10::grade {

// The test of the checks that cover every step of the part (FLIP of the whole frame against the
// reference stage): it comes after the steps.
constexpr int kWholeFrame = 1000;

struct StepResult {
    int step = 0;                      // a tutorial step, or kWholeFrame
    std::vector<const Check*> checks;  // the checks that cover the step (empty when not graded)
    bool passed = false;               // every check of the step passed
    double points = 0.0;               // earned, rounded to 0.01
    double maxPoints = 0.0;            // rounded to 0.01; a report's steps add up to exactly 100
};

// Points per step, from today's score (the share of checks passed): each check is worth 100 / checks,
// split evenly over the steps it covers; a check covering every step goes to the kWholeFrame test. A report that was not graded (build-failed, crashed, ...)
// has no checks: every step of the part gets an equal share and 0 points.
std::vector<StepResult> stepResults(const Report& report);

// The names --format accepts.
const std::vector<std::string>& formatNames();

// Writes the result of each format in `formats` into `dir` (the submission's report folder), each to a
// temporary file renamed into place; throws t10::Error naming the file that could not be written.
void writeFormats(const Report& report, const std::vector<std::string>& formats, const std::string& dir);

// Helpers shared with class_index.cpp.
std::string jsonQuote(const std::string& text);  // a JSON string; invalid UTF-8 bytes become U+FFFD
std::string htmlEscape(const std::string& text);
void writeFileAtomically(const std::string& path, const std::string& content);

} // namespace t10::grade
