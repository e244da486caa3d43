// The readback's scoped binding (readback.cpp, texel_readback.cpp, texel_readback_web.cpp): a texture
// bound to unit 0 for a query or a read, and what unit 0 and the active unit held put back after.
#pragma once
#include "t10/gl.hpp"

namespace t10 {

class TextureOnUnit0 {
public:
    explicit TextureOnUnit0(GLuint texture) {
        glGetIntegerv(GL_ACTIVE_TEXTURE, &active_);
        glActiveTexture(GL_TEXTURE0);
        glGetIntegerv(GL_TEXTURE_BINDING_2D, &previous_);
        glBindTexture(GL_TEXTURE_2D, texture);
    }
    ~TextureOnUnit0() {
        glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(previous_));
        glActiveTexture(static_cast<GLenum>(active_));
    }
    TextureOnUnit0(const TextureOnUnit0&) = delete;
    TextureOnUnit0& operator=(const TextureOnUnit0&) = delete;

private:
    GLint active_ = 0;
    GLint previous_ = 0;
};

} // namespace t10
