// The fixed interface between the host code and the shaders (design notes, "Fixed interface"),
// and the tutorial's constants, as named values. common/, extras/, the tests and the tools use
// these names; the stage files keep the tutorial's literals where the tutorial writes literals, and
// the test "contract: shaders agree with contract.hpp" reads the shaders to keep both in step.
#pragma once

namespace t10::contract {

// Texture units the post-process reads (GL_TEXTURE0 + unit).
constexpr unsigned kAccumulationUnit = 15; // HDR scene, GL_RGBA16F
constexpr unsigned kLuminanceKeyUnit = 16; // log luminance, GL_R16 (GL_R16F in exercise 40), full mip chain
constexpr unsigned kBloomUnit = 17;        // bloom, GL_R11F_G11F_B10F, 2 levels
// The units --dump writes, in order.
constexpr unsigned kPostProcessUnits[] = {kAccumulationUnit, kLuminanceKeyUnit, kBloomUnit};

// Uniform block InvResolution { vec2 v2InvResolution; }.
constexpr unsigned kInvResolutionBinding = 7;

// The smallest framebuffer side: the bloom texture has two mipmap levels, and a 1x1 texture can
// only have one.
constexpr int kMinFramebufferSide = 2;
// The largest side --size accepts.
constexpr int kMaxFramebufferSide = 16384;

// The tutorial's constants.
constexpr double kLumaRed = 0.2126; // Rec. 709 luminance weights
constexpr double kLumaGreen = 0.7152;
constexpr double kLumaBlue = 0.0722;
constexpr double kEpsilon = 1e-8;              // keeps log() finite for black pixels
constexpr double kWhitePoint = 0.22;           // Yw, the smallest luminance shown as pure white
constexpr double kBloomThresholdFactor = 2.95; // bloom where Y >= 2.95 x Yw
constexpr double kBloomWeight = 0.98;          // the bloom is added with this weight
constexpr double kGaussSigma = 2.5;            // in half-resolution texels
constexpr double kInnerTap = 0.524;            // taps at 0, +-0.524 sigma, +-1.282 sigma
constexpr double kOuterTap = 1.282;
constexpr int kBlurPasses = 5; // horizontal + vertical pass pairs

// extras/ (steps 37-40): uniform locations of its post-process shaders. The two programs share
// locations 0 and 2; location 1 is the threshold in the luminance pass and the weight in the final one.
// A stage's command line and t10-grade: --then separates the runs of one process (app.hpp), and
// before each later run the stage prints a line starting with kThenMarker (then "N of M"), where
// the grader splits the process's log into the cases' logs.
constexpr const char* kThenOption = "--then";
constexpr const char* kThenMarker = "t10: run ";

namespace extras {
constexpr int kWhitePointLocation = 0;     // both programs: float fYwhite
constexpr int kRangeMappingLocation = 2;   // both programs: bool bRangeMapping
constexpr int kBloomThresholdLocation = 1; // PostProcessInit.frag: float fBloomThreshold (a multiple of Yw)
constexpr int kBloomStrengthLocation = 1;  // PostProcess.frag: float fBloomStrength
constexpr int kBloomSwitchLocation = 3;    // PostProcess.frag: bool bBloom
} // namespace extras

} // namespace t10::contract
