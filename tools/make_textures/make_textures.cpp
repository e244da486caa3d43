// make_textures OUT_DIR: procedurally generates the scene's TGA textures (common/assets/*.tga).
//
// Three materials, each a diffuse map (24-bit colour, sRGB), a tangent-space normal map (24-bit,
// derived from the height field by central differences) and a DEPTH map (8-bit grey):
//   bricks_*  the walls           tiles_*  the floor           crate_*  the crates and the ceiling
// Depth convention (as in parallax occlusion mapping, seed 003): 0 = the top of the surface,
// 1 = the deepest point; i.e. depth = 1 - height.
// Normal maps follow the OpenGL convention: +X along +u (to the right), +Y along +v (up the image).
// Rows are written bottom row first with a bottom-left origin, so v = 0 is the first row.
//
// The TGA writer is written here on purpose, independent of the project's loader, so the loader is
// tested against files it did not produce. bricks_depth and crate_depth are RLE grey (type 11),
// crate_diffuse is RLE true-colour (type 10), the rest are raw (types 2 and 3).
// Everything is deterministic: noise comes from an integer hash with fixed seeds, no <random>.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

constexpr int kSize = 256; // every texture is kSize x kSize and tiles seamlessly
constexpr float kPi = 3.14159265358979f;

// ---------------------------------------------------------------------------------------------
// Images: floats in [0, 1], row 0 at the bottom.

struct Grey {
    std::vector<float> v = std::vector<float>(static_cast<std::size_t>(kSize) * kSize, 0.0f);
    float& at(int x, int y) { return v[static_cast<std::size_t>(wrap(y)) * kSize + wrap(x)]; }
    float at(int x, int y) const { return v[static_cast<std::size_t>(wrap(y)) * kSize + wrap(x)]; }
    static int wrap(int i) { return ((i % kSize) + kSize) % kSize; }
};

struct Colour {
    float r, g, b;
};

Colour operator*(Colour c, float s) { return {c.r * s, c.g * s, c.b * s}; }
Colour mix(Colour a, Colour b, float t) {
    return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t};
}

struct Rgb {
    std::vector<Colour> v = std::vector<Colour>(static_cast<std::size_t>(kSize) * kSize, Colour{0, 0, 0});
    Colour& at(int x, int y) { return v[static_cast<std::size_t>(y) * kSize + x]; }
    const Colour& at(int x, int y) const { return v[static_cast<std::size_t>(y) * kSize + x]; }
};

struct MaterialMaps {
    Rgb diffuse;
    Grey height; // 1 = top of the surface
};

// ---------------------------------------------------------------------------------------------
// Deterministic noise.

