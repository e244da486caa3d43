// Uploads 8-bit images as immutable, fully mip-mapped 2D textures (trilinear and repeating unless
// the caller's sampling says otherwise). The levels of linear data (normals, heights, grey and
// linear colour) with power-of-two sides are made on the CPU (mipmaps.hpp): llvmpipe's own texels bit
// for bit, without the blit shader glGenerateMipmap compiles per format (tens of milliseconds each on
// llvmpipe, in every process). sRGB colour keeps glGenerateMipmap: drivers filter it through
// approximate sRGB curves that no CPU formula reproduces exactly, and the goldens hold llvmpipe's.
#include "t10/texture.hpp"

#include "t10/error.hpp"
#include "t10/mipmaps.hpp"
#include "t10/tga.hpp"
#include "platform_parts.hpp"

#include <algorithm>
#include <string>

namespace t10 {

namespace {

// The full chain down to 1x1: floor(log2(max(w, h))) + 1. (The tutorial's ceil(log2(...)) is one
// level short for power-of-two sizes.)
GLsizei mipLevelCount(int width, int height) {
    int side = std::max(width, height);
    GLsizei levels = 1;
    while (side > 1) {
        side >>= 1;
        ++levels;
    }
    return levels;
}

bool isPowerOfTwo(int side) { return side > 0 && (side & (side - 1)) == 0; }

struct Formats {
    GLenum internalFormat;
    GLenum format;
};

Formats formatsFor(int channels, bool srgb) {
    switch (channels) {
    case 1: return {GL_R8, GL_RED}; // grey data (heights, masks) is never sRGB
    case 3: return {srgb ? GLenum(GL_SRGB8) : GLenum(GL_RGB8), GL_RGB};
    case 4: return {srgb ? GLenum(GL_SRGB8_ALPHA8) : GLenum(GL_RGBA8), GL_RGBA};
    default: throw Error("uploadTexture: unsupported channel count " + std::to_string(channels));
    }
}

} // namespace

Texture uploadTexture(const Image8& input, bool srgb, const TextureSampling& sampling) {
    if (input.width < 1 || input.height < 1 || input.empty())
        throw Error("uploadTexture: empty image");
    Image8 converted;
    const Image8& image = uploadablePixels(input, converted); // the platform's (platform_parts.hpp)
    const Formats f = formatsFor(image.channels, srgb);

    // Restore whatever the active unit held afterwards (it may be unit 15, the accumulation texture).
    GLint previousBinding = 0;
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &previousBinding);

    Texture texture = makeTexture();
    glBindTexture(GL_TEXTURE_2D, texture.get());
    const GLsizei levels = mipLevelCount(image.width, image.height);
    glTexStorage2D(GL_TEXTURE_2D, levels, f.internalFormat, image.width, image.height);

    // Rows of 1- and 3-channel images are tightly packed, not 4-byte aligned.
    GLint previousAlignment = 4;
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &previousAlignment);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, image.width, image.height, f.format, GL_UNSIGNED_BYTE,
                    image.data.data());
    // Power-of-two sides only: there every level is exact 2x2 blocks, as the GPU's filter sees them.
    const bool srgbFormat = f.internalFormat == GL_SRGB8 || f.internalFormat == GL_SRGB8_ALPHA8;
    const bool cpuLevels = !srgbFormat && isPowerOfTwo(image.width) && isPowerOfTwo(image.height);
    Image8 below;
    const Image8* above = &image;
    for (GLint level = 1; level < levels && cpuLevels; ++level) {
        below = nextMipLevel(*above);
        glTexSubImage2D(GL_TEXTURE_2D, level, 0, 0, below.width, below.height, f.format, GL_UNSIGNED_BYTE,
                        below.data.data());
        above = &below;
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, previousAlignment);
    if (!cpuLevels) glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, sampling.minFilter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, sampling.magFilter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, sampling.wrapS);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, sampling.wrapT);
    if (image.channels == 1) {
        // Sampling a grey texture gives (g, g, g, 1), not (g, 0, 0, 1).
        const GLint swizzle[4] = {GL_RED, GL_RED, GL_RED, GL_ONE};
        glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_RGBA, swizzle);
    }
    glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(previousBinding));
    return texture;
}

Texture loadTextureTga(const std::string& path, bool srgb) {
    return uploadTexture(loadTga(path), srgb);
}

} // namespace t10
