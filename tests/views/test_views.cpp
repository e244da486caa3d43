// Checks that each view shows what it says: the images written with --view NAME --output are
// decoded with the encodings of t10::views and compared with the buffers the same run wrote with
// --dump and the CPU reference of tests/numeric. T10_DUMP_DIR points at the views' folder
// (tests/views_tests.cmake renders them first).
#include "t10/dumps.hpp"
#include "reference.hpp"

#include "t10/error.hpp"
#include "t10/file.hpp"
#include "t10/image_io.hpp"
#include "t10/view_catalogue.hpp"

#include "t10_catch.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <regex>
#include <sstream>
#include <unordered_map>

namespace {

using t10::Image8;
using t10::ImageF;
namespace views = t10::views;

constexpr const char* kPart1 = "tutorial10_part1_tonemap";
constexpr const char* kPart2 = "tutorial10_part2_bloom";
constexpr const char* kPart3 = "tutorial10_part3_gaussian";

std::array<int, 3> toBytes(const views::Rgb& colour) {
    return {t10::ref::toUnorm8(colour[0]), t10::ref::toUnorm8(colour[1]), t10::ref::toUnorm8(colour[2])};
}

int byteDistance(const Image8& image, int x, int y, const std::array<int, 3>& expected) {
    int worst = 0;
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(image.at(x, y, c)) - expected[static_cast<std::size_t>(c)]));
    return worst;
}

// The texel of a w x h level behind framebuffer pixel (x, y), as View.frag picks it.
int texelOf(int pixel, int levelSize, int frameSize) { return std::min(pixel * levelSize / frameSize, levelSize - 1); }

// The colour scale decoded: the position on the scale of the nearest of 6 x 1024 + 1 samples.
double decodeScale(const Image8& image, int x, int y) {
    static const std::vector<std::array<int, 3>> samples = [] {
        std::vector<std::array<int, 3>> table;
        for (int i = 0; i <= 6 * 1024; ++i) {
            const views::Rgb colour = views::colourScale(i / (6.0 * 1024.0));
            table.push_back({int(std::lround(colour[0] * 255 * 16)), int(std::lround(colour[1] * 255 * 16)),
                             int(std::lround(colour[2] * 255 * 16))});
        }
        return table;
    }();
    // A view has a few hundred colours among its ~14,000 pixels: each colour is searched once (the
    // search over every sample, unoptimised in a debug build, cost make test about 5 CPU-seconds).
    static std::unordered_map<std::uint32_t, double> decoded;
    const std::uint32_t key = std::uint32_t(image.at(x, y, 0)) << 16 | std::uint32_t(image.at(x, y, 1)) << 8 | image.at(x, y, 2);
    if (const auto found = decoded.find(key); found != decoded.end())
        return found->second;
    long best = -1;
    std::size_t bestIndex = 0;
    for (std::size_t i = 0; i < samples.size(); ++i) {
        long d = 0;
        for (int c = 0; c < 3; ++c) {
            const long e = long(image.at(x, y, c)) * 16 - samples[i][static_cast<std::size_t>(c)];
            d += e * e;
        }
        if (best < 0 || d < best) {
            best = d;
            bestIndex = i;
        }
    }
    return decoded[key] = static_cast<double>(bestIndex) / (6.0 * 1024.0);
}

std::string readText(const std::string& path) {
    const std::vector<std::uint8_t> bytes = t10::readFile(path); // throws naming the file and the reason
    return std::string(bytes.begin(), bytes.end());
}

// "accumulation 1" -> 1 in the nan caption; -1 if the target is not listed.
long countIn(const std::string& caption, const std::string& target) {
    std::smatch match;
    if (!std::regex_search(caption, match, std::regex("[ (]" + target + " ([0-9]+)"))) return -1;
    return std::stol(match[1]);
}

bool nonFinite(const ImageF& image, int x, int y) {
    for (int c = 0; c < image.channels; ++c) {
        if (!std::isfinite(image.at(x, y, c))) return true;
    }
    return false;
}

