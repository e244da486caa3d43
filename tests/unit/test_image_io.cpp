// Unit tests for the image readers and writers (common/content/src/image_io.cpp). The readers are checked
// against files from independent writers (Pillow's PNG, ImageMagick's EXR and PFM, see
// tests/fixtures/*/make_fixtures.*) whose pixels follow a known formula, so row order and values are
// pinned down; the round trips then pin the writers. PFM bytes are also checked directly. Every
// failure must throw t10::Error naming the file. Only t10_common is needed: no stb or OpenEXR here.
#include "t10/error.hpp"
#include "t10/file.hpp"
#include "t10/image_io.hpp"

#include "t10_catch.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {

const std::string kImageIoFixtureDir = std::string(T10_TEST_FIXTURE_DIR);

// The 7x5 fixtures' formula (tests/fixtures/tga/make_fixtures.py, small_pixel), row 0 = bottom.
int expectedRgb(int x, int y, int channel) {
    switch (channel) {
    case 0: return 10 + 35 * x;
    case 1: return 10 + 50 * y;
    default: return (x * 5 + y) * 7;
    }
}

std::string scratchPath(const std::string& name) {
    const std::filesystem::path dir = std::filesystem::path(T10_TEST_TMP_DIR) / "image_io";
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

void writeText(const std::string& path, const std::string& content) {
    std::ofstream out(path, std::ios::binary);
    out << content;
    REQUIRE(out);
}

std::vector<std::uint8_t> readImageBytes(const std::string& path) { return t10::readFile(path); }

// Distinct values per pixel and channel, different between the bottom and the top row.
t10::Image8 makeImage8(int w, int h, int c) {
    t10::Image8 img(w, h, c);
    for (std::size_t i = 0; i < img.data.size(); ++i) img.data[i] = static_cast<std::uint8_t>((i * 37 + 11) % 256);
    return img;
}

void requireThrowsNaming(void (*fn)(const std::string&), const std::string& path) {
    try {
        fn(path);
        FAIL("no t10::Error thrown for " << path);
    } catch (const t10::Error& e) {
        INFO("message: " << e.what());
        CHECK_THAT(e.what(), Catch::Contains(path));
        CHECK(e.exitCode() == 1);
    }
}

} // namespace

TEST_CASE("PNG round trip keeps pixels and orientation", "[image_io]") {
    const int channels = GENERATE(1, 3, 4);
    INFO(channels << " channels");
    const t10::Image8 img = makeImage8(5, 3, channels);
    const std::string path = scratchPath("round_trip_" + std::to_string(channels) + ".png");
    t10::writePng(path, img);

    const t10::Image8 back = t10::readPng(path);
    REQUIRE(back.width == 5);
    REQUIRE(back.height == 3);
    REQUIRE(back.channels == channels);
    CHECK(back.data == img.data);
}

TEST_CASE("PNG reader returns the bottom row first", "[image_io]") {
    // Written by Pillow from a known formula: an independent check of readPng's orientation. With
    // the round trip above it also pins writePng's.
    const std::string name = GENERATE(as<std::string>{}, "rgb24_raw_bl", "rgba32_raw_bl");
    const t10::Image8 img = t10::readPng(kImageIoFixtureDir + "/tga/" + name + ".png");
    REQUIRE(img.width == 7);
    REQUIRE(img.height == 5);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 7; ++x)
            for (int c = 0; c < 3; ++c) REQUIRE(img.at(x, y, c) == expectedRgb(x, y, c));
}

TEST_CASE("PNG errors name the file", "[image_io]") {
    requireThrowsNaming([](const std::string& p) { t10::readPng(p); }, scratchPath("missing.png"));
    const std::string garbage = scratchPath("garbage.png");
    writeText(garbage, "this is not a PNG file");
    requireThrowsNaming([](const std::string& p) { t10::readPng(p); }, garbage);
    const std::string truncated = scratchPath("truncated.png");
    t10::writePng(truncated, makeImage8(16, 16, 3));
    std::vector<std::uint8_t> bytes = readImageBytes(truncated);
    bytes.resize(bytes.size() / 2);
    writeText(truncated, std::string(bytes.begin(), bytes.end()));
    requireThrowsNaming([](const std::string& p) { t10::readPng(p); }, truncated);
    // A JPEG named .png gets the glTF loader's JPEG checks before stb: a Huffman table of 16 x 255
    // codes (Debian's stb would write past its tables) is refused by name, and so is a GIF.
    const std::string jpeg = scratchPath("huffman.png");
    std::string dht = "\xFF\xD8\xFF\xC4";
    dht += std::string("\x00\x13\x00", 3) + std::string(16, '\xFF');
    writeText(jpeg, dht);
    CHECK_THROWS_WITH(t10::readPng(jpeg), jpeg + ": cannot read PNG: corrupt JPEG (a Huffman table with more than 256 codes)");
    const std::string gif = scratchPath("image.png");
    writeText(gif, "GIF89a\x01\x00\x01\x00\x00\x00\x00;");
    CHECK_THROWS_WITH(t10::readPng(gif), gif + ": cannot read PNG: not a PNG or JPEG file");
    requireThrowsNaming([](const std::string& p) { t10::writePng(p, makeImage8(2, 2, 3)); },
                        scratchPath("no_such_dir/out.png"));
    requireThrowsNaming([](const std::string& p) { t10::writePng(p, t10::Image8{}); }, scratchPath("empty.png"));
    requireThrowsNaming([](const std::string& p) { t10::writePng(p, t10::Image8(2, 2, 2)); }, scratchPath("two.png"));
}

