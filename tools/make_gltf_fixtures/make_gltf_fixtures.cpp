// make_gltf_fixtures OUT_DIR          the glTF loader's test fixtures (tests/gltf/)
// make_gltf_fixtures --big N OUT.glb  one mesh of about N triangles (the load-time benchmark)
// make_gltf_fixtures --example OUT.glb the model the site renders (site/assets/models/)
//
// Each feature fixture is a tiny scene built so that one property can be measured in the rendered
// HDR frame (see tests/gltf/test_gltf_render.cpp for what is measured). Every one is written three
// ways: NAME.gltf with NAME.bin and image files beside it, NAME_embedded.gltf with data URIs, and
// NAME.glb with everything in the binary chunk. The malformed files (bad_*.gltf / bad_*.glb) are
// written by hand below, each with exactly one fault.
#include "gltf_builder.hpp"

#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>
#include <stb_image_write.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using t10::gltf::Builder;

void writeBytes(const fs::path& path, const std::vector<unsigned char>& bytes) {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    if (!out) throw std::runtime_error(path.string() + ": cannot write");
}

void writeText(const fs::path& path, const std::string& text) {
    writeBytes(path, std::vector<unsigned char>(text.begin(), text.end()));
}

// --- Images: RGB, given top row first (as an image is seen). ------------------------------------

struct Rgb8 {
    int width, height;
    std::vector<unsigned char> data;
};

void appendBytes(void* context, void* data, int size) {
    auto* out = static_cast<std::vector<unsigned char>*>(context);
    out->insert(out->end(), static_cast<unsigned char*>(data), static_cast<unsigned char*>(data) + size);
}

std::vector<unsigned char> png(const Rgb8& image) {
    std::vector<unsigned char> out;
    stbi_write_png_to_func(&appendBytes, &out, image.width, image.height, 3, image.data.data(), image.width * 3);
    return out;
}

std::vector<unsigned char> jpeg(const Rgb8& image) {
    std::vector<unsigned char> out;
    stbi_write_jpg_to_func(&appendBytes, &out, image.width, image.height, 3, image.data.data(), 95);
    return out;
}

// Uncompressed true-colour TGA (type 2), bottom-left origin: rows bottom first, BGR.
std::vector<unsigned char> tga(const Rgb8& image) {
    std::vector<unsigned char> out(18, 0);
    out[2] = 2;
    out[12] = static_cast<unsigned char>(image.width & 255);
    out[13] = static_cast<unsigned char>(image.width >> 8);
    out[14] = static_cast<unsigned char>(image.height & 255);
    out[15] = static_cast<unsigned char>(image.height >> 8);
    out[16] = 24;
    for (int y = image.height - 1; y >= 0; --y)
        for (int x = 0; x < image.width; ++x) {
            const unsigned char* p = &image.data[static_cast<std::size_t>((y * image.width + x) * 3)];
            out.insert(out.end(), {p[2], p[1], p[0]});
        }
    return out;
}

// Top half one colour, bottom half another: shows whether v runs the right way.
Rgb8 halves(unsigned char topR, unsigned char topG, unsigned char topB, unsigned char botR, unsigned char botG,
            unsigned char botB) {
    Rgb8 image{8, 8, {}};
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            if (y < 4) image.data.insert(image.data.end(), {topR, topG, topB});
            else image.data.insert(image.data.end(), {botR, botG, botB});
        }
    return image;
}

// --- Geometry. -------------------------------------------------------------------------------------

// A unit square in the XY plane facing +Z, centred on the origin, UV (0,0) at the top left.
struct Square {
    std::vector<glm::vec3> positions{{-0.5f, 0.5f, 0}, {-0.5f, -0.5f, 0}, {0.5f, -0.5f, 0}, {0.5f, 0.5f, 0}};
    std::vector<glm::vec3> normals{4, glm::vec3(0, 0, 1)};
    std::vector<glm::vec2> uvs{{0, 0}, {0, 1}, {1, 1}, {1, 0}};
};

// A cube of edge 1 centred on the origin, 24 vertices, outward normals, counter-clockwise.
tinygltf::Primitive cube(Builder& b, int material) {
    std::vector<glm::vec3> p, n;
    std::vector<std::uint32_t> idx;
    const glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int a = 0; a < 3; ++a)
        for (const float s : {1.0f, -1.0f}) {
            const glm::vec3 normal = axes[a] * s;
            const glm::vec3 u = axes[(a + 1) % 3] * s;
            const glm::vec3 v = glm::cross(normal, u);
            const auto base = static_cast<std::uint32_t>(p.size());
            for (const glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
                p.push_back(0.5f * (normal + c.x * u + c.y * v));
                n.push_back(normal);
            }
            for (const std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) idx.push_back(base + i);
        }
    tinygltf::Primitive prim;
    prim.material = material;
    prim.attributes["POSITION"] = b.floats(p, true);
    prim.attributes["NORMAL"] = b.floats(n);
    prim.indices = b.indices(idx, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
    return prim;
}

tinygltf::Material emissive(const std::string& name, glm::vec3 colour, float strength, Builder& b) {
    tinygltf::Material m;
    m.name = name;
    m.pbrMetallicRoughness.baseColorFactor = {0, 0, 0, 1};
    m.emissiveFactor = {colour.r, colour.g, colour.b};
    if (strength != 1.0f) {
        b.use("KHR_materials_emissive_strength");
        tinygltf::Value::Object ext;
        ext["emissiveStrength"] = tinygltf::Value(double(strength));
        m.extensions["KHR_materials_emissive_strength"] = tinygltf::Value(ext);
    }
    return m;
}

