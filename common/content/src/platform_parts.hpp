// What common/content leaves to the platform (a private header of the layer): the pixels a texture is
// uploaded from (texture.cpp), the source GL compiles for a shader file and what is set on a program
// after linking (shader.cpp). The desktop's are platform_parts.cpp; the browser build compiles
// platform_parts_web.cpp instead (common/CMakeLists.txt).
#pragma once
#include "t10/gl.hpp"
#include "t10/image.hpp"
#include "t10/program_layout.hpp"

#include <string>

namespace t10 {

// `image`, or `converted` filled with the form of it this platform's GL stores: the image itself on
// the desktop; in the browser grey and RGB images become RGBA.
const Image8& uploadablePixels(const Image8& image, Image8& converted);

// The source GL compiles for `file` (of GL stage `stage`): the file's own on the desktop; in the
// browser its GLSL ES 3.00 translation, what the translation took out of the source added to `layout`.
std::string compiledSource(std::string source, const std::string& file, GLenum stage, ProgramLayout& layout);
// After linking: sets what `layout` holds on `program` (the browser build; nothing on the desktop).
void applyLayout(GLuint program, const ProgramLayout& layout);

} // namespace t10
