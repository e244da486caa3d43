// Builds the site's derived figures from rendered frames:
//   make_figure crop OUT.png X Y W H SCALE IN.png...
//       the same W x H region (X, Y from the top left) of every input, enlarged SCALE times with
//       nearest-neighbour sampling (pixels stay square) and placed side by side, 8 px apart;
//   make_figure heat OUT.png FULL BEFORE.png AFTER.png
//       the light AFTER adds to BEFORE: max(0, luma(AFTER) - luma(BEFORE)) on a black-red-yellow-
//       white ramp that reaches white at FULL 8-bit levels.
// Exit 2 on bad usage, 1 when an image cannot be read or written (the message names the file).
#include "t10/error.hpp"
#include "t10/image_io.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

constexpr int kGap = 8;
constexpr std::uint8_t kGapGrey = 40;

struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

int toInt(const char* text, const char* what, int lo, int hi) {
    char* end = nullptr;
    const long v = std::strtol(text, &end, 10);
    if (end == text || *end != '\0' || v < lo || v > hi)
        throw UsageError(std::string(what) + " must be a whole number from " + std::to_string(lo) + " to " +
                         std::to_string(hi) + ", not '" + text + "'");
    return static_cast<int>(v);
}

double luma(const t10::Image8& image, int x, int y) {
    return 0.2126 * image.at(x, y, 0) + 0.7152 * image.at(x, y, 1) + 0.0722 * image.at(x, y, 2);
}

// Row 0 of an Image8 is the bottom row; figures are described from the top left.
int fromTop(const t10::Image8& image, int y) { return image.height - 1 - y; }

t10::Image8 crop(const std::vector<t10::Image8>& inputs, int x0, int y0, int w, int h, int scale) {
    const int count = static_cast<int>(inputs.size());
    t10::Image8 out(count * w * scale + (count - 1) * kGap, h * scale, 3);
    std::fill(out.data.begin(), out.data.end(), kGapGrey);
    for (int k = 0; k < count; ++k) {
        const t10::Image8& in = inputs[static_cast<std::size_t>(k)];
        if (x0 + w > in.width || y0 + h > in.height)
            throw UsageError("the region " + std::to_string(x0) + "," + std::to_string(y0) + " " + std::to_string(w) +
                             "x" + std::to_string(h) + " does not fit a " + std::to_string(in.width) + "x" +
                             std::to_string(in.height) + " image");
        for (int y = 0; y < out.height; ++y)
            for (int x = 0; x < w * scale; ++x)
                for (int c = 0; c < 3; ++c)
                    out.at(k * (w * scale + kGap) + x, fromTop(out, y), c) =
                        in.at(x0 + x / scale, fromTop(in, y0 + y / scale), c % in.channels);
    }
    return out;
}

t10::Image8 heat(const t10::Image8& before, const t10::Image8& after, double full) {
    if (before.width != after.width || before.height != after.height)
        throw UsageError("the two images differ in size");
    t10::Image8 out(after.width, after.height, 3);
    for (int y = 0; y < after.height; ++y)
        for (int x = 0; x < after.width; ++x) {
            const double t = std::clamp((luma(after, x, y) - luma(before, x, y)) / full, 0.0, 1.0);
            // black -> red (t 1/3) -> yellow (2/3) -> white (1)
            const double rgb[3] = {std::min(1.0, 3.0 * t), std::clamp(3.0 * t - 1.0, 0.0, 1.0),
                                   std::clamp(3.0 * t - 2.0, 0.0, 1.0)};
            for (int c = 0; c < 3; ++c) out.at(x, y, c) = static_cast<std::uint8_t>(std::lround(255.0 * rgb[c]));
        }
    return out;
}

int run(int argc, char** argv) {
    const std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "crop" && argc >= 9) {
        std::vector<t10::Image8> inputs;
        for (int i = 8; i < argc; ++i) inputs.push_back(t10::readPng(argv[i]));
        const int x = toInt(argv[3], "X", 0, 16383), y = toInt(argv[4], "Y", 0, 16383);
        const int w = toInt(argv[5], "W", 1, 16384), h = toInt(argv[6], "H", 1, 16384);
        const int scale = toInt(argv[7], "SCALE", 1, 16);
        t10::writePng(argv[2], crop(inputs, x, y, w, h, scale));
        return 0;
    }
    if (mode == "heat" && argc == 6) {
        const int full = toInt(argv[3], "FULL", 1, 255);
        t10::writePng(argv[2], heat(t10::readPng(argv[4]), t10::readPng(argv[5]), full));
        return 0;
    }
    throw UsageError("expected 'crop OUT.png X Y W H SCALE IN.png...' or 'heat OUT.png FULL BEFORE.png AFTER.png'");
}

} // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const UsageError& e) {
        std::fprintf(stderr, "make_figure: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "make_figure: %s\n", e.what());
        return 1;
    }
}