tinygltf::Material matte(const std::string& name, glm::vec3 colour) {
    tinygltf::Material m;
    m.name = name;
    m.pbrMetallicRoughness.baseColorFactor = {colour.r, colour.g, colour.b, 1};
    m.pbrMetallicRoughness.metallicFactor = 0;
    m.pbrMetallicRoughness.roughnessFactor = 1;
    return m;
}

tinygltf::Node at(const std::string& name, glm::vec3 t) {
    tinygltf::Node n;
    n.name = name;
    n.translation = {t.x, t.y, t.z};
    return n;
}

// A camera at `eye` looking at `target` (+Y up), vertical field of view in degrees.
void camera(Builder& b, const std::string& name, glm::vec3 eye, glm::vec3 target, float fovDegrees) {
    tinygltf::Camera c;
    c.name = name;
    c.type = "perspective";
    c.perspective.yfov = glm::radians(fovDegrees);
    c.perspective.znear = 0.1;
    c.perspective.zfar = 100;
    b.model.cameras.push_back(c);
    const glm::vec3 f = glm::normalize(target - eye);
    const float yaw = std::atan2(f.x, -f.z);
    const float pitch = std::asin(f.y);
    const glm::quat q = glm::angleAxis(-yaw, glm::vec3(0, 1, 0)) * glm::angleAxis(pitch, glm::vec3(1, 0, 0));
    tinygltf::Node n = at("camera " + name, eye);
    n.rotation = {q.x, q.y, q.z, q.w};
    n.camera = static_cast<int>(b.model.cameras.size() - 1);
    b.node(n);
}

// --- Output in three forms. ------------------------------------------------------------------------

// `images` are (name, bytes, mime): files beside NAME.gltf, data URIs in NAME_embedded.gltf, buffer
// views in NAME.glb. `build` makes the scene given the image indices.
using ImageList = std::vector<std::tuple<std::string, std::vector<unsigned char>, std::string>>;

template <typename Build>
void writeThreeWays(const fs::path& dir, const std::string& name, const ImageList& images, Build build) {
    for (int form = 0; form < 3; ++form) {
        Builder b;
        std::vector<int> imageIndices;
        for (const auto& [file, bytes, mime] : images) {
            if (form == 0) {
                writeBytes(dir / file, bytes);
                imageIndices.push_back(b.imageUri(file));
            } else if (form == 1 && mime == "image/x-tga") {
                // tinygltf reads data URIs of PNG, JPEG and octet-stream only: TGA stays a file.
                writeBytes(dir / file, bytes);
                imageIndices.push_back(b.imageUri(file));
            } else {
                imageIndices.push_back(b.imageEmbedded(bytes, mime, form == 1));
            }
        }
        build(b, imageIndices);
        if (form == 0) b.write((dir / (name + ".gltf")).string(), false, name + ".bin");
        if (form == 1) b.write((dir / (name + "_embedded.gltf")).string(), false, "");
        if (form == 2) b.write((dir / (name + ".glb")).string(), true, "");
    }
}

// Three cubes, emissive strength 1, 4 and 16 from left to right, seen by camera "front".
void emissiveCubes(const fs::path& dir) {
    writeThreeWays(dir, "emissive_cubes", {}, [](Builder& b, const std::vector<int>&) {
        camera(b, "front", {0, 0, 6}, {0, 0, 0}, 40);
        const float strengths[] = {1.0f, 4.0f, 16.0f};
        for (int i = 0; i < 3; ++i) {
            const int m = b.material(emissive("strength " + std::to_string(int(strengths[i])), {1, 0.5f, 0.25f},
                                              strengths[i], b));
            tinygltf::Node n = at("cube " + std::to_string(i), {-1.5f + 1.5f * float(i), 0, 0});
            n.mesh = b.mesh("cube", {cube(b, m)});
            b.node(n);
        }
    });
}

// A grey floor 10 x 10 m at y = 0, one point light 1 m above (1.5, 0, -1) and one spot light
// pointing straight down at (-2, 0, 1) with a 20-30 degree cone; camera "top" looks down on them
// from above the front edge (not straight down, where yaw is undefined).
void lights(const fs::path& dir) {
    writeThreeWays(dir, "lights", {}, [](Builder& b, const std::vector<int>&) {
        camera(b, "top", {0, 7, 4}, {0, 0, 0}, 70);
        const int grey = b.material(matte("floor", {0.5f, 0.5f, 0.5f}));
        Square s;
        std::vector<glm::vec3> p;
        for (const glm::vec3& v : s.positions) p.push_back(glm::vec3(v.x, 0, -v.y) * 10.0f);
        tinygltf::Primitive prim;
        prim.material = grey;
        prim.attributes["POSITION"] = b.floats(p, true);
        prim.attributes["NORMAL"] = b.floats(std::vector<glm::vec3>(4, glm::vec3(0, 1, 0)));
        prim.indices = b.indices({0, 1, 2, 0, 2, 3}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE);
        tinygltf::Node floor;
        floor.name = "floor";
        floor.mesh = b.mesh("floor", {prim});
        b.node(floor);
        tinygltf::Light point;
        point.type = "point";
        point.color = {1, 1, 1};
        point.intensity = 2;
        b.light(b.node(at("point", {1.5f, 1, -1})), point);
        tinygltf::Light spot;
        spot.type = "spot";
        spot.color = {1, 1, 1};
        spot.intensity = 8;
        spot.spot.innerConeAngle = glm::radians(20.0);
        spot.spot.outerConeAngle = glm::radians(30.0);
        tinygltf::Node n = at("spot", {-2, 2, 1});
        // Local -Z turned to point down (-Y): a quarter turn about +X.
        const glm::quat q = glm::angleAxis(glm::radians(-90.0f), glm::vec3(1, 0, 0));
        n.rotation = {q.x, q.y, q.z, q.w};
        b.light(b.node(n), spot);
    });
}

