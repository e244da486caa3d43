// Measured properties of the glTF fixtures rendered by Part 3 (tests/gltf/gltf_tests.cmake renders
// each fixture in its three forms into renders/<fixture><form>_<camera>.exr, the HDR
// accumulation buffer, 320x180; T10_GLTF_DIR holds fixtures/ and renders/). World points are projected with the camera the loader read, so a
// wrong camera, transform, texture orientation or light position moves what is measured.
#include "t10/camera.hpp"
#include "t10/gltf_scene.hpp"
#include "t10/image_io.hpp"

#include "t10_catch.hpp"

#include <cstdlib>
#include <string>

namespace {

std::string env(const char* name) {
    const char* value = std::getenv(name);
    REQUIRE(value != nullptr);
    return value;
}

const char* kForms[] = {"", "_embedded", "_glb"};
std::string fileOf(const std::string& name, const std::string& form) {
    return env("T10_GLTF_DIR") + "/fixtures/" + name + (form == "_glb" ? ".glb" : form + ".gltf");
}

struct Render {
    t10::ImageF hdr;
    t10::Camera camera;

    // Pixel (x right, y up from the bottom row) where a world point lands.
    glm::vec2 project(const glm::vec3& world) const {
        const glm::vec4 clip = camera.projection(float(hdr.width) / float(hdr.height)) * camera.view() * glm::vec4(world, 1);
        const glm::vec2 ndc = glm::vec2(clip) / clip.w;
        return {(ndc.x * 0.5f + 0.5f) * float(hdr.width), (ndc.y * 0.5f + 0.5f) * float(hdr.height)};
    }
    glm::vec3 at(glm::vec2 pixel) const {
        const int x = std::clamp(int(pixel.x), 0, hdr.width - 1);
        const int y = std::clamp(int(pixel.y), 0, hdr.height - 1);
        return {hdr.at(x, y, 0), hdr.at(x, y, 1), hdr.at(x, y, 2)};
    }
    glm::vec3 at(const glm::vec3& world) const { return at(project(world)); }
};

Render load(const std::string& name, const std::string& form, const std::string& cameraName) {
    const t10::SceneDescription d = t10::loadGltfScene(fileOf(name, form));
    const t10::CameraPreset* preset = d.findCamera(cameraName);
    REQUIRE(preset != nullptr);
    return {t10::readExr(env("T10_GLTF_DIR") + "/renders/" + name + form + "_" + cameraName + ".exr"), t10::Camera(*preset)};
}

float luminance(const glm::vec3& c) {
    return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
}

} // namespace

// The accumulation buffer is RGBA16F: half floats hold 11 significant bits, so values agree with
// the exact emission to 0.1%; 1% leaves room for filtering at the sample point and nothing else.
TEST_CASE("emissive-strength cubes: 1, 4 and 16 times the factor, in that order", "[gltf][render][emissive]") {
    for (const char* form : kForms) {
        INFO("form '" << form << "'");
        const Render r = load("emissive_cubes", form, "front");
        const glm::vec3 a = r.at(glm::vec3(-1.5f, 0, 0.5f));
        const glm::vec3 b = r.at(glm::vec3(0, 0, 0.5f));
        const glm::vec3 c = r.at(glm::vec3(1.5f, 0, 0.5f));
        // Emission (1, 0.5, 0.25) x strength, plus a little of the default lights on the black
        // base colour: none (the base colour is black and the specular weight of rough material 0).
        CHECK(a.r == Approx(1.0f).epsilon(0.01));
        CHECK(b.r == Approx(4.0f).epsilon(0.01));
        CHECK(c.r == Approx(16.0f).epsilon(0.01));
        CHECK(c.g == Approx(8.0f).epsilon(0.01));
        CHECK(luminance(a) < luminance(b));
        CHECK(luminance(b) < luminance(c));
    }
}

