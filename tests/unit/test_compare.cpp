// The golden comparison itself: it must accept driver-level noise and reject visible changes,
// or the golden tests prove nothing.
#include "t10/compare.hpp"

#include "t10/error.hpp"

#include "t10_catch.hpp"

#include <filesystem>
#include <fstream>

namespace {

t10::Image8 gradient(int width, int height) {
    t10::Image8 image(width, height, 3);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c) image.at(x, y, c) = static_cast<std::uint8_t>((x * 3 + y * 5 + c * 70) % 256);
    return image;
}

const t10::test::Tolerance kTolerance{8, 0.002, 0.5};

} // namespace

TEST_CASE("identical images pass with zero error", "[compare]") {
    const auto image = gradient(64, 48);
    const auto result = t10::test::compareImages(image, image, kTolerance);
    CHECK(result.passed);
    CHECK(result.maxError == 0);
    CHECK(result.meanError == 0.0);
}

TEST_CASE("one-step noise everywhere passes", "[compare]") {
    const auto image = gradient(64, 48);
    auto noisy = image;
    for (std::size_t i = 0; i < noisy.data.size(); i += 7) noisy.data[i] = static_cast<std::uint8_t>(noisy.data[i] ^ 1);
    CHECK(t10::test::compareImages(image, noisy, kTolerance).passed);
}

TEST_CASE("a visibly altered image fails", "[compare]") {
    const auto image = gradient(64, 48);
    const auto result = t10::test::compareImages(image, t10::test::visiblyAltered(image), kTolerance);
    CHECK_FALSE(result.passed);
    CHECK(result.failingFraction > 0.05);
}

TEST_CASE("a uniform shift of a few steps fails on the mean", "[compare]") {
    const auto image = gradient(64, 48);
    auto shifted = image;
    for (auto& v : shifted.data) v = static_cast<std::uint8_t>(v < 250 ? v + 3 : v);
    const auto result = t10::test::compareImages(image, shifted, kTolerance);
    CHECK(result.failingFraction == 0.0); // under the per-pixel threshold...
    CHECK_FALSE(result.passed);           // ...but the mean error catches it
}

TEST_CASE("a size mismatch fails", "[compare]") {
    CHECK_FALSE(t10::test::compareImages(gradient(64, 48), gradient(48, 64), kTolerance).passed);
}

TEST_CASE("the heat map marks exactly the changed pixels", "[compare]") {
    const auto image = gradient(16, 16);
    auto changed = image;
    changed.at(3, 5, 1) = static_cast<std::uint8_t>(changed.at(3, 5, 1) ^ 0x80);
    const auto map = t10::test::differenceHeatMap(image, changed);
    CHECK(map.at(3, 5, 0) == 255);
    CHECK(map.at(4, 5, 0) == 0);
}

TEST_CASE("tolerance files need every key with a reason", "[compare]") {
    const std::filesystem::path dir = T10_TEST_TMP_DIR;
    std::filesystem::create_directories(dir);
    const auto write = [&](const std::string& name, const std::string& text) {
        std::ofstream(dir / name) << text;
        return (dir / name).string();
    };
    const auto good = write("good.tolerance", "# header\nthreshold = 8 # noise\nmax_fraction = 0.01 # edges\n"
                                              "max_mean = 0.5 # drift\n");
    const auto tolerance = t10::test::readTolerance(good);
    CHECK(tolerance.threshold == 8);
    CHECK(tolerance.maxFraction == Approx(0.01));
    CHECK(tolerance.maxMean == Approx(0.5));
    CHECK_THROWS_AS(t10::test::readTolerance(write("noreason.tolerance", "threshold = 8\nmax_fraction = 0.01 # a\n"
                                                                          "max_mean = 0.5 # b\n")),
                    t10::Error);
    CHECK_THROWS_AS(t10::test::readTolerance(write("missing.tolerance", "threshold = 8 # a\n")), t10::Error);
    CHECK_THROWS_AS(t10::test::readTolerance((dir / "absent.tolerance").string()), t10::Error);
}
