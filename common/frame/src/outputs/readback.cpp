// GPU-to-CPU reads; see readback.hpp.
#include "t10/readback.hpp"

#include "t10/error.hpp"

#include <string>
#include <utility>

namespace t10 {

namespace {

// Binds `texture` to unit 0 for a query and puts back what was there (and the active unit).
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

} // namespace

Image8 readDefaultFramebuffer(int width, int height) {
    Image8 image(width, height, 3);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
#ifdef __EMSCRIPTEN__
    glReadBuffer(GL_BACK); // WebGL 2's default framebuffer has only its back buffer
#else
    GLint drawBuffer = GL_BACK;
    glGetIntegerv(GL_DRAW_BUFFER, &drawBuffer);
    glReadBuffer(static_cast<GLenum>(drawBuffer));
#endif
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, image.data.data());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    return image;
}

ImageF readTextureLevel(GLuint texture, int level, bool rgba) {
    const TextureOnUnit0 bound(texture);
    GLint width = 0;
    GLint height = 0;
    GLint format = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, level, GL_TEXTURE_WIDTH, &width);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, level, GL_TEXTURE_HEIGHT, &height);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, level, GL_TEXTURE_INTERNAL_FORMAT, &format);
    const bool single = format == GL_R16 || format == GL_R16F || format == GL_R32F || format == GL_R8;
    const int channels = rgba ? 4 : (single ? 1 : 3);
    ImageF image(width, height, channels);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTexImage(GL_TEXTURE_2D, level, channels == 4 ? GL_RGBA : (channels == 1 ? GL_RED : GL_RGB), GL_FLOAT,
                  image.data.data());
    return image;
}

void TexelReadback::request(GLuint texture, int level) {
    const TextureOnUnit0 bound(texture);
#ifdef __EMSCRIPTEN__
    // No pixel-pack copy of a texture level in WebGL 2: the platform reads it through a framebuffer,
    // which waits for the GPU (one texel, once a frame).
    float value = 0.0f;
    glGetTexImage(GL_TEXTURE_2D, level, GL_RED, GL_FLOAT, &value);
    read_ = value;
    return;
#endif
    // Only a 1x1 level fits the one-float buffer (the last level of a full mip chain).
    GLint width = 0;
    GLint height = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, level, GL_TEXTURE_WIDTH, &width);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, level, GL_TEXTURE_HEIGHT, &height);
    if (width != 1 || height != 1) {
        throw Error("TexelReadback: level " + std::to_string(level) + " is " + std::to_string(width) + "x" +
                    std::to_string(height) + ", not 1x1");
    }
    Slot& slot = slots_[static_cast<std::size_t>(next_)];
    next_ = (next_ + 1) % kSlots;
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
    slot.serial = ++serial_;
}

std::optional<float> TexelReadback::poll() {
#ifdef __EMSCRIPTEN__
    return std::exchange(read_, std::nullopt);
#endif
    std::optional<float> newest;
    long newestSerial = 0;
    for (Slot& slot : slots_) {
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
    for (Slot& slot : slots_) {
        if (slot.fence != nullptr) glDeleteSync(slot.fence);
        if (slot.buffer != 0) glDeleteBuffers(1, &slot.buffer);
        slot = Slot{};
    }
    next_ = 0;
}

} // namespace t10