// One emissive cube at (1, 0.5, -2) and two cameras that see it from different places: "left"
// (from x = -4) and "high" (from above). Also the framing camera the loader adds.
void cameras(const fs::path& dir) {
    writeThreeWays(dir, "cameras", {}, [](Builder& b, const std::vector<int>&) {
        camera(b, "left", {-4, 0.5f, 1}, {0, 0.5f, -1}, 50);
        camera(b, "high", {1, 6, 0}, {1, 0.5f, -2}, 50);
        const int m = b.material(emissive("white", {1, 1, 1}, 8, b));
        tinygltf::Node n = at("cube", {1, 0.5f, -2});
        n.mesh = b.mesh("cube", {cube(b, m)});
        b.node(n);
    });
}

// Nine emissive squares in a 3 x 3 grid (x -2, 0, 2; y 2, 0, -2), each encoded another way and
// placed by another kind of transform; all must look the same (emission 2.0 in green).
void geometry(const fs::path& dir) {
    writeThreeWays(dir, "geometry", {}, [](Builder& b, const std::vector<int>&) {
        camera(b, "front", {0, 0, 9}, {0, 0, 0}, 45);
        const int m = b.material(emissive("green", {0, 1, 0}, 2, b));
        const Square s;
        auto indexed = [&](std::vector<std::uint32_t> indices, int type, int mode) {
            tinygltf::Primitive p;
            p.material = m;
            p.mode = mode;
            p.attributes["POSITION"] = b.floats(s.positions, true);
            p.attributes["NORMAL"] = b.floats(s.normals);
            if (!indices.empty()) p.indices = b.indices(indices, type);
            return p;
        };
        std::vector<tinygltf::Primitive> prims;
        prims.push_back(indexed({0, 1, 2, 0, 2, 3}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_MODE_TRIANGLES));
        prims.push_back(indexed({0, 1, 2, 0, 2, 3}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_MODE_TRIANGLES));
        prims.push_back(indexed({0, 1, 2, 0, 2, 3}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_MODE_TRIANGLES));
        // Strip 1 0 2 3 -> (1,0,2) and (2,0,3)... with glTF's winding rule: (v0,v1,v2), (v2,v1,v3).
        prims.push_back(indexed({0, 1, 3, 2}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_MODE_TRIANGLE_STRIP));
        prims.push_back(indexed({0, 1, 2, 3}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_MODE_TRIANGLE_FAN));
        {
            // Not indexed: six vertices.
            tinygltf::Primitive p;
            p.material = m;
            std::vector<glm::vec3> pos, nrm;
            for (const int i : {0, 1, 2, 0, 2, 3}) {
                pos.push_back(s.positions[static_cast<std::size_t>(i)]);
                nrm.push_back(s.normals[static_cast<std::size_t>(i)]);
            }
            p.attributes["POSITION"] = b.floats(pos, true);
            p.attributes["NORMAL"] = b.floats(nrm);
            prims.push_back(p);
        }
        {
            // Interleaved position + normal + uv in one strided view (32 bytes per vertex).
            std::vector<float> data;
            for (std::size_t i = 0; i < 4; ++i) {
                data.insert(data.end(), {s.positions[i].x, s.positions[i].y, s.positions[i].z, s.normals[i].x,
                                         s.normals[i].y, s.normals[i].z, s.uvs[i].x, s.uvs[i].y});
            }
            const int view = b.view(data.data(), data.size() * 4, TINYGLTF_TARGET_ARRAY_BUFFER, 32);
            tinygltf::Primitive p;
            p.material = m;
            p.attributes["POSITION"] = b.accessor(view, 0, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, 4);
            b.model.accessors.back().minValues = {-0.5, -0.5, 0};
            b.model.accessors.back().maxValues = {0.5, 0.5, 0};
            p.attributes["NORMAL"] = b.accessor(view, 12, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, 4);
            p.attributes["TEXCOORD_0"] = b.accessor(view, 24, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, 4);
            p.indices = b.indices({0, 1, 2, 0, 2, 3}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE);
            prims.push_back(p);
        }
        {
            // Strided but not interleaved: positions every 20 bytes, with padding; no normals
            // (the loader makes flat ones).
            std::vector<float> data;
            for (std::size_t i = 0; i < 4; ++i)
                data.insert(data.end(), {s.positions[i].x, s.positions[i].y, s.positions[i].z, -1.0f, -1.0f});
            const int view = b.view(data.data(), data.size() * 4, TINYGLTF_TARGET_ARRAY_BUFFER, 20);
            tinygltf::Primitive p;
            p.material = m;
            p.attributes["POSITION"] = b.accessor(view, 0, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, 4);
            b.model.accessors.back().minValues = {-0.5, -0.5, 0};
            b.model.accessors.back().maxValues = {0.5, 0.5, 0};
            p.indices = b.indices({0, 1, 2, 0, 2, 3}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
            prims.push_back(p);
        }
        // The ninth: two primitives in one mesh (the two triangles, separately).
        tinygltf::Primitive first = indexed({0, 1, 2}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_MODE_TRIANGLES);
        tinygltf::Primitive second = indexed({0, 2, 3}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_MODE_TRIANGLES);

        // Placement: row by row, left to right.
        const glm::vec3 centres[9] = {{-2, 2, 0}, {0, 2, 0}, {2, 2, 0}, {-2, 0, 0}, {0, 0, 0},
                                      {2, 0, 0},  {-2, -2, 0}, {0, -2, 0}, {2, -2, 0}};
        for (int i = 0; i < 9; ++i) {
            const int mesh = i < 8 ? b.mesh("square " + std::to_string(i), {prims[static_cast<std::size_t>(i)]})
                                   : b.mesh("two primitives", {first, second});
            const glm::vec3 c = centres[i];
            if (i % 3 == 0) {
                // A matrix (column-major): translation in the last column.
                tinygltf::Node n;
                n.name = "matrix " + std::to_string(i);
                n.matrix = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, c.x, c.y, c.z, 1};
                n.mesh = mesh;
                b.node(n);
            } else if (i % 3 == 1) {
                // TRS: a half turn about Z (the square is symmetric) and scale 1.
                tinygltf::Node n = at("trs " + std::to_string(i), c);
                const glm::quat q = glm::angleAxis(glm::radians(180.0f), glm::vec3(0, 0, 1));
                n.rotation = {q.x, q.y, q.z, q.w};
                n.scale = {1, 1, 1};
                n.mesh = mesh;
                b.node(n);
            } else {
                // Nested: a parent scaled by 2 and moved, the child scaled by 0.5.
                tinygltf::Node child;
                child.name = "child " + std::to_string(i);
                child.scale = {0.5, 0.5, 0.5};
                child.mesh = mesh;
                b.model.nodes.push_back(child);
                tinygltf::Node parent = at("parent " + std::to_string(i), c);
                parent.scale = {2, 2, 2};
                parent.children = {static_cast<int>(b.model.nodes.size() - 1)};
                b.node(parent);
            }
        }
    });
}

