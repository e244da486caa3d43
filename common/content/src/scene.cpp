// The HDR scene every stage renders, drawn from a SceneDescription (see gltf_scene.hpp): the built-in
// room with its crates and light cubes (tools/make_scene) or a user's glTF file. Output goes to the
// GL_RGBA16F accumulation texture, which stays bound to texture unit 15 for the post-process stages.
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

constexpr GLuint kCameraBinding = 0;
constexpr GLuint kLightBinding = 1; // binding 7 belongs to the stages' InvResolution block
constexpr GLuint kDiffuseUnit = 0;
constexpr GLuint kNormalUnit = 1;
constexpr GLuint kDepthUnit = 2;
constexpr GLuint kEmissiveUnit = 3;
// Explicit uniform locations in Scene.frag.
constexpr GLint kParallaxScaleLocation = 0;
constexpr GLint kShininessLocation = 1;
constexpr GLint kSpecularLocation = 2;
constexpr GLint kBaseColourLocation = 3;
constexpr GLint kEmissiveLocation = 4;
constexpr GLint kAlphaModeLocation = 5;
constexpr GLint kAlphaCutoffLocation = 6;
constexpr GLint kNormalScaleLocation = 7;
constexpr GLint kMaxParallaxLayersLocation = 8;
constexpr float kFullParallaxLayers = 100.0f; // Scene.frag's search at grazing angles

// std140 mirrors of the uniform blocks (vec4/mat4 members only, so no padding surprises).
struct CameraBlock {
    glm::mat4 view;
    glm::mat4 projection;
    glm::vec4 position;
};

struct LightBlock {
    glm::vec4 position[kMaxSceneLights];  // xyz: world position
    glm::vec4 colour[kMaxSceneLights];    // rgb: intensity (the numerator of the 1/d^2 falloff)
    glm::vec4 spot[kMaxSceneLights];      // xyz: cone direction, w: cos(outer angle); -2 for point lights
    glm::vec4 cone[kMaxSceneLights];      // x: cos(inner angle), y: 1/range (0: unlimited)
    glm::ivec4 count; // only .x is read (int iLightCount)
};

// Fills the buffers and records the vertex layout (attribute locations 0-5 of Scene.vert) in `vao`.
void uploadGeometry(const SceneMesh& data, GLuint vao, GLuint vertices, GLuint indices) {
    glBindVertexArray(vao);
    glBindBuffer(GL_ARRAY_BUFFER, vertices);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.vertices.size() * sizeof(SceneVertex)),
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
        {0, 3, offsetof(SceneVertex, position)}, {1, 3, offsetof(SceneVertex, normal)},
        {2, 3, offsetof(SceneVertex, tangent)},  {3, 3, offsetof(SceneVertex, bitangent)},
        {4, 2, offsetof(SceneVertex, uv)},       {5, 4, offsetof(SceneVertex, uvBounds)},
    };
    for (const Attribute& a : attributes) {
        glEnableVertexAttribArray(a.location);
        glVertexAttribPointer(a.location, a.size, GL_FLOAT, GL_FALSE, sizeof(SceneVertex),
                              reinterpret_cast<const void*>(a.offset));
    }
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

Texture onePixel(std::uint8_t r, std::uint8_t g, std::uint8_t b, bool srgb) {
    Image8 image(1, 1, 3);
    image.data = {r, g, b};
    return uploadTexture(image, srgb);
}

} // namespace

struct Scene::Material {
    GLuint diffuse;  // texture names owned by Scene::textures_ or the one-pixel stand-ins
    GLuint normal;
    GLuint depth;
    GLuint emissive;
    const SceneMaterial* data;
};

struct Scene::Mesh {
    VertexArray vao;
    Buffer vertices;
    Buffer indices;
    GLsizei indexCount = 0;
    int material = 0; // index into materials_
};