TEST_CASE("EXR round trip keeps HDR values within half precision", "[image_io]") {
    // Half floats have 11 significant bits, so round-to-nearest gives a relative error of at most
    // 2^-11 for normal values; everything here is normal (or exactly zero) and below 65504.
    const double kRelTolerance = std::ldexp(1.0, -11);
    const float kValues[] = {0.0f,     0.001f, 0.25f,  1.0f,    1.5f,    2.95f * 0.22f,
                             3.14159f, 15.0f,  100.7f, 1234.5f, 60000.0f, 65504.0f};
    const int channels = GENERATE(3, 4);
    INFO(channels << " channels");
    t10::ImageF img(4, 3, channels);
    for (std::size_t i = 0; i < img.data.size(); ++i)
        img.data[i] = kValues[i % std::size(kValues)] * (i % 2 ? 1.0f : 0.99f); // 0.99: off the half grid
    const std::string path = scratchPath("round_trip_" + std::to_string(channels) + ".exr");
    t10::writeExr(path, img);

    const t10::ImageF back = t10::readExr(path);
    REQUIRE(back.width == 4);
    REQUIRE(back.height == 3);
    REQUIRE(back.channels == 4);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 4; ++x) {
            for (int c = 0; c < 3; ++c) {
                const double want = img.at(x, y, c);
                INFO("x " << x << " y " << y << " c " << c << " want " << want << " got " << back.at(x, y, c));
                CHECK(std::abs(back.at(x, y, c) - want) <= kRelTolerance * std::abs(want));
            }
            const double alpha = channels == 4 ? img.at(x, y, 3) : 1.0;
            CHECK(std::abs(back.at(x, y, 3) - alpha) <= kRelTolerance * std::abs(alpha));
        }
}

TEST_CASE("EXR reader returns the bottom row first", "[image_io]") {
    // Written by ImageMagick from the formula's 8-bit values (value / 255, no alpha channel).
    const double kRelTolerance = std::ldexp(1.0, -11); // half precision, as above
    const t10::ImageF img = t10::readExr(kImageIoFixtureDir + "/image_io/rgb_7x5.exr");
    REQUIRE(img.width == 7);
    REQUIRE(img.height == 5);
    REQUIRE(img.channels == 4);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 7; ++x) {
            for (int c = 0; c < 3; ++c) {
                const double want = expectedRgb(x, y, c) / 255.0;
                INFO("x " << x << " y " << y << " c " << c << " want " << want << " got " << img.at(x, y, c));
                REQUIRE(std::abs(img.at(x, y, c) - want) <= kRelTolerance * want);
            }
            REQUIRE(img.at(x, y, 3) == 1.0f); // absent alpha reads as 1
        }
}

TEST_CASE("EXR of a grey image has equal RGB and alpha 1", "[image_io]") {
    t10::ImageF img(2, 2, 1);
    img.data = {0.5f, 2.0f, 8.0f, 32.0f};
    const std::string path = scratchPath("grey.exr");
    t10::writeExr(path, img);
    const t10::ImageF back = t10::readExr(path);
    REQUIRE(back.channels == 4);
    CHECK(back.at(1, 1, 0) == 32.0f); // powers of two are exact in half
    CHECK(back.at(1, 1, 1) == 32.0f);
    CHECK(back.at(1, 1, 2) == 32.0f);
    CHECK(back.at(1, 1, 3) == 1.0f);
    CHECK(back.at(0, 0, 0) == 0.5f);
}

TEST_CASE("EXR errors name the file", "[image_io]") {
    requireThrowsNaming([](const std::string& p) { t10::readExr(p); }, scratchPath("missing.exr"));
    const std::string garbage = scratchPath("garbage.exr");
    writeText(garbage, "this is not an OpenEXR file, not even close");
    requireThrowsNaming([](const std::string& p) { t10::readExr(p); }, garbage);
    const std::string empty = scratchPath("empty.exr");
    writeText(empty, "");
    requireThrowsNaming([](const std::string& p) { t10::readExr(p); }, empty);
    requireThrowsNaming([](const std::string& p) { t10::writeExr(p, t10::ImageF(2, 2, 3)); },
                        scratchPath("no_such_dir/out.exr"));
}

