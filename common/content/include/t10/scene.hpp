// The scene as it stands before Tutorial 10, drawn from a SceneDescription (a glTF file: the built-in
// room of tools/make_scene, or --scene FILE): normal mapping, parallax occlusion mapping where a
// material has a depth map, per-fragment Blinn-Phong lighting from HDR point and spot lights, and
// emissive surfaces (the bright sources bloom spreads). It renders into a GL_RGBA16F accumulation
// texture that stays bound to texture unit 15, which is what every post-process stage reads.
#pragma once
#include "t10/camera.hpp"
#include "t10/contract.hpp"
#include "t10/gl_object.hpp"
#include "t10/gltf_scene.hpp"
#include "t10/image.hpp"
#include "t10/shader.hpp"

#include <optional>
#include <vector>

namespace t10 {

class Scene {
public:
    // Uploads the description's geometry and textures; loads the scene shaders through `shaders`.
    Scene(const ShaderManager& shaders, const SceneDescription& description);
    // A fixed HDR image in place of the room (the --input option and the numeric tests): no room is
    // loaded, uploaded or compiled, since none is drawn. The image needs 3 or 4 channels and must
    // match the size given to resize().
    explicit Scene(ImageF input);
    ~Scene();
    Scene(const Scene&) = delete;
    Scene& operator=(const Scene&) = delete;

    // (Re)creates the accumulation texture (GL_RGBA16F) and its depth buffer at this size and binds
    // the texture to unit 15. Width and height must be at least 1.
    void resize(int width, int height);

    // Renders into the accumulation framebuffer with depth testing, leaving it bound for drawing.
    // A scene made from an input image uploads that image instead (the camera does not matter).
    void render(const Camera& camera);

    // Interactive speed on software renderers (the window sets these; headless renders keep the
    // defaults, so the golden images do not change). With render-on-change, render() skips drawing
    // when the camera and the size are those of the last full-quality frame (the accumulation
    // texture still holds it); while the camera moves the parallax search takes at most
    // `movingLayers` steps (default 100, at least 10), and the first frame after it stops is drawn
    // at full quality again, so a still view looks exactly like a headless render.
    void setRenderOnChange(bool on, float movingLayers = 100.0f) {
        renderOnChange_ = on;
        movingParallaxLayers_ = movingLayers;
        lastCamera_.clear();
    }

    GLuint accumulationTexture() const { return accumulation_.get(); }
    int width() const { return width_; }
    int height() const { return height_; }

private:
    struct Mesh;
    struct Material;
    std::vector<SceneMaterial> description_; // the materials' settings, which materials_ point into
    std::vector<Mesh> meshes_;
    std::vector<Material> materials_;
    std::vector<Texture> textures_;
    Texture whiteTexture_;  // stands in for a missing base colour or emissive texture
    Texture flatNormalTexture_;
    Texture flatDepthTexture_;
    std::vector<SceneLight> lights_;
    Program surfaceProgram_;
    Buffer cameraUbo_;
    Buffer lightUbo_;
    Texture accumulation_;
    Renderbuffer depth_;
    Framebuffer framebuffer_;
    std::optional<ImageF> input_;
    int width_ = 0;
    int height_ = 0;
    float movingParallaxLayers_ = 100.0f;
    bool renderOnChange_ = false;
    std::vector<float> lastCamera_; // the camera block of the last drawn frame (empty: none)
    bool lastFull_ = false;         // that frame was drawn at full quality
};

} // namespace t10