// Three squares with emissive textures, PNG, JPEG and TGA from left to right: each image's top
// half is red and bottom half green (sRGB 188 = linear 0.5), sampled NEAREST and clamped.
void textures(const fs::path& dir) {
    const Rgb8 image = halves(188, 0, 0, 0, 188, 0);
    const ImageList images{{"halves.png", png(image), "image/png"},
                           {"halves.jpg", jpeg(image), "image/jpeg"},
                           {"halves.tga", tga(image), "image/x-tga"}};
    writeThreeWays(dir, "textures", images, [](Builder& b, const std::vector<int>& imageIndices) {
        camera(b, "front", {0, 0, 5}, {0, 0, 0}, 45);
        const int sampler = b.sampler(9728, 9728, 33071, 33071); // NEAREST, NEAREST, CLAMP, CLAMP
        const Square s;
        for (int i = 0; i < 3; ++i) {
            tinygltf::Material m = emissive("texture " + std::to_string(i), {1, 1, 1}, 4, b);
            m.emissiveTexture.index = b.texture(imageIndices[static_cast<std::size_t>(i)], sampler);
            const int material = b.material(m);
            tinygltf::Primitive p;
            p.material = material;
            p.attributes["POSITION"] = b.floats(s.positions, true);
            p.attributes["NORMAL"] = b.floats(s.normals);
            p.attributes["TEXCOORD_0"] = b.floats(s.uvs);
            p.indices = b.indices({0, 1, 2, 0, 2, 3}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
            tinygltf::Node n = at("square " + std::to_string(i), {-1.5f + 1.5f * float(i), 0, 0});
            n.mesh = b.mesh("square", {p});
            b.node(n);
        }
    });
}

// Double-sided and alpha modes over a blue emissive backdrop (z = -2), seen by camera "front":
// left, a double-sided green square turned away from the camera (drawn); middle, the same but
// single-sided (culled: backdrop); right, a MASK square with alpha 0.3 < cutoff 0.5 (discarded:
// backdrop); top, a BLEND square, red emission 2 at alpha 0.5 (half red, half backdrop).
void materials(const fs::path& dir) {
    writeThreeWays(dir, "materials", {}, [](Builder& b, const std::vector<int>&) {
        camera(b, "front", {0, 0, 6}, {0, 0, 0}, 45);
        const Square s;
        auto square = [&](const std::string& name, const tinygltf::Material& m, glm::vec3 at_, float scale, bool away) {
            const int material = b.material(m);
            tinygltf::Primitive p;
            p.material = material;
            p.attributes["POSITION"] = b.floats(s.positions, true);
            p.attributes["NORMAL"] = b.floats(s.normals);
            p.indices = b.indices({0, 1, 2, 0, 2, 3}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE);
            tinygltf::Node n = at(name, at_);
            n.scale = {scale, scale, scale};
            if (away) n.rotation = {0, 1, 0, 0}; // half a turn about +Y: the front faces -Z
            n.mesh = b.mesh(name, {p});
            b.node(n);
        };
        square("backdrop", emissive("blue", {0, 0, 1}, 1, b), {0, 0, -2}, 20, false);
        tinygltf::Material twoSided = emissive("green", {0, 1, 0}, 2, b);
        twoSided.doubleSided = true;
        square("double-sided", twoSided, {-1.5f, 0, 0}, 1, true);
        square("single-sided", emissive("red", {1, 0, 0}, 2, b), {0, 0, 0}, 1, true);
        tinygltf::Material mask = emissive("masked", {1, 0, 0}, 2, b);
        mask.alphaMode = "MASK";
        mask.alphaCutoff = 0.5;
        mask.pbrMetallicRoughness.baseColorFactor = {0, 0, 0, 0.3};
        square("mask", mask, {1.5f, 0, 0}, 1, false);
        tinygltf::Material blend = emissive("blended", {1, 0, 0}, 2, b);
        blend.alphaMode = "BLEND";
        blend.pbrMetallicRoughness.baseColorFactor = {0, 0, 0, 0.5};
        square("blend", blend, {0, 1.5f, 0}, 1, false);
    });
}

// Things drawn at rest or skipped with a warning: points, lines, a morph target, a skin, an
// orthographic camera, a directional light; plus one emissive square that must still render.
void warnings(const fs::path& dir) {
    writeThreeWays(dir, "warnings", {}, [](Builder& b, const std::vector<int>&) {
        camera(b, "front", {0, 0, 4}, {0, 0, 0}, 45);
        const int m = b.material(emissive("white", {1, 1, 1}, 2, b));
        const Square s;
        tinygltf::Primitive square;
        square.material = m;
        square.attributes["POSITION"] = b.floats(s.positions, true);
        square.indices = b.indices({0, 1, 2, 0, 2, 3}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
        tinygltf::Primitive morph = square;
        morph.targets.push_back({{"POSITION", b.floats(std::vector<glm::vec3>(4, glm::vec3(0, 0, 1)))}});
        tinygltf::Primitive points = square;
        points.mode = TINYGLTF_MODE_POINTS;
        points.indices = -1;
        tinygltf::Primitive lines = square;
        lines.mode = TINYGLTF_MODE_LINE_STRIP;
        tinygltf::Node n;
        n.name = "square";
        n.mesh = b.mesh("square with extras", {morph, points, lines});
        n.skin = 0;
        b.node(n);
        tinygltf::Skin skin;
        skin.joints = {static_cast<int>(b.model.nodes.size() - 1)};
        b.model.skins.push_back(skin);
        tinygltf::Camera ortho;
        ortho.type = "orthographic";
        ortho.orthographic.xmag = 1;
        ortho.orthographic.ymag = 1;
        ortho.orthographic.znear = 0.1;
        ortho.orthographic.zfar = 10;
        b.model.cameras.push_back(ortho);
        tinygltf::Node on;
        on.camera = static_cast<int>(b.model.cameras.size() - 1);
        b.node(on);
        tinygltf::Light sun;
        sun.type = "directional";
        b.light(b.node(at("sun", {0, 5, 0})), sun);
        b.use("EXT_unknown_but_optional");
    });
}

// --- Malformed files, one fault each (the tests name the message they expect). ------------------

const char* kTriangleHeader = R"("asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],)";

