// A t10-grade case rendered in the running page; see page_capture.hpp. The web build only: the page's
// loop (page_hooks.hpp) applies the case's settings and renders, and the outputs service writes the
// files, as after a binary's last frame.
#include "t10/page_capture.hpp"

#include "t10/app.hpp"
#include "t10/error.hpp"
#include "t10/outputs.hpp"
#include "t10/stage.hpp"

#include "page_hooks.hpp"

namespace t10 {

void capturePageCase(const std::vector<std::string>& args, const std::string& dir, bool passes) {
    App* app = page::app();
    if (app == nullptr) throw Error("the stage is not running");
    // The page's own settings back however the case ended (they applied before, so they apply again).
    struct Restore {
        ~Restore() {
            try {
                page::restoreArguments();
                page::requestFrame();
            } catch (const std::exception& error) {
                page::fail(std::string("the page's settings could not be put back after a check: ") + error.what());
            }
        }
    } restore;
    if (const std::string refused = page::applyArguments(args); !refused.empty()) throw Error(refused);
    if (passes) app->setObserver(makePassCapture(dir));
    try {
        page::renderNow();
    } catch (...) {
        app->setObserver(nullptr);
        throw;
    }
    app->setObserver(nullptr);
    OutputSettings outputs;
    outputs.dumpDir = dir;
    outputs.output = dir + "/frame.png";
    writeOutputs(outputs, page::width(), page::height(), app->scene());
}

std::string pageStageName() { return page::stage() != nullptr ? page::stage()->name : ""; }

} // namespace t10
