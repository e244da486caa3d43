// The browser build's parts of common/content (platform_parts.hpp; compiled instead of
// platform_parts.cpp):
// - textures: WebGL 2 has no texture swizzle, and makes mipmaps only of formats it can render to (not
//   GL_SRGB8), so grey and RGB images are uploaded as RGBA (g, g, g, 1) and (r, g, b, 1), which sample
//   alike;
// - shaders: every file is translated to GLSL ES 3.00 as it is loaded (glsl_es.hpp), and what the
//   translation moved out of the source (sampler units, block bindings, explicit uniform locations,
//   the subroutine uniforms) is collected into the program's layout, which the platform applies
//   after linking (gl_web.hpp).
#include "platform_parts.hpp"

#include "t10/error.hpp"
#include "t10/gl_web.hpp"
#include "t10/glsl_es.hpp"

#include <cstddef>
#include <utility>

namespace t10 {

const Image8& uploadablePixels(const Image8& image, Image8& converted) {
    if (image.channels != 1 && image.channels != 3) return image;
    converted = Image8(image.width, image.height, 4);
    const std::size_t pixels = image.data.size() / static_cast<std::size_t>(image.channels);
    for (std::size_t i = 0; i < pixels; ++i) {
        for (std::size_t c = 0; c < 3; ++c)
            converted.data[4 * i + c] = image.data[image.channels == 1 ? i : 3 * i + c];
        converted.data[4 * i + 3] = 255;
    }
    return converted;
}

std::string compiledSource(std::string source, const std::string& file, GLenum stage, ProgramLayout& layout) {
    if (stage != GL_VERTEX_SHADER && stage != GL_FRAGMENT_SHADER)
        throw Error(file + ": only vertex and fragment shaders are available in the web build (WebGL 2 "
                           "has no geometry, tessellation or compute shaders)");
    GlslEsShader es = translateToGlslEs(source, file, stage == GL_VERTEX_SHADER ? GlslStage::Vertex : GlslStage::Fragment);
    layout.append(es.layout);
    return std::move(es.source);
}

void applyLayout(GLuint program, const ProgramLayout& layout) { web::configureProgram(program, layout); }

} // namespace t10
