// The class at a glance, written after the gradebook: DIR/index.html (the score distribution, a
// student x step table of failures, a link to each report) and DIR/grades-lms.csv (one row per
// student id, for an LMS import). Also reads the roster that names submissions by student id.
#pragma once
#include "report/report.hpp"

#include <map>
#include <string>
#include <vector>

namespace t10::grade {

struct RosterEntry {
    std::string studentId;
    std::string name;  // may be empty
};

// A CSV with a header row: the key column `folder` (or `github_username`, as GitHub Classroom's roster
// export names it) holds what --name-from gives for a submission, the id column `student_id` (or
// `identifier`) the id the LMS knows; `name` is optional. Throws t10::Error naming the file, the line and
// the fault (no such column, an empty or repeated key or id).
std::map<std::string, RosterEntry> readRoster(const std::string& path);

// `names` maps a submission (its report folder) to the student's name, where a roster gave one. `more`
// is HTML to end the page with (t10-grade --similarity's pairs to review).
void writeClassIndex(const std::vector<Report>& reports, const std::map<std::string, std::string>& names,
                     const std::string& dir, const std::string& more = "");

} // namespace t10::grade
