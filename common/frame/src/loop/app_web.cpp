// The browser build's frame loop and the page's interface (compiled instead of app_native.cpp,
// common/CMakeLists.txt). The browser owns the loop: runStage() makes the page's WebPage, whose
// start() builds the stage and registers frame(), which draws a frame only when one is due (the frames
// the page asked for, a camera move, a setting changed through Module.t10Set) and tells the page
// through document.body.dataset:
// t10 = "loading" | "rendered" | "error" (the message in #t10-error) | "answered" (--help, --version:
// the text on the page), t10Frames = frames drawn. "rendered" is set once the GPU has finished the
// frame (a one-pixel readback), so that a page's first-frame time includes the drawing. A change that
// fails (Module.t10Set, or a frame drawn after it) puts the last settings that drew a frame back and
// says why (dataset.t10Notice); a page ends in "error" only with no earlier settings that drew a frame.
// The page (common/platform/web/index.html.in) turns its URL's query into argv.
#include "t10/app.hpp"

#include "t10/browser_limits.hpp"
#include "t10/error.hpp"
#include "t10/outputs.hpp"

#include "page_hooks.hpp"

#include <CLI/CLI.hpp>
#include <emscripten.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <iostream>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

EM_JS(void, t10PageState, (const char* state, int frames), {
    document.body.dataset.t10Frames = String(frames);
    document.body.dataset.t10 = UTF8ToString(state);
});
EM_JS(void, t10PageError, (const char* message), { Module["t10ShowError"](UTF8ToString(message)); });
// --help and --version: the text the binary prints, on the page (dataset.t10 = "answered").
EM_JS(void, t10PageText, (const char* text), { Module["t10ShowText"](UTF8ToString(text)); });
// A change that was not applied (the last good settings drew again): "" clears it.
EM_JS(void, t10PageNotice, (const char* message), { document.body.dataset.t10Notice = UTF8ToString(message); });

