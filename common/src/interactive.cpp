// Window-mode speed settings for the scene (see t10/interactive.hpp).
#include "t10/interactive.hpp"

#include <cstdio>

namespace t10 {

bool isSoftwareRenderer(const std::string& renderer) {
    return renderer.find("llvmpipe") != std::string::npos || renderer.find("softpipe") != std::string::npos;
}

std::string tuneSceneForWindow(Scene& scene) {
    scene.setRenderOnChange(true);
    const auto* text = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    if (text == nullptr || !isSoftwareRenderer(text)) return "";
    scene.setMaxParallaxLayers(kSoftwareWindowParallaxLayers);
    char note[200];
    std::snprintf(note, sizeof note,
                  "note: software renderer (%s): the window uses at most %.0f parallax layers (headless renders: "
                  "100) and redraws the scene only when the camera moves",
                  text, double(kSoftwareWindowParallaxLayers));
    return note;
}

} // namespace t10
