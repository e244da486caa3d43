// The black-background check: when a large share of the frame is black (a model on nothing), the
// tutorial's key Ya, a geometric mean of Y + epsilon, is pulled towards epsilon and everything lit
// burns to white. The run says so once, with the key it got and what to do (site/notes.md, "A black
// background and the key").
#pragma once
#include <optional>
#include <string>

namespace t10 {

// Pixels with Y + epsilon below this count as black (the background, not a dark surface: the
// scene's ambient term alone keeps a lit surface far above it).
constexpr double kBlackLuminance = 1e-6;
// The warning fires from this share of black pixels: at 20% the key is already about 25 times below
// the key of the lit pixels alone (for lit pixels around Y = 0.1, 0.2 x ln(1e-8 / 0.1) = -3.2).
constexpr double kBlackShareWarned = 0.2;

struct BlackShare {
    double share = 0.0;    // of the frame's pixels, 0..1
    double key = 0.0;      // the key Ya the tone map used (readSceneKey)
    double litKey = 0.0;   // Ya of the pixels that are not black (0 when there are none)
};

// Measures the luminance texture on unit 16 (level 0: each pixel's log luminance, range-mapped in
// GL_R16 or plain in GL_R16F). Nothing when unit 16 holds no texture (Part 0). Needs a current
// context; leaves the active texture unit as it was.
std::optional<BlackShare> measureBlackShare();

// The one-line warning for `m`, or nothing when the share is below kBlackShareWarned.
std::optional<std::string> blackBackgroundWarning(const BlackShare& m);

} // namespace t10
