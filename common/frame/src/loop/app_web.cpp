// The browser build's frame loop and the page's interface (compiled instead of app_native.cpp,
// common/CMakeLists.txt). The browser owns the loop: runStage() makes the page's WebPage, whose
// start() builds the stage and registers frame(), which draws a frame only when one is due (the frames
// the page asked for, a camera move, a setting changed through Module.t10Set) and tells the page
// through document.body.dataset:
// t10 = "loading" | "rendered" | "error" (the message in #t10-error), t10Frames = frames drawn.
// The page (common/platform/web/index.html.in) turns its URL's query into argv.
#include "t10/app.hpp"

#include "t10/error.hpp"
#include "t10/outputs.hpp"

#include "page_hooks.hpp"

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

class WebPage;

namespace {

WebPage* g_page = nullptr;
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

// The page's App and what the browser's loop keeps between its calls (a friend of App: it drives the
// services App::run drives on the desktop).
class WebPage {
public:
    WebPage(const Stage& stage, const Settings& settings, Context& context, std::vector<std::string> args)
        : app_(stage, settings, context), args_(std::move(args)) {}
    // Builds the stage and hands frame() to the browser's loop.
    void start();
    // Called once per animation frame; draws a frame only when something asked for one.
    void frame();
    // Module.t10Set(name, value): the command line `args` (the page's, plus every setting made
    // since) parsed again with `--name value` appended; "" or the message the binary would print.
    std::string set(const std::string& name, const std::string& value);
    // Module.t10Options(): the stage's options as JSON (names, types, ranges, current values).
    std::string options() const;
    // The page's other services (page_hooks.hpp).
    App& app() { return app_; }
    void rebuildStage();
    void requestFrame();
    std::string applyArguments(const std::vector<std::string>& more);

private:
    std::string apply(const Settings& next); // set()'s second half: rebuild what changed

