// Uploads images as mip-mapped, repeating 2D textures.
#pragma once
#include "t10/gl_object.hpp"
#include "t10/image.hpp"

#include <string>

namespace t10 {

// Full mip chain, trilinear filtering, GL_REPEAT. Grey images become GL_R8, RGB GL_RGB8, RGBA GL_RGBA8.
// `srgb` stores colour images as sRGB so lighting happens in linear space.
Texture uploadTexture(const Image8& image, bool srgb);
// loadTga + uploadTexture; throws t10::Error with the loader's message.
Texture loadTextureTga(const std::string& path, bool srgb);

} // namespace t10