Scene::Scene(const ShaderManager& shaders, const SceneDescription& description)
    : description_(description.materials) {
    surfaceProgram_ = Program(shaders.createProgram({"Scene.vert", "Scene.frag"}));

    whiteTexture_ = onePixel(255, 255, 255, true);
    flatNormalTexture_ = onePixel(128, 128, 255, false);
    flatDepthTexture_ = onePixel(0, 0, 0, false);
    for (const SceneTexture& t : description.textures) {
        const Image8& source = description.images.at(static_cast<std::size_t>(t.image));
        TextureSampling sampling{t.sampler.minFilter, t.sampler.magFilter, t.sampler.wrapS, t.sampler.wrapT};
        if (t.srgb && source.channels == 1) {
            // Grey colour data is still sRGB-encoded; GL has no one-channel sRGB format.
            Image8 rgb(source.width, source.height, 3);
            for (std::size_t i = 0; i < source.data.size(); ++i)
                rgb.data[3 * i] = rgb.data[3 * i + 1] = rgb.data[3 * i + 2] = source.data[i];
            textures_.push_back(uploadTexture(rgb, true, sampling));
        } else {
            textures_.push_back(uploadTexture(source, t.srgb, sampling));
        }
    }
    auto textureOr = [&](int index, const Texture& fallback) {
        return index >= 0 ? textures_.at(static_cast<std::size_t>(index)).get() : fallback.get();
    };
    for (const SceneMaterial& m : description_) {
        materials_.push_back({textureOr(m.baseColourTexture, whiteTexture_), textureOr(m.normalTexture, flatNormalTexture_),
                              textureOr(m.depthTexture, flatDepthTexture_), textureOr(m.emissiveTexture, whiteTexture_),
                              &m});
    }

    // Opaque meshes first, in the file's order, then the blended ones (drawn over them).
    for (int pass = 0; pass < 2; ++pass) {
        for (const SceneMesh& data : description.meshes) {
            const bool blended = description_.at(static_cast<std::size_t>(data.material)).alphaMode == AlphaMode::Blend;
            if (blended != (pass == 1)) continue;
            Mesh mesh;
            mesh.vao = makeVertexArray();
            mesh.vertices = makeBuffer();
            mesh.indices = makeBuffer();
            mesh.indexCount = static_cast<GLsizei>(data.indices.size());
            mesh.material = data.material;
            uploadGeometry(data, mesh.vao.get(), mesh.vertices.get(), mesh.indices.get());
            meshes_.push_back(std::move(mesh));
        }
    }

    lights_ = description.lights;
    LightBlock lightBlock{};
    for (std::size_t i = 0; i < lights_.size() && i < kMaxSceneLights; ++i) {
        const SceneLight& l = lights_[i];
        lightBlock.position[i] = glm::vec4(l.position, 1.0f);
        lightBlock.colour[i] = glm::vec4(l.intensity, 1.0f);
        lightBlock.spot[i] = glm::vec4(l.direction, l.spot ? l.outerConeCos : -2.0f);
        lightBlock.cone[i] = glm::vec4(l.spot ? l.innerConeCos : 1.0f, l.range > 0.0f ? 1.0f / l.range : 0.0f, 0, 0);
    }
    lightBlock.count.x = static_cast<int>(std::min<std::size_t>(lights_.size(), kMaxSceneLights));
    lightUbo_ = makeBuffer();
    glBindBuffer(GL_UNIFORM_BUFFER, lightUbo_.get());
    glBufferData(GL_UNIFORM_BUFFER, sizeof(LightBlock), &lightBlock, GL_STATIC_DRAW);
    cameraUbo_ = makeBuffer();
    glBindBuffer(GL_UNIFORM_BUFFER, cameraUbo_.get());
    glBufferData(GL_UNIFORM_BUFFER, sizeof(CameraBlock), nullptr, GL_DYNAMIC_DRAW);
    glBindBuffer(GL_UNIFORM_BUFFER, 0);
}

Scene::Scene(ImageF input) {
    if (input.channels != 3 && input.channels != 4)
        throw Error("Scene: an input image needs 3 or 4 channels, not " + std::to_string(input.channels));
    input_ = std::move(input);
}

Scene::~Scene() = default;

