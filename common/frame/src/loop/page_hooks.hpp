// What the browser's page loop (app_web.cpp) offers the page's other services, which the page calls
// between frames: the shader editing (shader_edit_web.cpp) and the check (check_web.cpp). A private
// header of the frame layer, compiled in the web build only.
#pragma once
#include <string>
#include <vector>

namespace t10 {

class App;
struct Stage;

namespace page {

// The running page's App and stage; nullptr before the stage runs or after it stopped on an error.
App* app();
const Stage* stage();

// GL_Quit, then GL_Init at the current size at once (App::requestRebuild waits for the next frame);
// throws what GL_Init throws, with the stage left unbuilt: build it again before the next frame.
void rebuildStage();

// A frame is due: the loop draws it and the page's state goes "loading", then "rendered".
void requestFrame();

// The page's command line and every Module.t10Set since, with `more` appended, applied at once (as
// Module.t10Set applies a setting: the size, the camera, the stage rebuilt); "" or what refused it.
// The page's own settings are not changed: restoreArguments() puts them back.
std::string applyArguments(const std::vector<std::string>& more);
void restoreArguments();
// The stage's render of one frame into the default framebuffer at once (a requested rebuild first; no
// view, no UI): what --output and --dump read after a binary's last frame.
void renderNow();
// The current framebuffer size.
int width();
int height();

// Stops the page's loop with `message` shown as the page's error (the page cannot draw any more).
void fail(const std::string& message);

} // namespace page
} // namespace t10
