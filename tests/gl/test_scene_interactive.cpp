// The window's interactive shortcuts in Scene (t10/interactive.hpp): render-on-change must skip only
// an unchanged view, and the frame after the camera stops must be exactly the full-quality frame
// (what headless renders and the golden images show).
#include "gl_context.hpp"

#include "t10/gl_object.hpp"
#include "t10/gltf_scene.hpp"
#include "t10/interactive.hpp"
#include "t10/readback.hpp"
#include "t10/scene.hpp"

#include "t10_catch.hpp"

#include <memory>

namespace {

constexpr int kSide = 96;

t10::ImageF renderAccumulation(t10::Scene& scene, const t10::Camera& camera) {
    scene.render(camera);
    return t10::readTextureLevel(scene.accumulationTexture(), 0);
}

// Marks the accumulation texture so that a skipped render is visible.
void paint(const t10::Scene& scene) {
    const t10::Framebuffer framebuffer = t10::makeFramebuffer();
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.get());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, scene.accumulationTexture(), 0);
    glClearColor(1.0f, 2.0f, 3.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace

TEST_CASE("render-on-change skips an unchanged view and redraws a still one at full quality", "[scene]") {
    const auto context = t10::test::makeTestContext();
    const t10::ShaderManager shaders({T10_COMMON_SHADER_DIR});
    const t10::SceneDescription description = t10::loadGltfScene(t10::builtInScenePath());
    t10::Scene scene(shaders, description);
    scene.resize(kSide, kSide);
    t10::Camera camera(description.cameras.front());
    t10::Camera moved = camera;
    moved.look(40.0f, 25.0f); // a grazing view of the floor: the parallax search needs many layers

    const t10::ImageF full = renderAccumulation(scene, moved);   // the default: every frame drawn
    scene.setRenderOnChange(true, 10.0f);
    const t10::ImageF first = renderAccumulation(scene, moved);  // nothing drawn yet: full quality
    CHECK(first.data == full.data);

    paint(scene);
    const t10::ImageF skipped = renderAccumulation(scene, moved); // same view: not drawn again
    CHECK(skipped.data != full.data);

    renderAccumulation(scene, camera);                            // moving: 10 layers
    const t10::ImageF moving = renderAccumulation(scene, moved);  // still moving
    CHECK(moving.data != full.data);                              // fewer layers show
    const t10::ImageF still = renderAccumulation(scene, moved);   // stopped: full quality again
    CHECK(still.data == full.data);
}

TEST_CASE("Mesa's CPU rasterisers count as software renderers", "[scene]") {
    CHECK(t10::isSoftwareRenderer("llvmpipe (LLVM 15.0.6, 256 bits)"));
    CHECK(t10::isSoftwareRenderer("softpipe"));
    CHECK_FALSE(t10::isSoftwareRenderer("NVIDIA GeForce RTX 4090/PCIe/SSE2"));
    CHECK_FALSE(t10::isSoftwareRenderer("AMD Radeon RX 7900 XTX (radeonsi, navi31, LLVM 15.0.7, DRM 3.54)"));
}