// A triangle whose buffer is a data URI of `bytes`; `extra` is spliced into the JSON.
std::string triangleJson(const std::vector<unsigned char>& bytes, const std::string& accessors,
                         const std::string& nodes = R"("nodes": [{"mesh": 0}],)", const std::string& mode = "") {
    return std::string("{") + kTriangleHeader + nodes +
           R"("meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1)" + mode + R"(}]}],)" +
           R"("buffers": [{"byteLength": )" + std::to_string(bytes.size()) +
           R"(, "uri": "data:application/octet-stream;base64,)" + Builder::base64(bytes) + R"("}],)" + accessors + "}";
}

std::vector<unsigned char> triangleBytes(float badValue = 0.0f, std::uint16_t lastIndex = 2) {
    const float p[9] = {0, 0, 0, 1, 0, 0, 0, 1, badValue};
    const std::uint16_t idx[3] = {0, 1, lastIndex};
    std::vector<unsigned char> bytes(reinterpret_cast<const unsigned char*>(p), reinterpret_cast<const unsigned char*>(p) + 36);
    bytes.insert(bytes.end(), reinterpret_cast<const unsigned char*>(idx), reinterpret_cast<const unsigned char*>(idx) + 6);
    bytes.insert(bytes.end(), {0, 0});
    return bytes;
}

const char* kTriangleViews = R"("bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                                               {"buffer": 0, "byteOffset": 36, "byteLength": 6}],)";
const char* kTriangleAccessors =
    R"("accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0,0,0], "max": [1,1,0]},
                     {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}])";

