// The views of the chain and how each turns a buffer into display colours: the catalogue of view
// names (--view NAME), the colour scale, the range mapping of the luminance, the EV bands. Pure
// functions without GL, so the tests decode the views' images with the same functions.
#pragma once
#include "t10/contract.hpp"

#include <array>
#include <optional>
#include <string>

namespace t10 {

enum class View { Final, Hdr, Luminance, Key, Bloom0, Bloom1, Blur, Ev, Nan };
constexpr int kViewCount = 9;

// "final", "hdr", "luminance", "key", "bloom0", "bloom1", "blur", "ev", "nan"
const char* viewName(View view);
std::optional<View> findView(const std::string& name);
// Every view name in cycling order, comma separated (for --help and messages).
std::string allViewNames();

namespace views {

constexpr double kYwhite = contract::kWhitePoint;
constexpr double kBloomThreshold = contract::kBloomThresholdFactor * contract::kWhitePoint;

// hdr, bloom0, bloom1, blur: linear colour x exposure, clamped, then a 1/2.2 power so that dark
// interiors stay visible. The hdr exposure puts the bloom threshold at display white (white in the
// hdr view is what blooms); the bloom views sit three stops lower so their peaks keep some shape.
constexpr double kHdrExposure = 1.0 / kBloomThreshold;
constexpr double kBloomExposure = kHdrExposure / 8.0;
constexpr double kDisplayGamma = 2.2;
double displayEncode(double linear, double exposure);

// The colour scale of the luminance, key and ev views: six segments, each moving one channel over
// its full range (dark blue, blue, cyan, green, yellow, red, white), so every 8-bit colour on it
// belongs to one value and an image decodes back to numbers. Not perceptually uniform; decodable.
constexpr int kScaleStops = 7;
using Rgb = std::array<double, 3>;
const std::array<Rgb, kScaleStops>& colourScaleStops();
Rgb colourScale(double t); // t clamped to [0, 1]

// The luminance view shows the range-mapped log luminance (step 5) on the colour scale. These are
// the CPU reference's functions (common/reference/) at the chain's white point, not copies of them.
double rangeMap(double y, double ywhite = kYwhite);
double keyFromMapped(double mapped, double ywhite = kYwhite);
// Middle grey dg of step 9 from the scene key Ya (ref::middleGrey).
double middleGrey(double key);

// The ev view: each pixel's HDR luminance in whole stops around the key Ya, one colour-scale band
// per stop from kEvLowest (dark blue) to kEvHighest (red), clamped, drawn full where the tone map lifts the pixel
// (its displayed luminance is above its scene luminance) and at half intensity where it compresses
// it; pixels the operator burns to white (Yr >= Yw) are white, pixels that end as 8-bit black are black.
constexpr int kEvLowest = -6;
constexpr int kEvHighest = 5;
constexpr double kEvScaleTop = 5.0 / 6.0; // the bands end at red on the scale, so white only means burnt
enum class EvKind { Black, Burnt, Lifted, Compressed };
struct EvClass {
    EvKind kind;
    int stop; // kEvLowest..kEvHighest (meaningless for Black and Burnt)
};
EvClass classifyEv(double y, double key, double ywhite = kYwhite);
Rgb evColour(const EvClass& ev);

// The nan view marks non-finite texels of any target in this colour (magenta).
constexpr Rgb kSignal = {1.0, 0.0, 1.0};

// The legend strip along the bottom of the luminance, key and ev views: its height in pixels for a
// framebuffer `height` high (rows below it show the image). The key view's strip is the colour
// scale from left to right with the key's column marked: black in the upper half, white in the lower.
int legendHeight(int height);

} // namespace views

} // namespace t10
