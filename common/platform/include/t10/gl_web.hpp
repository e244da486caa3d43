// The browser build's GL layer (common/platform/web/include/glad/gl.h, src/gl_web.cpp): what a
// program's translated shaders need set after linking, and the WebGL 2 extensions found at start.
// Only the web build compiles gl_web.cpp; this header is GL-type-free so that common/content can
// describe a program without knowing how the platform applies it.
#pragma once
#include <string>
#include <vector>

namespace t10::web {

struct NamedValue {
    std::string name;
    int value;
};

struct SubroutineUniform {
    unsigned shaderStage; // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER
    int location;         // the subroutine uniform's layout(location) in the GLSL 4.30 source
    std::string uniformName; // the int uniform the translation declared for it
};

// What GLSL ES 3.00 cannot say in the shader and the platform sets after linking.
struct ProgramLayout {
    std::vector<NamedValue> samplerUnits;     // sampler uniform -> texture unit
    std::vector<NamedValue> blockBindings;    // uniform block -> binding point
    std::vector<NamedValue> uniformLocations; // uniform -> its explicit location (arrays: the first)
    std::vector<SubroutineUniform> subroutineUniforms;
};

// Applies `layout` to the linked `program` (units, bindings) and records its location map, used by
// every later glUniform*, glGetUniformLocation and glUniformSubroutinesuiv on it.
void configureProgram(unsigned program, const ProgramLayout& layout);

// Set by the web context once the WebGL 2 context exists: EXT_texture_norm16, and whether GL_R16 can
// be emulated without it (GL_R32F, linearly filtered through OES_texture_float_linear; gl_web.cpp).
void setTextureNorm16(bool available, bool emulation);
bool textureNorm16();

} // namespace t10::web
