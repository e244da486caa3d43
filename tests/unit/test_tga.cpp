// Unit tests for the TGA loader (common/content/src/tga.cpp). Valid files come from an independent writer
// (Pillow, see tests/fixtures/tga/make_fixtures.py) and are compared with a reference PNG that
// Pillow wrote and stb decodes, plus a few pixels checked against the generator's formula. Malformed
// files are built byte by byte here: every one must give "<name>: <fault>", never a crash, an
// out-of-bounds read (run under ASan) or an allocation sized from an unchecked header.
#include "t10/image_io.hpp"
#include "t10/error.hpp"
#include "t10/file.hpp"
#include "t10/tga.hpp"

#include "t10_catch.hpp"

#include <chrono>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

namespace {

using Bytes = std::vector<std::uint8_t>;

const std::string kTgaFixtureDir = std::string(T10_TEST_FIXTURE_DIR) + "/tga/";

struct Header {
    int idLength = 0;
    int colourMapType = 0;
    int imageType = 2;
    int colourMapLength = 0;
    int colourMapEntryBits = 0;
    int width = 2;
    int height = 2;
    int depth = 24;
    int descriptor = 0;
};

void putU16(Bytes& b, int v) {
    b.push_back(static_cast<std::uint8_t>(v & 0xFF));
    b.push_back(static_cast<std::uint8_t>((v >> 8) & 0xFF));
}

Bytes makeHeader(const Header& h) {
    Bytes b;
    b.push_back(static_cast<std::uint8_t>(h.idLength));
    b.push_back(static_cast<std::uint8_t>(h.colourMapType));
    b.push_back(static_cast<std::uint8_t>(h.imageType));
    putU16(b, 0); // first colour-map entry
    putU16(b, h.colourMapLength);
    b.push_back(static_cast<std::uint8_t>(h.colourMapEntryBits));
    putU16(b, 0); // x origin
    putU16(b, 0); // y origin
    putU16(b, h.width);
    putU16(b, h.height);
    b.push_back(static_cast<std::uint8_t>(h.depth));
    b.push_back(static_cast<std::uint8_t>(h.descriptor));
    return b;
}

Bytes withData(Bytes b, std::size_t count, std::uint8_t value = 0x55) {
    b.insert(b.end(), count, value);
    return b;
}

// The message of the t10::Error that `decode` throws, or "" when it throws nothing.
template <typename F>
std::string errorOf(F decode) {
    try {
        decode();
    } catch (const t10::Error& error) {
        return error.what();
    }
    return "";
}

std::string decodeError(const Bytes& b, const std::string& name = "bad.tga") {
    return errorOf([&] { t10::decodeTga(b.data(), b.size(), name); });
}

// A header followed by `dataBytes` filler bytes, decoded as "bad.tga".
std::string headerError(const Header& h, std::size_t dataBytes) {
    return decodeError(withData(makeHeader(h), dataBytes));
}

Bytes readTgaBytes(const std::string& path) { return t10::readFile(path); }

// The generator's formula for the 7x5 fixtures (make_fixtures.py, small_pixel), row 0 = bottom.
std::uint8_t expectedSmall(int x, int y, int channel, int channels) {
    if (channels == 1) return static_cast<std::uint8_t>(5 + 7 * (x + 7 * y));
    switch (channel) {
    case 0: return static_cast<std::uint8_t>(10 + 35 * x);
    case 1: return static_cast<std::uint8_t>(10 + 50 * y);
    case 2: return static_cast<std::uint8_t>((x * 5 + y) * 7);
    default: return static_cast<std::uint8_t>(255 - (x + y * 7) * 5);
    }
}

} // namespace

TEST_CASE("TGA fixtures from an independent writer decode to their reference PNGs", "[tga]") {
    const std::string name = GENERATE(as<std::string>{},
        "grey8_raw_bl", "grey8_raw_tl", "grey8_rle_bl", "grey8_rle_tl",
        "rgb24_raw_bl", "rgb24_raw_tl", "rgb24_rle_bl", "rgb24_rle_tl",
        "rgba32_raw_bl", "rgba32_raw_tl", "rgba32_rle_bl", "rgba32_rle_tl",
        "rgb24_raw_bl_imageid", "tall_grey8_raw_bl",
        "wide_rgb24_rle_bl", "wide_rgb24_raw_tl", "wide_grey8_rle_tl", "wide_rgba32_rle_tl");
    INFO("fixture " << name);
    t10::Image8 tga;
    REQUIRE_NOTHROW(tga = t10::loadTga(kTgaFixtureDir + name + ".tga"));
    const t10::Image8 reference = t10::readPng(kTgaFixtureDir + name + ".png");
    REQUIRE(tga.width == reference.width);
    REQUIRE(tga.height == reference.height);
    REQUIRE(tga.channels == reference.channels);
    CHECK(tga.data == reference.data);
}