std::uint32_t hash32(std::uint32_t x) {
    // A well-mixing integer hash (lowbias32 by Chris Wellons).
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

std::uint32_t hash3(int a, int b, std::uint32_t seed) {
    return hash32(static_cast<std::uint32_t>(a) * 0x9e3779b1u ^ hash32(static_cast<std::uint32_t>(b) + seed * 0x85ebca6bu));
}

// Uniform in [0, 1).
float random01(int a, int b, std::uint32_t seed) {
    return static_cast<float>(hash3(a, b, seed) >> 8) * (1.0f / 16777216.0f);
}

float smooth(float t) { return t * t * (3.0f - 2.0f * t); }

float smoothstep(float e0, float e1, float x) {
    const float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
    return smooth(t);
}

// Value noise on a lattice of `period` x `period` cells that wraps, so the texture tiles.
// x and y are in cells. Returns [0, 1).
float valueNoise(float x, float y, int period, std::uint32_t seed) {
    const float fx = std::floor(x);
    const float fy = std::floor(y);
    const int ix = static_cast<int>(fx);
    const int iy = static_cast<int>(fy);
    const float tx = smooth(x - fx);
    const float ty = smooth(y - fy);
    auto lattice = [&](int i, int j) {
        return random01(((i % period) + period) % period, ((j % period) + period) % period, seed);
    };
    const float a = lattice(ix, iy) + (lattice(ix + 1, iy) - lattice(ix, iy)) * tx;
    const float b = lattice(ix, iy + 1) + (lattice(ix + 1, iy + 1) - lattice(ix, iy + 1)) * tx;
    return a + (b - a) * ty;
}

// Fractal sum of octaves; `cells` is the number of lattice cells across the texture at the first
// octave. Each octave doubles the frequency and halves the amplitude. Returns about [0, 1].
float fbm(float px, float py, int cells, int octaves, std::uint32_t seed) {
    float sum = 0.0f;
    float amplitude = 0.5f;
    float total = 0.0f;
    for (int o = 0; o < octaves; ++o) {
        const float scale = static_cast<float>(cells) / static_cast<float>(kSize);
        sum += amplitude * valueNoise(px * scale, py * scale, cells, seed + static_cast<std::uint32_t>(o) * 101u);
        total += amplitude;
        amplitude *= 0.5f;
        cells *= 2;
    }
    return sum / total;
}

// ---------------------------------------------------------------------------------------------
// Materials.

// Running bond brick wall: 8 courses of 4 bricks (64 x 32 texels), every other course offset by
// half a brick. Mortar joints are recessed; brick faces have bevelled, slightly chipped edges.
MaterialMaps makeBricks() {
    constexpr int kBrickW = 64;
    constexpr int kBrickH = 32;
    constexpr float kMortarHalf = 2.5f; // half the joint width in texels
    constexpr std::uint32_t kSeed = 1234u;
    const Colour palette[] = {
        {0.60f, 0.25f, 0.18f}, {0.52f, 0.22f, 0.16f}, {0.66f, 0.33f, 0.22f},
        {0.45f, 0.19f, 0.15f}, {0.58f, 0.30f, 0.24f}, {0.35f, 0.17f, 0.14f},
    };
    const Colour mortar{0.62f, 0.60f, 0.56f};

    MaterialMaps m;
    for (int y = 0; y < kSize; ++y) {
        const int course = y / kBrickH;
        const int shift = (course % 2) * (kBrickW / 2);
        for (int x = 0; x < kSize; ++x) {
            const int sx = (x + shift) % kSize;
            const int brick = sx / kBrickW;
            const float lx = static_cast<float>(sx % kBrickW) + 0.5f;
            const float ly = static_cast<float>(y % kBrickH) + 0.5f;
            const float fx = static_cast<float>(x);
            const float fy = static_cast<float>(y);
            // Distance to the nearest joint centre line, roughened so edges look chipped.
            const float rough = (fbm(fx, fy, 32, 3, kSeed + 7u) - 0.5f) * 3.0f;
            const float edge = std::min(std::min(lx, static_cast<float>(kBrickW) - lx),
                                        std::min(ly, static_cast<float>(kBrickH) - ly)) + rough;
            // 0 in the joint, 1 on the brick face, with a 3-texel bevel between.
            const float face = smoothstep(kMortarHalf, kMortarHalf + 3.0f, edge);

            const float brickNoise = fbm(fx, fy, 16, 4, kSeed + 1u);
            const float tilt = (random01(brick, course, kSeed + 3u) - 0.5f) * 0.08f * (lx / kBrickW - 0.5f);
            const float brickHeight = 0.88f + 0.12f * brickNoise + tilt;
            const float mortarHeight = 0.12f + 0.10f * fbm(fx, fy, 64, 3, kSeed + 5u);
            m.height.at(x, y) = std::clamp(mortarHeight + (brickHeight - mortarHeight) * face, 0.0f, 1.0f);

            const int pick = static_cast<int>(random01(brick, course, kSeed) * 6.0f) % 6;
            const float shade = 0.85f + 0.3f * random01(brick, course, kSeed + 11u);
            const float grain = 0.75f + 0.5f * fbm(fx, fy, 64, 4, kSeed + 13u);
            const float speck = random01(x, y, kSeed + 17u) > 0.97f ? 0.7f : 1.0f;
            Colour brickColour = palette[pick] * (shade * grain * speck);
            // Darken towards the joints, as dirt and occlusion do.
            brickColour = brickColour * (0.75f + 0.25f * smoothstep(kMortarHalf, kMortarHalf + 8.0f, edge));
            const Colour mortarColour = mortar * (0.8f + 0.35f * fbm(fx, fy, 64, 3, kSeed + 19u));
            m.diffuse.at(x, y) = mix(mortarColour, brickColour, face);
        }
    }
    return m;
}

// Square stone floor tiles, 4 x 4 per texture (64 texels each), with grout joints and marbled
// veining. Each tile gets its own tone and a slight tilt.
MaterialMaps makeTiles() {
    constexpr int kTile = 64;
    constexpr float kGroutHalf = 2.0f;
    constexpr std::uint32_t kSeed = 4321u;
    const Colour light{0.58f, 0.55f, 0.50f};
    const Colour dark{0.34f, 0.35f, 0.38f};
    const Colour grout{0.22f, 0.21f, 0.20f};

    MaterialMaps m;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const int tx = x / kTile;
            const int ty = y / kTile;
            const float lx = static_cast<float>(x % kTile) + 0.5f;
            const float ly = static_cast<float>(y % kTile) + 0.5f;
            const float fx = static_cast<float>(x);
            const float fy = static_cast<float>(y);
            const float edge = std::min(std::min(lx, static_cast<float>(kTile) - lx),
                                        std::min(ly, static_cast<float>(kTile) - ly));
            const float face = smoothstep(kGroutHalf, kGroutHalf + 4.0f, edge);

            const float slopeX = (random01(tx, ty, kSeed + 1u) - 0.5f) * 0.10f;
            const float slopeY = (random01(tx, ty, kSeed + 2u) - 0.5f) * 0.10f;
            const float tileHeight = 0.90f + 0.05f * fbm(fx, fy, 8, 4, kSeed + 3u) +
                                     slopeX * (lx / kTile - 0.5f) + slopeY * (ly / kTile - 0.5f);
            const float groutHeight = 0.40f + 0.08f * fbm(fx, fy, 64, 2, kSeed + 4u);
            m.height.at(x, y) = std::clamp(groutHeight + (tileHeight - groutHeight) * face, 0.0f, 1.0f);

            // Checkerboard of two stones, each tile varied, with turbulent veins.
            const bool checker = ((tx + ty) % 2) == 0;
            const Colour base = checker ? light : dark;
            const float tone = 0.85f + 0.3f * random01(tx, ty, kSeed + 5u);
            const float turbulence = fbm(fx, fy, 8, 5, kSeed + 6u + static_cast<std::uint32_t>(tx * 4 + ty));
            const float vein = std::pow(std::abs(std::sin((fx + fy * 0.6f) * (2.0f * kPi / kSize) * 2.0f +
                                                          turbulence * 9.0f)), 0.25f);
            const float cloud = 0.85f + 0.3f * fbm(fx, fy, 16, 4, kSeed + 7u);
            Colour stone = base * (tone * cloud * (0.7f + 0.3f * vein));
            const Colour groutColour = grout * (0.8f + 0.4f * fbm(fx, fy, 64, 2, kSeed + 8u));
            m.diffuse.at(x, y) = mix(groutColour, stone, face);
        }
    }
    return m;
}

