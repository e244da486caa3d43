// The GLSL 4.30 -> GLSL ES 3.00 translator of the browser build: the stages keep their desktop shader
// files, and the web ShaderManager runs each one through translateToGlslEs() before compiling it with
// WebGL2. GL-free (unit-tested in the native build). It reads student files, so any input gives either
// a translation or a t10::Error naming the file, the line and the construct.
//
// What it does (glsl_es.cpp has the details):
// - `#version 430 core` -> `#version 300 es` and default precisions (highp float, int and samplers);
//   every other line keeps its line number, so the browser's compile log points into the file.
//   Comments become spaces.
// - `layout(binding = N)` leaves sampler uniforms and uniform blocks (reported in the layout's
//   samplerUnits and blockBindings); `layout(location = N)` leaves plain uniforms (uniformLocations) and the varyings
//   between the stages (ES matches those by name); vertex inputs and fragment outputs keep theirs. A
//   uniform block without a packing layout gets std140 (ES would make it `shared`, whose offsets the
//   host would have to query; std140 is the layout the C++ structs follow).
// - Subroutines become plain functions, an int uniform per subroutine uniform (subroutineUniforms) and
//   a function under the subroutine uniform's name that calls the function whose index the int holds.
// - An integer literal passed as a texture function's bias or level of detail becomes a float literal
//   (GLSL 4.30 converts it implicitly; ES 3.00 has no implicit conversions).
// - What has no ES 3.00 form (compute, images, buffers, doubles, ...) is an error, never dropped.
// unboundedLoops() reads a source with the same lexer for the page's shader edits (issue 52): the loops a
// page cannot bound, each on its line, refused before they reach a GPU.
#pragma once
#include "t10/program_layout.hpp"
#include "t10/shader_messages.hpp"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace t10 {

struct GlslEsShader {
    std::string source;   // GLSL ES 3.00, same line numbers as the input
    ProgramLayout layout; // what the translation took out of the source, for the platform to set after linking
};

// The largest source accepted, in bytes (the course's largest shader is under 10 KiB).
constexpr std::size_t kGlslEsMaxSourceBytes = 1u << 20;

// Throws t10::Error "FILE:LINE: <construct> cannot be translated to GLSL ES 3.00 (<why>)" (or another
// "FILE:LINE: ..." message for malformed input).
GlslEsShader translateToGlslEs(std::string_view source, const std::string& fileName, GlslStage stage);

// The most iterations a shader edited in the page may run for a pixel: nested loops, and the loops of a
// function called inside a loop, multiplied (loops one after the other do not add up).
constexpr std::uint64_t kGlslMaxLoopIterations = 1024;

// The loops of `source` a page cannot bound, each {line, message} on its line of the file; none when
// every loop is bounded. A shader that never ends stops the browser's GPU process, and the tab with it,
// so the page's edits (Module.t10SetShader) refuse these before anything compiles them. Bounded is
// `for (int i = A; i < B; ++i)` with integer literals A and B (any of <, <=, >, >=; ++, --, += C, -= C
// with C a literal), counting towards B, within int, and `i` not changed in the body (assigned, stepped,
// passed to an out or inout parameter or to a macro, named in a macro used there, or a macro itself),
// at most kGlslMaxLoopIterations times with the loops around it and those of the functions it calls.
// Refused: while and do loops, other for loops, token pasting
// (`##` could spell a loop) and macros that could hide a loop or a call (a loop keyword in a macro, a
// macro naming one of the file's functions or calling its own parameter, a function named by a macro).
// The course's own stage shaders have no loops. Throws what translateToGlslEs throws for text it cannot
// read (a NUL byte, an unclosed comment), as "FILE:LINE: ...".
std::vector<ShaderMessage> unboundedLoops(std::string_view source, const std::string& fileName);

} // namespace t10
