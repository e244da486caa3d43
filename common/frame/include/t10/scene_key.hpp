// Reads the scene key Ya back from the luminance texture a stage keeps on texture unit 16 (its 1x1
// level), so that `--verbose` can print the exposure each frame.
#pragma once
#include <optional>

namespace t10 {

struct SceneKey {
    double stored = 0.0;     // the texel as stored: range-mapped log luminance (GL_R16) or ln Ya (GL_R16F)
    double ya = 0.0;         // the key Ya itself
    bool rangeMapped = true; // GL_R16: undone with the tutorial's white point 0.22 and epsilon 1e-8
};

// The key of the last frame, or nothing when unit 16 holds no texture (Part 0). Needs a current
// context; leaves the active texture unit as it was.
std::optional<SceneKey> readSceneKey();

} // namespace t10
