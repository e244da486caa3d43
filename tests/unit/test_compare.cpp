// The golden comparison itself: it must accept driver-level noise and reject visible changes,
// or the golden tests prove nothing.
#include "t10/compare.hpp"
#include "t10/compare_export.hpp"

#include "t10/error.hpp"

#include "t10_catch.hpp"

#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

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

// The browser's compare page calls these C functions (exported from a student's web module): they
// must give the verdict compareImages gives, on RGBA with alpha ignored, and say what is wrong.
TEST_CASE("the compare page's C functions give compareImages' verdict", "[compare]") {
    const std::filesystem::path dir = T10_TEST_TMP_DIR;
    std::filesystem::create_directories(dir);
    const std::string path = (dir / "page.tolerance").string();
    std::ofstream(path) << "threshold = 8 # noise\nmax_fraction = 0.002 # edges\nmax_mean = 0.5 # drift\n";
    const auto image = gradient(64, 48);
    const auto load = [](int slot, const t10::Image8& rgb, std::uint8_t alpha) {
        std::uint8_t* buffer = t10_compare_buffer(slot, rgb.width * rgb.height * 4);
        REQUIRE(buffer != nullptr);
        for (std::size_t p = 0; p < rgb.data.size() / 3; ++p) {
            std::memcpy(buffer + p * 4, &rgb.data[p * 3], 3);
            buffer[p * 4 + 3] = alpha;
        }
    };
    const std::uint8_t* heat = nullptr;
    const auto run = [&](const t10::Image8& actual) {
        load(0, image, 255);
        load(1, actual, 17); // a different alpha: ignored, as the goldens are RGB
        heat = t10_compare_buffer(2, image.width * image.height * 4);
        return nlohmann::json::parse(t10_compare_rgba(image.width, image.height, path.c_str()));
    };
    const auto same = run(image);
    CHECK(same["passed"] == true);
    CHECK(same["maxError"] == 0);
    CHECK(same["tolerance"]["threshold"] == 8);
    CHECK(same["tolerance"]["file"].get<std::string>().find("# drift") != std::string::npos);

    const auto altered = t10::test::visiblyAltered(image);
    const auto direct = t10::test::compareImages(image, altered, t10::test::readTolerance(path));
    const auto changed = run(altered);
    CHECK(changed["passed"] == false);
    CHECK(changed["failingFraction"].get<double>() == Approx(direct.failingFraction));
    CHECK(changed["meanError"].get<double>() == Approx(direct.meanError));
    CHECK(changed["summary"] == direct.summary);
    // The heat-map in slot 2 is differenceHeatMap's, with alpha 255.
    const auto map = t10::test::differenceHeatMap(image, altered);
    REQUIRE(heat != nullptr);
    bool heatMatches = true;
    for (std::size_t p = 0; p < map.data.size() / 3; ++p) {
        heatMatches = heatMatches && std::memcmp(heat + p * 4, &map.data[p * 3], 3) == 0 && heat[p * 4 + 3] == 255;
    }
    CHECK(heatMatches);

    CHECK(nlohmann::json::parse(t10_compare_rgba(image.width, image.height, (dir / "absent").string().c_str()))
              ["error"].get<std::string>().find("absent") != std::string::npos);
    CHECK(nlohmann::json::parse(t10_compare_rgba(65, 48, path.c_str()))["error"].get<std::string>().find("bytes") !=
          std::string::npos);
    CHECK(t10_compare_buffer(4, 16) == nullptr);
    CHECK(t10_compare_buffer(0, 0) == nullptr);
}