TEST_CASE("TGA 7x5 fixtures match the generator formula with row 0 at the bottom and RGB order", "[tga]") {
    // Independent of readPng's flip: the expected values come from the formula itself.
    const std::string name = GENERATE(as<std::string>{},
        "grey8_raw_bl", "grey8_raw_tl", "grey8_rle_bl", "grey8_rle_tl",
        "rgb24_raw_bl", "rgb24_raw_tl", "rgb24_rle_bl", "rgb24_rle_tl",
        "rgba32_raw_bl", "rgba32_raw_tl", "rgba32_rle_bl", "rgba32_rle_tl", "rgb24_raw_bl_imageid");
    INFO("fixture " << name);
    t10::Image8 img;
    REQUIRE_NOTHROW(img = t10::loadTga(kTgaFixtureDir + name + ".tga"));
    REQUIRE(img.width == 7);
    REQUIRE(img.height == 5);
    const int expectedChannels = name.rfind("grey8", 0) == 0 ? 1 : name.rfind("rgba32", 0) == 0 ? 4 : 3;
    REQUIRE(img.channels == expectedChannels);
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            for (int c = 0; c < img.channels; ++c) {
                INFO("x " << x << " y " << y << " channel " << c);
                REQUIRE(img.at(x, y, c) == expectedSmall(x, y, c, img.channels));
            }
}

TEST_CASE("TGA wide fixture with header sizes above 127 and RLE runs over 128 pixels", "[tga]") {
    t10::Image8 tga;
    REQUIRE_NOTHROW(tga = t10::loadTga(kTgaFixtureDir + "wide_rgb24_rle_bl.tga"));
    REQUIRE(tga.width == 400);
    REQUIRE(tga.height == 2);
    // Bottom row (row 0): a ramp of 50, then a run of 350 of (17, 170, 34).
    CHECK(tga.at(49, 0, 0) == 49);
    for (int x = 50; x < 400; ++x) REQUIRE((tga.at(x, 0, 0) == 17 && tga.at(x, 0, 1) == 170));
    // Top row: a run of 300 of (200, 40, 90), then a ramp.
    for (int x = 0; x < 300; ++x) REQUIRE((tga.at(x, 1, 0) == 200 && tga.at(x, 1, 2) == 90));
    CHECK(tga.at(399, 1, 0) == 99);
}

TEST_CASE("TGA RLE packets may cross scan lines", "[tga]") {
    Header h;
    h.imageType = 10;
    h.width = 3;
    h.height = 2;
    Bytes b = makeHeader(h);
    // A run of 4 pixels (two rows' worth minus 2) then a raw packet of 2 pixels.
    b.insert(b.end(), {0x83, 1, 2, 3, 0x01, 10, 20, 30, 40, 50, 60});
    t10::Image8 r;
    REQUIRE_NOTHROW(r = t10::decodeTga(b.data(), b.size(), "cross.tga"));
    // Bottom-left origin: the file's first pixels are the bottom row; BGR in the file, RGB out.
    CHECK(r.at(0, 0, 0) == 3);
    CHECK(r.at(0, 0, 2) == 1);
    CHECK(r.at(0, 1, 0) == 3);
    CHECK(r.at(1, 1, 0) == 30);
    CHECK(r.at(2, 1, 0) == 60);
    CHECK(r.at(2, 1, 2) == 40);
}

TEST_CASE("TGA colour map on a true-colour image is skipped by its declared length", "[tga]") {
    const int entryBits = GENERATE(15, 16, 24, 32);
    INFO("entry size " << entryBits);
    Header h;
    h.colourMapType = 1;
    h.colourMapLength = 3;
    h.colourMapEntryBits = entryBits;
    h.width = 1;
    h.height = 1;
    Bytes b = withData(makeHeader(h), static_cast<std::size_t>(3 * ((entryBits + 7) / 8)), 0xEE);
    b.insert(b.end(), {9, 8, 7});
    t10::Image8 r;
    REQUIRE_NOTHROW(r = t10::decodeTga(b.data(), b.size(), "map.tga"));
    CHECK(r.at(0, 0, 0) == 7);
    CHECK(r.at(0, 0, 1) == 8);
    CHECK(r.at(0, 0, 2) == 9);
}