// A wooden crate face: a raised frame around the border, a raised diagonal brace, and recessed
// horizontal planks with dark gaps between them. Small nail heads sit in the frame corners.
MaterialMaps makeCrate() {
    constexpr float kFrame = 30.0f;   // frame width in texels
    constexpr float kBrace = 32.0f;   // brace width, measured across the diagonal
    constexpr int kPlanks = 4;
    constexpr std::uint32_t kSeed = 777u;
    const Colour frameWood{0.46f, 0.30f, 0.16f};
    const Colour plankWood{0.62f, 0.44f, 0.25f};
    const float size = static_cast<float>(kSize);

    MaterialMaps m;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const float px = static_cast<float>(x) + 0.5f;
            const float py = static_cast<float>(y) + 0.5f;
            // Distance inside the frame's inner edge (negative within the frame).
            const float toBorder = std::min(std::min(px, size - px), std::min(py, size - py));
            const float frame = 1.0f - smoothstep(kFrame - 2.0f, kFrame + 1.0f, toBorder);
            const float frameBevel = smoothstep(0.0f, 4.0f, toBorder);
            // Brace along the diagonal from bottom-left to top-right.
            const float diag = std::abs(px - py) / std::sqrt(2.0f);
            const float brace = 1.0f - smoothstep(kBrace * 0.5f - 2.0f, kBrace * 0.5f + 1.0f, diag);
            // Planks: horizontal boards separated by narrow gaps.
            const float plankH = size / kPlanks;
            const float inPlank = std::fmod(py, plankH);
            const float gapDist = std::min(inPlank, plankH - inPlank);
            const float plankFace = smoothstep(1.0f, 3.0f, gapDist);
            const int plank = static_cast<int>(py / plankH);

            const float raised = std::max(frame, brace);
            const float plankHeight = 0.25f + 0.25f * plankFace +
                                      0.04f * fbm(px, py, 16, 3, kSeed + static_cast<std::uint32_t>(plank));
            float height = plankHeight + (0.95f - plankHeight) * raised;
            height *= 0.6f + 0.4f * frameBevel; // rounded outer edge of the crate
            // Nail heads: little domes in the frame corners.
            for (const float cx : {kFrame * 0.5f, size - kFrame * 0.5f}) {
                for (const float cy : {kFrame * 0.5f, size - kFrame * 0.5f}) {
                    const float r = std::hypot(px - cx, py - cy);
                    if (r < 5.0f) height = std::max(height, 0.95f + 0.05f * std::sqrt(1.0f - (r * r) / 25.0f));
                }
            }
            m.height.at(x, y) = std::clamp(height, 0.0f, 1.0f);

            // Wood grain: stretched noise along the board direction (diagonal on the brace,
            // horizontal on planks, along the side on the frame).
            float gu = px;
            float gv = py;
            if (brace > 0.5f && frame < 0.5f) {
                gu = (px + py) * 0.7071f;
                gv = (py - px) * 0.7071f;
            } else if (frame > 0.5f && (px < kFrame || px > size - kFrame) && !(py < kFrame || py > size - kFrame)) {
                std::swap(gu, gv); // vertical side rails
            }
            const float rings = fbm(gu * 0.15f, gv * 2.0f, 8, 4, kSeed + 50u);
            const float grain = 0.75f + 0.25f * std::sin(rings * 40.0f);
            const float board = 0.85f + 0.3f * random01(plank, 0, kSeed + 60u);
            Colour wood = raised > 0.5f ? frameWood * grain : plankWood * (grain * board);
            wood = wood * (0.55f + 0.45f * plankFace * (1.0f - raised) + 0.45f * raised);
            wood = wood * (0.8f + 0.2f * frameBevel);
            const bool nail = height > 0.955f;
            m.diffuse.at(x, y) = nail ? Colour{0.30f, 0.30f, 0.32f} : wood;
        }
    }
    return m;
}

