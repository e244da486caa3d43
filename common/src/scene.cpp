// The HDR scene every stage renders: a dim, closed brick room with a tiled floor, a timbered ceiling
// and three wooden crates, all parallax-occlusion and normal mapped, lit per fragment by a few HDR
// point lights: small lamps drawn as very bright emissive cubes, and daylight through a window in
// the back wall. Luminance spans more than three decades (median about 0.03, sources up to 80).
// Output goes to the GL_RGBA16F accumulation texture, which stays bound to texture unit 15 for the
// post-process stages.
#include "t10/scene.hpp"

#include "t10/error.hpp"
#include "t10/framebuffer.hpp"
#include "t10/texture.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>

namespace t10 {

namespace {

constexpr int kMaxLights = 8; // the size of the Lights block arrays in Scene.frag and Light.vert
constexpr GLuint kCameraBinding = 0;
constexpr GLuint kLightBinding = 1; // binding 7 belongs to the stages' InvResolution block
constexpr GLuint kDiffuseUnit = 0;
constexpr GLuint kNormalUnit = 1;
constexpr GLuint kDepthUnit = 2;
// Explicit uniform locations in Scene.frag and Light.vert.
constexpr GLint kParallaxScaleLocation = 0;
constexpr GLint kShininessLocation = 1;
constexpr GLint kSpecularLocation = 2;
constexpr GLint kEmissionLocation = 3;
constexpr GLint kLightHalfSizeLocation = 0;
constexpr GLint kLightRadianceLocation = 1;

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

// The parallax scales must match the normal maps' depth in make_textures.cpp (scale x 256 texels).
constexpr float kBrickParallax = 0.04f;
constexpr float kTileParallax = 0.02f;
constexpr float kCrateParallax = 0.06f;

// std140 mirrors of the uniform blocks (vec4/mat4 members only, so no padding surprises).
struct CameraBlock {
    glm::mat4 view;
    glm::mat4 projection;
    glm::vec4 position;
};

struct LightBlock {
    glm::vec4 position[kMaxLights];
    glm::vec4 colour[kMaxLights];
    glm::ivec4 count; // only .x is read (int iLightCount)
};

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

} // namespace

struct Scene::Material {
    Texture diffuse;
    Texture normal;
    Texture depth;
    float parallaxScale;
    float shininess;
    float specular;
    glm::vec3 emission{0.0f}; // light the surface gives off (times its albedo); only the window
};

struct Scene::Mesh {
    VertexArray vao;
    Buffer vertices;
    Buffer indices;
    GLsizei indexCount = 0;
    // Index into materials_; -1 marks the light cube, drawn once per light with Light.vert/frag.
    int material = -1;
};

namespace {

// Fills the buffers and records the vertex layout (attribute locations 0-5 of Scene.vert) in `vao`.
void uploadGeometry(const MeshData& data, GLuint vao, GLuint vertices, GLuint indices) {
    glBindVertexArray(vao);
    glBindBuffer(GL_ARRAY_BUFFER, vertices);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.vertices.size() * sizeof(Vertex)),
                 data.vertices.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices); // recorded in the vertex array
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.indices.size() * sizeof(GLuint)),
                 data.indices.data(), GL_STATIC_DRAW);
    struct Attribute {
        GLuint location;
        GLint size;
        std::size_t offset;
    };
    const Attribute attributes[] = {
        {0, 3, offsetof(Vertex, position)}, {1, 3, offsetof(Vertex, normal)},
        {2, 3, offsetof(Vertex, tangent)},  {3, 3, offsetof(Vertex, bitangent)},
        {4, 2, offsetof(Vertex, uv)},       {5, 4, offsetof(Vertex, uvBounds)},
    };
    for (const Attribute& a : attributes) {
        glEnableVertexAttribArray(a.location);
        glVertexAttribPointer(a.location, a.size, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                              reinterpret_cast<const void*>(a.offset));
    }
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

} // namespace

