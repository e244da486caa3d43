// The rubric of t10-grade: points per tutorial step, read from grader/scoring/rubric.txt (or the file
// T10_GRADE_RUBRIC names), documented in site/instructors.md.
#pragma once
#include <map>
#include <string>

namespace t10::grade {

using Rubric = std::map<int, double>; // step -> points

// The points of the part's steps; throws t10::Error naming the file and line on a fault.
Rubric loadRubric(int part);
// The rubric file loadRubric reads: $T10_GRADE_RUBRIC if set, else the one in the source tree.
std::string rubricPath();

} // namespace t10::grade
