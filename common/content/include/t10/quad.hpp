// The full-screen quad every post-process pass draws: vec2 positions at attribute 0 and GLubyte
// indices, drawn with glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, 0). Its vertex shader is
// common/shaders/FullScreenQuad.vert.
#pragma once
#include "t10/gl_object.hpp"

namespace t10 {

class FullScreenQuad {
public:
    FullScreenQuad();
    // Binds the vertex array (with its element buffer) so the tutorial's draw call works as written.
    void bind() const;

private:
    VertexArray vao_;
    Buffer vertices_;
    Buffer indices_;
};

} // namespace t10
