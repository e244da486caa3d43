// imgcompare: compares a rendered PNG with its golden under the golden's tolerance file.
// On failure it writes the actual image and a difference heat-map next to --diff-prefix.
//   imgcompare GOLDEN.png ACTUAL.png TOLERANCE [--diff-prefix P] [--alter] [--expect-reject]
// --alter inverts a block of ACTUAL first; --expect-reject succeeds only if the comparison fails
// (the tests that prove a golden can fail).
#include "t10/compare.hpp"

#include "t10/error.hpp"
#include "t10/image_io.hpp"

#include <iostream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    std::vector<std::string> positional;
    std::string diffPrefix;
    bool alter = false;
    bool expectReject = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--alter") {
            alter = true;
        } else if (arg == "--expect-reject") {
            expectReject = true;
        } else if (arg == "--diff-prefix" && i + 1 < argc) {
            diffPrefix = argv[++i];
        } else if (arg.rfind("--", 0) == 0) {
            std::cerr << "imgcompare: error: unknown option " << arg << "\n";
            return 2;
        } else {
            positional.push_back(arg);
        }
    }
    if (positional.size() != 3) {
        std::cerr << "usage: imgcompare GOLDEN.png ACTUAL.png TOLERANCE [--diff-prefix P] [--alter] [--expect-reject]\n";
        return 2;
    }
    try {
        const t10::Image8 golden = t10::readPng(positional[0]);
        t10::Image8 actual = t10::readPng(positional[1]);
        if (alter) actual = t10::test::visiblyAltered(actual);
        const t10::test::Tolerance tolerance = t10::test::readTolerance(positional[2]);
        const t10::test::Comparison result = t10::test::compareImages(golden, actual, tolerance);
        std::cout << positional[1] << " vs " << positional[0] << ": " << result.summary << "\n";
        if (expectReject) {
            std::cout << (result.passed ? "FAIL: the golden accepted an image it must reject\n"
                                        : "ok: rejected as it should be\n");
            return result.passed ? 1 : 0;
        }
        if (!result.passed) {
            if (!diffPrefix.empty()) {
                t10::writePng(diffPrefix + ".actual.png", actual);
                t10::writePng(diffPrefix + ".diff.png", t10::test::differenceHeatMap(golden, actual));
                std::cout << "wrote " << diffPrefix << ".actual.png and " << diffPrefix << ".diff.png\n";
            }
            std::cout << "FAIL: outside the golden's tolerance\n";
            return 1;
        }
        std::cout << "ok\n";
        return 0;
    } catch (const t10::Error& error) {
        std::cerr << "imgcompare: error: " << error.what() << "\n";
        return 1;
    }
}
