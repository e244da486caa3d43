// Reading GPU images back to the CPU: the default framebuffer and texture levels at once (output
// files, tests), and a single texel a few frames late without stalling the pipeline (a value a
// stage shows or checks every frame, such as extras' scene key).
#pragma once
#include "t10/gl.hpp"
#include "t10/image.hpp"

#include <memory>
#include <optional>

namespace t10 {

// Reads the default framebuffer (what the window shows) as 8-bit RGB, bottom row first.
Image8 readDefaultFramebuffer(int width, int height);
// Reads one level of a 2D texture as float with 1 or 3 channels (or 4 with rgba = true).
ImageF readTextureLevel(GLuint texture, int level, bool rgba = false);

// The 2D texture bound on a texture unit (texture 0 for none), its level 0's internal format and its
// immutable level count (0 for a mutable texture); the active unit is put back.
struct BoundTexture {
    GLuint texture = 0;
    GLint format = 0;
    GLint levels = 0;
};
BoundTexture textureOnUnit(GLuint unit);

// The texture level a colour attachment of the framebuffer bound to `target` renders into (texture 0
// when the attachment is empty or a renderbuffer).
struct AttachedLevel {
    GLuint texture = 0;
    GLint level = 0;
    GLint face = 0;
};
AttachedLevel attachedLevel(GLenum target, GLenum attachment);

// The red channel of a 1x1 texture level (t10::Error for any other size), copied into a pixel buffer with a fence
// after each request() and read by poll() once the GPU has got there: the value is a few frames
// old, and no frame waits for it. GL objects are made on the first request(); destroy() deletes
// them (call it while the context is current: the destructor does no GL). The browser build reads the
// texel at once instead (texel_readback_web.cpp).
class TexelReadback {
public:
    TexelReadback();
    ~TexelReadback();
    TexelReadback(const TexelReadback&) = delete;
    TexelReadback& operator=(const TexelReadback&) = delete;

    void request(GLuint texture, int level);
    // The newest value whose copy has finished since the last poll(), if any.
    std::optional<float> poll();
    void destroy();

private:
    struct State; // the platform's, made by the first request(): texel_readback.cpp / texel_readback_web.cpp
    std::unique_ptr<State> state_;
};

} // namespace t10
