// libFuzzer target: the GLSL 4.30 -> ES 3.00 translator (t10::translateToGlslEs) on arbitrary bytes, as
// a fragment and as a vertex shader. A translation must start with `#version 300 es` and keep the
// input's line count (plus the two lines of `#line 2` when #version was the first line); an error must
// be a t10::Error naming the input (anything else escapes and is a finding). The page's loop refusal
// (t10::unboundedLoops) on the same bytes. Sanitizers catch the rest.
#include "t10/error.hpp"
#include "t10/glsl_es.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace {

// Line breaks as GLSL counts them: \n, \r\n and a lone \r.
std::size_t lineBreaks(std::string_view text) {
    std::size_t count = 0;
    for (std::size_t i = 0; i < text.size(); ++i)
        if (text[i] == '\n' || (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n'))) ++count;
    return count;
}

void check(std::string_view source, t10::GlslStage stage) {
    try {
        const t10::GlslEsShader es = t10::translateToGlslEs(source, "fuzz.glsl", stage);
        const std::size_t in = lineBreaks(source);
        const std::size_t out = static_cast<std::size_t>(std::count(es.source.begin(), es.source.end(), '\n'));
        if (es.source.rfind("#version 300 es\n", 0) != 0 && es.source != "#version 300 es") __builtin_trap();
        if (out != in && out != in + 2) __builtin_trap(); // a rewrite moved the lines
        if (es.source.find('\0') != std::string::npos) __builtin_trap();
    } catch (const t10::Error& error) {
        if (std::string(error.what()).rfind("fuzz.glsl:", 0) != 0) __builtin_trap(); // names the file
    }
}

// The page's loop refusal (t10::unboundedLoops) reads the same bytes: each refusal on a line the input
// has (0: the file as a whole), an error naming the input.
void checkLoops(std::string_view source) {
    try {
        for (const t10::ShaderMessage& m : t10::unboundedLoops(source, "fuzz.glsl"))
            if (m.line < 0 || static_cast<std::size_t>(m.line) > lineBreaks(source) + 1 || m.message.empty()) __builtin_trap();
    } catch (const t10::Error& error) {
        if (std::string(error.what()).rfind("fuzz.glsl:", 0) != 0) __builtin_trap();
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view source(reinterpret_cast<const char*>(data), size);
    check(source, t10::GlslStage::Fragment);
    check(source, t10::GlslStage::Vertex);
    checkLoops(source);
    return 0;
}
