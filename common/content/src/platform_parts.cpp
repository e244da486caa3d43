// The desktop's parts of common/content (platform_parts.hpp): GL 4.3 stores grey, RGB and RGBA images
// as they are (a grey texture samples as (g, g, g, 1) through its swizzle, texture.cpp) and compiles
// the shader files as they are, explicit bindings, locations and subroutines included, so nothing is
// left to set after linking.
#include "platform_parts.hpp"

namespace t10 {

const Image8& uploadablePixels(const Image8& image, Image8&) { return image; }

std::string compiledSource(std::string source, const std::string&, GLenum, ProgramLayout&) { return source; }

void applyLayout(GLuint, const ProgramLayout&) {}

} // namespace t10
