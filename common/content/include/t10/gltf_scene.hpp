// The scene as data: a glTF 2.0 file (.gltf or .glb) read through tinygltf into a CPU description
// that Scene uploads and draws. Geometry is flattened into world space (one mesh per node and
// primitive), images are decoded (PNG and JPEG through stb, TGA through the project's own loader)
// and stored bottom row first like every other image here, with texture coordinates flipped to
// match. Every fault in the file ends in t10::Error("<file>: <fault>"); nothing is sized from a
// count before the bytes that back it have been checked. What is read, warned about and refused
// is listed in site/building.md ("Your own scene").
#pragma once
#include "t10/camera.hpp"
#include "t10/image.hpp"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace t10 {

// One vertex as Scene.vert reads it (attribute locations 0-5).
struct SceneVertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec3 tangent;   // direction of increasing u
    glm::vec3 bitangent; // direction of increasing v (v = 0 is the image's bottom row)
    glm::vec2 uv;
    glm::vec4 uvBounds;  // parallax edge discard rectangle (u min, v min, u max, v max)
};

// UV bounds that never discard (files without the _T10_UV_BOUNDS attribute).
constexpr float kNoUvBound = 1.0e30f;

// Sampler state as GL enums (glTF uses the same numbers).
struct SamplerSettings {
    int minFilter = 0x2703; // GL_LINEAR_MIPMAP_LINEAR
    int magFilter = 0x2601; // GL_LINEAR
    int wrapS = 0x2901;     // GL_REPEAT
    int wrapT = 0x2901;
};

struct SceneTexture {
    int image = -1; // index into SceneDescription::images
    bool srgb = false;
    SamplerSettings sampler;
};

enum class AlphaMode { Opaque, Mask, Blend };

struct SceneMaterial {
    std::string name;
    glm::vec4 baseColour{1.0f};      // linear factor (texture is sRGB, decoded to linear by GL)
    int baseColourTexture = -1;      // indices into SceneDescription::textures; -1: none
    int normalTexture = -1;
    float normalScale = 1.0f;
    glm::vec3 emissive{0.0f};        // emissiveFactor x KHR_materials_emissive_strength
    int emissiveTexture = -1;
    int depthTexture = -1;           // T10_materials_parallax: 0 = top, 1 = deepest
    float parallaxScale = 0.0f;      // UV units of the deepest point
    float shininess = 32.0f;         // Blinn-Phong exponent
    float specular = 0.0f;           // specular weight
    bool doubleSided = false;
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
};

struct SceneMesh {
    std::string name;                // "<mesh name>/<primitive>" for messages
    std::vector<SceneVertex> vertices;
    std::vector<std::uint32_t> indices; // triangle list, counter-clockwise front faces
    int material = -1;               // index into materials; the loader always sets one
};

struct SceneLight {
    std::string name;
    bool spot = false;
    glm::vec3 position{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f}; // spot lights: where the cone points
    glm::vec3 intensity{1.0f};       // colour x glTF intensity: candela, the numerator of 1/d^2
    float range = 0.0f;              // 0: unlimited
    float innerConeCos = 1.0f;
    float outerConeCos = 0.0f;
};

// The most lights a scene uses: the size of Scene.frag's Lights block arrays (Scene uploads that many;
// the loader warns about the rest).
constexpr std::size_t kMaxSceneLights = 8;

struct SceneDescription {
    std::string source;              // the file it came from
    std::vector<Image8> images;      // bottom row first; 1, 3 or 4 channels
    std::vector<SceneTexture> textures;
    std::vector<SceneMaterial> materials;
    std::vector<SceneMesh> meshes;
    std::vector<SceneLight> lights;
    std::vector<CameraPreset> cameras; // the file's cameras, then "framing" (the whole scene)
    std::vector<std::string> warnings; // one line per kind of thing skipped or approximated
    std::size_t triangleCount = 0;
    std::size_t vertexCount = 0;
    bool defaultLights = false;      // the file had no lights: the default rig was added
    glm::vec3 boundsMin{0.0f};
    glm::vec3 boundsMax{0.0f};

    // nullptr when there is no camera of that name.
    const CameraPreset* findCamera(const std::string& name) const;
    std::string cameraNames() const; // "a, b, c" for messages
};

struct GltfLoadLimits {
    // After node instancing (a small file can instance one mesh many times): 2^23 triangles and
    // 2^24 vertices keep the CPU copy under about 1.5 GiB.
    std::size_t maxTriangles = std::size_t(1) << 23;
    std::size_t maxVertices = std::size_t(1) << 24;
    // Images: each side at most this, and at most maxImagePixels in all images together.
    int maxImageSide = 16384;
    std::size_t maxImagePixels = std::size_t(1) << 28;
    // false: external files (buffers, images) are refused (the fuzzer reads only memory).
    bool allowExternalFiles = true;
};

// The committed built-in scene (common/assets/scene.gltf, written by tools/make_scene).
std::string builtInScenePath();

// Reads a .gltf or .glb file. Throws t10::Error("<path>: <fault>").
SceneDescription loadGltfScene(const std::string& path, const GltfLoadLimits& limits = {});
// The same from memory: `name` is used in messages, external references resolve against baseDir.
SceneDescription loadGltfSceneFromMemory(const std::uint8_t* bytes, std::size_t size, const std::string& name,
                                         const std::string& baseDir, const GltfLoadLimits& limits = {});

} // namespace t10
