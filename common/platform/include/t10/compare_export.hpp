// The golden comparison (t10/compare.hpp) as plain C functions, for the browser's compare page
// (?compare=1): the web build exports them from a student's module, so the page judges the student's
// frame with the same code as the golden tests and imgcompare, not with a second implementation.
#pragma once
#include <cstdint>

extern "C" {

// A zeroed buffer of `bytes` bytes inside the module that the page fills (slot 0: the reference frame,
// 1: the student's frame, 2: the heat-map the comparison writes, 3: text, such as the tolerance file's
// NUL-terminated path). Returns null for a bad slot or size. The page needs no runtime helper
// (ccall, string conversion), which emscripten versions include differently.
std::uint8_t* t10_compare_buffer(int slot, int bytes);

// Compares two RGBA images of width x height, rows in the same order, held in slots 0 (expected)
// and 1 (actual) of t10_compare_buffer, under the tolerance file at tolerancePath (the golden
// test's format). Alpha is ignored: the goldens are RGB. Writes the difference heat-map (RGBA, alpha
// 255) into slot 2 when it is large enough. Returns JSON, valid until the next call:
//   {"passed":bool,"sizeMatches":bool,"failingFraction":f,"meanError":f,"maxError":n,"summary":"...",
//    "tolerance":{"threshold":n,"maxFraction":f,"maxMean":f,"file":"<the file's text>"}}
// or {"error":"<message naming the file or argument>"}.
const char* t10_compare_rgba(int width, int height, const char* tolerancePath);

}
