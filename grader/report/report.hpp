// What t10-grade writes for each submission (report.json, report.html) and for the class
// (gradebook.csv), and how the score is computed.
#pragma once
#include "checks/check.hpp"
#include "report/status.hpp"
#include "scoring/rubric.hpp"
#include "scoring/score.hpp"
#include "intake/submission_files.hpp"

#include <string>
#include <vector>

namespace t10::grade {

struct Report {
    std::string submission;  // the folder's name
    std::string path;        // the folder as given
    int part = 0;
    Status status = Status::GraderError; // set by the run (status.hpp)
    std::string message;     // for a status other than graded: what happened, with the tool's own words
    std::vector<Check> checks;
    double seconds = 0.0;    // wall time to grade it
    Rubric rubric;           // points per step of the part (rubric.hpp)
    std::string isolation;   // namespaces | uid | none: how the submission's code was contained
    std::string fill;        // --fill-from-reference: unchanged | all | none
    std::vector<SubmissionFile> files; // every file of the submission folder and where each came from
    // What the score reads of the report (scoring/score.hpp).
    Scored scored() const;
    // 0-100 (scoring/score.hpp's score): the whole points of the steps no failed check blames; at
    // most 99 while any check fails; 0 for any status other than graded. Every output shows this number.
    int score() const;
    int passedCount() const;
    // The steps the failed checks blame, each once, in tutorial order.
    std::vector<int> failedSteps() const;
    // "fix first: step 9 - <the diagnosis of the first check that blames it>", or "" when all passed;
    // for a status other than graded, the first compiler or shader error as "fix first: FILE:LINE:
    // error: ..." (FILE relative to the submission), else the first line of the message.
    std::string fixFirst() const;
};

// The link to a tutorial step: $T10_GRADE_TUTORIAL_URL (the course site's page, for reports read
// elsewhere), else tutorial10.html beside the report as the site's own pages link it, with #step-N.
std::string stepAnchor(int step);

void writeReportJson(const Report& report, const std::string& path);
void writeReportHtml(const Report& report, const std::string& path);
// One row per submission: submission,part,status,score,passed,total,failed_checks,failed_steps,isolation,
// fill_from_reference
void writeGradebook(const std::vector<Report>& reports, const std::string& path);

} // namespace t10::grade
