// What the browser's page loop (app_web.cpp) offers the page's other services, which the page calls
// between frames: the shader editing (shader_edit_web.cpp) and the check (check_web.cpp). A private
// header of the frame layer, compiled in the web build only.
#pragma once
#include <string>

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

// Stops the page's loop with `message` shown as the page's error (the page cannot draw any more).
void fail(const std::string& message);

} // namespace page
} // namespace t10
