// The desktop's half of the frame loop (app.hpp; the browser build compiles app_web.cpp instead,
// common/CMakeLists.txt): App::run renders the frames in a loop of its own, in a window or headless,
// and writes the outputs after the last one; runStage runs the command line's runs one after another
// (--then) in one context.
#include "t10/app.hpp"

#include "t10/bench.hpp"
#include "t10/contract.hpp"
#include "t10/error.hpp"
#include "t10/exposure_check.hpp"
#include "t10/gl_defaults.hpp"
#include "t10/outputs.hpp"
#include "t10/scene_key.hpp"
#include "t10/stats.hpp"

#include <GLFW/glfw3.h>

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

} // namespace

void App::setUpWindow() {
    // A window showing --input keeps the image's size.
    if (!settings_.scene.input.empty()) glfwSetWindowAttrib(context_.window(), GLFW_RESIZABLE, GLFW_FALSE);
    // After the camera's callbacks, so that the UI's chain to them.
    if (stage_.makeUi != nullptr) ui_ = stage_.makeUi(context_.window());
}

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
    // frame's scene while nothing moved (render-on-change, see the top of app.cpp).
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

} // namespace t10