long countNonFinite(const ImageF& image) {
    long count = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) count += nonFinite(image, x, y) ? 1 : 0;
    }
    return count;
}

void checkLuminance(const std::string& stage) {
    const t10::test::Dump dump = t10::test::loadDump(stage + "/luminance");
    const ImageF buffer = dump.level(16, 0);
    const Image8& image = dump.frame;
    REQUIRE(image.width == dump.accumulation.width);
    // Tolerance 0.002 on the [0, 1] scale (0.034 in natural log, 3.4 % in luminance): the scale
    // moves one channel by 255 steps per sixth, so one 8-bit rounding step is 0.00065 (0.00087 on
    // the first sixth, which spans 191 steps); GL_R16 adds 1.5e-5.
    constexpr double kDecodeTolerance = 0.002;
    double worst = 0.0;      // against the GL_R16 buffer the view shows
    double worstCpu = 0.0;   // against the CPU log luminance of the HDR buffer
    long offCpu = 0;
    long pixels = 0;
    const int legend = views::legendHeight(image.height);
    for (int y = legend; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const double decoded = decodeScale(image, x, y);
            worst = std::max(worst, std::abs(decoded - buffer.at(x, y, 0)));
            const t10::ref::Rgb colour{dump.accumulation.at(x, y, 0), dump.accumulation.at(x, y, 1),
                                       dump.accumulation.at(x, y, 2)};
            const double cpu = std::clamp(t10::ref::rangeMappedLogLuminance(t10::ref::luminance(colour)), 0.0, 1.0);
            worstCpu = std::max(worstCpu, std::abs(decoded - cpu));
            offCpu += std::abs(decoded - cpu) > kDecodeTolerance ? 1 : 0;
            ++pixels;
        }
    }
    INFO(stage << ": worst decoded difference " << worst << " from the buffer, " << worstCpu << " from the CPU; "
               << offCpu << " of " << pixels << " pixels off the CPU value by more than " << kDecodeTolerance);
    CHECK( worst <= kDecodeTolerance );
    // Against the CPU: the luminance pass samples the HDR buffer bilinearly at pixel centres, and
    // llvmpipe's coordinates there are not exact, so at a lamp's edge a pixel picks up a little of
    // its neighbour (measured: 3 of 13,760 pixels, at most 0.0024). Allow 0.1 % of the pixels, each
    // within 0.01 (17 % in luminance).
    CHECK( offCpu <= pixels / 1000 );
    CHECK( worstCpu <= 0.01 );
    // The legend runs the scale from left to right.
    CHECK( decodeScale(image, 0, 0) < 0.01 );
    CHECK( decodeScale(image, image.width - 1, 0) > 0.99 );
}

void checkBloom1(const std::string& stage) {
    const t10::test::Dump dump = t10::test::loadDump(stage + "/bloom1");
    const ImageF level1 = dump.level(17, 1);
    const Image8& image = dump.frame;
    Image8 expected(image.width, image.height, 3);
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const int tx = texelOf(x, level1.width, image.width);
            const int ty = texelOf(y, level1.height, image.height);
            for (int c = 0; c < 3; ++c) {
                expected.at(x, y, c) =
                    t10::ref::toUnorm8(views::displayEncode(level1.at(tx, ty, c), views::kBloomExposure));
            }
        }
    }
    const t10::test::ByteError error = t10::test::byteError(image, expected);
    // One 8-bit step: the GPU's pow() and float-to-unorm rounding against double precision.
    INFO(stage << ": max " << error.max << " mean " << error.mean);
    CHECK( error.max <= 1 );
    // Not vacuous: some of the level is bright enough to show.
    CHECK( *std::max_element(expected.data.begin(), expected.data.end()) > 64 );
}

