// The glTF loader without a GL context: the built-in scene, each feature fixture in its three
// forms (external files, embedded data URIs, GLB), and every malformed file with the message it
// must give. Fixtures come from tools/make_gltf_fixtures (ctest runs it first, into
// T10_GLTF_FIXTURES).
#include "t10/error.hpp"
#include "t10/gltf_scene.hpp"

#include "t10_catch.hpp"

#include <cstdlib>
#include <regex>
#include <string>

namespace {

std::string fixture(const std::string& name) {
    const char* dir = std::getenv("T10_GLTF_FIXTURES");
    REQUIRE(dir != nullptr);
    return std::string(dir) + "/" + name;
}

const char* kForms[] = {".gltf", "_embedded.gltf", ".glb"};

bool hasWarning(const t10::SceneDescription& d, const std::string& text) {
    for (const std::string& w : d.warnings)
        if (w.find(text) != std::string::npos) return true;
    return false;
}

} // namespace

TEST_CASE("the built-in scene: five camera presets, five lights, POM materials, the window", "[gltf]") {
    const t10::SceneDescription d = t10::loadGltfScene(t10::builtInScenePath());
    INFO(d.cameraNames());
    REQUIRE(d.cameras.size() == 6); // default, floor, lights, crates, dark, then the loader's framing camera
    CHECK(d.cameras[0].name == "default");
    CHECK(d.findCamera("floor") != nullptr);
    CHECK(d.findCamera("lights") != nullptr);
    CHECK(d.findCamera("crates") != nullptr);
    CHECK(d.findCamera("dark") != nullptr);
    CHECK(d.cameras[5].name == "framing");
    CHECK(d.findCamera("Default") == nullptr); // names are case-sensitive
    for (const t10::CameraPreset& c : d.cameras) {
        CHECK_FALSE(c.description.empty());
        CHECK(c.description.find('\n') == std::string::npos);
    }
    // The default preset as it was written in camera.cpp: (0, 1.6, 1.5), yaw 0, pitch -6, fov 60.
    const t10::CameraPreset& def = d.cameras[0];
    CHECK(def.position.x == Approx(0.0f).margin(1e-6));
    CHECK(def.position.y == Approx(1.6f));
    CHECK(def.position.z == Approx(1.5f));
    CHECK(def.yawDegrees == Approx(0.0f).margin(1e-4));
    CHECK(def.pitchDegrees == Approx(-6.0f).margin(1e-4));
    CHECK(def.fovDegrees == Approx(60.0f).margin(1e-4));

    REQUIRE(d.lights.size() == 5);
    CHECK_FALSE(d.defaultLights);
    // The daylight behind the window, then the white lamp, as tools/make_scene lists them.
    CHECK(d.lights[0].position.z == Approx(-8.15f));
    CHECK(d.lights[0].intensity.b == Approx(0.85f));
    CHECK(d.lights[1].position.x == Approx(-1.3f));
    CHECK(d.lights[1].intensity.r == Approx(2.0f));
    CHECK(d.warnings.empty());

    int pom = 0;
    int emissive = 0;
    for (const t10::SceneMaterial& m : d.materials) {
        if (m.parallaxScale > 0.0f) {
            ++pom;
            CHECK(m.depthTexture >= 0);
            CHECK(m.baseColourTexture >= 0);
            CHECK(m.normalTexture >= 0);
        }
        if (m.emissiveTexture >= 0) ++emissive; // the window: daylight times the tile texture
    }
    CHECK(pom == 3);
    CHECK(emissive == 1);
    // Each lamp's cube shows 40 times the intensity it lights the room with.
    bool whiteCube = false;
    for (const t10::SceneMaterial& m : d.materials)
        if (m.emissive.r == Approx(80.0f) && m.emissive.g == Approx(80.0f)) whiteCube = true;
    CHECK(whiteCube);
    // Every mesh's UV bounds hold its UVs (the parallax edge discard would trim everything otherwise).
    for (const t10::SceneMesh& mesh : d.meshes)
        for (const t10::SceneVertex& v : mesh.vertices) {
            CHECK(v.uv.x >= v.uvBounds.x - 1e-5f);
            CHECK(v.uv.y >= v.uvBounds.y - 1e-5f);
            CHECK(v.uv.x <= v.uvBounds.z + 1e-5f);
            CHECK(v.uv.y <= v.uvBounds.w + 1e-5f);
        }
}

