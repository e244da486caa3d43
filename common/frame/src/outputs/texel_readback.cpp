// TexelReadback on the desktop: the level copied into a pixel buffer with a fence, read once the GPU
// has got there; see readback.hpp. The browser build compiles texel_readback_web.cpp instead
// (common/CMakeLists.txt).
#include "t10/readback.hpp"

#include "t10/error.hpp"
#include "texture_on_unit0.hpp"

#include <array>
#include <memory>
#include <string>

namespace t10 {

// A ring of one-float pixel buffers, each with the fence of its copy.
struct TexelReadback::State {
    static constexpr int kSlots = 4;
    struct Slot {
        GLuint buffer = 0;
        GLsync fence = nullptr;
        long serial = 0;
    };
    std::array<Slot, kSlots> slots{};
    int next = 0;
    long serial = 0;
};

TexelReadback::TexelReadback() = default;
TexelReadback::~TexelReadback() = default;

void TexelReadback::request(GLuint texture, int level) {
    const TextureOnUnit0 bound(texture);
    // Only a 1x1 level fits the one-float buffer (the last level of a full mip chain).
    GLint width = 0;
    GLint height = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, level, GL_TEXTURE_WIDTH, &width);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, level, GL_TEXTURE_HEIGHT, &height);
    if (width != 1 || height != 1) {
        throw Error("TexelReadback: level " + std::to_string(level) + " is " + std::to_string(width) + "x" +
                    std::to_string(height) + ", not 1x1");
    }
    if (state_ == nullptr) state_ = std::make_unique<State>();
    State::Slot& slot = state_->slots[static_cast<std::size_t>(state_->next)];
    state_->next = (state_->next + 1) % State::kSlots;
    if (slot.fence != nullptr) {
        // Not read yet after kSlots frames: drop it rather than wait.
        glDeleteSync(slot.fence);
        slot.fence = nullptr;
    }
    GLint previousPack = 0;
    glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &previousPack);
    if (slot.buffer == 0) {
        glGenBuffers(1, &slot.buffer);
        glBindBuffer(GL_PIXEL_PACK_BUFFER, slot.buffer);
        glBufferData(GL_PIXEL_PACK_BUFFER, sizeof(float), nullptr, GL_STREAM_READ);
    }
    glBindBuffer(GL_PIXEL_PACK_BUFFER, slot.buffer);
    glGetTexImage(GL_TEXTURE_2D, level, GL_RED, GL_FLOAT, nullptr);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, static_cast<GLuint>(previousPack));
    slot.fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    slot.serial = ++state_->serial;
}

std::optional<float> TexelReadback::poll() {
    if (state_ == nullptr) return std::nullopt;
    std::optional<float> newest;
    long newestSerial = 0;
    for (State::Slot& slot : state_->slots) {
        if (slot.fence == nullptr) continue;
        if (glClientWaitSync(slot.fence, 0, 0) == GL_TIMEOUT_EXPIRED) continue;
        glDeleteSync(slot.fence);
        slot.fence = nullptr;
        float value = 0.0f;
        GLint previousPack = 0;
        glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &previousPack);
        glBindBuffer(GL_PIXEL_PACK_BUFFER, slot.buffer);
        glGetBufferSubData(GL_PIXEL_PACK_BUFFER, 0, sizeof value, &value);
        glBindBuffer(GL_PIXEL_PACK_BUFFER, static_cast<GLuint>(previousPack));
        if (slot.serial > newestSerial) {
            newestSerial = slot.serial;
            newest = value;
        }
    }
    return newest;
}

void TexelReadback::destroy() {
    if (state_ == nullptr) return;
    for (State::Slot& slot : state_->slots) {
        if (slot.fence != nullptr) glDeleteSync(slot.fence);
        if (slot.buffer != 0) glDeleteBuffers(1, &slot.buffer);
    }
    state_.reset();
}

} // namespace t10