void malformed(const fs::path& dir) {
    const auto ok = triangleBytes();
    // A valid one for contrast: the tests render it (exit 0) before trusting the others' failures.
    writeText(dir / "good_triangle.gltf", triangleJson(ok, std::string(kTriangleViews) + kTriangleAccessors));
    writeText(dir / "bad_json.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [ {");
    writeText(dir / "bad_wrong_type.gltf",
              triangleJson(ok, std::string(kTriangleViews) +
                                   R"("accessors": [{"bufferView": 0, "componentType": 5126, "count": "three", "type": "VEC3"},
                                        {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}])"));
    // GLB: right magic, wrong total length.
    {
        std::vector<unsigned char> glb = {'g', 'l', 'T', 'F', 2, 0, 0, 0, 0xff, 0xff, 0, 0, 20, 0, 0, 0, 'J', 'S', 'O', 'N'};
        writeBytes(dir / "bad_header.glb", glb);
    }
    writeText(dir / "bad_missing_buffer.gltf",
              std::string("{") + kTriangleHeader + R"("nodes": [{"mesh": 0}], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
                 "buffers": [{"byteLength": 36, "uri": "no_such_file.bin"}],
                 "bufferViews": [{"buffer": 0, "byteLength": 36}],
                 "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}]})");
    writeBytes(dir / "short.bin", std::vector<unsigned char>(20, 0));
    writeText(dir / "bad_short_buffer.gltf",
              std::string("{") + kTriangleHeader + R"("nodes": [{"mesh": 0}], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
                 "buffers": [{"byteLength": 36, "uri": "short.bin"}],
                 "bufferViews": [{"buffer": 0, "byteLength": 36}],
                 "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}]})");
    const std::string texturedMaterial =
        R"("materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}], "textures": [{"source": 0}],)";
    writeText(dir / "bad_missing_image.gltf",
              triangleJson(ok, texturedMaterial + R"("images": [{"uri": "no_such_image.png"}],)" + kTriangleViews +
                                   kTriangleAccessors));
    {
        std::vector<unsigned char> truncated = png(halves(1, 2, 3, 4, 5, 6));
        truncated.resize(truncated.size() / 2);
        writeBytes(dir / "truncated.png", truncated);
        writeText(dir / "bad_truncated_image.gltf",
                  triangleJson(ok, texturedMaterial + R"("images": [{"uri": "truncated.png"}],)" + kTriangleViews +
                                       kTriangleAccessors));
    }
    writeText(dir / "bad_accessor_range.gltf",
              triangleJson(ok, std::string(kTriangleViews) +
                                   R"("accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3"},
                                        {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}])"));
    writeText(dir / "bad_view_range.gltf",
              triangleJson(ok, std::string(R"("bufferViews": [{"buffer": 0, "byteOffset": 8, "byteLength": 40},
                                               {"buffer": 0, "byteOffset": 36, "byteLength": 6}],)") +
                                   kTriangleAccessors));
    writeText(dir / "bad_index.gltf",
              triangleJson(triangleBytes(0.0f, 7), std::string(kTriangleViews) + kTriangleAccessors));
    writeText(dir / "bad_nan.gltf", triangleJson(triangleBytes(std::numeric_limits<float>::quiet_NaN()),
                                                 std::string(kTriangleViews) + kTriangleAccessors));
    writeText(dir / "bad_inf.gltf", triangleJson(triangleBytes(std::numeric_limits<float>::infinity()),
                                                 std::string(kTriangleViews) + kTriangleAccessors));
    writeText(dir / "bad_cycle.gltf",
              triangleJson(ok, std::string(kTriangleViews) + kTriangleAccessors,
                           R"("nodes": [{"mesh": 0, "children": [1]}, {"children": [2]}, {"children": [1]}],)"));
    writeText(dir / "bad_cycle_root.gltf",
              triangleJson(ok, std::string(kTriangleViews) + kTriangleAccessors,
                           R"("nodes": [{"mesh": 0, "children": [1]}, {"children": [0]}],)"));
    {
        // No scene at all: the roots are the nodes without a parent, and a cycle has none.
        std::string json = triangleJson(ok, std::string(kTriangleViews) + kTriangleAccessors,
                                        R"("nodes": [{"mesh": 0}, {"children": [2]}, {"children": [1]}],)");
        const std::string scenes = R"("scene": 0, "scenes": [{"nodes": [0]}],)";
        json.erase(json.find(scenes), scenes.size());
        writeText(dir / "bad_cycle_sceneless.gltf", json);
    }
    writeText(dir / "bad_required_draco.gltf",
              triangleJson(ok, std::string(R"("extensionsUsed": ["KHR_draco_mesh_compression"],
                                              "extensionsRequired": ["KHR_draco_mesh_compression"],)") +
                                   kTriangleViews + kTriangleAccessors));
    // A chain of 100000 nodes: deep, but legal; loading it must not overflow the stack.
    {
        std::string nodes = R"("nodes": [)";
        const int depth = 100000;
        for (int i = 0; i < depth; ++i)
            nodes += i + 1 < depth ? "{\"children\": [" + std::to_string(i + 1) + "]}," : std::string("{\"mesh\": 0}");
        nodes += "],";
        writeText(dir / "deep_chain.gltf", triangleJson(ok, std::string(kTriangleViews) + kTriangleAccessors, nodes));
    }
}