TEST_CASE("PFM round trip is exact and stores the bottom row first", "[image_io]") {
    const int channels = GENERATE(1, 3);
    INFO(channels << " channels");
    t10::ImageF img(3, 2, channels);
    for (std::size_t i = 0; i < img.data.size(); ++i)
        img.data[i] = static_cast<float>(i) * 0.1f + (i % 3 == 0 ? 1e-8f : 1234.567f) - (i % 4 == 1 ? 7.5f : 0.0f);
    const std::string path = scratchPath("round_trip_" + std::to_string(channels) + ".pfm");
    t10::writePfm(path, img);

    const t10::ImageF back = t10::readPfm(path);
    REQUIRE(back.width == 3);
    REQUIRE(back.height == 2);
    REQUIRE(back.channels == channels);
    CHECK(back.data == img.data);

    const std::vector<std::uint8_t> bytes = readImageBytes(path);
    const std::string header = std::string(channels == 1 ? "Pf" : "PF") + "\n3 2\n-1.0\n";
    REQUIRE(bytes.size() == header.size() + img.data.size() * 4);
    CHECK(std::string(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(header.size())) == header);
    // First value after the header: bottom-left pixel, little-endian.
    std::uint32_t bits = 0;
    for (std::size_t i = 0; i < 4; ++i) bits |= static_cast<std::uint32_t>(bytes[header.size() + i]) << (8 * i);
    float first = 0.0f;
    std::memcpy(&first, &bits, sizeof first);
    CHECK(first == img.at(0, 0, 0));
}

TEST_CASE("PFM of an RGBA image drops alpha", "[image_io]") {
    t10::ImageF img(2, 1, 4);
    img.data = {1, 2, 3, 4, 5, 6, 7, 8};
    const std::string path = scratchPath("rgba.pfm");
    t10::writePfm(path, img);
    const t10::ImageF back = t10::readPfm(path);
    REQUIRE(back.channels == 3);
    CHECK(back.data == std::vector<float>{1, 2, 3, 5, 6, 7});
}

TEST_CASE("PFM reader reads an independent big-endian file bottom row first", "[image_io]") {
    // ImageMagick writes PFM big-endian (scale +1.0). Values are 8-bit / 255 computed in double
    // and stored as float: allow a float rounding step.
    const t10::ImageF img = t10::readPfm(kImageIoFixtureDir + "/image_io/rgb_7x5_big_endian.pfm");
    REQUIRE(img.width == 7);
    REQUIRE(img.height == 5);
    REQUIRE(img.channels == 3);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 7; ++x)
            for (int c = 0; c < 3; ++c) REQUIRE(img.at(x, y, c) == Approx(expectedRgb(x, y, c) / 255.0).epsilon(1e-6));
}

TEST_CASE("PFM reader accepts big-endian files", "[image_io]") {
    const std::string path = scratchPath("big_endian.pfm");
    std::string content = "Pf\n2 1\n1.0\n";
    content += std::string("\x3f\x80\x00\x00", 4); // 1.0f
    content += std::string("\xc0\x00\x00\x00", 4); // -2.0f
    writeText(path, content);
    const t10::ImageF back = t10::readPfm(path);
    CHECK(back.data == std::vector<float>{1.0f, -2.0f});
}

TEST_CASE("PFM reader rejects bad headers and short data naming the file", "[image_io]") {
    struct Case {
        const char* name;
        std::string content;
    };
    const std::string eightBytes(8, '\0');
    const Case cases[] = {
        {"empty", ""},
        {"magic", "P6\n1 1\n255\n" + eightBytes},
        {"magic_only", "PF"},
        {"zero_width", "Pf\n0 1\n-1.0\n" + eightBytes},
        {"zero_height", "Pf\n1 0\n-1.0\n" + eightBytes},
        {"negative", "Pf\n-2 1\n-1.0\n" + eightBytes},
        {"too_wide", "Pf\n65537 1\n-1.0\n" + eightBytes},
        {"huge", "PF\n65536 65536\n-1.0\n" + eightBytes},
        {"not_a_number", "Pf\nabc 1\n-1.0\n" + eightBytes},
        {"overflow", "Pf\n99999999999999999999999 1\n-1.0\n" + eightBytes},
        {"zero_scale", "Pf\n1 1\n0\n" + eightBytes},
        {"bad_scale", "Pf\n1 1\nx\n" + eightBytes},
        {"scale_trailing", "Pf\n1 1\n-1.0x\n" + eightBytes},
        {"no_scale", "Pf\n1 1"},
        {"short_data", "PF\n2 2\n-1.0\n" + eightBytes},
    };
    for (const Case& c : cases) {
        INFO("case " << c.name);
        const std::string path = scratchPath(std::string("bad_") + c.name + ".pfm");
        writeText(path, c.content);
        requireThrowsNaming([](const std::string& p) { t10::readPfm(p); }, path);
    }
    requireThrowsNaming([](const std::string& p) { t10::readPfm(p); }, scratchPath("missing.pfm"));
    requireThrowsNaming([](const std::string& p) { t10::writePfm(p, t10::ImageF(1, 1, 3)); },
                        scratchPath("no_such_dir/out.pfm"));
}