// ---------------------------------------------------------------------------------------------
// Derived maps.

// Tangent-space normals from the height field by central differences (wrapping at the borders so
// the map tiles). `depthTexels` is how many texels deep height 0 lies below height 1: the same
// depth the shader's parallax scale gives (scale x texture size), so shading and parallax agree.
Rgb normalsFromHeight(const Grey& h, float depthTexels) {
    Rgb n;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const float dx = (h.at(x + 1, y) - h.at(x - 1, y)) * 0.5f * depthTexels;
            const float dy = (h.at(x, y + 1) - h.at(x, y - 1)) * 0.5f * depthTexels;
            const float len = std::sqrt(dx * dx + dy * dy + 1.0f);
            n.at(x, y) = {(-dx / len) * 0.5f + 0.5f, (-dy / len) * 0.5f + 0.5f, (1.0f / len) * 0.5f + 0.5f};
        }
    }
    return n;
}

Grey depthFromHeight(const Grey& h) {
    Grey d;
    for (std::size_t i = 0; i < d.v.size(); ++i) d.v[i] = 1.0f - h.v[i];
    return d;
}

// ---------------------------------------------------------------------------------------------
// TGA writer: 8-bit grey or 24-bit BGR, bottom-left origin, raw or RLE, with a TGA 2.0 footer.

std::uint8_t toByte(float v) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

void put16(std::vector<std::uint8_t>& out, int v) {
    out.push_back(static_cast<std::uint8_t>(v & 0xff));
    out.push_back(static_cast<std::uint8_t>((v >> 8) & 0xff));
}

// Encodes one scan line of pixels (`bpp` bytes each) as RLE packets; packets never cross lines.
void encodeRleLine(const std::uint8_t* line, int width, int bpp, std::vector<std::uint8_t>& out) {
    auto same = [&](int a, int b) {
        return std::equal(line + a * bpp, line + (a + 1) * bpp, line + b * bpp);
    };
    int i = 0;
    while (i < width) {
        int run = 1;
        while (i + run < width && run < 128 && same(i, i + run)) ++run;
        if (run >= 2) {
            out.push_back(static_cast<std::uint8_t>(0x80 | (run - 1)));
            out.insert(out.end(), line + i * bpp, line + (i + 1) * bpp);
            i += run;
            continue;
        }
        // A raw packet: gather pixels until two equal neighbours start a run (or 128 pixels).
        int count = 1;
        while (i + count < width && count < 128 && !(i + count + 1 < width && same(i + count, i + count + 1)))
            ++count;
        out.push_back(static_cast<std::uint8_t>(count - 1));
        out.insert(out.end(), line + i * bpp, line + (i + count) * bpp);
        i += count;
    }
}