void checkEv(const std::string& stage) {
    const t10::test::Dump dump = t10::test::loadDump(stage + "/ev");
    const double key = t10::ref::keyFromMapped(dump.luminanceKey());
    const Image8& image = dump.frame;
    const int legend = views::legendHeight(image.height);
    long mismatched = 0;
    long pixels = 0;
    std::array<long, 4> kinds{};
    for (int y = legend; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const t10::ref::Rgb colour{dump.accumulation.at(x, y, 0), dump.accumulation.at(x, y, 1),
                                       dump.accumulation.at(x, y, 2)};
            const views::EvClass ev = views::classifyEv(t10::ref::luminance(colour), key);
            ++kinds[static_cast<std::size_t>(ev.kind)];
            mismatched += byteDistance(image, x, y, toBytes(views::evColour(ev))) > 1 ? 1 : 0;
            ++pixels;
        }
    }
    // A pixel within float rounding of a stop or class boundary may land on the other side on the
    // GPU (float32 against double): allow 0.2 % of the pixels.
    const long allowed = pixels / 500;
    INFO(stage << ": " << mismatched << " of " << pixels << " pixels differ; black " << kinds[0] << ", burnt "
               << kinds[1] << ", lifted " << kinds[2] << ", compressed " << kinds[3]);
    CHECK( mismatched <= allowed );
    // The default view holds burnt, lifted and black-or-compressed pixels, so every class is exercised.
    CHECK( kinds[1] > 0 );
    CHECK( kinds[2] > 0 );
}

void checkKey(const std::string& stage) {
    const t10::test::Dump dump = t10::test::loadDump(stage + "/key");
    const double mapped = dump.luminanceKey();
    const Image8& image = dump.frame;
    const std::array<int, 3> expected = toBytes(views::colourScale(mapped));
    const int legend = views::legendHeight(image.height);
    int worst = 0;
    for (int y = legend; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) worst = std::max(worst, byteDistance(image, x, y, expected));
    }
    // One 8-bit step: float against double in the colour scale's interpolation.
    CHECK( worst <= 1 );
    // The strip below the swatch: the scale from left to right, and one column marked black over
    // white where the key lies on it.
    std::vector<int> marked;
    int worstStrip = 0;
    for (int x = 0; x < image.width; ++x) {
        const bool black = byteDistance(image, x, legend - 1, {0, 0, 0}) == 0;
        const bool white = byteDistance(image, x, 0, {255, 255, 255}) == 0;
        if (black && white) {
            marked.push_back(x);
            continue;
        }
        const std::array<int, 3> scale = toBytes(views::colourScale((x + 0.5) / image.width));
        for (int y = 0; y < legend; ++y) worstStrip = std::max(worstStrip, byteDistance(image, x, y, scale));
    }
    CHECK( worstStrip <= 1 );
    REQUIRE( marked.size() == 1 );
    // The marker's column: the key's position on the scale times the width, give or take one column
    // for float against double at a column boundary (one column of 160 is 1/160 of the scale, 0.1 in
    // natural log luminance, an 11 % change of Ya).
    const int expectedColumn = std::clamp(int(mapped * image.width), 0, image.width - 1);
    INFO(stage << ": key at " << mapped << " on the scale, marker in column " << marked.front() << ", expected "
               << expectedColumn);
    CHECK( std::abs(marked.front() - expectedColumn) <= 1 );
}