TEST_CASE("TGA malformed headers give an error naming the file and the fault", "[tga]") {
    using Catch::Contains;
    using Catch::StartsWith;

    SECTION("empty and truncated header") {
        CHECK(decodeError({}) == "bad.tga: truncated header (0 of 18 bytes)");
        Bytes b = makeHeader(Header{});
        b.resize(7);
        CHECK(decodeError(b) == "bad.tga: truncated header (7 of 18 bytes)");
        CHECK(errorOf([] { t10::decodeTga(nullptr, 100, "null.tga"); }) == "null.tga: truncated header (0 of 18 bytes)");
    }
    SECTION("zero width or height") {
        Header h;
        h.width = 0;
        CHECK_THAT(headerError(h, 12), StartsWith("bad.tga: ") && Contains("zero width or height"));
        h.width = 2;
        h.height = 0;
        CHECK_THAT(headerError(h, 12), StartsWith("bad.tga: ") && Contains("zero width or height"));
    }
    SECTION("sides over the limit") {
        Header h;
        h.width = t10::kTgaMaxSide + 1;
        h.height = 1;
        CHECK(headerError(h, 100) == "bad.tga: width 16385 exceeds 16384");
        h.width = 1;
        h.height = t10::kTgaMaxSide + 1;
        CHECK(headerError(h, 100) == "bad.tga: height 16385 exceeds 16384");
        h.width = 65535;
        h.height = 65535;
        CHECK_THAT(headerError(h, 10), Contains("exceeds 16384"));
    }
    SECTION("colour-mapped images are unsupported") {
        const int type = GENERATE(1, 9);
        Header h;
        h.imageType = type;
        h.colourMapType = 1;
        h.colourMapLength = 2;
        h.colourMapEntryBits = 24;
        h.depth = 8;
        CHECK_THAT(headerError(h, 64),
                   StartsWith("bad.tga: unsupported image type " + std::to_string(type) + " (colour-mapped)"));
    }
    SECTION("no image data and unknown types") {
        Header h;
        h.imageType = 0;
        CHECK_THAT(headerError(h, 12), StartsWith("bad.tga: ") && Contains("type 0"));
        h.imageType = 99;
        CHECK_THAT(headerError(h, 12), StartsWith("bad.tga: unsupported image type 99"));
        h.imageType = 32; // Huffman-compressed colour-mapped: not supported either
        CHECK_THAT(headerError(h, 12), Contains("unsupported image type 32"));
    }
    SECTION("unsupported pixel depths") {
        Header h;
        h.depth = 16;
        CHECK_THAT(headerError(h, 64),
                   StartsWith("bad.tga: unsupported pixel depth 16 for true-colour"));
        h.depth = 8;
        CHECK_THAT(headerError(h, 64), Contains("unsupported pixel depth 8 for true-colour"));
        h.depth = 15;
        h.imageType = 10;
        CHECK_THAT(headerError(h, 64), Contains("unsupported pixel depth 15 for true-colour"));
        h.imageType = 3;
        h.depth = 24;
        CHECK_THAT(headerError(h, 64), StartsWith("bad.tga: unsupported pixel depth 24 for grey"));
        h.imageType = 11;
        h.depth = 16; // grey + alpha
        CHECK_THAT(headerError(h, 64), Contains("unsupported pixel depth 16 for grey"));
    }
    SECTION("right-to-left pixel order is rejected") {
        Header h;
        h.descriptor = 0x10;
        CHECK_THAT(headerError(h, 12), StartsWith("bad.tga: ") && Contains("right-to-left"));
    }
    SECTION("invalid colour-map type") {
        Header h;
        h.colourMapType = 2;
        CHECK_THAT(headerError(h, 12), Contains("invalid colour-map type 2"));
    }
    SECTION("image-ID field and colour map running past the end") {
        Header h;
        h.idLength = 40;
        CHECK_THAT(headerError(h, 12), StartsWith("bad.tga: ") && Contains("image-ID field truncated"));
        h.idLength = 0;
        h.colourMapType = 1;
        h.colourMapLength = 1000;
        h.colourMapEntryBits = 24;
        CHECK_THAT(headerError(h, 12), StartsWith("bad.tga: ") && Contains("colour map truncated"));
    }
}

