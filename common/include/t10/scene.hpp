// The scene as it stands before Tutorial 10: a room (floor, walls) and boxes with normal mapping and
// parallax occlusion mapping, lit per fragment (Blinn-Phong) by HDR point lights that are also drawn
// as emissive cubes. It renders into a GL_RGBA16F accumulation texture that stays bound to texture
// unit 15, which is what every post-process stage reads.
#pragma once
#include "t10/camera.hpp"
#include "t10/contract.hpp"
#include "t10/gl_object.hpp"
#include "t10/image.hpp"
#include "t10/shader.hpp"

#include <filesystem>
#include <optional>
#include <vector>

namespace t10 {

struct PointLight {
    glm::vec3 position;
    glm::vec3 colour; // linear HDR intensity it lights the room with (components up to 2.4); its cube shows 40x that
};

class Scene {
public:
    // Loads the TGA textures from assetDir and the scene shaders through `shaders`.
    Scene(const ShaderManager& shaders, const std::filesystem::path& assetDir);
    ~Scene();
    Scene(const Scene&) = delete;
    Scene& operator=(const Scene&) = delete;

    // (Re)creates the accumulation texture (GL_RGBA16F) and its depth buffer at this size and binds
    // the texture to unit 15. Width and height must be at least 1.
    void resize(int width, int height);

    // Renders into the accumulation framebuffer with depth testing, leaving it bound for drawing.
    // With an input image set, uploads that image instead of drawing the room.
    void render(const Camera& camera);

    // Replaces the room by a fixed HDR image (the --input option and the numeric tests). The image
    // must match the size given to resize(); channels 3 or 4.
    void setInputImage(std::optional<ImageF> image);

    GLuint accumulationTexture() const { return accumulation_.get(); }
    int width() const { return width_; }
    int height() const { return height_; }

private:
    struct Mesh;
    struct Material;
    std::vector<Mesh> meshes_;
    std::vector<Material> materials_;
    std::vector<PointLight> lights_;
    Program surfaceProgram_;
    Program lightProgram_;
    Buffer cameraUbo_;
    Buffer lightUbo_;
    Texture accumulation_;
    Renderbuffer depth_;
    Framebuffer framebuffer_;
    std::optional<ImageF> input_;
    int width_ = 0;
    int height_ = 0;
};

} // namespace t10
