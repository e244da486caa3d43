// Interactive speed in a window on a machine without a GPU. Mesa's software renderers (llvmpipe,
// softpipe) spend most of a 1280x720 frame in the scene pass (parallax search with up to 100
// layers, eight lights), so a window re-renders the scene only when the camera or the size changes,
// and on a software renderer with fewer parallax layers while the camera moves (a still view is
// redrawn once at full quality). Headless renders (golden images, numeric tests, benches) are
// untouched.
#pragma once
#include "t10/scene.hpp"

#include <string>

namespace t10 {

// The parallax layer limit while the camera moves in a window on a software renderer (full: 100).
constexpr float kSoftwareWindowParallaxLayers = 24.0f;

// True for renderer strings of Mesa's CPU rasterisers ("llvmpipe (LLVM ...)", "softpipe").
bool isSoftwareRenderer(const std::string& renderer);

// Sets up `scene` for a window with the current context: render-on-change always, and the lower
// layer limit while moving where the renderer is software. Returns a note for the user ("" if none).
std::string tuneSceneForWindow(Scene& scene);

} // namespace t10
