// Image comparison: the golden tests' tolerance model (per-channel threshold, fraction of failing
// pixels, mean error), its file format, and the difference heat-map; imgcompare, the tests and the
// grader share it.
#pragma once
#include "t10/image.hpp"

#include <string>

namespace t10::test {

struct Tolerance {
    int threshold = 0;        // a pixel fails when any channel differs by more than this (8-bit steps)
    double maxFraction = 0.0; // largest allowed fraction of failing pixels
    double maxMean = 0.0;     // largest allowed mean absolute difference over all channels (8-bit steps)
};

struct Comparison {
    bool sizeMatches = false;
    double failingFraction = 0.0;
    double meanError = 0.0;
    int maxError = 0;
    bool passed = false;
    std::string summary; // one line with the measured figures against the bounds
};

// Reads "threshold = 8   # reason" style lines; each of the three keys must be present, and each
// must carry a reason after '#'. Throws t10::Error naming the file and line otherwise.
Tolerance readTolerance(const std::string& path);

// The difference of two 8-bit images of the same size, in 8-bit steps: the one metric of the golden
// tests and the numeric tests. A pixel is over the threshold when any channel differs by more.
struct ImageDifference {
    int maxError = 0;
    double meanError = 0.0;             // over all channels of all pixels
    double fractionOverThreshold = 0.0; // of the pixels
};
ImageDifference imageDifference(const Image8& a, const Image8& b, int threshold);

Comparison compareImages(const Image8& expected, const Image8& actual, const Tolerance& tolerance);

// Per-pixel largest channel difference, scaled x4 and coloured black -> red -> yellow -> white.
Image8 differenceHeatMap(const Image8& expected, const Image8& actual);

// A deterministic, clearly visible alteration (a block covering 1/16 of the image, inverted), used to
// prove that a tolerance is not blind.
Image8 visiblyAltered(const Image8& image);

} // namespace t10::test
