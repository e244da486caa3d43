// make_scene OUT.gltf: writes the built-in scene (common/assets/scene.gltf + scene.bin) that every
// stage loads through the glTF loader (common/content/src/gltf_scene.cpp), referring to the committed TGA
// textures next to it. The room, the crates, the lights and the camera presets below are the code
// that used to build the scene in common/content/src/scene.cpp, moved here unchanged: edit the scene here,
// run `build/bin/make_scene common/assets/scene.gltf`, and commit both files (a test checks that
// the committed files are what this tool writes).
//
// glTF conventions applied on the way out: v runs down the image (v_gltf = 1 - v), the tangent's w
// gives the bitangent's side, lights are KHR_lights_punctual (colour x intensity = the old HDR
// colour) on nodes that also carry the emissive light cubes, and the parallax depth map, scale,
// shininess and specular weight go into the T10_materials_parallax extension (site/building.md).
#include "gltf_builder.hpp"
#include "t10/camera.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace {

using GLuint = std::uint32_t; // keeps the moved code below as it was

// The room: x in [-4.5, 4.5], y in [0, 3.5], z in [-8, 2] (the camera presets rely on this).
constexpr float kRoomMinX = -4.5f;
constexpr float kRoomMaxX = 4.5f;
constexpr float kRoomHeight = 3.5f;
constexpr float kRoomMinZ = -8.0f;
constexpr float kRoomMaxZ = 2.0f;
// Metres covered by one repeat of the brick and tile textures (bricks 50 x 25 cm, tiles 50 cm).
constexpr float kWallMetresPerUv = 2.0f;
constexpr float kFloorMetresPerUv = 2.0f;
constexpr float kCeilingMetresPerUv = 2.5f; // the crate texture, as 2.5 m timber panels

constexpr float kLightCubeHalfSize = 0.12f;
// --- The scene's light (the HDR content; see the light list and the window below). ---------------
// A lamp cube's surface radiance per unit of the intensity it lights the room with: small sources
// are far brighter than the light they cast (a 0.24 m cube of intensity 1 shows luminance 60).
constexpr float kLampRadiancePerIntensity = 40.0f;
// The window in the back wall: x in [-1.2, 1.2], y in [1.6, 3.1], daylight radiance times the tile
// texture (its grout reads as the frame between the panes): luminance about 60 on the panes.
const glm::vec3 kWindowMin{-0.8f, 1.9f, -7.97f};
const glm::vec2 kWindowSize{1.6f, 1.0f};
const glm::vec3 kWindowEmission{20.0f, 22.0f, 27.0f};

// The parallax scales must match the normal maps' depth in make_textures.cpp (scale x 256 texels).
constexpr float kBrickParallax = 0.04f;
constexpr float kTileParallax = 0.02f;
constexpr float kCrateParallax = 0.06f;

struct PointLight {
    glm::vec3 position;
    glm::vec3 colour; // linear HDR intensity it lights the room with (components up to 2.4); its cube shows 40x that
};

using t10::CameraPreset; // name, description, position, yaw, pitch, field of view

struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec3 tangent;   // direction of increasing u
    glm::vec3 bitangent; // direction of increasing v
    glm::vec2 uv;
    glm::vec4 uvBounds;  // the face's UV rectangle, for the parallax edge discard
};

struct MeshData {
    std::vector<Vertex> vertices;
    std::vector<GLuint> indices;