TEST_CASE("TGA malformed pixel data gives an error naming the file and the fault", "[tga]") {
    using Catch::Contains;
    using Catch::StartsWith;
    Header h;
    h.width = 4;
    h.height = 3;

    SECTION("raw data one byte short") {
        h.depth = GENERATE(24, 32);
        const Bytes b = withData(makeHeader(h), static_cast<std::size_t>(4 * 3 * h.depth / 8 - 1));
        CHECK_THAT(decodeError(b), StartsWith("bad.tga: pixel data truncated"));
    }
    SECTION("raw grey data one byte short") {
        h.imageType = 3;
        h.depth = 8;
        CHECK_THAT(headerError(h, 11), StartsWith("bad.tga: pixel data truncated"));
    }
    SECTION("RLE stream ends before the image is complete") {
        h.imageType = 10;
        Bytes b = makeHeader(h);
        b.insert(b.end(), {0x84, 1, 2, 3}); // 5 of 12 pixels
        CHECK_THAT(decodeError(b), StartsWith("bad.tga: RLE data truncated"));
    }
    SECTION("RLE run packet without its pixel value") {
        h.imageType = 10;
        Bytes b = makeHeader(h);
        b.insert(b.end(), {0x89, 1, 2, 3, 0x81, 1}); // 10 pixels, then a run of 2 missing 2 bytes
        CHECK_THAT(decodeError(b), StartsWith("bad.tga: RLE data truncated"));
    }
    SECTION("RLE raw packet without all its pixels") {
        h.imageType = 11;
        h.depth = 8;
        Bytes b = makeHeader(h);
        b.insert(b.end(), {0x0B, 1, 2, 3, 4, 5}); // raw packet of 12, only 5 present
        CHECK_THAT(decodeError(b), StartsWith("bad.tga: RLE data truncated"));
    }
    SECTION("RLE packet running past the end of the image") {
        h.imageType = 10;
        Bytes b = makeHeader(h);
        b.insert(b.end(), {0x8A, 1, 2, 3, 0x81, 4, 5, 6}); // 11 + 2 > 12 pixels
        CHECK(decodeError(b) == "bad.tga: RLE packet runs past the end of the image");
        Bytes raw = makeHeader(h);
        raw.push_back(0x7F); // a raw packet of 128 pixels in a 12-pixel image
        raw.insert(raw.end(), 128 * 3, 0x11);
        CHECK(decodeError(raw) == "bad.tga: RLE packet runs past the end of the image");
    }
}

TEST_CASE("TGA with a huge valid header and no data fails without allocating the image", "[tga]") {
    // 16384 x 16384 x 4 bytes would be a 1 GiB allocation (and 1 GiB of zeroing) per call if the
    // loader allocated before checking the data length; 50 calls would then take seconds. Checked
    // first, each call takes microseconds.
    Header h;
    h.width = t10::kTgaMaxSide;
    h.height = t10::kTgaMaxSide;
    h.depth = 32;
    const Bytes raw = withData(makeHeader(h), 10);
    h.imageType = 10;
    const Bytes rle = withData(makeHeader(h), 10);
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < 50; ++i) {
        REQUIRE_THAT(decodeError(raw), Catch::Contains("pixel data truncated"));
        REQUIRE_THAT(decodeError(rle), Catch::Contains("RLE data truncated"));
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    CHECK(seconds < 1.0);
}

TEST_CASE("TGA truncated or corrupted fixtures never crash", "[tga]") {
    // Every prefix of a valid file, and random byte changes to it, must give a result or an error;
    // under AddressSanitizer this also proves there is no out-of-bounds read.
    const std::string name = GENERATE(as<std::string>{}, "rgba32_rle_tl", "rgb24_raw_bl_imageid", "wide_grey8_rle_tl");
    INFO("fixture " << name);
    const Bytes full = readTgaBytes(kTgaFixtureDir + name + ".tga");
    const std::size_t pixelBytesEnd = full.size() - 26; // the TGA 2.0 footer is 26 bytes, not needed
    for (std::size_t n = 0; n < pixelBytesEnd; ++n) {
        const std::string err = errorOf([&] { t10::decodeTga(full.data(), n, "cut.tga"); });
        INFO("prefix of " << n << " bytes");
        REQUIRE_THAT(err, Catch::StartsWith("cut.tga: ") && Catch::Contains("truncated"));
    }
    REQUIRE_NOTHROW(t10::decodeTga(full.data(), pixelBytesEnd, "cut.tga"));

    std::mt19937 rng(1234); // fixed seed: the same mutations every run
    std::uniform_int_distribution<std::size_t> where(0, full.size() - 1);
    std::uniform_int_distribution<int> value(0, 255);
    for (int i = 0; i < 2000; ++i) {
        Bytes b = full;
        for (int k = 0; k < 3; ++k) b[where(rng)] = static_cast<std::uint8_t>(value(rng));
        try {
            const t10::Image8 r = t10::decodeTga(b.data(), b.size(), "mutated.tga");
            REQUIRE(r.data.size() == static_cast<std::size_t>(r.width) * r.height * r.channels);
        } catch (const t10::Error& error) {
            REQUIRE_THAT(error.what(), Catch::StartsWith("mutated.tga: "));
        }
    }
}

TEST_CASE("TGA missing file gives an error naming the path", "[tga]") {
    const std::string path = kTgaFixtureDir + "does_not_exist.tga";
    CHECK_THROWS_AS(t10::loadTga(path), t10::Error);
    CHECK(errorOf([&] { t10::loadTga(path); }) == path + ": cannot open file: No such file or directory");
}

TEST_CASE("TGA loadTga on a directory fails cleanly", "[tga]") {
    CHECK_THROWS_AS(t10::loadTga(kTgaFixtureDir), t10::Error);
    CHECK_THAT(errorOf([&] { t10::loadTga(kTgaFixtureDir); }), Catch::StartsWith(kTgaFixtureDir + ": "));
}
