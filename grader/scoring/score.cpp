// The score and its split over the steps; see score.hpp.
#include "scoring/score.hpp"

#include "part/part.hpp"

#include <algorithm>
#include <map>
#include <set>

namespace t10::grade {

std::vector<int> blamedSteps(const std::vector<Check>& checks) {
    std::set<int> steps;
    for (const Check& check : checks)
        for (int step : failedSteps(check)) steps.insert(step);
    return {steps.begin(), steps.end()};
}

int score(const Scored& scored) {
    if (!scored.graded || scored.checks.empty()) return 0;
    const std::vector<int> failed = blamedSteps(scored.checks);
    int total = 0;
    for (const auto& [step, points] : wholePoints(scored.rubric, scored.part))
        if (!std::binary_search(failed.begin(), failed.end(), step)) total += points;
    const bool allPassed = std::all_of(scored.checks.begin(), scored.checks.end(), [](const Check& c) { return c.passed; });
    return allPassed ? total : std::min(total, 99);
}

std::vector<StepResult> stepResults(const Scored& scored) {
    // A step fails when a failed check blames it, so one mistake costs its step once.
    const std::vector<int> failed = blamedSteps(scored.checks);
    const std::map<int, int> whole = wholePoints(scored.rubric, scored.part);
    const int target = score(scored);
    std::vector<StepResult> out;
    int earned = 0;
    for (int step : partInfo(scored.part).steps) {
        StepResult s;
        s.step = step;
        for (const Check& c : scored.checks) {
            const std::vector<int> blamed = failedSteps(c);
            const bool covers = std::find(c.steps.begin(), c.steps.end(), step) != c.steps.end();
            const bool blames = std::find(blamed.begin(), blamed.end(), step) != blamed.end();
            if (blames || (covers && c.passed)) s.checks.push_back(&c);
        }
        s.passed = scored.graded && !scored.checks.empty() && !std::binary_search(failed.begin(), failed.end(), step);
        const auto at = whole.find(step);
        s.maxPoints = at == whole.end() ? 0 : at->second;
        s.points = s.passed ? s.maxPoints : 0;
        earned += s.points;
        out.push_back(s);
    }
    // The score is at most 99 while any check fails: where no step is blamed (a rubric that gives the
    // blamed steps 0 points), the point held back comes off the last passed step that has one.
    for (auto s = out.rbegin(); earned > target && s != out.rend(); ++s) {
        const int held = std::min(s->points, earned - target);
        if (held == 0) continue;
        s->points -= held;
        earned -= held;
        s->note = std::to_string(held) + " point held back: 100 only when every check passes";
    }
    return out;
}

} // namespace t10::grade