TEST_CASE("emissive strength multiplies the emissive factor", "[gltf]") {
    for (const char* form : kForms) {
        INFO(form);
        const t10::SceneDescription d = t10::loadGltfScene(fixture(std::string("emissive_cubes") + form));
        REQUIRE(d.meshes.size() == 3);
        CHECK(d.triangleCount == 36);
        const float strengths[] = {1, 4, 16};
        for (int i = 0; i < 3; ++i) {
            const t10::SceneMaterial& m = d.materials[static_cast<std::size_t>(d.meshes[static_cast<std::size_t>(i)].material)];
            CHECK(m.emissive.r == Approx(strengths[i]));
            CHECK(m.emissive.g == Approx(0.5f * strengths[i]));
        }
        CHECK(d.defaultLights); // the file has no lights: the default rig
        CHECK(d.lights.size() == 3);
        CHECK(d.cameras.front().name == "front");
    }
}

TEST_CASE("every mesh encoding and node transform gives the same square", "[gltf]") {
    for (const char* form : kForms) {
        INFO(form);
        const t10::SceneDescription d = t10::loadGltfScene(fixture(std::string("geometry") + form));
        CHECK(d.triangleCount == 18);
        CHECK(d.meshes.size() == 10); // the last square is two primitives
        for (const t10::SceneMesh& mesh : d.meshes) {
            INFO(mesh.name);
            glm::vec3 lo(1e9f), hi(-1e9f);
            for (const t10::SceneVertex& v : mesh.vertices) {
                lo = glm::min(lo, v.position);
                hi = glm::max(hi, v.position);
                CHECK(v.normal.z == Approx(1.0f)); // given or generated flat, towards the camera
            }
            // A unit square (or half of one) on the grid at z = 0.
            CHECK(hi.x - lo.x == Approx(1.0f));
            CHECK(hi.y - lo.y == Approx(1.0f));
            CHECK(std::abs(lo.z) < 1e-5f);
            const float cx = 0.5f * (lo.x + hi.x);
            CHECK(std::abs(cx - std::round(cx / 2) * 2) < 1e-5f);
            for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
                // Counter-clockwise seen from +Z: strips and fans keep their winding.
                const glm::vec3 a = mesh.vertices[mesh.indices[t]].position;
                const glm::vec3 b = mesh.vertices[mesh.indices[t + 1]].position;
                const glm::vec3 c = mesh.vertices[mesh.indices[t + 2]].position;
                CHECK(glm::cross(b - a, c - a).z > 0.0f);
            }
        }
    }
}

TEST_CASE("images: PNG, JPEG and TGA stored bottom row first, UVs flipped to match", "[gltf]") {
    for (const char* form : kForms) {
        INFO(form);
        const t10::SceneDescription d = t10::loadGltfScene(fixture(std::string("textures") + form));
        REQUIRE(d.images.size() == 3);
        for (std::size_t i = 0; i < 3; ++i) {
            INFO("image " << i);
            const t10::Image8& image = d.images[i];
            REQUIRE(image.width == 8);
            // Row 0 is the bottom: green. The top row is red. (JPEG is lossy: a margin of 12.)
            CHECK(std::abs(image.at(0, 0, 1) - 188) <= 12);
            CHECK(image.at(0, 0, 0) <= 12);
            CHECK(std::abs(image.at(0, 7, 0) - 188) <= 12);
            CHECK(image.at(0, 7, 1) <= 12);
        }
        REQUIRE(d.textures.size() == 3);
        for (const t10::SceneTexture& t : d.textures) {
            CHECK(t.srgb); // emissive textures hold colour
            CHECK(t.sampler.minFilter == 9728);
            CHECK(t.sampler.wrapS == 33071);
        }
        // glTF's (0, 0) is the image's top left: here (0, 1).
        const t10::SceneVertex& topLeft = d.meshes[0].vertices[0];
        CHECK(topLeft.position.y > 0.0f);
        CHECK(topLeft.uv.y == Approx(1.0f));
        // Generated tangents follow u, bitangents v (up the image).
        CHECK(topLeft.tangent.x == Approx(1.0f));
        CHECK(topLeft.bitangent.y == Approx(1.0f));
    }
}

