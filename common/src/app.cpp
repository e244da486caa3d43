// The frame loop: context, scene, the stage's callbacks, resizes and rebuilds, GL error checks;
// input, output files, the benchmark and the UI are services of their own (see app.hpp).
#include "t10/app.hpp"
#include "t10/scene_key.hpp"

#include "t10/bench.hpp"
#include "t10/contract.hpp"
#include "t10/error.hpp"
#include "t10/exposure_check.hpp"
#include "t10/gpu_timers.hpp"
#include "t10/image_io.hpp"
#include "t10/input_image.hpp"
#include "t10/interactive.hpp"
#include "t10/outputs.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <numeric>

namespace t10 {

namespace {

constexpr double kTitleInterval = 0.5; // seconds between title updates

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string glString(GLenum name) {
    const auto* text = reinterpret_cast<const char*>(glGetString(name));
    return text != nullptr ? text : "?";
}

std::vector<std::filesystem::path> shaderSearchPath(const Stage& stage, const Options& options) {
    std::vector<std::filesystem::path> dirs;
    if (!options.shaderDir.empty()) dirs.emplace_back(options.shaderDir);
    dirs.emplace_back(stage.shaderDir);
    dirs.emplace_back(T10_COMMON_SHADER_DIR);
    return dirs;
}

} // namespace

App::App(const Stage& stage, const Options& options, Context& context)
    : stage_(stage), options_(options), context_(context), shaders_(shaderSearchPath(stage, options)),
      glErrors_(std::make_unique<GlErrorLog>()) {
    glErrors_->installDebugCallback();
    if (options_.verbose) {
        std::cout << "backend:  " << context_.description() << "\n"
                  << "vendor:   " << glString(GL_VENDOR) << "\n"
                  << "renderer: " << glString(GL_RENDERER) << "\n"
                  << "version:  " << glString(GL_VERSION) << "\n";
    }
    // The input image is checked before the scene is built, so a file that cannot be rendered (too
    // large for this context or the memory, a side of 1, no colour channel) is refused at once.
    ImageF image;
    if (!options_.input.empty()) image = loadInputImage(options_.input, options_.keepNonFinite, std::cerr);
    quad_ = std::make_unique<FullScreenQuad>();
    views_ = std::make_unique<ViewService>(shaders_, *findView(options_.view));
    views_->showThumbnails(options_.thumbnails);
    loadScene();
    context_.framebufferSize(width_, height_);
    if (!options_.input.empty()) {
        if (options_.sizeGiven && (image.width != options_.width || image.height != options_.height)) {
            throw UsageError("--input " + options_.input + " is " + std::to_string(image.width) + "x" +
                             std::to_string(image.height) + " but --size asks for " + std::to_string(options_.width) +
                             "x" + std::to_string(options_.height));
        }
        if (image.width != width_ || image.height != height_) {
            context_.requestSize(image.width, image.height);
            context_.framebufferSize(width_, height_);
        }
        scene_->setInputImage(std::move(image));
    }
    if (context_.isWindow()) {
        // Interactive speed without a GPU (t10/interactive.hpp); headless renders are unchanged.
        if (const std::string note = tuneSceneForWindow(*scene_); !note.empty()) std::cout << note << "\n";
        input_ = std::make_unique<CameraInput>(context_.window(), camera_);
        viewKeys_ = std::make_unique<ViewKeys>(context_.window());
        if (!options_.input.empty()) glfwSetWindowAttrib(context_.window(), GLFW_RESIZABLE, GLFW_FALSE);
        // After the camera's callbacks, so that the UI's chain to them.
        if (stage_.makeUi != nullptr) ui_ = stage_.makeUi(context_.window());
    }
    if (stage_.timers != nullptr) stage_.timers->create();
}

void App::loadScene() {
    const std::string file = options_.scene.empty() ? builtInScenePath() : options_.scene;
    const auto start = Clock::now();
    const SceneDescription description = loadGltfScene(file);
    const double loadMs = secondsSince(start) * 1000.0;
    for (const std::string& warning : description.warnings) std::cerr << "warning: " << file << ": " << warning << "\n";
    const CameraPreset* preset =
        options_.camera.empty() ? &description.cameras.front() : description.findCamera(options_.camera);
    if (preset == nullptr)
        throw UsageError("--camera " + options_.camera + ": unknown camera (" + file + " has " +
                         description.cameraNames() + ")");
    camera_ = Camera(*preset);
    scene_ = std::make_unique<Scene>(shaders_, description);
    if (options_.verbose) {
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
    if (!options_.input.empty() && (width != scene_->width() || height != scene_->height()) && scene_->width() != 0) {
        throw Error("--input " + options_.input + ": the framebuffer cannot be resized while an input image is shown");
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
    stage_.render(*this);
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

int App::run() {
    // Every output asked for is written after the last frame, or the run fails saying why.
    if (options_.frames == 0 && context_.isWindow() && wantsOutputs(options_))
        throw UsageError("--output, --exr and --dump are written after the last of --frames N frames: give --frames");
    std::string notWritten = "the window was closed before the last frame";
    resize(width_, height_);
    const bool window = context_.isWindow();
    if (options_.bench > 0 && stageReady_) {
        runBench(*this, stage_, options_.bench, options_.benchCsv);
        checkGlErrors("in the benchmark");
        // In a window the benchmark is all that was asked for.
        if (window) glfwSetWindowShouldClose(context_.window(), GLFW_TRUE);
    }
    const int frames = options_.frames > 0 ? options_.frames : (window ? 0 : 1);
    std::vector<double> times;
    auto last = Clock::now();
    auto titleTime = last;
    for (int frame = 0; frames == 0 || frame < frames; ++frame) {
        context_.pollEvents();
        if (context_.shouldClose()) break;
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
        if (options_.verbose) {
            std::cout << "frame " << frame << ": " << renderMs << " ms";
            if (const auto key = readSceneKey()) std::cout << ", key Ya " << key->ya;
            std::cout << "\n";
        }
        if (frames != 0 && frame == frames - 1) {
            writeOutputs(options_, width_, height_, *scene_);
            notWritten.clear();
            checkGlErrors("while reading the outputs");
        }
        if (window && secondsSince(titleTime) > kTitleInterval) {
            titleTime = Clock::now();
            showFrameTimeInTitle();
        }
        context_.swapBuffers();
    }
    if (wantsOutputs(options_) && !notWritten.empty())
        throw Error("the outputs asked for were not written: " + notWritten);
    if (options_.verbose && !times.empty()) printFrameTimes(times);
    return 0;
}

void App::followSize(int frame) {
    if (static_cast<std::size_t>(frame) < options_.resizeSequence.size()) {
        // Scripted resize (tests): the same path a window's size change takes.
        const auto [w, h] = options_.resizeSequence[static_cast<std::size_t>(frame)];
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

void App::printFrameTimes(std::vector<double> times) const {
    const double mean = std::accumulate(times.begin(), times.end(), 0.0) / static_cast<double>(times.size());
    std::sort(times.begin(), times.end());
    std::cout << "frames: " << times.size() << ", median frame time " << times[times.size() / 2] << " ms, mean "
              << mean << " ms\n";
}

int runStage(int argc, const char* const* argv, const Stage& stage) {
    Options options;
    const int parsed = parseCommandLine(argc, argv, stage.name, stage.summary, options, stage.addOptions);
    if (parsed >= 0) return parsed;
    try {
        ContextOptions contextOptions;
        contextOptions.backend = options.backend;
        contextOptions.headless = options.headless;
        contextOptions.width = options.width;
        contextOptions.height = options.height;
        contextOptions.title = stage.name;
#ifdef T10_GL_DEBUG
        contextOptions.debug = true;
#endif
        std::unique_ptr<Context> context = Context::create(contextOptions);
        App app(stage, options, *context);
        return app.run();
    } catch (const Error& error) {
        // UsageError is an Error with exit code 2.
        std::cerr << stage.name << ": error: " << error.what() << "\n";
        return error.exitCode();
    } catch (const std::exception& error) {
        std::cerr << stage.name << ": error: " << error.what() << "\n";
        return 1;
    }
}

} // namespace t10