void writeTga(const std::filesystem::path& path, const std::vector<std::uint8_t>& pixels, int bpp, bool rle) {
    std::vector<std::uint8_t> out;
    const int imageType = (bpp == 1 ? 3 : 2) + (rle ? 8 : 0); // 2/3 raw, 10/11 RLE
    out.push_back(0);                                        // no image ID
    out.push_back(0);                                        // no colour map
    out.push_back(static_cast<std::uint8_t>(imageType));
    out.insert(out.end(), 5, 0);                             // colour map specification (unused)
    put16(out, 0);                                           // x origin
    put16(out, 0);                                           // y origin
    put16(out, kSize);
    put16(out, kSize);
    out.push_back(static_cast<std::uint8_t>(bpp * 8));
    out.push_back(0); // descriptor: no alpha bits, bottom-left origin (rows stored bottom first)

    const std::size_t lineBytes = static_cast<std::size_t>(kSize) * bpp;
    for (int y = 0; y < kSize; ++y) {
        const std::uint8_t* line = pixels.data() + static_cast<std::size_t>(y) * lineBytes;
        if (rle)
            encodeRleLine(line, kSize, bpp, out);
        else
            out.insert(out.end(), line, line + lineBytes);
    }
    // TGA 2.0 footer: no extension or developer area.
    out.insert(out.end(), 8, 0);
    const char signature[] = "TRUEVISION-XFILE.";
    out.insert(out.end(), signature, signature + sizeof(signature)); // includes the final NUL

    std::ofstream file(path, std::ios::binary);
    file.write(reinterpret_cast<const char*>(out.data()), static_cast<std::streamsize>(out.size()));
    if (!file) throw std::runtime_error("cannot write " + path.string());
    std::cout << path.string() << ": " << kSize << "x" << kSize << ", " << bpp * 8 << " bpp, type "
              << imageType << ", " << out.size() << " bytes\n";
}

void writeColourTga(const std::filesystem::path& path, const Rgb& image, bool rle) {
    std::vector<std::uint8_t> bytes;
    bytes.reserve(image.v.size() * 3);
    for (const Colour& c : image.v) { // TGA stores blue, green, red
        bytes.push_back(toByte(c.b));
        bytes.push_back(toByte(c.g));
        bytes.push_back(toByte(c.r));
    }
    writeTga(path, bytes, 3, rle);
}

void writeGreyTga(const std::filesystem::path& path, const Grey& image, bool rle) {
    std::vector<std::uint8_t> bytes;
    bytes.reserve(image.v.size());
    for (const float v : image.v) bytes.push_back(toByte(v));
    writeTga(path, bytes, 1, rle);
}

struct Output {
    const char* name;
    MaterialMaps (*make)();
    float depthTexels; // must match the parallax scale in tools/make_scene/make_scene.cpp times kSize
    bool rleDiffuse;
    bool rleDepth;
};

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: make_textures OUT_DIR\n";
        return 2;
    }
    try {
        const std::filesystem::path outDir = argv[1];
        std::filesystem::create_directories(outDir);
        // depthTexels = parallax scale (UV units) x 256: bricks 0.04, tiles 0.02, the crate 0.06.
        const Output outputs[] = {
            {"bricks", makeBricks, 0.04f * kSize, false, true},
            {"tiles", makeTiles, 0.02f * kSize, false, false},
            {"crate", makeCrate, 0.06f * kSize, true, true},
        };
        for (const Output& o : outputs) {
            const MaterialMaps maps = o.make();
            const std::string base = o.name;
            writeColourTga(outDir / (base + "_diffuse.tga"), maps.diffuse, o.rleDiffuse);
            writeColourTga(outDir / (base + "_normal.tga"), normalsFromHeight(maps.height, o.depthTexels), false);
            writeGreyTga(outDir / (base + "_depth.tga"), depthFromHeight(maps.height), o.rleDepth);
        }
    } catch (const std::exception& e) {
        std::cerr << "make_textures: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