void checkNan(const std::string& name, bool fullResOnly) {
    const std::string dir = std::string(std::getenv("T10_DUMP_DIR")) + "/nan_" + name;
    const std::string caption = readText(dir + "/stdout.txt");
    INFO(caption);
    const ImageF hdr = t10::readExr(dir + "/hdr.exr"); // the accumulation as the GPU held it (RGBA)
    const long accumulation = countNonFinite(hdr);
    CHECK( countIn(caption, "accumulation") == accumulation );
    // The synthetic input has exactly one non-finite texel; loading may clamp it (then 0 remain).
    CHECK( accumulation <= 1 );
    const t10::test::Dump dump = t10::test::loadDump("nan_" + name);
    const int bloomLevels = dump.levelCount(17);
    ImageF bloom0;
    ImageF bloom1;
    if (bloomLevels >= 2) {
        bloom0 = dump.level(17, 0);
        bloom1 = dump.level(17, 1);
        CHECK( countIn(caption, "bloom0") == countNonFinite(bloom0) );
        CHECK( countIn(caption, "bloom1") == countNonFinite(bloom1) );
    }
    // Marked pixels: every pixel whose texel in the accumulation, bloom level 0 or bloom level 1 is
    // non-finite is magenta; with only full-resolution targets, no other pixel is.
    const Image8& image = dump.frame;
    long marked = 0;
    long missed = 0;
    long expectedMarked = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            bool bad = nonFinite(hdr, x, y);
            if (!bloom0.empty()) bad = bad || nonFinite(bloom0, x, y);
            if (!bloom1.empty()) {
                bad = bad || nonFinite(bloom1, texelOf(x, bloom1.width, image.width), texelOf(y, bloom1.height, image.height));
            }
            const bool magenta = byteDistance(image, x, y, toBytes(views::kSignal)) == 0;
            marked += magenta ? 1 : 0;
            expectedMarked += bad ? 1 : 0;
            missed += bad && !magenta ? 1 : 0;
        }
    }
    CHECK( missed == 0 );
    if (fullResOnly) CHECK( marked == expectedMarked );
    else CHECK( marked >= expectedMarked );
}

void checkThumbnails(const std::string& stage) {
    const t10::test::Dump dump = t10::test::loadDump(stage + "/thumbnails");
    const Image8& image = dump.frame;
    const ImageF& hdr = dump.accumulation;
    // The first of five slots is the hdr view of the accumulation at a fifth of the width.
    const int slotWidth = image.width / 5;
    const int slotHeight = slotWidth * image.height / image.width;
    int worst = 0;
    for (int y = 0; y < slotHeight; ++y) {
        for (int x = 0; x < slotWidth; ++x) {
            const int tx = texelOf(x, hdr.width, slotWidth);
            const int ty = texelOf(y, hdr.height, slotHeight);
            views::Rgb colour{};
            for (int c = 0; c < 3; ++c) colour[c] = views::displayEncode(hdr.at(tx, ty, c), views::kHdrExposure);
            worst = std::max(worst, byteDistance(image, x, y, toBytes(colour)));
        }
    }
    // One 8-bit step, as for the full-size views.
    CHECK( worst <= 1 );
    // The label band above the slot holds white glyph pixels on a dark ground.
    long white = 0;
    long dark = 0;
    for (int y = slotHeight; y < slotHeight + 14; ++y) {
        for (int x = 0; x < slotWidth; ++x) {
            white += image.at(x, y, 0) == 255 ? 1 : 0;
            dark += image.at(x, y, 0) < 40 ? 1 : 0;
        }
    }
    CHECK( white > 20 );
    CHECK( dark > white );
}

} // namespace

TEST_CASE("thumbnails show the accumulation and a label under the frame (part3)") { checkThumbnails(kPart3); }
TEST_CASE("luminance view decodes to the CPU log luminance (part1)") { checkLuminance(kPart1); }
TEST_CASE("luminance view decodes to the CPU log luminance (part3)") { checkLuminance(kPart3); }
TEST_CASE("key view is a flat swatch of the smallest luminance level with the key marked on a scale strip (part1)") { checkKey(kPart1); }
TEST_CASE("bloom1 view shows the read-back level 1 (part2)") { checkBloom1(kPart2); }
TEST_CASE("bloom1 view shows the read-back level 1 (part3)") { checkBloom1(kPart3); }
TEST_CASE("ev view matches the CPU classification of the HDR buffer (part1)") { checkEv(kPart1); }
TEST_CASE("ev view matches the CPU classification of the HDR buffer (part3)") { checkEv(kPart3); }
TEST_CASE("nan view counts and marks the non-finite texels (part1 NaN input)") { checkNan("part1_nan", true); }
TEST_CASE("nan view counts and marks the non-finite texels (part1 Inf input)") { checkNan("part1_inf", true); }
TEST_CASE("nan view counts and marks the non-finite texels (part3 Inf input)") { checkNan("part3_inf", false); }