Scene::Scene(const ShaderManager& shaders, const std::filesystem::path& assetDir) {
    surfaceProgram_ = Program(shaders.createProgram({"Scene.vert", "Scene.frag"}));
    lightProgram_ = Program(shaders.createProgram({"Light.vert", "Light.frag"}));

    auto loadMaterial = [&](const std::string& name, float parallaxScale, float shininess, float specular) {
        const auto file = [&](const char* kind) { return (assetDir / (name + kind)).string(); };
        return Material{loadTextureTga(file("_diffuse.tga"), true), loadTextureTga(file("_normal.tga"), false),
                        loadTextureTga(file("_depth.tga"), false), parallaxScale, shininess, specular};
    };
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

    const float w = kRoomMaxX - kRoomMinX;
    const float d = kRoomMaxZ - kRoomMinZ;
    const float h = kRoomHeight;
    const float wallMargin = kBrickParallax * kWallMetresPerUv;
    const float floorMargin = kTileParallax * kFloorMetresPerUv;
    const float ceilingMargin = kCrateParallax * kCeilingMetresPerUv;

    auto addMesh = [&](const MeshData& data, int material) {
        Mesh mesh;
        mesh.vao = makeVertexArray();
        mesh.vertices = makeBuffer();
        mesh.indices = makeBuffer();
        mesh.indexCount = static_cast<GLsizei>(data.indices.size());
        mesh.material = material;
        uploadGeometry(data, mesh.vao.get(), mesh.vertices.get(), mesh.indices.get());
        meshes_.push_back(std::move(mesh));
    };

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

    LightBlock lightBlock{};
    for (std::size_t i = 0; i < lights_.size() && i < kMaxLights; ++i) {
        lightBlock.position[i] = glm::vec4(lights_[i].position, 1.0f);
        lightBlock.colour[i] = glm::vec4(lights_[i].colour, 1.0f);
    }
    lightBlock.count.x = static_cast<int>(std::min<std::size_t>(lights_.size(), kMaxLights));
    lightUbo_ = makeBuffer();
    glBindBuffer(GL_UNIFORM_BUFFER, lightUbo_.get());
    glBufferData(GL_UNIFORM_BUFFER, sizeof(LightBlock), &lightBlock, GL_STATIC_DRAW);
    cameraUbo_ = makeBuffer();
    glBindBuffer(GL_UNIFORM_BUFFER, cameraUbo_.get());
    glBufferData(GL_UNIFORM_BUFFER, sizeof(CameraBlock), nullptr, GL_DYNAMIC_DRAW);
    glBindBuffer(GL_UNIFORM_BUFFER, 0);
}

Scene::~Scene() = default;

void Scene::resize(int width, int height) {
    if (width < 1 || height < 1)
        throw Error("Scene::resize: invalid size " + std::to_string(width) + "x" + std::to_string(height));
    width_ = width;
    height_ = height;

    // Immutable storage cannot change size, so a resize makes new objects.
    framebuffer_.reset();
    accumulation_ = makeTexture();
    glActiveTexture(GL_TEXTURE0 + contract::kAccumulationUnit);
    glBindTexture(GL_TEXTURE_2D, accumulation_.get());
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA16F, width, height);
    // One level only, so a non-mipmap filter; clamping keeps edge taps from wrapping around.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glActiveTexture(GL_TEXTURE0);

    depth_ = makeRenderbuffer();
    glBindRenderbuffer(GL_RENDERBUFFER, depth_.get());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);

    framebuffer_ = makeFramebuffer();
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, accumulation_.get(), 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.get());
    requireCompleteFramebuffer(GL_FRAMEBUFFER, "Scene: accumulation framebuffer");
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void Scene::setInputImage(std::optional<ImageF> image) {
    if (image && image->channels != 3 && image->channels != 4)
        throw Error("Scene: an input image needs 3 or 4 channels, not " + std::to_string(image->channels));
    input_ = std::move(image);
}