    App app_;
    std::vector<std::string> args_; // argv[1..] as the page gave it, then each t10Set
    int pending_ = 0;               // frames still to draw before the page is "rendered"
    int drawn_ = 0;                 // frames drawn so far (dataset.t10Frames)
    double last_ = 0.0;             // the last frame()'s time, for the camera keys' speed
};

namespace {

void frameLoop(void*) {
    try {
        g_page->frame();
    } catch (const std::exception& error) {
        emscripten_cancel_main_loop();
        const std::string message = std::string(g_stage->name) + ": error: " + error.what();
        std::cerr << message << "\n";
        t10PageError(message.c_str());
    }
}

} // namespace

// The page has no --input (refused) and its controls stand for the UI: a window needs nothing more.
void App::setUpWindow() {}

void WebPage::start() {
    app_.resize(app_.width_, app_.height_);
    pending_ = app_.settings_.run.frames > 0 ? app_.settings_.run.frames : 1;
    last_ = emscripten_get_now();
    t10PageState("loading", 0);
    emscripten_set_main_loop_arg(frameLoop, this, 0, 0);
}

void WebPage::frame() {
    const double now = emscripten_get_now();
    const double elapsed = (now - last_) / 1000.0;
    last_ = now;
    const CameraState before = cameraState(app_.camera_);
    if (app_.input_ != nullptr) app_.input_->update(elapsed);
    const View viewBefore = app_.views_->current();
    if (app_.viewKeys_ != nullptr) app_.viewKeys_->update(*app_.views_);
    if (cameraState(app_.camera_) != before || app_.views_->current() != viewBefore) pending_ = std::max(pending_, 1);
    if (pending_ == 0 || app_.width_ == 0 || app_.height_ == 0) return;
    const double start = emscripten_get_now();
    app_.renderFrame();
    app_.views_->draw(*app_.quad_, app_.width_, app_.height_);
    app_.frameTimeMs_ = emscripten_get_now() - start;
    app_.checkGlErrors("in frame " + std::to_string(drawn_));
    ++drawn_;
    --pending_;
    t10PageState(pending_ == 0 ? "rendered" : "loading", drawn_);
}

void WebPage::rebuildStage() {
    app_.quitStage();
    app_.buildStage();
}

void WebPage::requestFrame() {
    pending_ = std::max(pending_, 1);
    t10PageState("loading", drawn_);
}

std::string WebPage::applyArguments(const std::vector<std::string>& more) {
    std::vector<std::string> args = args_;
    args.insert(args.end(), more.begin(), more.end());
    Settings next;
    std::string message;
    if (parseCaptured(args, app_.stage_, next, message) >= 0) return message.empty() ? "not applied" : message;
    return apply(next);
}

std::string WebPage::set(const std::string& name, const std::string& value) {
    const Stage& stage = app_.stage_;
    std::vector<std::string> args = args_;
    args.push_back(value.empty() ? "--" + name : "--" + name + "=" + value);
    Settings next;
    std::string message;
    const int parsed = parseCaptured(args, stage, next, message);
    if (parsed >= 0) {
        // Put back what the stage's own options held (a failed parse may have set some of them).
        Settings previous;
        std::string ignored;
        parseCaptured(args_, stage, previous, ignored);
        return message.empty() ? "--" + name + ": not applied" : message;
    }
    // A value the parser accepts may still be refused when applied (an unknown --camera): then
    // everything is put back as it was and the message returned; the page keeps its frame.
    const std::vector<std::string> previousArgs = std::exchange(args_, std::move(args));
    const Settings previous = app_.settings_;
    try {
        return apply(next);
    } catch (const UsageError& error) {
        args_ = previousArgs;
        app_.settings_ = previous;
        Settings restored;
        std::string ignored;
        parseCaptured(args_, stage, restored, ignored);
        return std::string(stage.name) + ": error: " + error.what();
    }
}

std::string WebPage::apply(const Settings& next) {
    Settings& settings = app_.settings_;
    const bool sizeChanged = next.context.width != settings.context.width || next.context.height != settings.context.height;
    const bool cameraChanged = next.scene.camera != settings.scene.camera;
    const std::string viewBefore = settings.views.view;
    settings = next;
    if (cameraChanged) {
        app_.loadScene(true);
        app_.scene_->resize(app_.width_, app_.height_);
    }
    if (sizeChanged) {
        app_.context_.requestSize(next.context.width, next.context.height);
        app_.resize(next.context.width, next.context.height);
    } else {
        app_.requestRebuild(); // the stage's own settings (extras') are read again by GL_Init
    }
    if (settings.views.view != viewBefore && !app_.views_->select(*findView(settings.views.view)))
        return "--view " + settings.views.view + ": this stage has no such view";
    app_.views_->showThumbnails(settings.views.thumbnails);
    pending_ = std::max(pending_, settings.run.frames > 0 ? settings.run.frames : 1);
    t10PageState("loading", drawn_);
    return "";
}

std::string WebPage::options() const {
    CLI::App cli;
    Settings scratch;
    addSettingsOptions(cli, scratch, app_.stage_.addOptions);
    // The values given so far: the last of each name wins, as on the command line.
    std::map<std::string, std::string> given;
    for (const std::string& arg : args_) {
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
    for (View view : app_.views_->availableViews()) views.push_back(viewName(view));
    return nlohmann::json{{"stage", app_.stage_.name}, {"options", options}, {"views", views},
                          {"view", viewName(app_.views_->current())}}
        .dump();
}

namespace page {

App* app() { return g_page != nullptr ? &g_page->app() : nullptr; }
const Stage* stage() { return g_page != nullptr ? g_stage : nullptr; }
void rebuildStage() { g_page->rebuildStage(); }
void requestFrame() { g_page->requestFrame(); }
std::string applyArguments(const std::vector<std::string>& more) { return g_page->applyArguments(more); }
void restoreArguments() { g_page->applyArguments({}); }
void renderNow() { g_page->app().renderFrame(); }
int width() { return g_page->app().width(); }
int height() { return g_page->app().height(); }

void fail(const std::string& message) {
    emscripten_cancel_main_loop();
    g_page = nullptr;
    std::cerr << message << "\n";
    t10PageError(message.c_str());
}

} // namespace page

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
        g_page = new WebPage(stage, *settings, *context, std::move(args));
        g_page->start();
        return 0;
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
    if (t10::g_page == nullptr) return "the stage is not running";
    try {
        result = t10::g_page->set(name, value);
    } catch (const std::exception& error) {
        result = std::string(t10::g_stage->name) + ": error: " + error.what();
        t10PageError(result.c_str());
    }
    return result.c_str();
}

EMSCRIPTEN_KEEPALIVE const char* t10_options() {
    static std::string result;
    result = t10::g_page != nullptr ? t10::g_page->options() : "{}";
    return result.c_str();
}

}