// Wrongly typed or out-of-range properties, one per file: schema_base.gltf is a triangle that uses
// every kind of property the loader reads (material with textures and extensions, sampler, image,
// camera, light), and each schema_<case>.gltf changes one value of it (a JSON pointer and the new
// value; null removes it). tests/gltf/ names the JSON path each must be refused with. The first five
// are the kinds of tinygltf's own wrongTypes set (written here, not copied).
void schema(const fs::path& dir) {
    using Json = nlohmann::json;
    const auto bytes = triangleBytes();
    const std::vector<unsigned char> image = png(halves(128, 128, 255, 128, 128, 255));
    const Json base = {
        {"asset", {{"version", "2.0"}}},
        {"extensionsUsed", {"KHR_lights_punctual", "KHR_materials_emissive_strength"}},
        {"scene", 0},
        {"scenes", {{{"nodes", {0, 1, 2}}}}},
        {"nodes",
         {{{"name", "triangle"}, {"mesh", 0}, {"scale", {1, 1, 1}}},
          {{"camera", 0}, {"translation", {0.5, 0.5, 3}}, {"rotation", {0, 0, 0, 1}}},
          {{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}, {"translation", {0, 2, 2}}}}},
        {"meshes", {{{"name", "triangle"}, {"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1},
                                                             {"material", 0}, {"mode", 4}}}}}}},
        {"materials",
         {{{"name", "textured"},
           {"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1, 1}}, {"metallicFactor", 0}, {"roughnessFactor", 0.5}}},
           {"normalTexture", {{"index", 0}, {"scale", 1}}},
           {"emissiveFactor", {1, 1, 1}},
           {"alphaMode", "OPAQUE"},
           {"doubleSided", false},
           {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 2}}}}}}}},
        {"textures", {{{"source", 0}, {"sampler", 0}}}},
        {"samplers", {{{"magFilter", 9729}, {"minFilter", 9987}, {"wrapS", 10497}, {"wrapT", 10497}}}},
        {"images", {{{"uri", "data:image/png;base64," + Builder::base64(image)}}}},
        {"cameras", {{{"name", "front"}, {"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}}}}}},
        {"extensions", {{"KHR_lights_punctual", {{"lights", {{{"type", "point"}, {"intensity", 5}}}}}}}},
        {"buffers", {{{"byteLength", bytes.size()}, {"uri", "data:application/octet-stream;base64," + Builder::base64(bytes)}}}},
        {"bufferViews", {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 36}}, {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 6}}}},
        {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}},
                       {{"bufferView", 1}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}}}},
    };
    writeText(dir / "schema_base.gltf", base.dump(1));
    struct Change {
        const char* name;
        const char* pointer;
        Json value;
    };
    const Change changes[] = {
        // tinygltf's wrongTypes kinds
        {"normal_scale_string", "/materials/0/normalTexture/scale", "not a number"},
        {"mesh_name_number", "/meshes/0/name", 1},
        {"pbr_not_object", "/materials/0/pbrMetallicRoughness", "shiny"},
        {"texture_index_negative", "/materials/0/normalTexture/index", -1},
        {"primitives_object", "/meshes/0/primitives", {{"attributes", {{"POSITION", 0}}}}},
        // one per other kind the loader reads
        {"index_out_of_range", "/meshes/0/primitives/0/material", 5},
        {"integer_fraction", "/accessors/0/byteOffset", 1.5},
        {"integer_below_minimum", "/accessors/0/count", 0},
        {"array_object", "/nodes", Json::object()},
        {"array_length", "/nodes/0/translation", {1, 2}},
        {"number_string", "/nodes/0/scale/1", "2"},
        {"number_range", "/materials/0/pbrMetallicRoughness/metallicFactor", 2},
        {"number_exclusive", "/cameras/0/perspective/yfov", 0},
        {"enum_integer", "/meshes/0/primitives/0/mode", 7},
        {"enum_string", "/materials/0/alphaMode", "opaque"},
        {"enum_sampler", "/samplers/0/wrapS", 1},
        {"boolean_string", "/materials/0/doubleSided", "yes"},
        {"string_number", "/images/0/uri", 5},
        {"object_array", "/materials/0/normalTexture", {0}},
        {"required_missing", "/accessors/0/componentType", nullptr},
        {"extension_number", "/materials/0/extensions/KHR_materials_emissive_strength/emissiveStrength", "2"},
        {"light_index", "/nodes/2/extensions/KHR_lights_punctual/light", 3},
        {"light_type", "/extensions/KHR_lights_punctual/lights/0/type", "area"},
        {"texture_info_index", "/textures/0/source", 4},
        {"scene_index", "/scene", 1},
        {"scene_name_number", "/scenes/0/name", 1},
        {"children_index", "/nodes/0/children", {-1}},
    };
    for (const Change& c : changes) {
        Json json = base;
        const Json::json_pointer pointer(c.pointer);
        if (c.value.is_null()) json[pointer.parent_pointer()].erase(pointer.back());
        else json[pointer] = c.value;
        writeText(dir / (std::string("schema_") + c.name + ".gltf"), json.dump(1));
    }
    // The same check on a GLB's JSON chunk: primitives as an object.
    Json json = base;
    json["meshes"][0]["primitives"] = json["meshes"][0]["primitives"][0];
    std::string text = json.dump();
    while (text.size() % 4 != 0) text += ' ';
    std::vector<unsigned char> glb = {'g', 'l', 'T', 'F', 2, 0, 0, 0};
    auto u32 = [&](std::size_t v) {
        for (int i = 0; i < 4; ++i) glb.push_back(static_cast<unsigned char>(v >> (8 * i)));
    };
    u32(20 + text.size());
    u32(text.size());
    glb.insert(glb.end(), {'J', 'S', 'O', 'N'});
    glb.insert(glb.end(), text.begin(), text.end());
    writeBytes(dir / "schema_primitives_object.glb", glb);
}

// Scenes that draw nothing, refused with the reason: only points; no meshes at all; every
// primitive skipped (a triangle list of two indices).
void nothingToDraw(const fs::path& dir) {
    const auto ok = triangleBytes();
    writeText(dir / "nothing_points.gltf",
              triangleJson(ok, std::string(kTriangleViews) + kTriangleAccessors, R"("nodes": [{"mesh": 0}],)",
                           R"(, "mode": 0)"));
    writeText(dir / "nothing_no_meshes.gltf", std::string("{") + kTriangleHeader + R"("nodes": [{"name": "empty"}]})");
    writeText(dir / "nothing_skipped.gltf",
              triangleJson(ok, std::string(kTriangleViews) +
                                   R"("accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                                        {"bufferView": 1, "componentType": 5123, "count": 2, "type": "SCALAR"}])"));
}

// A unit cube, emissive, centred on the origin, on nothing: the framing camera and the
// black-background exposure warning are measured on it.
void unitCube(const fs::path& dir) {
    writeThreeWays(dir, "unit_cube", {}, [](Builder& b, const std::vector<int>&) {
        const int m = b.material(emissive("glow", {1, 0.5f, 0.25f}, 4, b));
        tinygltf::Node n;
        n.name = "cube";
        n.mesh = b.mesh("cube", {cube(b, m)});
        b.node(n);
    });
}

