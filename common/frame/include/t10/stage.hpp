// What a stage offers the frame loop. A stage is its Tutorial10.cpp: the tutorial's GL_Init /
// GL_Render / GL_Quit, and, in extras/, options, keys, a panel and pass timers. The loop calls
// them; a stage never calls its own GL_Init again (it asks App::requestRebuild()).
// It names the frame loop's types only by declaration, so it includes nothing of common/.
#pragma once
#include <functional>
#include <memory>
#include <string>

struct GLFWwindow;

namespace CLI {
class App;
}

namespace t10 {

class App;
class PassTimers;
class UiHost;

// Adds stage-specific options to the parser (extras/); may be empty.
using AddOptionsHook = std::function<void(CLI::App&)>;

struct Stage {
    const char* name;      // the stage folder, e.g. "tutorial10_part1_tonemap"
    const char* summary;   // one line for --help
    const char* shaderDir; // the stage's folder, fixed at configure time
    bool (*init)(App&);    // GL_Init: create programs, buffers and size-dependent objects
    void (*render)(App&);  // GL_Render: scene, then post-process into framebuffer 0
    void (*quit)();        // GL_Quit: delete everything GL_Init created
    // Stage-specific command-line options (extras/); may be empty.
    AddOptionsHook addOptions = {};
    // Window mode only: the UI host the panel draws with, made once per window (it survives
    // resizes and rebuilds); the shortcuts, called every frame unless a text field has the
    // keyboard; and the panel, drawn over the finished frame between the host's begin and end.
    std::unique_ptr<UiHost> (*makeUi)(GLFWwindow*) = nullptr;
    void (*keys)(App&) = nullptr;
    void (*panel)(App&) = nullptr;
    // The GPU timers the stage's passes begin (timers->begin("name")), if it times them: the loop
    // creates them once, opens and closes every frame and collects finished frames; --bench reports them.
    PassTimers* timers = nullptr;
    // The settings a --bench run used, for its heading (e.g. "5 blur passes, bloom on"); may be null.
    std::string (*benchSettings)() = nullptr;
};

} // namespace t10
