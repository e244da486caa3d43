// Window-mode speed settings for the scene (see t10/interactive.hpp).
#include "t10/interactive.hpp"

#include <cstdio>

namespace t10 {

bool isSoftwareRenderer(const std::string& renderer) {
    return renderer.find("llvmpipe") != std::string::npos || renderer.find("softpipe") != std::string::npos;
}

std::string tuneSceneForWindow(Scene& scene) {
    const auto* text = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    if (text == nullptr || !isSoftwareRenderer(text)) {
        scene.setRenderOnChange(true);
        return "";
    }
    scene.setRenderOnChange(true, kSoftwareWindowParallaxLayers);
    char note[240];
    std::snprintf(note, sizeof note,
                  "note: software renderer (%s): the scene is redrawn only when the camera moves, with at most "
                  "%.0f parallax layers while it moves (100 once it stops, as headless)",
                  text, double(kSoftwareWindowParallaxLayers));
    return note;
}

} // namespace t10
