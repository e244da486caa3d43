// Uploads images as mip-mapped, repeating 2D textures.
#pragma once
#include "t10/gl_object.hpp"
#include "t10/image.hpp"

#include <string>

namespace t10 {

// Filters and wrap modes (a glTF sampler); the defaults are trilinear and repeating.
struct TextureSampling {
    GLint minFilter = GL_LINEAR_MIPMAP_LINEAR;
    GLint magFilter = GL_LINEAR;
    GLint wrapS = GL_REPEAT;
    GLint wrapT = GL_REPEAT;
};

// Full mip chain. Grey images become GL_R8, RGB GL_RGB8, RGBA GL_RGBA8.
// `srgb` stores colour images as sRGB so lighting happens in linear space.
Texture uploadTexture(const Image8& image, bool srgb, const TextureSampling& sampling = {});
// loadTga + uploadTexture; throws t10::Error with the loader's message.
Texture loadTextureTga(const std::string& path, bool srgb);

} // namespace t10
