// The browser build's frame loop and the page's interface (compiled instead of App::run and
// runStage in app.cpp). The browser owns the loop: App::run() builds the stage and registers
// webFrame(), which draws a frame only when one is due (the frames the page asked for, a camera
// move, a setting changed through Module.t10Set) and tells the page through document.body.dataset:
// t10 = "loading" | "rendered" | "error" (the message in #t10-error), t10Frames = frames drawn.
// The page (common/platform/web/index.html.in) turns its URL's query into argv.
#include "t10/app.hpp"

#include "t10/error.hpp"
#include "t10/outputs.hpp"

#include <CLI/CLI.hpp>
#include <emscripten.h>
#include <nlohmann/json.hpp>

#include <iostream>
#include <sstream>
#include <utility>
#include <vector>

EM_JS(void, t10PageState, (const char* state, int frames), {
    document.body.dataset.t10Frames = String(frames);
    document.body.dataset.t10 = UTF8ToString(state);
});
EM_JS(void, t10PageError, (const char* message), { Module["t10ShowError"](UTF8ToString(message)); });

namespace t10 {

namespace {

App* g_app = nullptr;
const Stage* g_stage = nullptr;

// The options that read or write files, time the GPU or drive tests: a page has no files to give
// them and WebGL 2 no timer queries. Returns the message refusing the first one given, or "".
std::string unavailableOption(const Settings& s) {
    const char* const kNoFiles = "is not available in the web build (the page reads only the files packaged with "
                                 "it and writes none; read the frame from the canvas instead)";
    if (!s.outputs.output.empty()) return std::string("--output ") + kNoFiles;
    if (!s.outputs.exr.empty()) return std::string("--exr ") + kNoFiles + " (and OpenEXR has no WebAssembly build)";
    if (!s.outputs.dumpDir.empty()) return std::string("--dump ") + kNoFiles;
    if (!s.outputs.capturePassesDir.empty()) return std::string("--capture-passes ") + kNoFiles;
    if (!s.scene.scene.empty()) return std::string("--scene ") + kNoFiles;
    if (!s.scene.input.empty()) return std::string("--input ") + kNoFiles;
    if (!s.scene.shaderDir.empty()) return std::string("--shader-dir ") + kNoFiles;
    if (s.bench.frames > 0 || !s.bench.csv.empty())
        return "--bench is not available in the web build (WebGL 2 has no GPU timer queries)";
    if (!s.run.resizeSequence.empty()) return "--resize-sequence is not available in the web build";
    return "";
}

// parseSettings with its messages caught: -1 and "" when the run goes on, else the exit code and
// what the binary would have printed.
int parseCaptured(const std::vector<std::string>& args, const Stage& stage, Settings& settings, std::string& message) {
    std::vector<const char*> argv{stage.name};
    for (const std::string& arg : args) argv.push_back(arg.c_str());
    std::ostringstream err;
    std::ostringstream out;
    std::streambuf* const oldErr = std::cerr.rdbuf(err.rdbuf());
    std::streambuf* const oldOut = std::cout.rdbuf(out.rdbuf());
    const int parsed = parseSettings(static_cast<int>(argv.size()), argv.data(), stage.name, stage.summary, settings,
                                     stage.addOptions);
    std::cerr.rdbuf(oldErr);
    std::cout.rdbuf(oldOut);
    message = parsed == 0 ? out.str() : err.str();
    if (parsed < 0) {
        if (const std::string refused = unavailableOption(settings); !refused.empty()) {
            message = std::string(stage.name) + ": error: " + refused + "\n";
            return 2;
        }
    }
    while (!message.empty() && message.back() == '\n') message.pop_back();
    return parsed;
}

void frameLoop(void*) {
    try {
        g_app->webFrame();
    } catch (const std::exception& error) {
        emscripten_cancel_main_loop();
        const std::string message = std::string(g_stage->name) + ": error: " + error.what();
        std::cerr << message << "\n";
        t10PageError(message.c_str());
    }
}

struct CameraState {
    glm::vec3 position;
    float yaw, pitch, fov;
    bool operator!=(const CameraState& o) const {
        return position != o.position || yaw != o.yaw || pitch != o.pitch || fov != o.fov;
    }
};

CameraState cameraState(const Camera& camera) {
    return {camera.position(), camera.yawDegrees(), camera.pitchDegrees(), camera.fovDegrees()};
}

} // namespace

int App::run() {
    resize(width_, height_);
    webPending_ = settings_.run.frames > 0 ? settings_.run.frames : 1;
    webLast_ = emscripten_get_now();
    t10PageState("loading", 0);
    emscripten_set_main_loop_arg(frameLoop, this, 0, 0);
    return 0;
}

void App::webFrame() {
    const double now = emscripten_get_now();
    const double elapsed = (now - webLast_) / 1000.0;
    webLast_ = now;
    const CameraState before = cameraState(camera_);
    if (input_ != nullptr) input_->update(elapsed);
    const View viewBefore = views_->current();
    if (viewKeys_ != nullptr) viewKeys_->update(*views_);
    if (cameraState(camera_) != before || views_->current() != viewBefore) webPending_ = std::max(webPending_, 1);
    if (webPending_ == 0 || width_ == 0 || height_ == 0) return;
    const double start = emscripten_get_now();
    renderFrame();
    views_->draw(*quad_, width_, height_);
    frameTimeMs_ = emscripten_get_now() - start;
    checkGlErrors("in frame " + std::to_string(webDrawn_));
    ++webDrawn_;
    --webPending_;
    t10PageState(webPending_ == 0 ? "rendered" : "loading", webDrawn_);
}

std::string App::webSet(const std::string& name, const std::string& value) {
    std::vector<std::string> args = webArgs_;
    args.push_back(value.empty() ? "--" + name : "--" + name + "=" + value);
    Settings next;
    std::string message;
    const int parsed = parseCaptured(args, stage_, next, message);
    if (parsed >= 0) {
        // Put back what the stage's own options held (a failed parse may have set some of them).
        Settings previous;
        std::string ignored;
        parseCaptured(webArgs_, stage_, previous, ignored);
        return message.empty() ? "--" + name + ": not applied" : message;
    }
    // A value the parser accepts may still be refused when applied (an unknown --camera): then
    // everything is put back as it was and the message returned; the page keeps its frame.
    const std::vector<std::string> previousArgs = std::exchange(webArgs_, std::move(args));
    const Settings previous = settings_;
    try {
        return applyWebSettings(next);
    } catch (const UsageError& error) {
        webArgs_ = previousArgs;
        settings_ = previous;
        Settings restored;
        std::string ignored;
        parseCaptured(webArgs_, stage_, restored, ignored);
        return std::string(stage_.name) + ": error: " + error.what();
    }
}

std::string App::applyWebSettings(const Settings& next) {
    const bool sizeChanged = next.context.width != settings_.context.width || next.context.height != settings_.context.height;
    const bool cameraChanged = next.scene.camera != settings_.scene.camera;
    const std::string viewBefore = settings_.views.view;
    settings_ = next;
    if (cameraChanged) {
        loadScene(true);
        scene_->resize(width_, height_);
    }
    if (sizeChanged) {
        context_.requestSize(next.context.width, next.context.height);
        resize(next.context.width, next.context.height);
    } else {
        requestRebuild(); // the stage's own settings (extras') are read again by GL_Init
    }
    if (settings_.views.view != viewBefore && !views_->select(*findView(settings_.views.view)))
        return "--view " + settings_.views.view + ": this stage has no such view";
    views_->showThumbnails(settings_.views.thumbnails);
    webPending_ = std::max(webPending_, settings_.run.frames > 0 ? settings_.run.frames : 1);
    t10PageState("loading", webDrawn_);
    return "";
}

std::string App::webOptions() const {
    CLI::App cli;
    Settings scratch;
    addSettingsOptions(cli, scratch, stage_.addOptions);
    // The values given so far: the last of each name wins, as on the command line.
    std::map<std::string, std::string> given;
    for (const std::string& arg : webArgs_) {
        const std::size_t eq = arg.find('=');
        if (arg.rfind("--", 0) == 0) given[arg.substr(2, eq == std::string::npos ? std::string::npos : eq - 2)] =
            eq == std::string::npos ? "" : arg.substr(eq + 1);
    }
    nlohmann::json options = nlohmann::json::array();
    auto describe = [&](const CLI::Option* option, const std::string& group) {
        // The option's long name ("no-bloom" for CLI11's "--no-bloom{false}"); a short-only option or
        // the help flag is not a setting.
        const std::vector<std::string> longNames = option->get_lnames();
        if (longNames.empty() || longNames.front() == "help") return;
        const std::string& name = longNames.front();
        nlohmann::json entry{{"name", name},
                             {"group", group},
                             {"description", option->get_description()},
                             {"flag", option->get_expected_min() == 0},
                             {"type", option->get_type_name()},
                             {"default", option->get_default_str()}};
        if (const auto it = given.find(name); it != given.end()) entry["value"] = it->second;
        options.push_back(entry);
    };
    for (const CLI::Option* option : cli.get_options()) describe(option, "");
    for (const CLI::App* group : cli.get_subcommands({})) {
        for (const CLI::Option* option : group->get_options()) describe(option, group->get_group());
    }
    nlohmann::json views = nlohmann::json::array();
    for (View view : views_->availableViews()) views.push_back(viewName(view));
    return nlohmann::json{{"stage", stage_.name}, {"options", options}, {"views", views},
                          {"view", viewName(views_->current())}}
        .dump();
}

int runStage(int argc, const char* const* argv, const Stage& stageInMain) {
    // main()'s Stage ends when main() returns, before the browser calls the loop: a copy stays.
    const Stage& stage = *new Stage(stageInMain);
    g_stage = &stage;
    std::vector<std::string> args(argv + 1, argv + argc);
    auto* settings = new Settings;
    std::string message;
    const int parsed = parseCaptured(args, stage, *settings, message);
    if (parsed >= 0) {
        std::cerr << message << "\n";
        if (parsed != 0) t10PageError(message.c_str());
        return parsed;
    }
    try {
        ContextOptions contextOptions = settings->context;
        contextOptions.title = stage.name;
        // Kept for the page's lifetime: the browser calls the loop after main() returns.
        Context* context = Context::create(contextOptions).release();
        g_app = new App(stage, *settings, *context);
        g_app->setWebArguments(std::move(args));
        return g_app->run();
    } catch (const std::exception& error) {
        message = std::string(stage.name) + ": error: " + error.what();
        std::cerr << message << "\n";
        t10PageError(message.c_str());
        return 1;
    }
}

} // namespace t10

// The page's entry points (Module.t10Set and Module.t10Options wrap them; the strings they return
// live until the next call).
extern "C" {

EMSCRIPTEN_KEEPALIVE const char* t10_set(const char* name, const char* value) {
    static std::string result;
    if (t10::g_app == nullptr) return "the stage is not running";
    try {
        result = t10::g_app->webSet(name, value);
    } catch (const std::exception& error) {
        result = std::string(t10::g_stage->name) + ": error: " + error.what();
        t10PageError(result.c_str());
    }
    return result.c_str();
}

EMSCRIPTEN_KEEPALIVE const char* t10_options() {
    static std::string result;
    result = t10::g_app != nullptr ? t10::g_app->webOptions() : "{}";
    return result.c_str();
}

}