TEST_CASE("KHR_lights_punctual point and spot lights", "[gltf]") {
    for (const char* form : kForms) {
        INFO(form);
        const t10::SceneDescription d = t10::loadGltfScene(fixture(std::string("lights") + form));
        REQUIRE(d.lights.size() == 2);
        CHECK_FALSE(d.defaultLights);
        const t10::SceneLight& point = d.lights[0];
        CHECK_FALSE(point.spot);
        CHECK(point.position.x == Approx(1.5f));
        CHECK(point.position.y == Approx(1.0f));
        CHECK(point.intensity.g == Approx(2.0f));
        const t10::SceneLight& spot = d.lights[1];
        CHECK(spot.spot);
        CHECK(spot.direction.y == Approx(-1.0f));
        CHECK(spot.innerConeCos == Approx(std::cos(glm::radians(20.0f))));
        CHECK(spot.outerConeCos == Approx(std::cos(glm::radians(30.0f))));
    }
}

TEST_CASE("cameras are named presets; the framing camera comes last", "[gltf]") {
    for (const char* form : kForms) {
        INFO(form);
        const t10::SceneDescription d = t10::loadGltfScene(fixture(std::string("cameras") + form));
        CHECK(d.cameraNames() == "left, high, framing");
        const t10::CameraPreset* left = d.findCamera("left");
        REQUIRE(left != nullptr);
        CHECK(left->position.x == Approx(-4.0f));
        CHECK(left->fovDegrees == Approx(50.0f));
        CHECK(left->nearPlane == Approx(0.1f));
    }
}

TEST_CASE("points, lines, morph targets, skins and the rest: one warning each, the square still loads", "[gltf]") {
    for (const char* form : kForms) {
        INFO(form);
        const t10::SceneDescription d = t10::loadGltfScene(fixture(std::string("warnings") + form));
        for (const std::string& w : d.warnings) INFO(w);
        CHECK(d.triangleCount == 2);
        CHECK(hasWarning(d, "points are not drawn"));
        CHECK(hasWarning(d, "lines are not drawn"));
        CHECK(hasWarning(d, "morph targets are ignored"));
        CHECK(hasWarning(d, "is skinned"));
        CHECK(hasWarning(d, "orthographic"));
        CHECK(hasWarning(d, "directional"));
        CHECK(hasWarning(d, "optional extension EXT_unknown_but_optional is ignored"));
        CHECK(d.defaultLights); // the directional light was the only one
    }
}

TEST_CASE("double-sided and alpha modes are read", "[gltf]") {
    for (const char* form : kForms) {
        INFO(form);
        const t10::SceneDescription d = t10::loadGltfScene(fixture(std::string("materials") + form));
        REQUIRE(d.materials.size() == 6); // five, then the default material
        CHECK(d.materials[1].doubleSided);
        CHECK_FALSE(d.materials[2].doubleSided);
        CHECK(d.materials[3].alphaMode == t10::AlphaMode::Mask);
        CHECK(d.materials[3].alphaCutoff == Approx(0.5f));
        CHECK(d.materials[4].alphaMode == t10::AlphaMode::Blend);
        CHECK(d.materials[4].baseColour.a == Approx(0.5f));
    }
}

TEST_CASE("a chain of 100000 nodes loads without recursion", "[gltf]") {
    const t10::SceneDescription d = t10::loadGltfScene(fixture("deep_chain.gltf"));
    CHECK(d.triangleCount == 1);
}

