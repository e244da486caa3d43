// The browser build's GL layer (common/platform/web/include/glad/gl.h, src/gl_web.cpp): a program's
// layout applied after linking (program_layout.hpp), and the WebGL 2 extensions found at start. Only
// the web build compiles gl_web.cpp.
#pragma once
#include "t10/program_layout.hpp"

#include <utility>

namespace t10::web {

// Applies `layout` to the linked `program` (units, bindings) and records its location map, used by
// every later glUniform*, glGetUniformLocation and glUniformSubroutinesuiv on it.
void configureProgram(unsigned program, const ProgramLayout& layout);

// Called after every glDrawElements and glDrawArrays with `context` (nullptr: none): the capture hook's
// draw observation (draw_observation_web.cpp). Returns the hook it replaces.
using DrawHook = void (*)(void* context);
std::pair<DrawHook, void*> setDrawHook(DrawHook hook, void* context);

// Set by the web context once the WebGL 2 context exists: EXT_texture_norm16, and whether GL_R16 can
// be emulated without it (GL_R32F, linearly filtered through OES_texture_float_linear; gl_web.cpp).
void setTextureNorm16(bool available, bool emulation);
bool textureNorm16();

} // namespace t10::web
