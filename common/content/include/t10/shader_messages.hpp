// A student's shader edited in the page (the web build's shader-edit service, shader_edit_web.cpp)
// answers with its errors as {line, message} in the student's own file. GL-free, so that it is
// unit-tested natively: the checks made before the source reaches a compiler (valid UTF-8, a size the
// translator accepts) and the reading of what a compiler or the translator said into lines of the
// file. Line numbers are the file's: the translator keeps them (glsl_es.hpp) and the compilers' logs
// follow its #line; a line the file does not have (code the translation generated) becomes 0, "the
// file as a whole", never a line the student cannot find.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace t10 {

struct ShaderMessage {
    int line = 0;        // 1-based line of the student's file; 0: the file (or the program) as a whole
    std::string message; // what is wrong there, without the file name and line
};

// Nothing when `bytes` is UTF-8 text; else where it first is not (its line, and "byte 7: 0xff is not
// UTF-8 ..."): overlong forms, surrogates and code points above U+10FFFF are refused, as UTF-8 defines.
std::optional<ShaderMessage> utf8Problem(std::string_view bytes);

// The number of lines in `source` (a last line without a newline counts; "" has 1 line).
int lineCount(std::string_view source);

// The errors of a GLSL compiler's info log, each on its line of the file: ANGLE's and most drivers'
// "ERROR: 0:12: 'x' : undeclared identifier", Mesa's "0:12(5): error: ...". Summary lines ("ERROR: 1
// compilation errors. No code generated.") are dropped; a line above `lines` becomes 0. A log with
// errors in no form it knows gives one message of line 0 holding the whole log, so nothing is lost.
std::vector<ShaderMessage> compilerMessages(std::string_view log, int lines);

// A t10::Error's text from the translator or the shader manager, "FILE:LINE: message" (or "FILE:
// message"), as a message on that line of `file` (the "FILE:" prefix taken off).
ShaderMessage translatorMessage(std::string_view what, const std::string& file, int lines);

} // namespace t10
