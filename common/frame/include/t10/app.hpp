// The frame loop every stage runs: runStage() parses the command line (each service's options
// group, composed in settings.hpp) and creates the context;
// App owns the scene, the camera and the quad, calls the stage's GL_Init / GL_Render / GL_Quit,
// follows resizes and rebuild requests, and hands the rest to services: camera_input (keys and
// mouse), outputs (the files after the last frame), bench (--bench), views (--view, drawn over the
// stage's frame before the UI) and the stage's UI host. A FrameObserver (frame_observer.hpp, the
// capture hook) sees the stage's render and each of its draws.
// A stage's main() is one call to runStage().
#pragma once
#include "t10/camera.hpp"
#include "t10/camera_input.hpp"
#include "t10/context.hpp"
#include "t10/frame_observer.hpp"
#include "t10/framebuffer.hpp"
#include "t10/gl_errors.hpp"
#include "t10/quad.hpp"
#include "t10/scene.hpp"
#include "t10/settings.hpp"
#include "t10/shader.hpp"
#include "t10/stage.hpp"
#include "t10/ui_host.hpp"
#include "t10/views.hpp"

#include <memory>
#include <string>
#include <vector>

namespace t10 {

class App {
public:
    App(const Stage& stage, const Settings& settings, Context& context);
    ~App();
    App(const App&) = delete;
    App& operator=(const App&) = delete;

    // Current framebuffer size (the stage copies it into g_iWindowWidth / g_iWindowHeight).
    int width() const { return width_; }
    int height() const { return height_; }
    const ShaderManager& shaders() const { return shaders_; }
    Scene& scene() { return *scene_; }
    const Camera& camera() const { return camera_; }
    const FullScreenQuad& quad() const { return *quad_; }
    Context& context() { return context_; }
    // Milliseconds the last frame took (render + glFinish headless; swap to swap in a window).
    double frameTimeMs() const { return frameTimeMs_; }
    // The view selector (--view, V / Shift+V and T in a window, the list in extras' panel).
    ViewService& views() { return *views_; }

    // The stage's size-independent settings changed what GL_Init makes (extras' luminance format):
    // GL_Quit, then GL_Init at the current size, before the next frame.
    void requestRebuild() { rebuildRequested_ = true; }
    // The capture hook: `observer` sees every later frame's render and its draws (nullptr: none).
    // --capture-passes DIR installs the pass capture here.
    void setObserver(std::unique_ptr<FrameObserver> observer) { observer_ = std::move(observer); }

    // Renders until the frame count is reached or the window closes; returns the exit code (the
    // desktop's loop, app_native.cpp: in the browser the page's loop drives the App frame by frame).
    int run();
    // One frame of the stage into framebuffer 0: a requested rebuild, then GL_Render inside the
    // stage's pass timers (and inside the observer's hooks, if one is set). No input, UI, outputs or swap (the bench driver is handed exactly this).
    void renderFrame();

private:
    friend class WebPage; // the browser's page loop (app_web.cpp), which reaches the services below

    void loadScene(bool buildRoom); // --scene (or the built-in scene) and --camera; the room's GL objects if buildRoom
    void setUpWindow(); // the platform's part of a window's start-up (app_native.cpp: --input's size, the stage's UI)
    void resize(int width, int height);
    void buildStage();
    void quitStage();
    void followSize(int frame);
    void drawUi();
    void checkGlErrors(const std::string& when);
    // run()'s helpers (app_native.cpp).
    void showFrameTimeInTitle();
    void printFrameTimes(const std::vector<double>& times) const;
    void runBenchmark();

    const Stage& stage_;
    Settings settings_;
    Context& context_;
    ShaderManager shaders_;
    std::unique_ptr<FullScreenQuad> quad_;
    std::unique_ptr<Scene> scene_;
    Camera camera_;
    std::unique_ptr<CameraInput> input_;
    std::unique_ptr<UiHost> ui_;
    int width_ = 0;
    int height_ = 0;
    bool stageReady_ = false;
    bool rebuildRequested_ = false;
    double frameTimeMs_ = 0.0;
    std::unique_ptr<GlErrorLog> glErrors_;
    std::unique_ptr<ViewService> views_;
    std::unique_ptr<ViewKeys> viewKeys_;
    std::unique_ptr<FrameObserver> observer_;
};

// Runs a stage; returns the process exit code (0, 1 for runtime errors, 2 for bad usage).
// `--then` starts another run of the stage in the same process and headless context after the
// previous run's outputs are written, with options of its own (everything up to the next --then):
// t10-grade renders all the cases of a submission in one process, since a process's start-up
// (driver, LLVM's code for the scene's shaders, the scene) costs more than its small frames. Before
// each later run the context gets that run's size and the GL state it started with (gl_defaults.hpp),
// and contract::kThenMarker, the run's number and the count are printed on a line of their own.
int runStage(int argc, const char* const* argv, const Stage& stage);

} // namespace t10