TEST_CASE("point light: the brightest floor pixel lies under the light", "[gltf][render][point]") {
    for (const char* form : kForms) {
        INFO("form '" << form << "'");
        const Render r = load("lights", form, "top");
        const glm::vec2 foot = r.project({1.5f, 0, -1});
        // The brightest pixel within 30 px of where the light's foot should be (the spot's pool of
        // light lies 4 m away, about 60 px).
        glm::vec2 best(0);
        float peak = -1;
        for (int y = 0; y < r.hdr.height; ++y)
            for (int x = 0; x < r.hdr.width; ++x) {
                if (glm::distance(glm::vec2(float(x) + 0.5f, float(y) + 0.5f), foot) > 30.0f) continue;
                const float l = luminance(r.at(glm::vec2(float(x) + 0.5f, float(y) + 0.5f)));
                if (l > peak) {
                    peak = l;
                    best = {float(x) + 0.5f, float(y) + 0.5f};
                }
            }
        INFO("foot " << foot.x << "," << foot.y << " brightest " << best.x << "," << best.y);
        // 1/(d^2 + 0.05) falls by 1% within 0.07 m of the foot, about 2 px at this scale: 3 px.
        // (A light 0.5 m away from where the file puts it lands about 10 px off.)
        CHECK(glm::distance(best, foot) <= 3.0f);
        // Lit: intensity 2 cd at 1 m on albedo 0.5 (diffuse only): 2 / 1.05 x 0.5 = 0.95.
        CHECK(r.at(foot).g == Approx(0.95f).epsilon(0.05));
    }
}

TEST_CASE("spot light: lit inside the cone, dark outside it", "[gltf][render][spot]") {
    for (const char* form : kForms) {
        INFO("form '" << form << "'");
        const Render r = load("lights", form, "top");
        // Under the spot (2 m high): 8 cd / 4 m^2 x 0.5 = 1.0 (minus the softening). 1.5 m off the
        // axis is 37 degrees, outside the 30-degree outer cone: only the ambient term and the far
        // point light remain there.
        const glm::vec3 inside = r.at(glm::vec3(-2, 0, 1));
        const glm::vec3 outside = r.at(glm::vec3(-2, 0, -0.5f));
        CHECK(inside.g == Approx(0.99f).epsilon(0.05));
        CHECK(outside.g < 0.1f * inside.g);
    }
}

TEST_CASE("named cameras: the cube appears where each camera puts it", "[gltf][render][cameras]") {
    for (const char* form : kForms) {
        for (const char* name : {"left", "high", "framing"}) {
            INFO("form '" << form << "' camera " << name);
            const Render r = load("cameras", form, name);
            // The centroid of the emissive pixels (8 in the file; nothing else is that bright).
            glm::vec2 sum(0);
            int count = 0;
            for (int y = 0; y < r.hdr.height; ++y)
                for (int x = 0; x < r.hdr.width; ++x)
                    if (r.hdr.at(x, y, 0) > 4.0f) {
                        sum += glm::vec2(float(x) + 0.5f, float(y) + 0.5f);
                        ++count;
                    }
            REQUIRE(count > 20);
            if (std::string(name) == "framing") {
                // The framing camera shows the whole scene: the cube is large (over 2% of the
                // frame) and touches no edge.
                CHECK(count > r.hdr.width * r.hdr.height / 50);
                for (int x = 0; x < r.hdr.width; ++x)
                    CHECK((r.hdr.at(x, 0, 0) < 4.0f && r.hdr.at(x, r.hdr.height - 1, 0) < 4.0f));
                for (int y = 0; y < r.hdr.height; ++y)
                    CHECK((r.hdr.at(0, y, 0) < 4.0f && r.hdr.at(r.hdr.width - 1, y, 0) < 4.0f));
                continue;
            }
            const glm::vec2 expected = r.project({1, 0.5f, -2});
            INFO("centroid " << sum.x / float(count) << "," << sum.y / float(count) << " expected " << expected.x << "," << expected.y);
            // A cube's silhouette centroid is not exactly its centre's projection under perspective:
            // within 4 px at these distances (a wrong camera is tens of pixels off).
            CHECK(glm::distance(sum / float(count), expected) <= 4.0f);
        }
    }
}

TEST_CASE("every encoding and transform draws its square: nine green squares, gaps between", "[gltf][render][geometry]") {
    for (const char* form : kForms) {
        INFO("form '" << form << "'");
        const Render r = load("geometry", form, "front");
        for (int row = 0; row < 3; ++row)
            for (int col = 0; col < 3; ++col) {
                INFO("square " << row * 3 + col);
                const glm::vec3 centre(-2.0f + 2.0f * float(col), 2.0f - 2.0f * float(row), 0);
                const glm::vec3 c = r.at(centre);
                CHECK(c.g == Approx(2.0f).epsilon(0.01));
                CHECK(c.r < 0.01f);
                // A corner's neighbourhood, just inside, is also drawn (both triangles present).
                CHECK(r.at(centre + glm::vec3(0.4f, 0.4f, 0)).g == Approx(2.0f).epsilon(0.01));
                CHECK(r.at(centre + glm::vec3(-0.4f, -0.4f, 0)).g == Approx(2.0f).epsilon(0.01));
                // The gap to the right of it is not.
                CHECK(r.at(centre + glm::vec3(1.0f, 0, 0)).g < 0.1f);
            }
    }
}

