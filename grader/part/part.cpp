// The parts of the tutorial as t10-grade grades them; see part.hpp.
#include "part/part.hpp"

#include "t10/error.hpp"

#include <numeric>

namespace t10::grade {

namespace {

std::vector<int> stepsUpTo(int last) {
    std::vector<int> steps(static_cast<std::size_t>(last));
    std::iota(steps.begin(), steps.end(), 1);
    return steps;
}

Part describe(int number, std::string stage, int firstStep, int lastStep, std::vector<std::string> shaders,
              std::vector<std::string> asked) {
    Part p;
    p.number = number;
    p.stage = std::move(stage);
    p.firstStep = firstStep;
    p.lastStep = lastStep;
    p.shaders = std::move(shaders);
    p.asked = std::move(asked);
    p.steps = stepsUpTo(lastStep);
    p.frameSteps = {6, 7, 8, 9, 10};
    if (number >= 2) p.frameSteps.insert(p.frameSteps.end(), {19, 20});
    if (number >= 3) p.frameSteps.push_back(35);
    return p;
}

} // namespace

const Part& partInfo(int number) {
    // Part 3 leaves PostProcess.frag and PostProcessInit.frag as Part 2 has them.
    static const Part parts[] = {
        describe(1, "tutorial10_part1_tonemap", 1, 16, {"PostProcess.frag", "PostProcessInit.frag"},
                 {"Tutorial10.cpp", "PostProcess.frag", "PostProcessInit.frag"}),
        describe(2, "tutorial10_part2_bloom", 17, 25, {"PostProcess.frag", "PostProcessInit.frag"},
                 {"Tutorial10.cpp", "PostProcess.frag", "PostProcessInit.frag"}),
        describe(3, "tutorial10_part3_gaussian", 26, 36, {"PostProcess.frag", "PostProcessInit.frag", "Gauss.frag"},
                 {"Tutorial10.cpp", "Gauss.frag"}),
    };
    if (number < 1 || number > 3) throw Error("grader bug: there is no Part " + std::to_string(number));
    return parts[number - 1];
}

} // namespace t10::grade