void Scene::resize(int width, int height) {
    if (width < 1 || height < 1)
        throw Error("Scene::resize: invalid size " + std::to_string(width) + "x" + std::to_string(height));
    width_ = width;
    height_ = height;
    lastCamera_.clear(); // a new accumulation texture holds nothing yet

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

    const CameraBlock cameraBlock{camera.view(),
                                  camera.projection(static_cast<float>(width_) / static_cast<float>(height_)),
                                  glm::vec4(camera.position(), 1.0f)};
    // Render on change: the same camera on the same target gives the same image, which is still
    // in the accumulation texture. The state is left as a full render leaves it.
    float parallaxLayers = kFullParallaxLayers;
    if (renderOnChange_) {
        const auto* cameraFloats = reinterpret_cast<const float*>(&cameraBlock);
        std::vector<float> cameraKey(cameraFloats, cameraFloats + sizeof cameraBlock / sizeof(float));
        const bool same = cameraKey == lastCamera_;
        if (same && lastFull_) {
            glUseProgram(0);
            glBindVertexArray(0);
            glActiveTexture(GL_TEXTURE0);
            return;
        }
        // While the camera moves: the moving layer limit; once it stops: one full-quality frame.
        const bool moving = !same && !lastCamera_.empty();
        if (moving) parallaxLayers = movingParallaxLayers_;
        lastFull_ = !moving;
        lastCamera_ = std::move(cameraKey);
    }

    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDisable(GL_BLEND);
    glFrontFace(GL_CCW);
    glCullFace(GL_BACK);

    glBindBuffer(GL_UNIFORM_BUFFER, cameraUbo_.get());
    glBufferSubData(GL_UNIFORM_BUFFER, 0, sizeof(CameraBlock), &cameraBlock);
    glBindBuffer(GL_UNIFORM_BUFFER, 0);
    glBindBufferBase(GL_UNIFORM_BUFFER, kCameraBinding, cameraUbo_.get());
    glBindBufferBase(GL_UNIFORM_BUFFER, kLightBinding, lightUbo_.get());

    glUseProgram(surfaceProgram_.get());
    for (const Mesh& mesh : meshes_) {
        const Material& m = materials_[static_cast<std::size_t>(mesh.material)];
        const SceneMaterial& d = *m.data;
        // Single-sided surfaces are never seen from behind (the room from inside, the crates from
        // outside), so back faces are culled; double-sided ones are lit from the side they show.
        if (d.doubleSided) glDisable(GL_CULL_FACE);
        else glEnable(GL_CULL_FACE);
        // Blended surfaces come last (see the constructor) and do not hide what lies behind them.
        if (d.alphaMode == AlphaMode::Blend) {
            glEnable(GL_BLEND);
            glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            glDepthMask(GL_FALSE);
        }
        glActiveTexture(GL_TEXTURE0 + kDiffuseUnit);
        glBindTexture(GL_TEXTURE_2D, m.diffuse);
        glActiveTexture(GL_TEXTURE0 + kNormalUnit);
        glBindTexture(GL_TEXTURE_2D, m.normal);
        glActiveTexture(GL_TEXTURE0 + kDepthUnit);
        glBindTexture(GL_TEXTURE_2D, m.depth);
        glActiveTexture(GL_TEXTURE0 + kEmissiveUnit);
        glBindTexture(GL_TEXTURE_2D, m.emissive);
        glUniform1f(kParallaxScaleLocation, d.parallaxScale);
        glUniform1f(kShininessLocation, d.shininess);
        glUniform1f(kSpecularLocation, d.specular);
        glUniform4fv(kBaseColourLocation, 1, &d.baseColour[0]);
        glUniform3fv(kEmissiveLocation, 1, &d.emissive[0]);
        glUniform1i(kAlphaModeLocation, static_cast<GLint>(d.alphaMode));
        glUniform1f(kAlphaCutoffLocation, d.alphaCutoff);
        glUniform1f(kNormalScaleLocation, d.normalScale);
        glUniform1f(kMaxParallaxLayersLocation, parallaxLayers);
        glBindVertexArray(mesh.vao.get());
        glDrawElements(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT, nullptr);
    }

    glBindVertexArray(0);
    glUseProgram(0);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    // Units 0..3 held the materials; unit 15 was never touched and still holds the accumulation.
    glActiveTexture(GL_TEXTURE0);
}

} // namespace t10
