// Interactive speed in a window on a machine without a GPU. Mesa's software renderers (llvmpipe,
// softpipe) spend most of a 1280x720 frame in the scene's parallax search (up to 100 layers), so a
// window there gets fewer layers and re-renders the scene only when the camera or the size
// changes. Headless renders (the golden images, the numeric tests, the benches) are untouched.
#pragma once
#include "t10/scene.hpp"

#include <string>

namespace t10 {

// The parallax layer limit for a window on a software renderer (the full scene uses 100).
constexpr float kSoftwareWindowParallaxLayers = 24.0f;

// True for renderer strings of Mesa's CPU rasterisers ("llvmpipe (LLVM ...)", "softpipe").
bool isSoftwareRenderer(const std::string& renderer);

// Sets up `scene` for a window with the current context: render-on-change always, and the lower
// layer limit where the renderer is software. Returns a one-line note for the user ("" if none).
std::string tuneSceneForWindow(Scene& scene);

} // namespace t10
