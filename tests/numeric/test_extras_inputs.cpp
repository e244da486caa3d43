// make_extras_inputs: HDR inputs for the step 40 check of extras/ (tests/extras_tests.cmake).
//   inf.exr  64x64 grey 0.1 with one texel of +infinity
//   nan.exr  64x64 grey 0.1 with one texel of NaN
// Through GL_R16F (no range mapping) log(inf) = inf and log(NaN) = NaN reach the 1x1 level of the
// luminance texture, which is what a GPU whose glGenerateMipmap breaks float textures produces:
// the stage must say so. Through GL_R16 the value clamps to 1 and the key stays finite.
// usage: make_extras_inputs OUT_DIR
#include "t10/error.hpp"
#include "t10/image_io.hpp"

#include <filesystem>
#include <iostream>
#include <limits>

namespace {

t10::ImageF greyWith(float special) {
    constexpr int kSize = 64;
    t10::ImageF image(kSize, kSize, 4);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x)
            for (int c = 0; c < 4; ++c) image.at(x, y, c) = c == 3 ? 1.0f : 0.1f;
    for (int c = 0; c < 3; ++c) image.at(20, 30, c) = special;
    return image;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: make_extras_inputs OUT_DIR\n";
        return 2;
    }
    try {
        std::filesystem::create_directories(argv[1]);
        const std::string dir = argv[1];
        t10::writeExr(dir + "/inf.exr", greyWith(std::numeric_limits<float>::infinity()));
        t10::writeExr(dir + "/nan.exr", greyWith(std::numeric_limits<float>::quiet_NaN()));
        std::cout << "wrote " << dir << "/inf.exr and " << dir << "/nan.exr\n";
        return 0;
    } catch (const t10::Error& error) {
        std::cerr << "make_extras_inputs: error: " << error.what() << "\n";
        return 1;
    }
}