TEST_CASE("malformed files are refused with the file name and the fault", "[gltf]") {
    struct Case {
        const char* file;
        const char* message; // regex
    };
    const Case cases[] = {
        {"bad_json.gltf", "bad_json.gltf: .*parse error at line 1, column 43"},
        {"bad_wrong_type.gltf", "bad_wrong_type.gltf: accessors\\[0\\]\\.count: expected an integer >= 1, got a string \"three\""},
        {"bad_header.glb", "bad_header.glb: Invalid glTF binary"},
        {"bad_missing_buffer.gltf", "bad_missing_buffer.gltf: File not found : no_such_file.bin"},
        {"bad_short_buffer.gltf", "bad_short_buffer.gltf: File size mismatch : .*short.bin, requestedBytes 36, but got 20"},
        {"bad_missing_image.gltf", "bad_missing_image.gltf: image 0 \\(no_such_image.png\\) is missing"},
        {"bad_truncated_image.gltf", "bad_truncated_image.gltf: .*image 0 \\(truncated.png\\): cannot decode"},
        {"bad_accessor_range.gltf", "bad_accessor_range.gltf: .*accessor 0 \\(4 elements from offset 0\\) reads past the end"},
        {"bad_view_range.gltf", "bad_view_range.gltf: .*buffer view 0 \\(offset 8, length 40\\) lies outside buffer 0"},
        {"bad_index.gltf", "bad_index.gltf: .*index 7 \\(element 2\\) is beyond the vertex count 3"},
        {"bad_nan.gltf", "bad_nan.gltf: .*POSITION 2 is not finite"},
        {"bad_inf.gltf", "bad_inf.gltf: .*POSITION 2 is not finite"},
        {"bad_cycle.gltf", "bad_cycle.gltf: node 1 has two parents"},
        {"bad_cycle_root.gltf", "bad_cycle_root.gltf: scene 0 lists node 0, which is not a root \\(node cycle"},
        {"bad_cycle_sceneless.gltf", "bad_cycle_sceneless.gltf: node 1 is part of a cycle"},
        {"bad_required_draco.gltf", "bad_required_draco.gltf: requires the extension KHR_draco_mesh_compression"},
        {"no_such_file.glb", "no_such_file.glb: cannot open file: No such file or directory"},
    };
    for (const Case& c : cases) {
        INFO(c.file);
        std::string message;
        try {
            t10::loadGltfScene(fixture(c.file));
        } catch (const t10::Error& error) {
            message = error.what();
        }
        INFO(message);
        CHECK(std::regex_search(message, std::regex(c.message)));
    }
    // The good file they are variations of loads.
    CHECK(t10::loadGltfScene(fixture("good_triangle.gltf")).triangleCount == 1);
}

// Messages name the file and the JSON path; each regex is matched against the whole message.
TEST_CASE("wrongly typed or out-of-range properties are refused with their JSON path", "[gltf][schema]") {
    struct Case {
        const char* file;
        const char* message;
    };
    const Case cases[] = {
        // The kinds of tinygltf's wrongTypes set, which tinygltf 2.7 itself accepts with defaults.
        {"normal_scale_string.gltf", R"(materials\[0\]\.normalTexture\.scale: expected a number, got a string "not a number")"},
        {"mesh_name_number.gltf", R"(meshes\[0\]\.name: expected a string, got a number 1)"},
        {"pbr_not_object.gltf", R"(materials\[0\]\.pbrMetallicRoughness: expected an object, got a string "shiny")"},
        {"texture_index_negative.gltf", R"(materials\[0\]\.normalTexture\.index: expected an integer >= 0, got -1)"},
        {"primitives_object.gltf", R"(meshes\[0\]\.primitives: expected an array, got an object)"},
        {"primitives_object.glb", R"(meshes\[0\]\.primitives: expected an array, got an object)"},
        // One per other kind of property the loader reads.
        {"index_out_of_range.gltf", R"(meshes\[0\]\.primitives\[0\]\.material: materials\[5\] does not exist \(the file has 1\))"},
        {"integer_fraction.gltf", R"(accessors\[0\]\.byteOffset: expected an integer >= 0, got a number 1\.5)"},
        {"integer_below_minimum.gltf", R"(accessors\[0\]\.count: expected an integer >= 1, got 0)"},
        {"array_object.gltf", R"(nodes: expected an array, got an object)"},
        {"array_length.gltf", R"(nodes\[0\]\.translation: expected 3 numbers, got 2)"},
        {"number_string.gltf", R"(nodes\[0\]\.scale\[1\]: expected a number, got a string "2")"},
        {"number_range.gltf", R"(materials\[0\]\.pbrMetallicRoughness\.metallicFactor: expected a number from 0 to 1, got 2)"},
        {"number_exclusive.gltf", R"(cameras\[0\]\.perspective\.yfov: expected a number above 0, got 0)"},
        {"enum_integer.gltf", R"(meshes\[0\]\.primitives\[0\]\.mode: expected one of 0, 1, 2, 3, 4, 5, 6, got a number 7)"},
        {"enum_string.gltf", R"(materials\[0\]\.alphaMode: expected one of "OPAQUE", "MASK", "BLEND", got a string "opaque")"},
        {"enum_sampler.gltf", R"(samplers\[0\]\.wrapS: expected one of 33071, 33648, 10497, got a number 1)"},
        {"boolean_string.gltf", R"(materials\[0\]\.doubleSided: expected true or false, got a string "yes")"},
        {"string_number.gltf", R"(images\[0\]\.uri: expected a string, got a number 5)"},
        {"object_array.gltf", R"(materials\[0\]\.normalTexture: expected an object, got an array)"},
        {"required_missing.gltf", R"(accessors\[0\]\.componentType: missing \(the schema requires it\))"},
        {"extension_number.gltf",
         R"(materials\[0\]\.extensions\.KHR_materials_emissive_strength\.emissiveStrength: expected a number, got a string "2")"},
        {"light_index.gltf", R"(nodes\[2\]\.extensions\.KHR_lights_punctual\.light: KHR_lights_punctual light 3 does not exist \(the file has 1\))"},
        {"light_type.gltf", R"(extensions\.KHR_lights_punctual\.lights\[0\]\.type: expected one of "directional", "point", "spot", got a string "area")"},
        {"texture_info_index.gltf", R"(textures\[0\]\.source: images\[4\] does not exist \(the file has 1\))"},
        {"scene_index.gltf", R"(scene: scenes\[1\] does not exist \(the file has 1\))"},
        {"scene_name_number.gltf", R"(scenes\[0\]\.name: expected a string, got a number 1)"},
        {"children_index.gltf", R"(nodes\[0\]\.children\[0\]: expected an integer >= 0, got -1)"},
    };
    // The file they are variations of loads: the checks accept every property it uses.
    const t10::SceneDescription base = t10::loadGltfScene(fixture("schema_base.gltf"));
    CHECK(base.triangleCount == 1);
    CHECK(base.lights.size() == 1);
    CHECK(base.materials[0].normalTexture >= 0);
    for (const Case& c : cases) {
        const std::string file = std::string("schema_") + c.file;
        INFO(file);
        std::string message;
        try {
            t10::loadGltfScene(fixture(file));
        } catch (const t10::Error& error) {
            message = error.what();
        }
        INFO(message);
        // "<path of the file>: <JSON path>: <fault>", on one line.
        CHECK(std::regex_search(message, std::regex("^.*" + file + ": " + c.message + "$")));
    }
}

