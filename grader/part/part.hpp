// What t10-grade knows of each part of the tutorial: the reference stage it is graded against, the
// files a submission holds, and its steps (those a student of the part has done, which the rubric
// scores, and those that make the final frame). The one description the checks, the scoring, the
// reports and the command line read; tests/part_facts.py holds the other languages' copies (CMake,
// Python, shell) to it.
#pragma once
#include <string>
#include <vector>

namespace t10::grade {

struct Part {
    int number = 0;                   // 1, 2, 3
    std::string stage;                // the reference stage folder, tutorial10_part1_tonemap
    int firstStep = 0, lastStep = 0;  // the steps the part adds: 1-16, 17-25, 26-36
    std::vector<std::string> shaders; // the stage's shaders, beside Tutorial10.cpp
    std::vector<std::string> asked;   // the files the part's steps change (the stage diff)
    std::vector<int> steps;           // the steps a student of the part has done, 1 to lastStep: the rubric's
    std::vector<int> frameSteps;      // the steps whose result is the final frame (6-10, 19-20 from Part 2, 35 in Part 3)
};

// Part 1, 2 or 3; throws t10::Error for any other number (a grader bug: the command line refuses it).
const Part& partInfo(int number);

} // namespace t10::grade
