// The result files of the platforms courses grade on, written from a Report beside its report.json:
// Gradescope's results.json (gradescope-results.json), PrairieLearn's external grader results
// (prairielearn-results.json) and the JSON GitHub Classroom's grading reporter reads
// (classroom-result.json, and classroom-result.b64, its base64 as the reporter takes it from a step
// output). Every platform test is one tutorial step (plus one for the whole frame), with the points
// scoring/score.hpp's stepResults() gives it.
#pragma once
#include "report/report.hpp"

#include <string>
#include <vector>

namespace t10::grade {

// The names --format accepts.
const std::vector<std::string>& formatNames();

// Writes the result of each format in `formats` into `dir` (the submission's report folder), each to a
// temporary file renamed into place; throws t10::Error naming the file that could not be written.
void writeFormats(const Report& report, const std::vector<std::string>& formats, const std::string& dir);

} // namespace t10::grade
