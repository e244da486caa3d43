// What t10-grade writes for each submission (report.json, report.html) and for the class
// (gradebook.csv), and how the score is computed.
#pragma once
#include "checks.hpp"
#include "submission_files.hpp"

#include <string>
#include <vector>

namespace t10::grade {

struct Report {
    std::string submission;  // the folder's name
    std::string path;        // the folder as given
    int part = 0;
    std::string status;      // graded | empty | missing-files | build-failed | shader-error | crashed | timeout
    std::string message;     // for a status other than graded: what happened, with the tool's own words
    std::vector<Check> checks;
    double seconds = 0.0;    // wall time to grade it
    std::string isolation;   // namespaces | uid | none: how the submission's code was contained
    std::string fill;        // --fill-from-reference: unchanged | all | none
    std::vector<SubmissionFile> files; // every file of the submission folder and where each came from
    // 0-100: the share of checks passed, rounded down, so only a submission that passes every check
    // gets 100; 0 for any status other than graded.
    int score() const;
    int passedCount() const;
};

void writeReportJson(const Report& report, const std::string& path);
void writeReportHtml(const Report& report, const std::string& path);
// One row per submission: submission,part,status,score,passed,total,failed_checks,isolation,fill_from_reference
void writeGradebook(const std::vector<Report>& reports, const std::string& path);

} // namespace t10::grade
