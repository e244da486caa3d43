// GPU-to-CPU reads at once; see readback.hpp. TexelReadback is the platform's: texel_readback.cpp
// (a pixel buffer and a fence), texel_readback_web.cpp.
#include "t10/readback.hpp"

#include "texture_on_unit0.hpp"

#include <cstdint>
#include <vector>

namespace t10 {

Image8 readDefaultFramebuffer(int width, int height) {
    Image8 image(width, height, 3);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    // The buffer drawn into (the back buffer of a window): DRAW_BUFFER0 is what desktop GL calls
    // DRAW_BUFFER, and the one name WebGL 2 knows (its default framebuffer has only GL_BACK).
    GLint drawBuffer = GL_BACK;
    glGetIntegerv(GL_DRAW_BUFFER0, &drawBuffer);
    glReadBuffer(static_cast<GLenum>(drawBuffer));
    // RGBA, the one format WebGL 2 reads a default framebuffer in (the page's check reads its frame
    // here too); the alpha is dropped.
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    for (std::size_t p = 0; p < rgba.size() / 4; ++p)
        for (std::size_t c = 0; c < 3; ++c) image.data[p * 3 + c] = rgba[p * 4 + c];
    return image;
}

BoundTexture textureOnUnit(GLuint unit) {
    GLint active = 0;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    glActiveTexture(GL_TEXTURE0 + unit);
    GLint texture = 0;
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture);
    BoundTexture bound;
    bound.texture = static_cast<GLuint>(texture);
    if (texture != 0) {
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &bound.format);
        glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_IMMUTABLE_LEVELS, &bound.levels);
    }
    glActiveTexture(static_cast<GLenum>(active));
    return bound;
}

AttachedLevel attachedLevel(GLenum target, GLenum attachment) {
    AttachedLevel attached;
    GLint type = GL_NONE;
    glGetFramebufferAttachmentParameteriv(target, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
    if (type != GL_TEXTURE) return attached;
    GLint texture = 0;
    glGetFramebufferAttachmentParameteriv(target, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &texture);
    glGetFramebufferAttachmentParameteriv(target, attachment, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL,
                                          &attached.level);
    glGetFramebufferAttachmentParameteriv(target, attachment, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE,
                                          &attached.face);
    attached.texture = static_cast<GLuint>(texture);
    return attached;
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

} // namespace t10
