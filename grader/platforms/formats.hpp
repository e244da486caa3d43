// The result files of the platforms courses grade on, written from a Report beside its report.json:
// Gradescope's results.json (gradescope-results.json), PrairieLearn's external grader results
// (prairielearn-results.json) and the JSON GitHub Classroom's grading reporter reads
// (classroom-result.json, and classroom-result.b64, its base64 as the reporter takes it from a step
// output). Every platform test is one tutorial step (plus one for the whole frame): stepResults() is
// the one place that groups the checks and gives each step its points.
#pragma once
#include "report/report.hpp"

#include <string>
#include <vector>

namespace t10::grade {

struct StepResult {
    int step = 0;                      // a tutorial step
    std::vector<const Check*> checks;  // the failed checks that blame the step, the passed ones that cover it
    bool passed = false;               // graded, and no failed check blames the step
    int points = 0;                    // earned: maxPoints when passed, else 0; they add up to Report::score()
    int maxPoints = 0;                 // whole points (rubric.hpp's wholePoints); a part's add up to 100
    std::string note;                  // why a passed step earns less than maxPoints (the cap of 99), or ""
};

// One result per tutorial step of the part, worth the step's whole points (rubric.hpp's wholePoints):
// passed unless a failed check blames the step (Report::failedSteps). The earned points add up to
// exactly Report::score(), the number every output shows. A report that was not graded
// (build-failed, crashed, ...) fails every step.
std::vector<StepResult> stepResults(const Report& report);

// The names --format accepts.
const std::vector<std::string>& formatNames();

// Writes the result of each format in `formats` into `dir` (the submission's report folder), each to a
// temporary file renamed into place; throws t10::Error naming the file that could not be written.
void writeFormats(const Report& report, const std::vector<std::string>& formats, const std::string& dir);

} // namespace t10::grade
