// The program every stage runs: parse the command line, create the context, build the scene,
// call the stage's GL_Init / GL_Render / GL_Quit, handle input and resizes, and write the requested
// images. A stage's main() is one call to runStage().
#pragma once
#include "t10/camera.hpp"
#include "t10/cli.hpp"
#include "t10/context.hpp"
#include "t10/framebuffer.hpp"
#include "t10/gl_errors.hpp"
#include "t10/quad.hpp"
#include "t10/scene.hpp"
#include "t10/shader.hpp"
#include "t10/views.hpp"

#include <memory>

namespace t10 {

class App;

// What a stage hands to runStage(). The functions keep the tutorial's names in the stage.
struct Stage {
    const char* name;      // the stage folder, e.g. "tutorial10_part1_tonemap"
    const char* summary;   // one line for --help
    const char* shaderDir; // the stage's folder, fixed at configure time
    bool (*init)(App&);    // GL_Init: create programs, buffers and size-dependent objects
    void (*render)(App&);  // GL_Render: scene, then post-process into framebuffer 0
    void (*quit)();        // GL_Quit: delete everything GL_Init created
    AddOptionsHook addOptions = {};
};

class App {
public:
    App(const Stage& stage, const Options& options, Context& context);
    ~App();

    // Current framebuffer size (the stage copies it into g_iWindowWidth / g_iWindowHeight).
    int width() const { return width_; }
    int height() const { return height_; }
    const Options& options() const { return options_; }
    const ShaderManager& shaders() const { return shaders_; }
    Scene& scene() { return *scene_; }
    const Camera& camera() const { return camera_; }
    const FullScreenQuad& quad() const { return *quad_; }
    Context& context() { return context_; }
    // Milliseconds the last frame took (render + glFinish headless; swap to swap in a window).
    double frameTimeMs() const { return frameTimeMs_; }
    // The view selector (--view, the V key, the extras panel's list).
    ViewService& views() { return *views_; }

    // Renders until the frame count is reached or the window closes; returns the exit code.
    int run();

private:
    void resize(int width, int height);
    void handleInput(double seconds);
    void writeOutputs();

    const Stage& stage_;
    Options options_;
    Context& context_;
    ShaderManager shaders_;
    std::unique_ptr<FullScreenQuad> quad_;
    std::unique_ptr<Scene> scene_;
    Camera camera_;
    int width_ = 0;
    int height_ = 0;
    bool stageReady_ = false;
    double frameTimeMs_ = 0.0;
    bool lookActive_ = false;
    double lastCursorX_ = 0.0;
    double lastCursorY_ = 0.0;
    std::unique_ptr<GlErrorLog> glErrors_;
    std::unique_ptr<ViewService> views_;
};

// Runs a stage; returns the process exit code (0, 1 for runtime errors, 2 for bad usage).
int runStage(int argc, const char* const* argv, const Stage& stage);

// Reads the default framebuffer (what the window shows) as 8-bit RGB, bottom row first.
Image8 readDefaultFramebuffer(int width, int height);
// Reads one level of a 2D texture as float with 1 or 3 channels (or 4 with rgba = true).
ImageF readTextureLevel(GLuint texture, int level, bool rgba = false);

} // namespace t10