TEST_CASE("a scene that draws nothing is refused with why", "[gltf]") {
    CHECK_THROWS_WITH(t10::loadGltfScene(fixture("nothing_points.gltf")),
                      Catch::EndsWith("nothing_points.gltf: nothing to draw: the scene's only primitive is points or "
                                      "lines, which are not drawn"));
    CHECK_THROWS_WITH(t10::loadGltfScene(fixture("nothing_no_meshes.gltf")),
                      Catch::EndsWith("nothing_no_meshes.gltf: nothing to draw: the file has no meshes"));
    CHECK_THROWS_WITH(t10::loadGltfScene(fixture("nothing_skipped.gltf")),
                      Catch::EndsWith("nothing to draw: every primitive was skipped (1 primitive: 0 points or lines, "
                                      "1 without a whole triangle)"));
    // The warnings fixture has points and lines too, but also a square: it loads.
    CHECK(t10::loadGltfScene(fixture("warnings.glb")).triangleCount == 2);
}

TEST_CASE("limits: too many triangles after instancing are refused", "[gltf]") {
    t10::GltfLoadLimits limits;
    limits.maxTriangles = 17;
    CHECK_THROWS_WITH(t10::loadGltfScene(fixture("geometry.glb"), limits),
                      Catch::Contains("more than 17 triangles"));
    limits = {};
    limits.allowExternalFiles = false;
    CHECK_THROWS_WITH(t10::loadGltfScene(fixture("geometry.gltf"), limits), Catch::Contains("geometry.bin"));
}

TEST_CASE("fuzzer findings stay fixed", "[gltf]") {
    // A GLB whose embedded JPEG declares Huffman tables of more than 256 codes: Debian's stb_image
    // wrote past its tables (found by fuzz/gltf under UBSan); the loader refuses it first.
    CHECK_THROWS_WITH(t10::loadGltfScene(std::string(T10_TEST_FIXTURE_DIR) + "/gltf/fuzz_jpeg_huffman_overflow.glb"),
                      Catch::Contains("image 1: corrupt JPEG (a Huffman table with more than 256 codes)"));
}