// The example the site shows (site/assets/models/bloom_example.glb): a dim grey corner (floor and
// back wall) lit by one point light, with three emissive cubes of strength 2, 8 and 32 on the
// floor; camera "front". The backdrop gives the tone map's key something to adapt to, so that
// only the bright cubes burn out and bloom.
void example(const std::string& path) {
    Builder b;
    camera(b, "front", {0, 1.8f, 6.5f}, {0, 0.7f, 0}, 45);
    const int grey = b.material(matte("backdrop", {0.45f, 0.42f, 0.4f}));
    auto quad = [&](const std::string& name, glm::vec3 origin, glm::vec3 u, glm::vec3 v) {
        const glm::vec3 n = glm::normalize(glm::cross(u, v));
        tinygltf::Primitive p;
        p.material = grey;
        p.attributes["POSITION"] = b.floats(std::vector<glm::vec3>{origin, origin + u, origin + u + v, origin + v}, true);
        p.attributes["NORMAL"] = b.floats(std::vector<glm::vec3>(4, n));
        p.indices = b.indices({0, 1, 2, 0, 2, 3}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE);
        tinygltf::Node node;
        node.name = name;
        node.mesh = b.mesh(name, {p});
        b.node(node);
    };
    quad("floor", {-6, 0, 4}, {12, 0, 0}, {0, 0, -7});
    quad("wall", {-6, 0, -3}, {12, 0, 0}, {0, 6, 0});
    const glm::vec3 colours[3] = {{1.0f, 0.45f, 0.15f}, {0.25f, 0.55f, 1.0f}, {1.0f, 0.95f, 0.85f}};
    const float strengths[3] = {2, 8, 32};
    for (int i = 0; i < 3; ++i) {
        const int m = b.material(emissive("glow " + std::to_string(int(strengths[i])), colours[i], strengths[i], b));
        tinygltf::Node n = at("cube " + std::to_string(i), {-2.0f + 2.0f * float(i), 0.5f, 0});
        n.rotation = {0, 0.2588190451, 0, 0.9659258263}; // 30 degrees about +Y
        n.mesh = b.mesh("cube", {cube(b, m)});
        b.node(n);
    }
    tinygltf::Light light;
    light.type = "point";
    light.color = {1, 0.9, 0.8};
    light.intensity = 6;
    b.light(b.node(at("lamp", {-1, 4, 3})), light);
    const fs::path parent = fs::path(path).parent_path();
    if (!parent.empty()) fs::create_directories(parent);
    b.write(path, true, "");
}

// One mesh of about `triangles` triangles: a grid with positions, normals, UVs and u32 indices.
void big(const std::string& path, long triangles) {
    const int side = std::max(2, static_cast<int>(std::sqrt(static_cast<double>(triangles) / 2.0)));
    Builder b;
    std::vector<glm::vec3> p, n;
    std::vector<glm::vec2> uv;
    for (int y = 0; y <= side; ++y)
        for (int x = 0; x <= side; ++x) {
            const float u = float(x) / float(side);
            const float v = float(y) / float(side);
            p.emplace_back(u * 10 - 5, 0.2f * std::sin(u * 40) * std::cos(v * 40), v * 10 - 5);
            n.emplace_back(0, 1, 0);
            uv.emplace_back(u * 8, v * 8);
        }
    std::vector<std::uint32_t> idx;
    idx.reserve(static_cast<std::size_t>(side) * side * 6);
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            const auto i = static_cast<std::uint32_t>(y * (side + 1) + x);
            const auto row = static_cast<std::uint32_t>(side + 1);
            idx.insert(idx.end(), {i, i + row, i + 1, i + 1, i + row, i + row + 1});
        }
    tinygltf::Primitive prim;
    prim.material = b.material(matte("grid", {0.6f, 0.6f, 0.6f}));
    prim.attributes["POSITION"] = b.floats(p, true);
    prim.attributes["NORMAL"] = b.floats(n);
    prim.attributes["TEXCOORD_0"] = b.floats(uv);
    prim.indices = b.indices(idx);
    tinygltf::Node node;
    node.mesh = b.mesh("grid", {prim});
    b.node(node);
    const fs::path parent = fs::path(path).parent_path();
    if (!parent.empty()) fs::create_directories(parent);
    b.write(path, true, "");
    std::cout << "wrote " << path << " (" << idx.size() / 3 << " triangles)\n";
}

} // namespace

int main(int argc, char** argv) {
    try {
        if (argc == 3 && std::string(argv[1]) == "--example") {
            example(argv[2]);
            return 0;
        }
        if (argc == 4 && std::string(argv[1]) == "--big") {
            big(argv[3], std::stol(argv[2]));
            return 0;
        }
        if (argc != 2) {
            std::cerr << "usage: make_gltf_fixtures OUT_DIR | --big TRIANGLES OUT.glb | --example OUT.glb\n";
            return 2;
        }
        const fs::path dir = argv[1];
        fs::create_directories(dir);
        emissiveCubes(dir);
        lights(dir);
        cameras(dir);
        geometry(dir);
        textures(dir);
        materials(dir);
        warnings(dir);
        malformed(dir);
        schema(dir);
        nothingToDraw(dir);
        unitCube(dir);
        std::cout << "wrote the glTF fixtures into " << dir.string() << "\n";
    } catch (const std::exception& error) {
        std::cerr << "make_gltf_fixtures: " << error.what() << "\n";
        return 1;
    }
    return 0;
}
