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
    GLint active = 0;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    glActiveTexture(GL_TEXTURE0 + contract::kLuminanceKeyUnit);
    GLint texture = 0;
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture);
    std::optional<SceneKey> key;
    if (texture != 0) {
        GLint levels = 0;
        GLint format = 0;
        glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
        const ImageF last = readTextureLevel(static_cast<GLuint>(texture), std::max(levels, 1) - 1);
        if (last.width == 1 && last.height == 1) {
            SceneKey k;
            k.stored = last.data[0];
            k.rangeMapped = format != GL_R16F;
            // GL_R16 holds the range mapping of steps 5 and 9 (undone with the tutorial's white point).
            k.ya = k.rangeMapped ? ref::keyFromMapped(k.stored) : std::exp(k.stored);
            key = k;
        }
    }
    glActiveTexture(static_cast<GLenum>(active));
    return key;
}

} // namespace t10
