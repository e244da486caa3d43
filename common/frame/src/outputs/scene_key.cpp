// Reading the scene key back from unit 16; see scene_key.hpp.
#include "t10/scene_key.hpp"

#include "t10/contract.hpp"
#include "t10/gl.hpp"
#include "t10/readback.hpp"

#include "reference.hpp"

#include <algorithm>
#include <cmath>

namespace t10 {

std::optional<SceneKey> readSceneKey() {
    const BoundTexture bound = textureOnUnit(contract::kLuminanceKeyUnit);
    if (bound.texture == 0) return std::nullopt;
    const ImageF last = readTextureLevel(bound.texture, std::max(bound.levels, 1) - 1);
    if (last.width != 1 || last.height != 1) return std::nullopt;
    SceneKey k;
    k.stored = last.data[0];
    k.rangeMapped = bound.format != GL_R16F;
    // GL_R16 holds the range mapping of steps 5 and 9 (undone with the tutorial's white point).
    k.ya = k.rangeMapped ? ref::keyFromMapped(k.stored) : std::exp(k.stored);
    return k;
}

} // namespace t10