void Scene::render(const Camera& camera) {
    if (!framebuffer_) throw Error("Scene::render called before Scene::resize");
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
    glViewport(0, 0, width_, height_);
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);

    if (input_) {
        if (input_->width != width_ || input_->height != height_)
            throw Error("Scene: input image is " + std::to_string(input_->width) + "x" +
                        std::to_string(input_->height) + " but the scene is " + std::to_string(width_) + "x" +
                        std::to_string(height_));
        glClear(GL_DEPTH_BUFFER_BIT);
        GLint previousAlignment = 4;
        glGetIntegerv(GL_UNPACK_ALIGNMENT, &previousAlignment);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glActiveTexture(GL_TEXTURE0 + contract::kAccumulationUnit);
        glBindTexture(GL_TEXTURE_2D, accumulation_.get());
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width_, height_, input_->channels == 3 ? GL_RGB : GL_RGBA,
                        GL_FLOAT, input_->data.data());
        glActiveTexture(GL_TEXTURE0);
        glPixelStorei(GL_UNPACK_ALIGNMENT, previousAlignment);
        return;
    }

    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDisable(GL_BLEND);
    // The room is seen from inside and the crates from outside: back faces are never visible.
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);

    const CameraBlock cameraBlock{camera.view(),
                                  camera.projection(static_cast<float>(width_) / static_cast<float>(height_)),
                                  glm::vec4(camera.position(), 1.0f)};
    glBindBuffer(GL_UNIFORM_BUFFER, cameraUbo_.get());
    glBufferSubData(GL_UNIFORM_BUFFER, 0, sizeof(CameraBlock), &cameraBlock);
    glBindBuffer(GL_UNIFORM_BUFFER, 0);
    glBindBufferBase(GL_UNIFORM_BUFFER, kCameraBinding, cameraUbo_.get());
    glBindBufferBase(GL_UNIFORM_BUFFER, kLightBinding, lightUbo_.get());

    glUseProgram(surfaceProgram_.get());
    for (const Mesh& mesh : meshes_) {
        if (mesh.material < 0) continue;
        const Material& m = materials_[static_cast<std::size_t>(mesh.material)];
        glActiveTexture(GL_TEXTURE0 + kDiffuseUnit);
        glBindTexture(GL_TEXTURE_2D, m.diffuse.get());
        glActiveTexture(GL_TEXTURE0 + kNormalUnit);
        glBindTexture(GL_TEXTURE_2D, m.normal.get());
        glActiveTexture(GL_TEXTURE0 + kDepthUnit);
        glBindTexture(GL_TEXTURE_2D, m.depth.get());
        glUniform1f(kParallaxScaleLocation, m.parallaxScale);
        glUniform1f(kShininessLocation, m.shininess);
        glUniform1f(kSpecularLocation, m.specular);
        glUniform3fv(kEmissionLocation, 1, &m.emission.x);
        glBindVertexArray(mesh.vao.get());
        glDrawElements(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT, nullptr);
    }

    glUseProgram(lightProgram_.get());
    glUniform1f(kLightHalfSizeLocation, kLightCubeHalfSize);
    glUniform1f(kLightRadianceLocation, kLampRadiancePerIntensity);
    const auto lightCount = static_cast<GLsizei>(std::min<std::size_t>(lights_.size(), kMaxLights));
    for (const Mesh& mesh : meshes_) {
        if (mesh.material >= 0) continue;
        glBindVertexArray(mesh.vao.get());
        glDrawElementsInstanced(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT, nullptr, lightCount);
    }

    glBindVertexArray(0);
    glUseProgram(0);
    glDisable(GL_CULL_FACE);
    // Units 0..2 held the materials; unit 15 was never touched and still holds the accumulation.
    glActiveTexture(GL_TEXTURE0);
}

} // namespace t10
