// make_test_images: writes the synthetic HDR inputs the numeric tests post-process with --input:
//   hot.exr  128x128 grey 0.05 with one 2x2 block of 20.0 centred on a texel of the half-size grid
//   dim.exr  128x128 smooth gradient whose luminance stays below the bloom threshold (2.95 x 0.22)
//   extremes.exr  64x64: 16 rows exactly black (a tone map without a guard divides 0 by 0
//            there), below them grey steps from 0.001 to 50 in luminance, so that pixels sit below,
//            at and far above the white point Yw = 0.22 and the bloom threshold 2.95 x Yw
//   ramp.exr  64x64: 16 rows exactly black, above them every pixel a different luminance from 0.001
//            to 50 (log-spaced, 0.35% apart), in four tints: t10-grade fits the white point, the
//            bloom threshold and the luminance weights to it, so no value of them falls between two
//            pixels by more than a fraction of a percent
//   inf.exr, nan.exr  64x64 grey 0.1 with one texel of +infinity / NaN: through GL_R16F (no range
//            mapping) log(inf) and log(NaN) reach the 1x1 luminance level, which is what a GPU whose
//            glGenerateMipmap breaks float textures produces (exercise 40); through GL_R16 the value
//            clamps to 1 and the key stays finite
// usage: make_test_images OUT_DIR
#include "t10/error.hpp"
#include "t10/image_io.hpp"

#include <filesystem>
#include <iostream>
#include <cmath>
#include <limits>

namespace {

constexpr int kSize = 128;
constexpr float kBackground = 0.05f;
constexpr float kHot = 20.0f;
constexpr int kHotX = 64; // the block covers 64..65: exactly texel 32 of the half-size grid
constexpr int kHotY = 64;

t10::ImageF hotPixel() {
    t10::ImageF image(kSize, kSize, 4);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x)
            for (int c = 0; c < 4; ++c) image.at(x, y, c) = c == 3 ? 1.0f : kBackground;
    for (int y = kHotY; y < kHotY + 2; ++y)
        for (int x = kHotX; x < kHotX + 2; ++x)
            for (int c = 0; c < 3; ++c) image.at(x, y, c) = kHot;
    return image;
}

t10::ImageF dimGradient() {
    t10::ImageF image(kSize, kSize, 4);
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            // Luminance peaks near 0.5, below the 0.649 threshold.
            image.at(x, y, 0) = 0.5f * float(x) / float(kSize - 1) + 0.01f;
            image.at(x, y, 1) = 0.45f * float(y) / float(kSize - 1) + 0.01f;
            image.at(x, y, 2) = 0.3f * float(x + y) / float(2 * kSize - 2) + 0.01f;
            image.at(x, y, 3) = 1.0f;
        }
    }
    return image;
}

t10::ImageF extremes() {
    constexpr int kExtremesSize = 64;
    constexpr int kBlackRows = 16;
    t10::ImageF image(kExtremesSize, kExtremesSize, 4);
    for (int y = 0; y < kExtremesSize; ++y) {
        for (int x = 0; x < kExtremesSize; ++x) {
            // Grey from 10^-3 to 10^1.7 along x (a step every 4 pixels), tinted by row so that the
            // channels differ; the top rows stay black.
            const float grey = std::pow(10.0f, -3.0f + 4.7f * float(x / 4) / float(kExtremesSize / 4 - 1));
            const float tint = float(y % 4) * 0.1f;
            const bool black = y >= kExtremesSize - kBlackRows;
            image.at(x, y, 0) = black ? 0.0f : grey * (1.0f + tint);
            image.at(x, y, 1) = black ? 0.0f : grey;
            image.at(x, y, 2) = black ? 0.0f : grey * (1.0f - tint);
            image.at(x, y, 3) = 1.0f;
        }
    }
    return image;
}

t10::ImageF ramp() {
    constexpr int kRampSize = 64;
    constexpr int kBlackRows = 16;
    constexpr int kLit = kRampSize * (kRampSize - kBlackRows);
    // Tints with Rec. 709 luminance 1, different enough that the weights can be told apart.
    constexpr float kTints[4][3] = {{1.0f, 1.0f, 1.0f}, {1.6f, 0.85f, 0.6f}, {0.5f, 1.1f, 1.6f}, {1.2f, 0.9f, 1.8f}};
    t10::ImageF image(kRampSize, kRampSize, 4);
    for (int y = 0; y < kRampSize; ++y) {
        for (int x = 0; x < kRampSize; ++x) {
            // Black rows first, then the ramp from its dimmest pixels, so that the bloom of the
            // brightest rows does not reach the black ones (the 0/0 check needs them exactly black).
            const bool black = y < kBlackRows;
            const int index = (y - kBlackRows) * kRampSize + x;
            const float lum = std::pow(10.0f, -3.0f + 4.7f * float(index) / float(kLit - 1));
            const float* tint = kTints[x % 4];
            const float tintLum = 0.2126f * tint[0] + 0.7152f * tint[1] + 0.0722f * tint[2];
            for (int c = 0; c < 3; ++c) image.at(x, y, c) = black ? 0.0f : lum * tint[c] / tintLum;
            image.at(x, y, 3) = 1.0f;
        }
    }
    return image;
}

t10::ImageF greyWith(float special) {
    constexpr int kSpecialSize = 64;
    t10::ImageF image(kSpecialSize, kSpecialSize, 4);
    for (int y = 0; y < kSpecialSize; ++y)
        for (int x = 0; x < kSpecialSize; ++x)
            for (int c = 0; c < 4; ++c) image.at(x, y, c) = c == 3 ? 1.0f : 0.1f;
    for (int c = 0; c < 3; ++c) image.at(20, 30, c) = special;
    return image;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: make_test_images OUT_DIR\n";
        return 2;
    }
    try {
        std::filesystem::create_directories(argv[1]);
        const std::string dir = argv[1];
        t10::writeExr(dir + "/hot.exr", hotPixel());
        t10::writeExr(dir + "/dim.exr", dimGradient());
        t10::writeExr(dir + "/extremes.exr", extremes());
        t10::writeExr(dir + "/ramp.exr", ramp());
        t10::writeExr(dir + "/inf.exr", greyWith(std::numeric_limits<float>::infinity()));
        t10::writeExr(dir + "/nan.exr", greyWith(std::numeric_limits<float>::quiet_NaN()));
        std::cout << "wrote hot.exr, dim.exr, extremes.exr, ramp.exr, inf.exr and nan.exr into " << dir << "\n";
        return 0;
    } catch (const t10::Error& error) {
        std::cerr << "make_test_images: error: " << error.what() << "\n";
        return 1;
    }
}