    // A rectangle at `origin` spanning `uEdge` and `vEdge`, its front side facing cross(uEdge, vEdge).
    // The rectangles are flat and their UVs are linear along the edges, so the tangent and
    // bitangent (the directions in which u and v grow) are simply the normalised edges; this is
    // what the general per-triangle formula dPos = T du + B dv gives for them.
    void addQuad(const glm::vec3& origin, const glm::vec3& uEdge, const glm::vec3& vEdge,
                 const glm::vec2& uvOrigin, const glm::vec2& uvSize, const glm::vec4& uvBounds) {
        const glm::vec3 t = glm::normalize(uEdge);
        const glm::vec3 b = glm::normalize(vEdge);
        const glm::vec3 n = glm::normalize(glm::cross(uEdge, vEdge));
        const auto base = static_cast<GLuint>(vertices.size());
        const glm::vec2 corners[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        for (const glm::vec2& c : corners)
            vertices.push_back({origin + c.x * uEdge + c.y * vEdge, n, t, b, uvOrigin + c * uvSize, uvBounds});
        // Counter-clockwise seen from the front.
        for (const GLuint i : {0u, 1u, 2u, 0u, 2u, 3u}) indices.push_back(base + i);
    }

    // A room surface textured in world units (so patterns line up across the corners), extended
    // by `margin` metres past every edge. Parallax shifts the texture "into" the surface; where the
    // shifted coordinate leaves the extended rectangle the fragment is discarded, and what shows
    // through is the neighbouring surface's extension, i.e. the continuation of the wall below the
    // floor, as a real recessed surface would show. The margin is the deepest parallax depth.
    void addRoomFace(const glm::vec3& origin, const glm::vec3& uEdge, const glm::vec3& vEdge,
                     float metresPerUv, float margin) {
        const glm::vec3 uDir = glm::normalize(uEdge);
        const glm::vec3 vDir = glm::normalize(vEdge);
        const glm::vec2 size{glm::length(uEdge), glm::length(vEdge)};
        const glm::vec2 uvMin = glm::vec2(-margin) / metresPerUv;
        const glm::vec2 uvSize = (size + 2.0f * margin) / metresPerUv;
        addQuad(origin - margin * (uDir + vDir), uEdge + 2.0f * margin * uDir, vEdge + 2.0f * margin * vDir,
                uvMin, uvSize, glm::vec4(uvMin, uvMin + uvSize));
    }

    // A box standing on the floor: `centre` is the middle of its bottom face, `yawDegrees` turns it
    // about +Y. Each face carries the whole texture, UV [0, 1], and is trimmed at its own edges.
    // With `withBottom` false the face on the floor is left out.
    void addBox(const glm::vec3& bottomCentre, float edge, float yawDegrees, bool withBottom) {
        const float yaw = glm::radians(yawDegrees);
        const glm::vec3 ax{std::cos(yaw), 0.0f, -std::sin(yaw)};
        const glm::vec3 ay{0.0f, 1.0f, 0.0f};
        const glm::vec3 az{std::sin(yaw), 0.0f, std::cos(yaw)};
        const float h = 0.5f * edge;
        const glm::vec3 centre = bottomCentre + h * ay;
        struct Face {
            glm::vec3 normal, u, v;
        };
        // Each (u, v) pair satisfies cross(u, v) = normal, so every face is front-facing outwards.
        const Face faces[] = {{az, ax, ay}, {-az, -ax, ay}, {ax, -az, ay},
                              {-ax, az, ay}, {ay, ax, -az}, {-ay, ax, az}};
        for (const Face& f : faces) {
            if (!withBottom && f.normal == -ay) continue;
            addQuad(centre + h * (f.normal - f.u - f.v), edge * f.u, edge * f.v, {0, 0}, {1, 1}, {0, 0, 1, 1});
        }
    }
};

// --- Into glTF. ------------------------------------------------------------------------------------

// The mesh's vertices as glTF attributes; texture coordinates and their bounds flipped to v-down.
tinygltf::Primitive primitive(t10::gltf::Builder& b, const MeshData& data, int material) {
    std::vector<glm::vec3> positions, normals;
    std::vector<glm::vec4> tangents, bounds;
    std::vector<glm::vec2> uvs;
    for (const Vertex& v : data.vertices) {
        positions.push_back(v.position);
        normals.push_back(v.normal);
        const float w = glm::dot(glm::cross(v.normal, v.tangent), v.bitangent) < 0.0f ? -1.0f : 1.0f;
        tangents.emplace_back(v.tangent, w);
        uvs.emplace_back(v.uv.x, 1.0f - v.uv.y);
        bounds.emplace_back(v.uvBounds.x, 1.0f - v.uvBounds.w, v.uvBounds.z, 1.0f - v.uvBounds.y);
    }
    tinygltf::Primitive p;
    p.mode = TINYGLTF_MODE_TRIANGLES;
    p.material = material;
    p.attributes["POSITION"] = b.floats(positions, true);
    p.attributes["NORMAL"] = b.floats(normals);
    p.attributes["TANGENT"] = b.floats(tangents);
    p.attributes["TEXCOORD_0"] = b.floats(uvs);
    p.attributes["_T10_UV_BOUNDS"] = b.floats(bounds);
    p.indices = b.indices(data.indices);
    return p;
}

tinygltf::Value number(double v) {
    return tinygltf::Value(v);
}

tinygltf::Value textureInfo(int index) {
    tinygltf::Value::Object info;
    info["index"] = tinygltf::Value(index);
    return tinygltf::Value(info);
}

// T10_materials_parallax: the depth map and scale for parallax occlusion mapping, and the
// Blinn-Phong shininess and specular weight (glTF has no fields for any of them).
tinygltf::Value parallaxExtension(int depthTexture, float parallaxScale, float shininess, float specular) {
    tinygltf::Value::Object ext;
    if (depthTexture >= 0) ext["depthTexture"] = textureInfo(depthTexture);
    ext["parallaxScale"] = number(parallaxScale);
    ext["shininess"] = number(shininess);
    ext["specular"] = number(specular);
    return tinygltf::Value(ext);
}

void writeScene(const std::string& path) {
    t10::gltf::Builder b;
    b.use("T10_materials_parallax");
    b.use("KHR_materials_emissive_strength");
    b.model.asset.generator = "Tutorial 10 tools/make_scene";

    // The camera presets: glTF cameras on nodes listed first, so "default" is the scene's first.
    const std::vector<CameraPreset> presets{
        {"default", "Looks into the room: the window, the lamps, the brick walls, the tiled floor and the crates",
         {0.0f, 1.6f, 1.5f}, 0.0f, -6.0f, 60.0f},
        {"floor", "Low grazing view along the tiled floor, where parallax occlusion depth is most visible",
         {-3.2f, 0.35f, 0.8f}, 28.0f, -3.0f, 55.0f},
        {"lights", "Closer to the lamps: the white one, the warm one on the crate, the blue one and the window",
         {1.2f, 1.9f, -1.6f}, 4.0f, -3.0f, 60.0f},
        {"crates", "Three-quarter view of the crates, showing POM edges trimmed at the faces",
         {0.4f, 1.8f, -1.4f}, -12.0f, -19.0f, 55.0f},
        {"dark", "Turned away from the window and the lamps, towards the unlit end of the room: the exposure opens up",
         {0.5f, 1.6f, -3.0f}, 172.0f, -4.0f, 60.0f},
    };
    for (const CameraPreset& preset : presets) {
        tinygltf::Camera camera;
        camera.name = preset.name;
        camera.type = "perspective";
        camera.perspective.yfov = glm::radians(preset.fovDegrees);
        camera.perspective.znear = 0.05;
        camera.perspective.zfar = 100.0;
        tinygltf::Value::Object extras;
        extras["description"] = tinygltf::Value(preset.description);
        camera.extras = tinygltf::Value(extras);
        b.model.cameras.push_back(camera);
        tinygltf::Node node;
        node.name = "camera " + preset.name;
        node.camera = static_cast<int>(b.model.cameras.size() - 1);
        node.translation = {preset.position.x, preset.position.y, preset.position.z};
        // Local -Z is the view direction: turn by -yaw about +Y after pitching about +X.
        const glm::quat q = glm::angleAxis(glm::radians(-preset.yawDegrees), glm::vec3(0, 1, 0)) *
                            glm::angleAxis(glm::radians(preset.pitchDegrees), glm::vec3(1, 0, 0));
        node.rotation = {q.x, q.y, q.z, q.w};
        b.node(node);
    }

    // The materials as scene.cpp made them; each becomes a glTF material in this order, so the
    // indices below are the glTF ones. Images are shared by file name.
    struct Material {
        tinygltf::Material gltf;
        glm::vec3 emission{0.0f}; // light the surface gives off (times its albedo); only the window
    };
    std::map<std::string, int> textureOf;
    auto loadMaterial = [&](const std::string& name, float parallaxScale, float shininess, float specular) {
        auto texture = [&](const char* kind) {
            const std::string file = name + kind;
            if (!textureOf.count(file)) textureOf[file] = b.texture(b.imageUri(file));
            return textureOf[file];
        };
        Material m;
        m.gltf.name = name;
        m.gltf.pbrMetallicRoughness.baseColorTexture.index = texture("_diffuse.tga");
        m.gltf.normalTexture.index = texture("_normal.tga");
        m.gltf.extensions["T10_materials_parallax"] =
            parallaxExtension(texture("_depth.tga"), parallaxScale, shininess, specular);
        return m;
    };
    std::vector<Material> materials_;
    // Bricks are rough, the polished stone tiles glossy, the wood in between.
    materials_.push_back(loadMaterial("bricks", kBrickParallax, 24.0f, 0.25f));
    materials_.push_back(loadMaterial("tiles", kTileParallax, 96.0f, 0.6f));
    materials_.push_back(loadMaterial("crate", kCrateParallax, 32.0f, 0.3f));
    materials_.push_back(loadMaterial("tiles", 0.0f, 1.0f, 0.0f)); // the window: flat, unlit panes
    materials_.back().emission = kWindowEmission;
    constexpr int kBricks = 0;
    constexpr int kTiles = 1;
    constexpr int kCrate = 2;
    constexpr int kWindow = 3;

    for (Material& m : materials_) {
        if (m.emission != glm::vec3(0.0f)) {
            // Emission times albedo: the diffuse map as the emissive map, the colour as factor x strength.
            const float peak = std::max({m.emission.r, m.emission.g, m.emission.b});
            m.gltf.emissiveTexture.index = m.gltf.pbrMetallicRoughness.baseColorTexture.index;
            m.gltf.emissiveFactor = {m.emission.r / peak, m.emission.g / peak, m.emission.b / peak};
            tinygltf::Value::Object strength;
            strength["emissiveStrength"] = number(peak);
            m.gltf.extensions["KHR_materials_emissive_strength"] = tinygltf::Value(strength);
        }
        b.material(m.gltf);
    }

    const float w = kRoomMaxX - kRoomMinX;
    const float d = kRoomMaxZ - kRoomMinZ;
    const float h = kRoomHeight;
    const float wallMargin = kBrickParallax * kWallMetresPerUv;
    const float floorMargin = kTileParallax * kFloorMetresPerUv;
    const float ceilingMargin = kCrateParallax * kCeilingMetresPerUv;

    // Each mesh gets a node at the origin (the geometry is built in world space); material -1 marks
    // the light cube, which becomes one node per light below instead.
    const char* meshNames[] = {"crates", "floor", "ceiling", "walls", "window"};
    int meshCount = 0;
    tinygltf::Primitive lightCube;
    auto addMesh = [&](const MeshData& data, int material) {
        if (material < 0) {
            lightCube = primitive(b, data, material);
            return;
        }
        tinygltf::Node node;
        node.name = meshNames[meshCount++];
        node.mesh = b.mesh(node.name, {primitive(b, data, material)});
        b.node(node);
    };
    std::vector<PointLight> lights_;

    // Crates first: they are in front of the room, so early depth testing skips the walls behind.
    MeshData crates;
    crates.addBox({-1.5f, 0.0f, -4.6f}, 1.0f, 20.0f, false);
    crates.addBox({-1.45f, 1.0f, -4.65f}, 0.55f, 52.0f, true);
    crates.addBox({1.9f, 0.0f, -5.8f}, 1.2f, -14.0f, false);
    addMesh(crates, kCrate);

    // The room; every face's normal points inwards. Tiled floor, timbered ceiling (the crate
    // texture, repeated, reads as beams and braces), brick walls.
    MeshData floor;
    floor.addRoomFace({kRoomMinX, 0, kRoomMaxZ}, {w, 0, 0}, {0, 0, -d}, kFloorMetresPerUv, floorMargin);
    addMesh(floor, kTiles);

    MeshData ceiling;
    ceiling.addRoomFace({kRoomMinX, h, kRoomMinZ}, {w, 0, 0}, {0, 0, d}, kCeilingMetresPerUv, ceilingMargin);
    addMesh(ceiling, kCrate);

    MeshData walls;
    walls.addRoomFace({kRoomMinX, 0, kRoomMinZ}, {w, 0, 0}, {0, h, 0}, kWallMetresPerUv, wallMargin); // back
    walls.addRoomFace({kRoomMaxX, 0, kRoomMaxZ}, {-w, 0, 0}, {0, h, 0}, kWallMetresPerUv, wallMargin); // front
    walls.addRoomFace({kRoomMinX, 0, kRoomMaxZ}, {0, 0, -d}, {0, h, 0}, kWallMetresPerUv, wallMargin); // left
    walls.addRoomFace({kRoomMaxX, 0, kRoomMinZ}, {0, 0, d}, {0, h, 0}, kWallMetresPerUv, wallMargin);  // right
    addMesh(walls, kBricks);

    // The window: 4 x 2 panes of the tile texture, facing into the room just in front of the wall.
    MeshData window;
    window.addQuad(kWindowMin, {kWindowSize.x, 0, 0}, {0, kWindowSize.y, 0}, {0, 0}, {1.0f, 0.5f}, {0, 0, 1, 0.5f});
    addMesh(window, kWindow);

    MeshData cube;
    cube.addBox({0.0f, -1.0f, 0.0f}, 2.0f, 0.0f, true); // spans [-1, 1]; Light.vert scales it
    addMesh(cube, -1);

    // A dim room lit by a few small, very bright sources: the daylight through the window (a light
    // just outside it, its cube hidden by the wall), a white lamp hanging in the middle, a warm lamp
    // on the big crate, a red lamp by the left wall and a blue one by the right wall. Intensities
    // are linear HDR; the cubes show kLampRadiancePerIntensity times as much.
    lights_ = {
        {{0.0f, 2.4f, -8.15f}, {0.6f, 0.7f, 0.85f}},
        {{-1.3f, 2.3f, -4.0f}, {2.0f, 2.0f, 2.0f}},
        {{1.9f, 1.35f, -5.8f}, {2.4f, 1.5f, 0.7f}},
        {{-4.1f, 1.9f, -3.0f}, {1.2f, 0.15f, 0.08f}},
        {{4.1f, 2.1f, -4.6f}, {0.1f, 0.25f, 1.4f}},
    };

    for (std::size_t i = 0; i < lights_.size(); ++i) {
        const PointLight& light = lights_[i];
        const float peak = std::max({light.colour.r, light.colour.g, light.colour.b});
        const glm::vec3 colour = light.colour / peak;
        // The cube's emission: the lamp's surface, kLampRadiancePerIntensity times its intensity.
        const float cubeStrength = peak * kLampRadiancePerIntensity;
        tinygltf::Material m;
        m.name = "light " + std::to_string(i);
        m.pbrMetallicRoughness.baseColorFactor = {0.0, 0.0, 0.0, 1.0}; // emission only, unlit
        m.emissiveFactor = {colour.r, colour.g, colour.b};
        tinygltf::Value::Object strength;
        strength["emissiveStrength"] = number(cubeStrength);
        m.extensions["KHR_materials_emissive_strength"] = tinygltf::Value(strength);
        m.extensions["T10_materials_parallax"] = parallaxExtension(-1, 0.0f, 1.0f, 0.0f);
        const int material = b.material(m);
        tinygltf::Node node;
        node.name = "light " + std::to_string(i);
        tinygltf::Primitive p = lightCube;
        p.material = material;
        node.mesh = b.mesh("light cube " + std::to_string(i), {p});
        node.translation = {light.position.x, light.position.y, light.position.z};
        node.scale = {kLightCubeHalfSize, kLightCubeHalfSize, kLightCubeHalfSize};
        const int n = b.node(node);
        tinygltf::Light l;
        l.name = node.name;
        l.type = "point";
        l.color = {colour.r, colour.g, colour.b};
        l.intensity = peak;
        b.light(n, l);
    }
    b.write(path, false, "scene.bin");
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: make_scene OUT.gltf   (writes OUT.gltf and scene.bin next to it)\n";
        return 2;
    }
    try {
        writeScene(argv[1]);
    } catch (const std::exception& error) {
        std::cerr << "make_scene: " << error.what() << "\n";
        return 1;
    }
    std::cout << "wrote " << argv[1] << "\n";
    return 0;
}
