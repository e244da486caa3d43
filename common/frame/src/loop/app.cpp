// The frame loop: context, scene, the stage's callbacks, resizes and rebuilds, GL error checks;
// input, output files, the benchmark and the UI are services of their own (see app.hpp).
//
// A window does not render like a headless run on every machine: tuneSceneForWindow()
// (interactive.hpp) makes the scene pass render only when the camera or the size changes, and on
// Mesa's software renderers with fewer parallax layers while the camera moves. Headless runs
// (goldens, numeric tests, benchmarks) render every frame at full quality.
#include "t10/app.hpp"
#include "t10/scene_key.hpp"

#include "t10/bench.hpp"
#include "t10/contract.hpp"
#include "t10/error.hpp"
#include "t10/exposure_check.hpp"
#include "t10/gl_defaults.hpp"
#include "t10/gpu_timers.hpp"
#include "t10/input_image.hpp"
#include "t10/interactive.hpp"
#include "t10/outputs.hpp"
#include "t10/stats.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <numeric>

namespace t10 {

namespace {

[[maybe_unused]] constexpr double kTitleInterval = 0.5; // seconds between title updates (not in the browser build)

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string glString(GLenum name) {
    const auto* text = reinterpret_cast<const char*>(glGetString(name));
    return text != nullptr ? text : "?";
}

std::vector<std::string> shaderSearchPath(const Stage& stage, const SceneSettings& scene) {
    std::vector<std::string> dirs;
    if (!scene.shaderDir.empty()) dirs.emplace_back(scene.shaderDir);
    dirs.emplace_back(stage.shaderDir);
    dirs.emplace_back(T10_COMMON_SHADER_DIR);
    return dirs;
}

} // namespace

App::App(const Stage& stage, const Settings& settings, Context& context)
    : stage_(stage), settings_(settings), context_(context), shaders_(shaderSearchPath(stage, settings.scene)),
      glErrors_(std::make_unique<GlErrorLog>()) {
    glErrors_->installDebugCallback();
    if (settings_.run.verbose) {
        std::cout << "backend:  " << context_.description() << "\n"
                  << "vendor:   " << glString(GL_VENDOR) << "\n"
                  << "renderer: " << glString(GL_RENDERER) << "\n"
                  << "version:  " << glString(GL_VERSION) << "\n";
    }
    // The input image is checked before the scene is built, so a file that cannot be rendered (too
    // large for this context or the memory, a side of 1, no colour channel) is refused at once.
    const SceneSettings& scene = settings_.scene;
    const ContextOptions& size = settings_.context;
    ImageF image;
    if (!scene.input.empty()) image = loadInputImage(scene.input, scene.keepNonFinite, std::cerr);
    quad_ = std::make_unique<FullScreenQuad>();
    views_ = std::make_unique<ViewService>(shaders_, *findView(settings_.views.view));
    views_->showThumbnails(settings_.views.thumbnails);
    context_.framebufferSize(width_, height_);
    if (!scene.input.empty()) {
        if (size.sizeGiven && (image.width != size.width || image.height != size.height)) {
            throw UsageError("--input " + scene.input + " is " + std::to_string(image.width) + "x" +
                             std::to_string(image.height) + " but --size asks for " + std::to_string(size.width) + "x" +
                             std::to_string(size.height));
        }
        if (image.width != width_ || image.height != height_) {
            context_.requestSize(image.width, image.height);
            context_.framebufferSize(width_, height_);
        }
        // The image stands for the room. The room is still read when --scene or --camera names it,
        // so that a wrong name is reported as without --input; otherwise it is not loaded at all (the
        // grader's input cases render in about 40 % less CPU time: no textures, mip levels or shaders).
        if (!scene.scene.empty() || !scene.camera.empty()) loadScene(false);
        scene_ = std::make_unique<Scene>(std::move(image));
    } else {
        loadScene(true);
    }
    if (context_.isWindow()) {
        // Interactive speed without a GPU (t10/interactive.hpp; see the note at the top of this file).
        if (const std::string note = tuneSceneForWindow(*scene_); !note.empty()) std::cout << note << "\n";
        input_ = std::make_unique<CameraInput>(context_.window(), camera_);
        viewKeys_ = std::make_unique<ViewKeys>(context_.window());
#ifndef __EMSCRIPTEN__
        // (The web build has no --input, and its page's controls stand for the UI.)
        if (!scene.input.empty()) glfwSetWindowAttrib(context_.window(), GLFW_RESIZABLE, GLFW_FALSE);
        // After the camera's callbacks, so that the UI's chain to them.
        if (stage_.makeUi != nullptr) ui_ = stage_.makeUi(context_.window());
#endif
    }
    if (stage_.timers != nullptr) stage_.timers->create();
    if (!settings_.outputs.capturePassesDir.empty()) observer_ = makePassCapture(settings_.outputs.capturePassesDir);
}

void App::loadScene(bool buildRoom) {
    const std::string file = settings_.scene.scene.empty() ? builtInScenePath() : settings_.scene.scene;
    const auto start = Clock::now();
    const SceneDescription description = loadGltfScene(file);
    const double loadMs = secondsSince(start) * 1000.0;
    for (const std::string& warning : description.warnings) std::cerr << "warning: " << file << ": " << warning << "\n";
    const CameraPreset* preset =
        settings_.scene.camera.empty() ? &description.cameras.front() : description.findCamera(settings_.scene.camera);
    if (preset == nullptr)
        throw UsageError("--camera " + settings_.scene.camera + ": unknown camera (" + file + " has " +
                         description.cameraNames() + ")");
    camera_ = Camera(*preset);
    if (buildRoom) scene_ = std::make_unique<Scene>(shaders_, description);
    if (settings_.run.verbose) {
        std::cout << "scene:    " << file << ": " << description.triangleCount << " triangles, "
                  << description.materials.size() << " materials, " << description.lights.size()
                  << (description.defaultLights ? " default" : "") << " lights, loaded in " << loadMs << " ms\n";
    }
}

App::~App() {
    quitStage();
    if (stage_.timers != nullptr) stage_.timers->destroy();
    ui_.reset();
}

void App::buildStage() {
    if (!stage_.init(*this)) throw Error(std::string(stage_.name) + ": GL_Init failed");
    stageReady_ = true;
}

void App::quitStage() {
    if (stageReady_) stage_.quit();
    stageReady_ = false;
}

void App::resize(int width, int height) {
    quitStage();
    // A window manager may ignore the size limits: anything below 2x2 is treated like a minimised
    // window (nothing is rendered until it grows again).
    if (width < contract::kMinFramebufferSide || height < contract::kMinFramebufferSide) width = height = 0;
    width_ = width;
    height_ = height;
    if (width == 0 || height == 0) return; // minimised: nothing to render until it comes back
    const std::string& input = settings_.scene.input;
    if (!input.empty() && (width != scene_->width() || height != scene_->height()) && scene_->width() != 0) {
        throw Error("--input " + input + ": the framebuffer cannot be resized while an input image is shown");
    }
    scene_->resize(width, height);
    // Every size-dependent object of the stage is rebuilt exactly as at start-up.
    buildStage();
}

void App::renderFrame() {
    if (rebuildRequested_ && stageReady_) {
        quitStage();
        buildStage();
    }
    rebuildRequested_ = false;
    if (stage_.timers != nullptr) stage_.timers->beginFrame();
    if (observer_ != nullptr) {
        DrawObservation draws(*observer_);
        observer_->beginRender();
        stage_.render(*this);
        observer_->endRender();
    } else {
        stage_.render(*this);
    }
    if (stage_.timers != nullptr) stage_.timers->endFrame();
}

void App::drawUi() {
    if (ui_ == nullptr) return;
    if (stage_.keys != nullptr && !ui_->wantsKeyboard()) stage_.keys(*this);
    if (stage_.panel == nullptr) return;
    ui_->beginFrame();
    stage_.panel(*this);
    ui_->endFrame();
}

void App::checkGlErrors(const std::string& when) {
    glErrors_->pollGetError();
    // A window destroyed from outside fails GL calls on its drawable: the loop ends at the next
    // shouldClose() check, with the outputs' rule deciding the exit code.
    if (context_.isWindow() && context_.shouldClose()) {
        glErrors_->clear();
        return;
    }
    if (!glErrors_->empty()) throw Error("GL error " + when + ":" + glErrors_->describe());
}

#ifndef __EMSCRIPTEN__ // the browser build's loop and runStage are in app_web.cpp
int App::run() {
    // Every output asked for is written after the last frame, or the run fails saying why.
    if (settings_.run.frames == 0 && context_.isWindow() && wantsOutputs(settings_.outputs))
        throw UsageError("--output, --exr and --dump are written after the last of --frames N frames: give --frames");
    const char* const kClosedEarly = "the window was closed before the last frame";
    std::string notWritten = kClosedEarly;
    resize(width_, height_);
    const bool window = context_.isWindow();
    if (settings_.bench.frames > 0 && stageReady_) runBenchmark();
    const int frames = settings_.run.frames > 0 ? settings_.run.frames : (window ? 0 : 1);
    std::vector<double> times;
    auto last = Clock::now();
    auto titleTime = last;
    // Every iteration renders the stage; in a window the scene pass inside it may reuse the last
    // frame's scene while nothing moved (render-on-change, see the top of this file).
    for (int frame = 0; frames == 0 || frame < frames; ++frame) {
        context_.pollEvents();
        if (context_.shouldClose()) {
            // A window destroyed from outside may first report a 0x0 framebuffer (below): the closing
            // is what ended the run, whatever the last frames looked like.
            if (!notWritten.empty()) notWritten = kClosedEarly;
            break;
        }
        followSize(frame);
        const double elapsed = secondsSince(last);
        last = Clock::now();
        if (input_ != nullptr) input_->update(elapsed);
        if (viewKeys_ != nullptr && (ui_ == nullptr || !ui_->wantsKeyboard())) viewKeys_->update(*views_);
        if (width_ == 0 || height_ == 0) {
            notWritten = "the last frame (" + std::to_string(frame) + ") was 0x0, like a minimised window";
            if (window) glfwWaitEventsTimeout(0.1);
            continue;
        }
        const auto start = Clock::now();
        renderFrame();
        if (stage_.timers != nullptr) stage_.timers->collect(false);
        views_->draw(*quad_, width_, height_);
        drawUi();
        if (!window) glFinish();
        const double renderMs = secondsSince(start) * 1000.0;
        frameTimeMs_ = window ? elapsed * 1000.0 : renderMs;
        checkGlErrors("in frame " + std::to_string(frame));
        times.push_back(renderMs);
        // Once: after the last frame, or the first in a window that runs until closed.
        if (frame == (frames == 0 ? 0 : frames - 1))
            if (const auto black = measureBlackShare())
                if (const auto warning = blackBackgroundWarning(*black)) std::cerr << "warning: " << *warning << "\n";
        if (settings_.run.verbose) {
            std::cout << "frame " << frame << ": " << renderMs << " ms";
            if (const auto key = readSceneKey()) std::cout << ", key Ya " << key->ya;
            std::cout << "\n";
        }
        if (frames != 0 && frame == frames - 1) {
            writeOutputs(settings_.outputs, width_, height_, *scene_);
            notWritten.clear();
            checkGlErrors("while reading the outputs");
        }
        if (window && secondsSince(titleTime) > kTitleInterval) {
            titleTime = Clock::now();
            showFrameTimeInTitle();
        }
        context_.swapBuffers();
    }
    if (wantsOutputs(settings_.outputs) && !notWritten.empty())
        throw Error("the outputs asked for were not written: " + notWritten);
    if (settings_.run.verbose && !times.empty()) printFrameTimes(times);
    return 0;
}

#endif

void App::followSize(int frame) {
    if (static_cast<std::size_t>(frame) < settings_.run.resizeSequence.size()) {
        // Scripted resize (tests): the same path a window's size change takes.
        const auto [w, h] = settings_.run.resizeSequence[static_cast<std::size_t>(frame)];
        context_.requestSize(w, h);
        resize(w, h);
    } else if (context_.isWindow()) {
        int w = 0;
        int h = 0;
        context_.framebufferSize(w, h);
        if (w != width_ || h != height_) resize(w, h);
    }
}

void App::showFrameTimeInTitle() {
    char title[160];
    std::snprintf(title, sizeof title, "%s - %.1f ms (%.0f fps) - view %s (V)", stage_.name, frameTimeMs_,
                  frameTimeMs_ > 0.0 ? 1000.0 / frameTimeMs_ : 0.0, viewName(views_->current()));
    context_.setTitle(title);
}

void App::runBenchmark() {
    BenchTarget target;
    target.name = stage_.name;
    target.width = width_;
    target.height = height_;
    if (stage_.benchSettings != nullptr) target.settings = stage_.benchSettings();
    target.renderFrame = [this] { renderFrame(); };
    target.timers = stage_.timers;
    runBench(settings_.bench, target);
    checkGlErrors("in the benchmark");
    // In a window the benchmark is all that was asked for.
    if (context_.isWindow()) glfwSetWindowShouldClose(context_.window(), GLFW_TRUE);
}

void App::printFrameTimes(const std::vector<double>& times) const {
    const double mean = std::accumulate(times.begin(), times.end(), 0.0) / static_cast<double>(times.size());
    std::cout << "frames: " << times.size() << ", median frame time " << median(times) << " ms, mean " << mean
              << " ms\n";
}

#ifndef __EMSCRIPTEN__
namespace {

// The command line split at every --then: one list of arguments per run, each starting with argv[0].
std::vector<std::vector<const char*>> splitRuns(int argc, const char* const* argv) {
    std::vector<std::vector<const char*>> runs(1, std::vector<const char*>{argv[0]});
    for (int i = 1; i < argc; ++i) {
        if (std::string(argv[i]) == contract::kThenOption) runs.push_back({argv[0]});
        else runs.back().push_back(argv[i]);
    }
    return runs;
}

} // namespace

int runStage(int argc, const char* const* argv, const Stage& stage) {
    const std::vector<std::vector<const char*>> runs = splitRuns(argc, argv);
    std::vector<Settings> settings(runs.size());
    for (std::size_t i = 0; i < runs.size(); ++i) {
        const int parsed = parseSettings(static_cast<int>(runs[i].size()), runs[i].data(), stage.name, stage.summary,
                                         settings[i], stage.addOptions);
        if (parsed >= 0) return parsed;
    }
    const std::string prefix = std::string(stage.name) + ": error: ";
    try {
        ContextOptions contextOptions = settings[0].context;
        contextOptions.title = stage.name;
#ifdef T10_GL_DEBUG
        contextOptions.debug = true;
#endif
        // A stage's own options set its globals (extras/): a later run would inherit what an earlier one set.
        if (runs.size() > 1 && stage.addOptions)
            throw UsageError(std::string(contract::kThenOption) + ": " + stage.name +
                             " has options of its own, which the runs would share: run it once per run");
        for (std::size_t i = 1; i < runs.size(); ++i) {
            const ContextOptions& later = settings[i].context;
            if (later.backend != contextOptions.backend || later.headless != contextOptions.headless)
                throw UsageError(std::string(contract::kThenOption) + ": run " + std::to_string(i + 1) +
                                 " asks for another --backend or --headless than the first run, whose context every run shares");
        }
        std::unique_ptr<Context> context = Context::create(contextOptions);
        if (runs.size() > 1 && context->isWindow())
            throw UsageError(std::string(contract::kThenOption) + " renders headless runs only (add --headless)");
        const GlDefaults defaults = readGlDefaults();
        for (std::size_t i = 0; i < runs.size(); ++i) {
            if (i > 0) {
                // The previous run's outputs are written: say where the next run's output starts (t10-grade
                // splits its log there), then give it the context a process of its own would start with.
                std::cout << contract::kThenMarker << (i + 1) << " of " << runs.size() << "\n" << std::flush;
                std::cerr << std::flush;
                std::fflush(nullptr);
                const ContextOptions& size = settings[i].context;
                context->requestSize(size.width, size.height);
                restoreGlDefaults(defaults, size.width, size.height);
            }
            App app(stage, settings[i], *context);
            if (const int code = app.run(); code != 0) return code;
        }
        return 0;
    } catch (const Error& error) {
        // UsageError is an Error with exit code 2.
        std::cerr << prefix << error.what() << "\n";
        return error.exitCode();
    } catch (const std::exception& error) {
        std::cerr << prefix << error.what() << "\n";
        return 1;
    }
}

#endif

} // namespace t10
