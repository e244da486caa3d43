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

// The score's one rounding: 100 whole points split over the rubric's steps in proportion to their
// points, by largest remainder (each step gets the whole part of its share; the points left go to the
// largest remainders, the earlier step first on a tie). They add up to exactly 100, so the score and
// every platform's step points are whole numbers that add up to each other. A step of the part that
// the rubric lacks (a report whose grading failed before the rubric was read) counts 1 point.
std::map<int, int> wholePoints(const Rubric& rubric, int part);

} // namespace t10::grade
