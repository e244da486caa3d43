// The cases every submission renders (cases.hpp): the list alone, without the inputs' files or the
// reference's renders, so that the page's check (grader/page/) renders the same cases from the one list.
#include "capture/cases.hpp"

namespace t10::grade {

// Small sizes keep a submission to a few seconds on a CPU renderer; 160x90 halves to 80x45 and its
// luminance chain passes odd sizes (45, 5), unlike 128x128.
std::vector<CaseSpec> cases(int part) {
    std::vector<CaseSpec> list{
        {"pot", "128x128 (power of two), camera default", true, {"--size", "128x128", "--camera", "default"}, 128, 128},
        {"npot", "160x90 (not a power of two), camera lights", true, {"--size", "160x90", "--camera", "lights"}, 160, 90},
        {"extremes", "64x64 input: black pixels, and every pixel a different luminance from 0.001 to 50", false,
         {"--input", "{inputs}/ramp.exr"}, 64, 64},
    };
    if (part >= 2) list.push_back({"hot", "128x128 input: one hot 2x2 block on grey", false, {"--input", "{inputs}/hot.exr"}, 128, 128});
    return list;
}

std::vector<std::string> caseArgs(const std::vector<std::string>& args, const std::string& inputs) {
    std::vector<std::string> replaced;
    for (std::string arg : args) {
        const auto at = arg.find("{inputs}");
        if (at != std::string::npos) arg.replace(at, 8, inputs);
        replaced.push_back(arg);
    }
    return replaced;
}

} // namespace t10::grade
