// The one score computation: the whole points (rubric.hpp) of the steps that no failed check blames.
// Report::score() and every platform's per-step tests (platforms/formats.cpp, report/class_index.cpp)
// read it from here, so the number a student sees and the points of the steps add up to each other.
#pragma once
#include "checks/check.hpp"
#include "scoring/rubric.hpp"

#include <string>
#include <vector>

namespace t10::grade {

// What the score reads of one graded submission.
struct Scored {
    int part = 0;
    const Rubric& rubric;
    bool graded = false;             // the run's status is graded (any other status scores 0)
    const std::vector<Check>& checks;
};

struct StepResult {
    int step = 0;                      // a tutorial step
    std::vector<const Check*> checks;  // the failed checks that blame the step, the passed ones that cover it
    bool passed = false;               // graded, and no failed check blames the step
    int points = 0;                    // earned: maxPoints when passed, else 0; they add up to score()
    int maxPoints = 0;                 // whole points (rubric.hpp's wholePoints); a part's add up to 100
    std::string note;                  // why a passed step earns less than maxPoints (the cap of 99), or ""
};

// The steps the failed checks blame, each once, in tutorial order.
std::vector<int> blamedSteps(const std::vector<Check>& checks);

// 0-100: the whole points of the steps no failed check blames; at most 99 while any check fails, so
// only a submission that passes every check gets 100; 0 when not graded or when no check ran.
int score(const Scored& scored);

// One result per tutorial step of the part, worth the step's whole points: passed unless a failed
// check blames the step. The earned points add up to exactly score(). A submission that was not
// graded (build-failed, crashed, ...) fails every step.
std::vector<StepResult> stepResults(const Scored& scored);

} // namespace t10::grade