namespace t10 {

class WebPage;

namespace {

WebPage* g_page = nullptr;
const Stage* g_stage = nullptr;

// parseSettings with its messages caught: -1 and "" when the run goes on, else the exit code and
// what the binary would have printed. Options a page cannot honour are refused by name before
// parsing (so that ?input=/etc/passwd is "not available", not "does not exist"), and sizes and frame
// counts beyond the browser's bounds after it (browser_limits.hpp).
int parseCaptured(const std::vector<std::string>& args, const Stage& stage, Settings& settings, std::string& message) {
    if (const std::string refused = browser::refusedByName(args); !refused.empty()) {
        message = std::string(stage.name) + ": error: " + refused;
        return 2;
    }
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
        if (const std::string beyond = browser::beyondBounds(settings); !beyond.empty()) {
            message = std::string(stage.name) + ": error: " + beyond;
            return 2;
        }
    }
    // --help (more than the version's one line) says what differs in the browser.
    if (parsed == 0 && std::count(message.begin(), message.end(), '\n') > 1) message += browser::helpNote();
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

// The choices CLI11's type text lists for `option` ("TEXT:{mip,exact}") that its checks accept here:
// extras' --key without exact in the browser (refusedInBrowser), so that no control offers it.
nlohmann::json honouredChoices(CLI::Option& option) {
    nlohmann::json choices = nlohmann::json::array();
    const std::string type = option.get_type_name();
    const std::size_t open = type.find('{');
    const std::size_t close = type.find('}', open);
    if (open == std::string::npos || close == std::string::npos) return choices;
    std::istringstream list(type.substr(open + 1, close - open - 1));
    for (std::string choice; std::getline(list, choice, ',');) {
        bool accepted = true;
        try {
            for (int i = 0; accepted; ++i) {
                std::string value = choice;
                accepted = (*option.get_validator(i))(value).empty();
            }
        } catch (const CLI::OptionNotFound&) {
            // past the last check
        }
        if (accepted) choices.push_back(choice);
    }
    return choices;
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
    // Called once per animation frame; draws a frame only when something asked for one (the frames
    // the page or a change asked for, a camera or a view that differs from the last frame's).
    void frame();
    // Module.t10Set(name, value): the command line `args` (the page's, plus every setting made
    // since) parsed again with `--name value` appended and applied at once (the stage rebuilt), so
    // that changes apply in the order they are made and the last one wins; "" or the message the
    // binary would print, the page's settings then as they were.
    std::string set(const std::string& name, const std::string& value);
    // Module.t10Options(): the stage's options as JSON (names, types, ranges, choices the page can
    // honour, current values).
    std::string options() const;
    // The page's other services (page_hooks.hpp).
    App& app() { return app_; }
    void rebuildStage();
    void requestFrame();
    std::string applyArguments(const std::vector<std::string>& more);
    // Module.t10Drawn(): what the last frame was drawn with (JSON: frames, args, view, fov).
    std::string drawn() const;
    // The mouse wheel, in notches (positive: towards the user, which zooms out), from the page.
    void wheel(double notches);
    // A frame failed: the last settings that drew a frame are put back and drawn again, the message
    // kept as the page's notice. False when there are none (the page never drew a frame).
    bool recover(const std::string& message);

private:
    std::string apply(const Settings& next); // set()'s second half: rebuild what changed
    void restoreStageOptions();              // the stage's own options (globals) as args_ says
    void finishGpu();                        // waits until the GPU has drawn the frame

    App app_;
    std::vector<std::string> args_; // argv[1..] as the page gave it, then each t10Set
    std::optional<std::vector<std::string>> good_; // the args of the last frame drawn
    int pending_ = 0;               // frames still to draw before the page is "rendered"
    int drawn_ = 0;                 // frames drawn so far (dataset.t10Frames)
    double last_ = 0.0;             // the last frame()'s time, for the camera keys' speed
    std::optional<CameraState> drawnCamera_; // the camera and view of the last frame
    View drawnView_ = View::Final;
};

namespace {

void frameLoop(void*) {
    try {
        g_page->frame();
    } catch (const std::exception& error) {
        const std::string message = std::string(g_stage->name) + ": error: " + error.what();
        std::cerr << message << "\n";
        if (g_page->recover(message)) return;
        emscripten_cancel_main_loop();
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
    if (app_.input_ != nullptr) app_.input_->update(elapsed);
    if (app_.viewKeys_ != nullptr) app_.viewKeys_->update(*app_.views_);
    // Compared with the last frame's, not with the state before update(): the wheel moves the camera
    // between two calls.
    if (drawnCamera_ && (cameraState(app_.camera_) != *drawnCamera_ || app_.views_->current() != drawnView_))
        pending_ = std::max(pending_, 1);
    if (pending_ == 0 || app_.width_ == 0 || app_.height_ == 0) return;
    const double start = emscripten_get_now();
    app_.renderFrame();
    app_.views_->draw(*app_.quad_, app_.width_, app_.height_);
    app_.checkGlErrors("in frame " + std::to_string(drawn_));
    drawnCamera_ = cameraState(app_.camera_);
    drawnView_ = app_.views_->current();
    ++drawn_;
    --pending_;
    if (pending_ == 0) finishGpu();
    app_.frameTimeMs_ = emscripten_get_now() - start;
    good_ = args_;
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

void WebPage::finishGpu() {
    // WebGL returns from the draw calls at once; a readback of one pixel of the frame returns once
    // everything before it is drawn. The bindings it changes are put back.
    GLint readFramebuffer = 0;
    GLint packBuffer = 0;
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFramebuffer);
    glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &packBuffer);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    unsigned char pixel[4] = {};
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(readFramebuffer));
    glBindBuffer(GL_PIXEL_PACK_BUFFER, static_cast<GLuint>(packBuffer));
}

void WebPage::wheel(double notches) {
    // Camera::zoom's steps are the desktop GLFW's: positive away from the user, narrowing the view.
    app_.camera_.zoom(static_cast<float>(-notches));
}

std::string WebPage::set(const std::string& name, const std::string& value) {
    const Stage& stage = app_.stage_;
    // The last of a name wins (the parser's policy), so an earlier one can go: a slider moved a
    // thousand times leaves one argument.
    std::vector<std::string> args;
    for (const std::string& arg : args_) {
        if (arg != "--" + name && arg.rfind("--" + name + "=", 0) != 0) args.push_back(arg);
    }
    args.push_back(value.empty() ? "--" + name : "--" + name + "=" + value);
    Settings next;
    std::string message;
    const int parsed = parseCaptured(args, stage, next, message);
    if (parsed >= 0) {
        restoreStageOptions(); // a failed parse may have set some of them
        return message.empty() ? "--" + name + ": not applied" : message;
    }
    // A value the parser accepts may still be refused when applied (an unknown --camera, a shader the
    // stage cannot build): then everything is put back as it was and the message returned; the page
    // keeps its frame.
    const std::vector<std::string> previousArgs = std::exchange(args_, std::move(args));
    const Settings previous = app_.settings_;
    std::string refused;
    try {
        refused = apply(next);
    } catch (const std::exception& error) {
        refused = std::string(stage.name) + ": error: " + error.what();
    }
    if (refused.empty()) {
        t10PageNotice("");
        return "";
    }
    args_ = previousArgs;
    restoreStageOptions();
    apply(previous); // what drew before draws again (a failure here is the page's error)
    return refused;
}

void WebPage::restoreStageOptions() {
    Settings restored;
    std::string ignored;
    parseCaptured(args_, app_.stage_, restored, ignored);
}

bool WebPage::recover(const std::string& message) {
    if (!good_ || *good_ == args_) return false;
    args_ = *good_;
    Settings restored;
    std::string ignored;
    if (parseCaptured(args_, app_.stage_, restored, ignored) >= 0) return false;
    try {
        apply(restored);
    } catch (const std::exception&) {
        return false;
    }
    t10PageNotice(("not applied: " + message).c_str());
    return true;
}

std::string WebPage::apply(const Settings& next) {
    Settings& settings = app_.settings_;
    const std::string viewBefore = settings.views.view;
    if (next.views.view != viewBefore && !app_.views_->available(*findView(next.views.view))) {
        std::string names;
        for (View view : app_.views_->availableViews()) names += (names.empty() ? "" : ", ") + std::string(viewName(view));
        return "--view " + next.views.view + ": this stage has no " + next.views.view + " (its views: " + names + ")";
    }
    const bool sizeChanged = next.context.width != settings.context.width || next.context.height != settings.context.height;
    const bool cameraChanged = next.scene.camera != settings.scene.camera;
    settings = next;
    if (cameraChanged) {
        app_.loadScene(true);
        app_.scene_->resize(app_.width_, app_.height_);
    }
    if (sizeChanged) {
        app_.context_.requestSize(next.context.width, next.context.height);
        app_.resize(next.context.width, next.context.height);
    } else {
        // The stage's own settings (extras') are read again by GL_Init, now, so that a setting it
        // cannot build is refused by t10Set rather than by a later frame.
        app_.quitStage();
        app_.buildStage();
    }
    if (settings.views.view != viewBefore) app_.views_->select(*findView(settings.views.view));
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
    auto describe = [&](CLI::Option* option, const std::string& group) {
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
        if (const nlohmann::json choices = honouredChoices(*option); !choices.empty()) entry["choices"] = choices;
        options.push_back(entry);
    };
    for (CLI::Option* option : cli.get_options()) describe(option, "");
    for (CLI::App* group : cli.get_subcommands({})) {
        for (CLI::Option* option : group->get_options()) describe(option, group->get_group());
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

std::string WebPage::drawn() const {
    nlohmann::json args = nlohmann::json::array();
    if (good_) args = *good_;
    return nlohmann::json{{"frames", drawn_},
                          {"args", args},
                          {"view", viewName(drawnView_)},
                          {"fov", drawnCamera_ ? drawnCamera_->fov : app_.camera_.fovDegrees()}}
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
        else t10PageText(message.c_str());
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

// The page's entry points (Module.t10Set, t10Options, t10Drawn and the page's wheel listener wrap
// them; the strings they return live until the next call).
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

EMSCRIPTEN_KEEPALIVE const char* t10_drawn() {
    static std::string result;
    result = t10::g_page != nullptr ? t10::g_page->drawn() : "{}";
    return result.c_str();
}

EMSCRIPTEN_KEEPALIVE void t10_wheel(double notches) {
    if (t10::g_page != nullptr) t10::g_page->wheel(notches);
}

EMSCRIPTEN_KEEPALIVE const char* t10_options() {
    static std::string result;
    result = t10::g_page != nullptr ? t10::g_page->options() : "{}";
    return result.c_str();
}

}
