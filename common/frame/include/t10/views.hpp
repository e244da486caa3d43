// The view selector: shows one buffer of the tone mapping and bloom chain instead of the final
// frame (--view NAME headless, a key in the window, a list in the extras panel). It reads only what
// a stage leaves bound after its frame (units 15, 16 and 17) and the framebuffers it rendered
// through, so stage code stays as the tutorial writes it. The encodings that turn a buffer into
// display colours live here too, so the tests decode the images with the same functions.
#pragma once
#include "t10/contract.hpp"
#include "t10/gl.hpp"
#include "t10/keys.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

struct GLFWwindow;

namespace t10 {

class FullScreenQuad;
class ShaderManager;

enum class View { Final, Hdr, Luminance, Key, Bloom0, Bloom1, Blur, Ev, Nan };
constexpr int kViewCount = 9;

// "final", "hdr", "luminance", "key", "bloom0", "bloom1", "blur", "ev", "nan"
const char* viewName(View view);
std::optional<View> findView(const std::string& name);
// Every view name in cycling order, comma separated (for --help and messages).
std::string allViewNames();

namespace views {

constexpr double kEpsilon = contract::kEpsilon;
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

// The luminance view shows the range-mapped log luminance (step 5) on the colour scale.
double rangeMap(double y, double ywhite = kYwhite);
double keyFromMapped(double mapped, double ywhite = kYwhite);
// Middle grey dg of step 9 from the scene key Ya.
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

// The legend strip along the bottom of the luminance and ev views: its height in pixels for a
// framebuffer `height` high (rows below it show the image).
int legendHeight(int height);

} // namespace views

// A target of the chain as found after the stage's frame.
struct ViewTarget {
    GLuint texture = 0;
    int level = 0;
    int width = 0;
    int height = 0;
    GLint format = 0;
};

class ViewService {
public:
    // `initial` must be a known view name (the command line checked it).
    ViewService(const ShaderManager& shaders, View initial);
    ~ViewService();
    ViewService(const ViewService&) = delete;
    ViewService& operator=(const ViewService&) = delete;

    // Draws the selected view (nothing for `final`) and the thumbnails over framebuffer 0. The
    // frame loop calls it after the stage's frame and before the UI. Throws t10::UsageError when the
    // stage lacks the view selected on the command line, listing the views it has.
    void draw(const FullScreenQuad& quad, int width, int height);

    View current() const { return current_; }
    // Views this stage has, as found in the last frame (before any frame: every view).
    bool available(View view) const;
    std::vector<View> availableViews() const;
    // Selects a view; false (and no change) if the stage lacks it.
    bool select(View view);
    // Moves to the next (+1) or previous (-1) view the stage has.
    void cycle(int direction);
    // The strip of thumbnails of every target along the bottom (window: T; --thumbnails).
    void showThumbnails(bool show) { thumbnails_ = show; }
    bool thumbnails() const { return thumbnails_; }
    // One line about what is shown: the view, its encoding, and its numbers (Ya, dg, counts).
    const std::string& caption() const { return caption_; }

private:
    void discover(int width, int height);
    void readKey();
    void countNonFinite();
    void updateCaption();
    void drawPass(View view, int x, int y, int width, int height, int legend) const;
    void drawThumbnails(int width, int height) const;

    const ShaderManager& shaders_;
    View current_;
    bool commandLineChecked_ = false;
    bool discovered_ = false;
    bool thumbnails_ = false;
    GLuint program_ = 0;
    ViewTarget accumulation_;
    ViewTarget luminance_;
    ViewTarget luminanceSmallest_;
    ViewTarget bloom0_;
    ViewTarget bloom1_;
    ViewTarget blur_;
    bool luminanceMapped_ = true; // GL_R16 holds the range-mapped value, GL_R16F (exercise 40) the log
    double ywhite_ = views::kYwhite;
    double key_ = 0.0;
    std::string caption_;
    std::string printedCaption_;
};

// The window's keys for the views: V next, Shift+V previous, T thumbnails on and off.
class ViewKeys {
public:
    explicit ViewKeys(GLFWwindow* window) : window_(window) {}
    void update(ViewService& views);

private:
    GLFWwindow* window_;
    KeyEdges edges_;
};

} // namespace t10
