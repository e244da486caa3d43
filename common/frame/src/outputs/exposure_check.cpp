// The black-background check of the key; see exposure_check.hpp.
#include "t10/exposure_check.hpp"

#include "t10/contract.hpp"
#include "t10/gl.hpp"
#include "t10/readback.hpp"
#include "t10/scene_key.hpp"

#include "reference.hpp"

#include <cmath>
#include <cstdio>

namespace t10 {

std::optional<BlackShare> measureBlackShare() {
    const BoundTexture key = textureOnUnit(contract::kLuminanceKeyUnit);
    if (key.texture == 0) return std::nullopt;
    const ImageF level = readTextureLevel(key.texture, 0);
    if (level.data.empty()) return std::nullopt;
    // Each texel back to ln(Y + epsilon): GL_R16 holds the range mapping of steps 5 and 9.
    const bool rangeMapped = key.format != GL_R16F;
    double sumAll = 0.0;
    double sumLit = 0.0;
    std::size_t black = 0;
    std::size_t counted = 0;
    for (const float texel : level.data) {
        const double y = rangeMapped ? ref::keyFromMapped(texel) : std::exp(double(texel));
        if (!std::isfinite(y)) continue; // a non-finite pixel is the nan view's business, not this one's
        const double lnY = std::log(y);
        ++counted;
        sumAll += lnY;
        if (y < kBlackLuminance) ++black;
        else sumLit += lnY;
    }
    if (counted == 0) return std::nullopt;
    BlackShare m;
    m.share = double(black) / double(counted);
    // The key the tone map used (the mip chain's 1x1 level), else the mean of level 0.
    const std::optional<SceneKey> used = readSceneKey();
    m.key = used ? used->ya : std::exp(sumAll / double(counted));
    m.litKey = black < counted ? std::exp(sumLit / double(counted - black)) : 0.0;
    return m;
}

std::optional<std::string> blackBackgroundWarning(const BlackShare& m) {
    if (m.share < kBlackShareWarned) return std::nullopt;
    char text[512];
    std::snprintf(text, sizeof text,
                  "%.0f%% of the frame is black (the background), which pulls the key down to Ya = %.3g "
                  "(the rest of the frame alone: %.3g), so what is lit burns to white. Give the scene a background "
                  "or an environment (walls, a floor, an emissive sky or backdrop); extras' --key exact "
                  "averages the same black pixels and does not help (site/notes.md, \"A black background\")",
                  100.0 * m.share, m.key, m.litKey);
    return std::string(text);
}

} // namespace t10
