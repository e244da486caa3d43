// Unit tests for the reliability rules of issue 14 that need no GL context: all-or-nothing file
// writes, the EXR reader's limits and header checks (including the two files the fuzz target found),
// and the clamping of non-finite input pixels.
#include "t10/error.hpp"
#include "t10/file.hpp"
#include "t10/image_io.hpp"

#include "t10_catch.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

namespace {

const std::string kReliabilityFixtureDir = std::string(T10_TEST_FIXTURE_DIR) + "/image_io/";

std::filesystem::path scratchDir(const std::string& name) {
    const std::filesystem::path dir = std::filesystem::path(T10_TEST_TMP_DIR) / "reliability" / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

// An independent reader (std::ifstream): file.cpp's writer is what these tests check.
std::string readWholeText(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::size_t fileCount(const std::filesystem::path& dir) {
    return static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator(dir), {}));
}

} // namespace

TEST_CASE("writeFileAtomically replaces the file whole and leaves no temporary file") {
    const auto dir = scratchDir("atomic");
    const std::string path = (dir / "out.bin").string();
    t10::writeFileAtomically(path, "first", 5, "test");
    t10::writeFileAtomically(path, "second", 6, "test");
    CHECK(readWholeText(path) == "second");
    CHECK(fileCount(dir) == 1);
}

TEST_CASE("writeFileAtomically fails with the system's reason and keeps what was there") {
    const auto dir = scratchDir("atomic_fail");
    // A missing folder: the temporary file cannot be created.
    const std::string missing = (dir / "no" / "such" / "out.png").string();
    try {
        t10::writeFileAtomically(missing, "x", 1, "PNG");
        FAIL("no error");
    } catch (const t10::Error& error) {
        CHECK_THAT(error.what(), Catch::StartsWith(missing + ": cannot write PNG"));
        CHECK_THAT(error.what(), Catch::Contains("No such file or directory"));
    }
    // A folder in the way: the rename fails, the folder and its content stay, the temporary goes.
    const auto blocked = dir / "blocked.png";
    std::filesystem::create_directories(blocked);
    std::ofstream(blocked / "keep.txt") << "kept";
    CHECK_THROWS_WITH(t10::writeFileAtomically(blocked.string(), "x", 1, "PNG"),
                      Catch::Contains("Is a directory"));
    CHECK(readWholeText(blocked / "keep.txt") == "kept");
    CHECK(fileCount(dir) == 1); // only blocked.png/: no temporary file left
}

TEST_CASE("writePng into a missing folder says why") {
    const auto dir = scratchDir("png");
    CHECK_THROWS_WITH(t10::writePng((dir / "none" / "a.png").string(), t10::Image8(2, 2, 3)),
                      Catch::Contains("No such file or directory"));
}

TEST_CASE("readExr refuses an image beyond the caller's limits before reading its pixels") {
    const std::string path = kReliabilityFixtureDir + "rgb_7x5.exr";
    t10::ExrLimits limits;
    limits.maxSide = 6;
    limits.maxSideReason = "test side";
    CHECK_THROWS_WITH(t10::readExr(path, limits),
                      Catch::Contains("the image is 7x5, larger than 6 on a side (test side)"));
    limits.maxSide = 7;
    limits.maxPixels = 34;
    limits.maxPixelsReason = "test pixels";
    CHECK_THROWS_WITH(t10::readExr(path, limits), Catch::Contains("more than 34 pixels (test pixels)"));
    // At the limits exactly it reads: the checks are not off by one.
    limits.maxPixels = 35;
    CHECK(t10::readExr(path, limits).width == 7);
}

TEST_CASE("the EXR files the fuzz target found are refused at once") {
    // The first two once made OpenEXR allocate about 2 GB from a header that claims it (7-10 s under
    // ASan); the third, a tile of 51204 x 1024 pixels over a small image, took 15 s; the fourth made
    // the tile check itself overflow (UBSan).
    for (const char* name : {"fuzz_opaque_attribute_2gb.exr", "fuzz_v3f_window_center.exr", "fuzz_huge_tile.exr",
                             "fuzz_tile_overflow.exr"}) {
        INFO(name);
        const auto start = std::chrono::steady_clock::now();
        CHECK_THROWS_WITH(t10::readExr(kReliabilityFixtureDir + name), Catch::Contains("is malformed") ||
                                                                Catch::Contains("more than the file holds") ||
                                                                Catch::Contains("larger than the image"));
        // Generous: the check itself takes microseconds; the allocation it prevents took seconds.
        CHECK(std::chrono::steady_clock::now() - start < std::chrono::milliseconds(500));
    }
}

TEST_CASE("clampNonFinite: +inf to the maximum, NaN and -inf to 0, counted per pixel") {
    const float inf = std::numeric_limits<float>::infinity();
    t10::ImageF image(3, 1, 4);
    for (float& v : image.data) v = 0.5f;
    image.at(0, 0, 0) = inf;                                       // pixel 0: +inf
    image.at(1, 0, 1) = -inf;                                      // pixel 1: -inf and NaN
    image.at(1, 0, 2) = std::numeric_limits<float>::quiet_NaN();
    CHECK(t10::clampNonFinite(image, t10::kHalfMax) == 2);
    CHECK(image.at(0, 0, 0) == t10::kHalfMax);
    CHECK(image.at(1, 0, 1) == 0.0f);
    CHECK(image.at(1, 0, 2) == 0.0f);
    CHECK(image.at(2, 0, 0) == 0.5f); // finite values stay
    CHECK(t10::clampNonFinite(image, t10::kHalfMax) == 0);
}
