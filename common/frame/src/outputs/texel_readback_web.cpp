// TexelReadback in the browser build (compiled instead of texel_readback.cpp, common/CMakeLists.txt):
// WebGL 2 has no pixel-pack copy of a texture level, so request() reads the texel at once through the
// platform's glGetTexImage (a framebuffer read, which waits for the GPU: one texel, once a frame) and
// poll() hands it over.
#include "t10/readback.hpp"

#include "texture_on_unit0.hpp"

#include <memory>
#include <utility>

namespace t10 {

struct TexelReadback::State {
    std::optional<float> read; // read at once, not yet polled
};

TexelReadback::TexelReadback() = default;
TexelReadback::~TexelReadback() = default;

void TexelReadback::request(GLuint texture, int level) {
    const TextureOnUnit0 bound(texture);
    float value = 0.0f;
    glGetTexImage(GL_TEXTURE_2D, level, GL_RED, GL_FLOAT, &value);
    if (state_ == nullptr) state_ = std::make_unique<State>();
    state_->read = value;
}

std::optional<float> TexelReadback::poll() {
    return state_ != nullptr ? std::exchange(state_->read, std::nullopt) : std::nullopt;
}

void TexelReadback::destroy() {} // request() made no GL object (a value not yet polled stays for poll())

} // namespace t10
