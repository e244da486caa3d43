// CPU mip levels (t10/mipmaps.hpp): sizes, the 2x2 mean and its rounding, odd sides.
#include "t10/mipmaps.hpp"

#include "t10_catch.hpp"

TEST_CASE("a level below halves each side, never below 1", "[mipmaps]") {
    const t10::Image8 a = t10::nextMipLevel(t10::Image8(256, 256, 3));
    CHECK((a.width == 128 && a.height == 128 && a.channels == 3));
    const t10::Image8 b = t10::nextMipLevel(t10::Image8(5, 1, 1));
    CHECK((b.width == 2 && b.height == 1));
    const t10::Image8 c = t10::nextMipLevel(t10::Image8(1, 1, 4));
    CHECK((c.width == 1 && c.height == 1 && c.channels == 4));
}

TEST_CASE("linear data is its 2x2 block's mean, rounded as a bilinear filter rounds", "[mipmaps]") {
    t10::Image8 image(2, 2, 1);
    image.data = {0, 255, 255, 255}; // rows 128 and 255, then 192 (the exact mean 191.25 would give 191)
    CHECK(int(t10::nextMipLevel(image).data[0]) == 192);
    image.data = {0, 1, 1, 0}; // each row 0.5 rounds up to 1
    CHECK(int(t10::nextMipLevel(image).data[0]) == 1);
    image.data = {10, 10, 12, 13}; // rows 10 and 13 (12.5 up), then 12 (11.5 up)
    CHECK(int(t10::nextMipLevel(image).data[0]) == 12);
}

TEST_CASE("an odd side's last column is not averaged past the edge", "[mipmaps]") {
    t10::Image8 image(3, 2, 1);
    image.data = {10, 20, 200, 30, 40, 200}; // bottom row first
    const t10::Image8 level = t10::nextMipLevel(image);
    REQUIRE(level.width == 1);
    CHECK(int(level.data[0]) == 25); // (10 + 20 + 30 + 40) / 4: the 200s are dropped
}