TEST_CASE("textures: the image's top half is at the top, sRGB 188 reads as linear 0.5", "[gltf][render][textures]") {
    for (const char* form : kForms) {
        INFO("form '" << form << "'");
        const Render r = load("textures", form, "front");
        for (int i = 0; i < 3; ++i) {
            INFO("square " << i << " (PNG, JPEG, TGA)");
            const float x = -1.5f + 1.5f * float(i);
            const glm::vec3 top = r.at(glm::vec3(x, 0.25f, 0));
            const glm::vec3 bottom = r.at(glm::vec3(x, -0.25f, 0));
            // Emission strength 4 x sRGB 188 (linear 0.5029): 2.01. JPEG rounds the colour by a
            // few steps: 4%.
            CHECK(top.r == Approx(2.01f).epsilon(0.04));
            CHECK(top.g < 0.1f);
            CHECK(bottom.g == Approx(2.01f).epsilon(0.04));
            CHECK(bottom.r < 0.1f);
        }
    }
}

TEST_CASE("a file with warnings still renders what it can", "[gltf][render][warnings]") {
    for (const char* form : kForms) {
        INFO("form '" << form << "'");
        const Render r = load("warnings", form, "front");
        CHECK(r.at(glm::vec3(0, 0, 0)).r == Approx(2.0f).epsilon(0.01));
    }
}

TEST_CASE("double-sided, single-sided, MASK and BLEND over an emissive backdrop", "[gltf][render][materials]") {
    for (const char* form : kForms) {
        INFO("form '" << form << "'");
        const Render r = load("materials", form, "front");
        const glm::vec3 twoSided = r.at(glm::vec3(-1.5f, 0, 0));
        const glm::vec3 culled = r.at(glm::vec3(0, 0, 0));
        const glm::vec3 masked = r.at(glm::vec3(1.5f, 0, 0));
        const glm::vec3 blended = r.at(glm::vec3(0, 1.5f, 0));
        // Emission is exact in half floats to 0.1%; 1% as elsewhere.
        CHECK(twoSided.g == Approx(2.0f).epsilon(0.01)); // seen from behind, still drawn
        CHECK(culled.r < 0.01f);                          // back face culled: the backdrop shows
        CHECK(culled.b == Approx(1.0f).epsilon(0.01));
        CHECK(masked.r < 0.01f);                          // alpha 0.3 below the cutoff: discarded
        CHECK(masked.b == Approx(1.0f).epsilon(0.01));
        CHECK(blended.r == Approx(1.0f).epsilon(0.01));   // half of red 2 over half of blue 1
        CHECK(blended.b == Approx(0.5f).epsilon(0.01));
    }
}

// The framing camera fills most of the frame with the scene's bounds: an emissive unit cube (red 4,
// nothing else in the file) covers at least a third of the 320x180 frame, and none of it is cut off
// by an edge. Emission is exact to 0.1% in half floats; the threshold 2 (half of it) counts every
// pixel the cube covers and none of the black background.
TEST_CASE("framing camera: a unit cube covers at least a third of the frame, whole", "[gltf][render][framing]") {
    for (const char* form : kForms) {
        INFO("form '" << form << "'");
        const Render r = load("unit_cube", form, "framing");
        int covered = 0;
        for (int y = 0; y < r.hdr.height; ++y)
            for (int x = 0; x < r.hdr.width; ++x)
                if (r.hdr.at(x, y, 0) > 2.0f) ++covered;
        const double share = double(covered) / double(r.hdr.width * r.hdr.height);
        INFO("the cube covers " << share * 100.0 << "% of the frame");
        CHECK(share >= 1.0 / 3.0);
        for (int x = 0; x < r.hdr.width; ++x)
            CHECK((r.hdr.at(x, 0, 0) < 2.0f && r.hdr.at(x, r.hdr.height - 1, 0) < 2.0f));
        for (int y = 0; y < r.hdr.height; ++y)
            CHECK((r.hdr.at(0, y, 0) < 2.0f && r.hdr.at(r.hdr.width - 1, y, 0) < 2.0f));
    }
}
