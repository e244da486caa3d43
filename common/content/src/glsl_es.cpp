// GLSL 4.30 -> GLSL ES 3.00 for the browser build (glsl_es.hpp says what and why). The translator is a
// lexer and a scan of the top-level declarations, not a compiler: it rewrites what it recognises (the
// version, layout qualifiers, subroutines, integer texture biases), refuses by name every construct
// that has no ES 3.00 form, and leaves everything else to the browser's compiler, whose log keeps the
// file's line numbers because every rewrite keeps its newlines. Nothing here recurses on the input.
#include "t10/glsl_es.hpp"

#include "t10/error.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <optional>
#include <set>
#include <unordered_map>
#include <unordered_set>

namespace t10 {

namespace {

constexpr int kMaxNesting = 256; // (, [ and { together; the course's shaders stay below 10
constexpr std::uint64_t kMaxLayoutValue = 65535; // so that a binding plus an array index stays an int
// Bounds that keep the subroutine checks (quadratic in these counts) fast on hostile input.
constexpr std::size_t kMaxSubroutineFunctions = 256;
constexpr std::size_t kMaxSubroutineUniforms = 64;

// Written after `#version 300 es`: ES has no default float precision in fragment shaders and none at
// all for most sampler types; desktop GLSL is highp throughout.
constexpr const char* kPrecisions =
    "precision highp float; precision highp int; precision highp sampler2D; precision highp sampler3D; "
    "precision highp samplerCube; precision highp sampler2DShadow; precision highp samplerCubeShadow; "
    "precision highp sampler2DArray; precision highp sampler2DArrayShadow; precision highp isampler2D; "
    "precision highp isampler3D; precision highp isamplerCube; precision highp isampler2DArray; "
    "precision highp usampler2D; precision highp usampler3D; precision highp usamplerCube; "
    "precision highp usampler2DArray;";

enum class Kind { Identifier, Number, Punct, Directive };

struct Token {
    Kind kind;
    std::size_t begin; // byte offsets into the prepared text
    std::size_t end;
    int line;
};

// A replacement of text_[begin, end): `text`, then as many newlines as the range held.
struct Edit {
    std::size_t begin;
    std::size_t end;
    std::string text;
};

struct LayoutQualifier {
    std::string name; // lower case: desktop GLSL's layout identifiers ignore case
    std::optional<int> value;
    int line;
};

// The qualifiers in front of a top-level declaration.
struct Prefix {
    std::vector<std::size_t> layoutTokens;            // index of each `layout` token of the prefix
    std::vector<std::pair<std::size_t, std::size_t>> layoutRanges; // token index ranges, `layout` to `)`
    std::vector<LayoutQualifier> layout;
    bool uniform = false, in = false, out = false;
    bool subroutine = false;                          // `subroutine` without a type list
    std::vector<std::string> subroutineTypes;         // `subroutine(A, B)`
    std::pair<std::size_t, std::size_t> subroutineRange{0, 0};
    std::size_t end = 0;                              // first token after the prefix
};

struct SubroutineType {
    std::string returnType;
    std::vector<std::pair<std::string, std::string>> params; // each parameter around its name: `out vec2`, `[2]`
    int line;
};

struct SubroutineFunction {
    std::string name;
    std::vector<std::string> types;
    int index;
    std::size_t definitionEnd; // byte offset after the body's `}`, 0 for a prototype
    int line;
};

struct SubroutineDeclaration { // a subroutine uniform as declared (ProgramLayout holds what the host sets)
    std::string typeName;
    std::string name;
    int location;
    std::size_t begin, end; // the declaration's bytes
    int line;
};

bool isIdentStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool isIdentChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Parses a GLSL integer literal (decimal, octal, hex, optional u/U) up to 2^32 - 1.
std::optional<std::uint64_t> parseIntLiteral(std::string_view s) {
    if (!s.empty() && (s.back() == 'u' || s.back() == 'U')) s.remove_suffix(1);
    if (s.empty()) return std::nullopt;
    int base = 10;
    if (s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
        base = 16;
        s.remove_prefix(2);
    } else if (s.size() > 1 && s[0] == '0') {
        base = 8;
        s.remove_prefix(1);
    }
    std::uint64_t value = 0;
    for (char c : s) {
        int digit = 0;
        if (c >= '0' && c <= '9') digit = c - '0';
        else if (c >= 'a' && c <= 'f') digit = c - 'a' + 10;
        else if (c >= 'A' && c <= 'F') digit = c - 'A' + 10;
        else return std::nullopt;
        if (digit >= base) return std::nullopt;
        value = value * static_cast<std::uint64_t>(base) + static_cast<std::uint64_t>(digit);
        if (value > 0xffffffffull) return std::nullopt;
    }
    return value;
}

std::string describeByte(unsigned char c) {
    char buffer[48];
    if (c >= 0x21 && c < 0x7f) std::snprintf(buffer, sizeof buffer, "character '%c'", c);
    else std::snprintf(buffer, sizeof buffer, "byte 0x%02X", static_cast<unsigned>(c));
    return buffer;
}

bool isGlslCharacter(char c) {
    if (isIdentChar(c)) return true;
    switch (c) {
    case ' ': case '\t': case '\v': case '\f': case '\n':
    case '.': case '+': case '-': case '/': case '*': case '%': case '<': case '>': case '[': case ']':
    case '(': case ')': case '{': case '}': case '^': case '|': case '&': case '~': case '=': case '!':
    case ':': case ';': case ',': case '?': case '#':
        return true;
    default:
        return false;
    }
}

// Why an identifier has no GLSL ES 3.00 form, or nullptr when it may pass.
const char* refusedReason(std::string_view id) {
    static const std::unordered_map<std::string_view, const char*> kRefused = [] {
        std::unordered_map<std::string_view, const char*> m;
        const char* doubles = "double precision: GLSL ES has only 32-bit floats";
        for (const char* t : {"double", "dvec2", "dvec3", "dvec4", "dmat2", "dmat3", "dmat4", "dmat2x2", "dmat2x3",
                              "dmat2x4", "dmat3x2", "dmat3x3", "dmat3x4", "dmat4x2", "dmat4x3", "dmat4x4",
                              "packDouble2x32", "unpackDouble2x32"})
            m[t] = doubles;
        const char* samplers = "this sampler type is not in GLSL ES 3.00, which has sampler2D, sampler3D, samplerCube, "
                               "sampler2DArray, their shadow forms and their isampler/usampler forms";
        for (const char* t : {"sampler1D", "sampler1DShadow", "sampler1DArray", "sampler1DArrayShadow", "isampler1D",
                              "usampler1D", "isampler1DArray", "usampler1DArray", "sampler2DRect",
                              "sampler2DRectShadow", "isampler2DRect", "usampler2DRect", "samplerBuffer",
                              "isamplerBuffer", "usamplerBuffer", "sampler2DMS", "isampler2DMS", "usampler2DMS",
                              "sampler2DMSArray", "isampler2DMSArray", "usampler2DMSArray", "samplerCubeArray",
                              "samplerCubeArrayShadow", "isamplerCubeArray", "usamplerCubeArray"})
            m[t] = samplers;
        m["atomic_uint"] = "atomic counters are not in GLSL ES 3.00";
        m["buffer"] = "shader storage blocks: WebGL2 has none";
        m["shared"] = "compute shared memory: WebGL2 has no compute shaders";
        for (const char* t : {"coherent", "volatile", "restrict", "readonly", "writeonly"})
            m[t] = "memory qualifiers belong to images and storage blocks, which WebGL2 lacks";
        m["patch"] = "tessellation: WebGL2 has none";
        m["sample"] = "per-sample interpolation is not in GLSL ES 3.00";
        m["noperspective"] = "GLSL ES 3.00 has only smooth and flat interpolation";
        m["precise"] = "the precise qualifier is not in GLSL ES 3.00";
        m["attribute"] = "a compatibility-profile keyword: use in";
        m["varying"] = "a compatibility-profile keyword: use in/out";
        const char* functions = "not a built-in function of GLSL ES 3.00";
        for (const char* t :
             {"textureQueryLevels", "textureQueryLod", "textureGather", "textureGatherOffset", "textureGatherOffsets",
              "textureSamples", "imageLoad", "imageStore", "imageSize", "imageSamples", "imageAtomicAdd",
              "imageAtomicMin", "imageAtomicMax", "imageAtomicAnd", "imageAtomicOr", "imageAtomicXor",
              "imageAtomicExchange", "imageAtomicCompSwap", "atomicAdd", "atomicMin", "atomicMax", "atomicAnd",
              "atomicOr", "atomicXor", "atomicExchange", "atomicCompSwap", "atomicCounter", "atomicCounterIncrement",
              "atomicCounterDecrement", "barrier", "memoryBarrier", "memoryBarrierAtomicCounter",
              "memoryBarrierBuffer", "memoryBarrierShared", "memoryBarrierImage", "groupMemoryBarrier", "EmitVertex",
              "EndPrimitive", "EmitStreamVertex", "EndStreamPrimitive", "dFdxFine", "dFdyFine", "dFdxCoarse",
              "dFdyCoarse", "fwidthFine", "fwidthCoarse", "interpolateAtCentroid", "interpolateAtSample",
              "interpolateAtOffset", "fma", "frexp", "ldexp", "bitfieldExtract", "bitfieldInsert", "bitfieldReverse",
              "bitCount", "findLSB", "findMSB", "uaddCarry", "usubBorrow", "umulExtended", "imulExtended",
              "packUnorm4x8", "packSnorm4x8", "unpackUnorm4x8", "unpackSnorm4x8", "ftransform", "texture1D",
              "texture2D", "texture3D", "textureCube", "shadow2D", "texture2DLod", "texture2DProj"})
            m[t] = functions;
        const char* variables = "not a built-in variable of GLSL ES 3.00";
        for (const char* t :
             {"gl_ClipDistance", "gl_CullDistance", "gl_PrimitiveID", "gl_PrimitiveIDIn", "gl_Layer",
              "gl_ViewportIndex", "gl_SampleID", "gl_SamplePosition", "gl_SampleMask", "gl_SampleMaskIn",
              "gl_NumSamples", "gl_NumWorkGroups", "gl_WorkGroupID", "gl_LocalInvocationID",
              "gl_GlobalInvocationID", "gl_LocalInvocationIndex", "gl_WorkGroupSize", "gl_InvocationID",
              "gl_PatchVerticesIn", "gl_TessLevelOuter", "gl_TessLevelInner", "gl_TessCoord", "gl_in", "gl_out",
              "gl_HelperInvocation", "gl_ClipVertex", "gl_FragColor", "gl_FragData", "gl_BaseVertex",
              "gl_BaseInstance", "gl_DrawID", "gl_VertexIndex", "gl_InstanceIndex"})
            m[t] = variables;
        return m;
    }();
    const auto found = kRefused.find(id);
    if (found != kRefused.end()) return found->second;
    // image1D .. uimage2DMSArray
    std::string_view rest = id;
    if (rest.size() > 1 && (rest[0] == 'i' || rest[0] == 'u') && rest[1] == 'i') rest.remove_prefix(1);
    if (rest.size() > 5 && rest.substr(0, 5) == "image" && (rest[5] == '1' || rest[5] == '2' || rest[5] == '3' ||
                                                            rest.substr(5) == "Cube" || rest.substr(5) == "Buffer" ||
                                                            rest.substr(5) == "CubeArray"))
        return "image load/store: WebGL2 has no images";
    return nullptr;
}

bool isSamplerType(std::string_view type) {
    if (!type.empty() && (type[0] == 'i' || type[0] == 'u')) type.remove_prefix(1);
    return type.substr(0, 7) == "sampler";
}

bool isPrefixKeyword(std::string_view id) {
    static const std::unordered_set<std::string_view> kKeywords = {
        "const", "uniform", "in", "out", "centroid", "flat", "smooth", "invariant", "highp", "mediump", "lowp"};
    return kKeywords.count(id) != 0;
}

std::string join(const std::vector<std::string>& parts, const char* separator) {
    std::string out;
    for (std::size_t i = 0; i < parts.size(); ++i) out += (i ? separator : "") + parts[i];
    return out;
}

class Translator {
public:
    Translator(std::string_view source, const std::string& fileName, GlslStage stage)
        : file_(fileName), stage_(stage) {
        prepare(source);
    }

    GlslEsShader run();

    // What unboundedLoops() reads: the text with its comments blanked, its tokens, a directive's words
    // and the bracket closing tokens()[open].
    const std::string& prepared() const { return text_; }
    const std::vector<Token>& tokens() const { return tokens_; }
    std::vector<Token> words(const Token& directive) const { return lex(directive.begin + 1, directive.end, directive.line); }
    std::size_t closing(std::size_t open) const { return matching(open); }

private:
    [[noreturn]] void fail(int line, const std::string& message) const {
        throw Error(file_ + ":" + std::to_string(line) + ": " + message);
    }
    [[noreturn]] void refuse(int line, const std::string& construct, const std::string& why) const {
        fail(line, construct + " cannot be translated to GLSL ES 3.00 (" + why + ")");
    }

    std::string_view text(const Token& t) const { return std::string_view(text_).substr(t.begin, t.end - t.begin); }
    std::string_view text(std::size_t i) const { return text(tokens_[i]); }
    bool isPunct(std::size_t i, char c) const {
        return i < tokens_.size() && tokens_[i].kind == Kind::Punct && text_[tokens_[i].begin] == c;
    }
    bool isIdent(std::size_t i) const { return i < tokens_.size() && tokens_[i].kind == Kind::Identifier; }
    std::size_t nextCode(std::size_t i) const { // the next token that is not a directive
        while (i < tokens_.size() && tokens_[i].kind == Kind::Directive) ++i;
        return i;
    }
    std::size_t matching(std::size_t open) const; // the bracket closing tokens_[open]

    void prepare(std::string_view source);
    void blankComments();
    std::vector<Token> lex(std::size_t begin, std::size_t end, int line) const;
    void readVersion() const;
    void checkDirectives() const;
    void checkBrackets() const;
    void checkIdentifiers() const;
    void scanDeclarations(std::size_t first);
    void declaration(std::size_t first, std::size_t last);
    Prefix readPrefix(std::size_t first, std::size_t last);
    void layoutList(std::size_t open, std::size_t close, std::vector<LayoutQualifier>& out) const;
    void erase(std::size_t from, std::size_t to);
    void rewriteLayout(const Prefix& p, std::size_t first, const std::vector<std::string>& kept);
    void uniformDeclaration(const Prefix& p, std::size_t first, std::size_t last);
    void uniformBlock(const Prefix& p, std::size_t first);
    void inOutDeclaration(const Prefix& p, std::size_t first);
    void subroutineDeclaration(const Prefix& p, std::size_t first, std::size_t last);
    void subroutineFunction(const Prefix& p, std::size_t first, std::size_t last);
    std::vector<std::pair<int, std::string>> subroutineCallees(const SubroutineDeclaration& u, std::size_t& lastEnd) const;
    std::string dispatchFunction(const SubroutineDeclaration& u, const SubroutineType& type, const std::string& indexName,
                                 const std::vector<std::pair<int, std::string>>& callees);
    std::string joinTokens(std::size_t from, std::size_t to) const;
    std::pair<std::string, std::string> parameter(std::size_t from, std::size_t to) const;
    int layoutValue(const LayoutQualifier& q) const;
    std::optional<std::uint64_t> arraySize(std::size_t& k) const;
    void emitSubroutines();
    void convertTextureLiterals();
    std::string uniqueName(std::string base);
    std::string assemble(int versionLine, std::size_t versionEnd) const;

    std::string file_;
    GlslStage stage_;
    std::string text_; // the source, newlines normalised to \n and comments blanked to spaces
    std::vector<Token> tokens_;
    std::unordered_set<std::string> names_; // every identifier of the source and those generated
    std::vector<Edit> edits_;
    bool defaultPacking_ = false; // a `layout(std140) uniform;` default statement was seen
    std::unordered_map<std::string, SubroutineType> subroutineTypes_;
    std::vector<SubroutineFunction> subroutineFunctions_;
    std::vector<SubroutineDeclaration> subroutineUniforms_;
    GlslEsShader out_;
};

void Translator::prepare(std::string_view source) {
    if (source.size() > kGlslEsMaxSourceBytes)
        throw Error(file_ + ": " + std::to_string(source.size()) + " bytes is more than the " +
                    std::to_string(kGlslEsMaxSourceBytes) + " bytes the GLSL ES translator accepts in one shader");
    text_.reserve(source.size());
    int line = 1;
    for (std::size_t i = 0; i < source.size(); ++i) {
        const char c = source[i];
        if (c == '\0') fail(line, "a NUL byte: the file is not GLSL text");
        if (c == '\r') { // \r\n and a lone \r both end a line, as in GLSL
            text_ += '\n';
            if (i + 1 < source.size() && source[i + 1] == '\n') ++i;
            ++line;
            continue;
        }
        text_ += c;
        if (c == '\n') ++line;
    }
    blankComments();
    tokens_ = lex(0, text_.size(), 1);
}

// Replaces comments by spaces (keeping their newlines) and checks the characters outside them.
void Translator::blankComments() {
    int line = 1;
    bool lineStart = true, directive = false;
    for (std::size_t i = 0; i < text_.size(); ++i) {
        const char c = text_[i];
        const char next = i + 1 < text_.size() ? text_[i + 1] : '\0';
        if (c == '\\' && next == '\n')
            refuse(line, "a line continuation (a backslash at the end of a line)", "join the lines");
        if (c == '/' && next == '/') {
            std::size_t end = text_.find('\n', i);
            if (end == std::string::npos) end = text_.size();
            if (end > i && text_[end - 1] == '\\' && end < text_.size())
                refuse(line, "a // comment ending in a backslash", "it would continue the comment onto the next line");
            std::fill(text_.begin() + static_cast<std::ptrdiff_t>(i), text_.begin() + static_cast<std::ptrdiff_t>(end), ' ');
            i = end - 1;
            continue;
        }
        if (c == '/' && next == '*') {
            const std::size_t close = text_.find("*/", i + 2);
            if (close == std::string::npos) fail(line, "a /* comment that is never closed");
            const int openLine = line;
            for (std::size_t k = i; k < close + 2; ++k) {
                if (text_[k] == '\n') ++line;
                else text_[k] = ' ';
            }
            if (directive && line != openLine)
                refuse(openLine, "a /* comment spanning lines inside a preprocessor directive",
                       "the directive would end at the comment's first line break");
            i = close + 1;
            continue;
        }
        if (!isGlslCharacter(c)) {
            const auto byte = static_cast<unsigned char>(c);
            fail(line, describeByte(byte) + (byte >= 0x80 ? " outside a comment: GLSL allows only ASCII there"
                                                          : " is not part of GLSL's character set"));
        }
        if (c == '\n') {
            ++line;
            lineStart = true;
            directive = false;
        } else if (c == '#' && lineStart) {
            directive = true;
            lineStart = false;
        } else if (c != ' ' && c != '\t' && c != '\v' && c != '\f') {
            lineStart = false;
        }
    }
}

// Tokens of text_[begin, end). A `#` first on its line makes the rest of the line one Directive token.
std::vector<Token> Translator::lex(std::size_t begin, std::size_t end, int line) const {
    std::vector<Token> tokens;
    bool lineStart = begin == 0;
    std::size_t i = begin;
    while (i < end) {
        const char c = text_[i];
        if (c == '\n') {
            ++line;
            lineStart = true;
            ++i;
            continue;
        }
        if (c == ' ' || c == '\t' || c == '\v' || c == '\f') {
            ++i;
            continue;
        }
        const std::size_t start = i;
        Kind kind = Kind::Punct;
        if (c == '#' && lineStart) {
            kind = Kind::Directive;
            while (i < end && text_[i] != '\n') ++i;
        } else if (isIdentStart(c)) {
            kind = Kind::Identifier;
            while (i < end && isIdentChar(text_[i])) ++i;
        } else if (std::isdigit(static_cast<unsigned char>(c)) ||
                   (c == '.' && i + 1 < end && std::isdigit(static_cast<unsigned char>(text_[i + 1])))) {
            kind = Kind::Number;
            const bool hex = c == '0' && i + 1 < end && (text_[i + 1] == 'x' || text_[i + 1] == 'X');
            while (i < end) {
                const char d = text_[i];
                const bool exponentSign = !hex && (d == '+' || d == '-') && (text_[i - 1] == 'e' || text_[i - 1] == 'E');
                if (!isIdentChar(d) && d != '.' && !exponentSign) break;
                ++i;
            }
        } else {
            ++i;
        }
        lineStart = false;
        tokens.push_back(Token{kind, start, i, line});
    }
    return tokens;
}

std::size_t Translator::matching(std::size_t open) const {
    int depth = 0;
    for (std::size_t i = open; i < tokens_.size(); ++i) {
        if (tokens_[i].kind != Kind::Punct) continue;
        const char c = text_[tokens_[i].begin];
        if (c == '(' || c == '[' || c == '{') ++depth;
        else if (c == ')' || c == ']' || c == '}') {
            if (--depth == 0) return i;
        }
    }
    return tokens_.size(); // checkBrackets() has ruled this out
}

// The first token must be a desktop `#version`.
void Translator::readVersion() const {
    if (tokens_.empty()) fail(1, "no #version directive (the file is empty): expected #version 430 core");
    const Token& first = tokens_[0];
    const std::vector<Token> words = lex(first.begin + 1, first.end, first.line);
    if (first.kind != Kind::Directive || words.empty() || text(words[0]) != "version")
        fail(first.line, "expected #version 430 core before anything else (only comments may come first)");
    const std::string profile = words.size() > 2 ? std::string(text(words[2])) : "";
    const std::string number = words.size() > 1 ? std::string(text(words[1])) : "";
    static const std::set<std::string> kDesktop = {"330", "400", "410", "420", "430", "440", "450", "460"};
    if (words.size() > 3 || !kDesktop.count(number) || !(profile.empty() || profile == "core"))
        refuse(first.line, "`" + std::string(text(first)) + "`",
               "the translator reads desktop GLSL 3.30 to 4.60 core shaders; the course's are #version 430 core");
}

void Translator::checkDirectives() const {
    for (std::size_t i = 1; i < tokens_.size(); ++i) {
        const Token& t = tokens_[i];
        if (t.kind != Kind::Directive) continue;
        const std::vector<Token> words = lex(t.begin + 1, t.end, t.line);
        if (words.empty()) continue; // the null directive
        const std::string_view name = text(words[0]);
        if (name == "version") fail(t.line, "a second #version directive");
        if (name == "extension")
            refuse(t.line, "#extension", "desktop GLSL extensions have no ES form in the browser; remove the line");
        if (name == "include") refuse(t.line, "#include", "GLSL has no #include without an extension");
        static const std::set<std::string_view> kPassed = {"define", "undef", "if", "ifdef", "ifndef", "elif",
                                                           "else", "endif", "line", "pragma", "error"};
        if (!kPassed.count(name)) fail(t.line, "unknown preprocessor directive #" + std::string(name));
        if (name != "define") continue;
        // Macros are not expanded: one that hides a layout or a subroutine would escape the rewrite.
        const std::string macro = words.size() > 1 ? std::string(text(words[1])) : "";
        for (std::size_t k = 2; k < words.size(); ++k) {
            const std::string_view word = text(words[k]);
            if (word == "layout" || word == "subroutine")
                refuse(t.line, "#define " + macro + " (a macro containing `" + std::string(word) + "`)",
                       "the translator does not expand macros; write the qualifier out where it is used");
            if (words[k].kind == Kind::Identifier)
                if (const char* why = refusedReason(word)) refuse(t.line, "`" + std::string(word) + "`", why);
        }
    }
}

void Translator::checkBrackets() const {
    std::vector<std::pair<char, int>> open;
    for (const Token& t : tokens_) {
        if (t.kind != Kind::Punct) continue;
        const char c = text_[t.begin];
        if (c == '(' || c == '[' || c == '{') {
            if (open.size() >= static_cast<std::size_t>(kMaxNesting))
                fail(t.line, "brackets nested more than " + std::to_string(kMaxNesting) + " deep");
            open.emplace_back(c == '(' ? ')' : c == '[' ? ']' : '}', t.line);
        } else if (c == ')' || c == ']' || c == '}') {
            if (open.empty() || open.back().first != c)
                fail(t.line, std::string("unmatched '") + c + "'" +
                                 (open.empty() ? "" : " (expected '" + std::string(1, open.back().first) +
                                                          "' for the bracket of line " + std::to_string(open.back().second) + ")") +
                                 "; brackets must balance outside #if branches too");
            open.pop_back();
        }
    }
    if (!open.empty()) fail(open.back().second, std::string("a bracket that is never closed (expected '") + open.back().first + "')");
}

void Translator::checkIdentifiers() const {
    for (std::size_t i = 0; i < tokens_.size(); ++i) {
        const Token& t = tokens_[i];
        if (t.kind == Kind::Identifier && text(t) == "layout" && isPunct(i + 1, '(')) {
            i = matching(i + 1); // layout identifiers (`shared`, ...) are checked by layoutList()
            continue;
        }
        if (t.kind == Kind::Identifier) {
            if (const char* why = refusedReason(text(t))) refuse(t.line, "`" + std::string(text(t)) + "`", why);
        } else if (t.kind == Kind::Number) {
            const std::string_view n = text(t);
            if (n.size() > 2 && (n.substr(n.size() - 2) == "lf" || n.substr(n.size() - 2) == "LF"))
                refuse(t.line, "the double-precision literal " + std::string(n), "GLSL ES has only 32-bit floats");
        }
    }
}

std::string Translator::joinTokens(std::size_t from, std::size_t to) const {
    std::string out;
    for (std::size_t i = from; i < to; ++i) {
        if (tokens_[i].kind == Kind::Directive) continue;
        const bool bracket = isPunct(i, '[') || isPunct(i, ']') || (!out.empty() && out.back() == '[');
        if (!out.empty() && !bracket) out += ' ';
        out += text(i);
    }
    return out;
}

int Translator::layoutValue(const LayoutQualifier& q) const {
    if (!q.value) fail(q.line, "layout(" + q.name + ") needs a value: layout(" + q.name + " = N)");
    return *q.value;
}

// At `[`: reads `[N]` and moves k past it; the size when N is an integer literal.
std::optional<std::uint64_t> Translator::arraySize(std::size_t& k) const {
    if (!isPunct(k, '[')) return std::nullopt;
    const std::size_t close = matching(k);
    const std::size_t inner = nextCode(k + 1);
    std::optional<std::uint64_t> size;
    if (inner < close && tokens_[inner].kind == Kind::Number && nextCode(inner + 1) == close)
        size = parseIntLiteral(text(inner));
    k = nextCode(close + 1);
    return size ? size : std::optional<std::uint64_t>(0); // 0: an array whose size is not a literal
}

void Translator::layoutList(std::size_t open, std::size_t close, std::vector<LayoutQualifier>& out) const {
    std::size_t i = open + 1;
    while (i < close) {
        if (!isIdent(i)) fail(tokens_[i].line, "a malformed layout qualifier list (expected a qualifier name)");
        LayoutQualifier q{std::string(text(i)), std::nullopt, tokens_[i].line};
        std::transform(q.name.begin(), q.name.end(), q.name.begin(),
                       [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); });
        ++i;
        if (isPunct(i, '=')) {
            const std::size_t v = i + 1;
            const auto value = v < close && tokens_[v].kind == Kind::Number ? parseIntLiteral(text(v)) : std::nullopt;
            if (value && *value > kMaxLayoutValue && (v + 1 >= close || isPunct(v + 1, ',')))
                refuse(tokens_[v].line, "layout(" + q.name + " = " + std::string(text(v)) + ")",
                       "no binding point, unit or location goes beyond " + std::to_string(kMaxLayoutValue));
            if (!value || (v + 1 < close && !isPunct(v + 1, ',')))
                refuse(tokens_[i].line, "layout(" + q.name + " = " + (v < close ? std::string(text(v)) : "") + "...)",
                       "the value must be an integer literal: the translator neither expands macros nor evaluates "
                       "expressions");
            q.value = static_cast<int>(*value);
            i = v + 1;
        }
        out.push_back(q);
        if (i < close && !isPunct(i, ',')) fail(tokens_[i].line, "a malformed layout qualifier list (expected ',')");
        ++i;
    }
}

Prefix Translator::readPrefix(std::size_t first, std::size_t last) {
    Prefix p;
    std::size_t i = first;
    while ((i = nextCode(i)) <= last && isIdent(i)) {
        const std::string_view word = text(i);
        if (word == "layout") {
            const std::size_t open = nextCode(i + 1);
            if (!isPunct(open, '(')) fail(tokens_[i].line, "`layout` without a qualifier list");
            const std::size_t close = matching(open);
            for (std::size_t k = open; k < close; ++k)
                if (tokens_[k].kind == Kind::Directive)
                    refuse(tokens_[k].line, "a preprocessor directive inside layout(...)", "the translator cannot follow it");
            p.layoutRanges.emplace_back(i, close);
            layoutList(open, close, p.layout);
            i = close + 1;
        } else if (word == "subroutine") {
            const std::size_t open = nextCode(i + 1);
            if (isPunct(open, '(')) {
                const std::size_t close = matching(open);
                for (std::size_t k = open + 1; k < close; ++k)
                    if (isIdent(k)) p.subroutineTypes.emplace_back(text(k));
                    else if (!isPunct(k, ',')) fail(tokens_[k].line, "a malformed subroutine(...) type list");
                p.subroutineRange = {i, close};
                i = close + 1;
            } else {
                p.subroutine = true;
                p.subroutineRange = {i, i};
                i = open;
            }
        } else if (isPrefixKeyword(word)) {
            p.uniform = p.uniform || word == "uniform";
            p.in = p.in || word == "in";
            p.out = p.out || word == "out";
            ++i;
        } else {
            break;
        }
    }
    p.end = i;
    return p;
}

// Removes the range and the spaces after it (a qualifier's own line keeps its newlines).
void Translator::erase(std::size_t from, std::size_t to) {
    std::size_t end = tokens_[to].end;
    while (end < text_.size() && (text_[end] == ' ' || text_[end] == '\t')) ++end;
    edits_.push_back({tokens_[from].begin, end, ""});
}

void Translator::rewriteLayout(const Prefix& p, std::size_t first, const std::vector<std::string>& kept) {
    for (const auto& [from, to] : p.layoutRanges) erase(from, to);
    if (!kept.empty()) edits_.push_back({tokens_[first].begin, tokens_[first].begin, "layout(" + join(kept, ", ") + ") "});
}

void Translator::scanDeclarations(std::size_t first) {
    std::size_t i = first;
    while ((i = nextCode(i)) < tokens_.size()) {
        std::size_t last = tokens_.size(), previous = tokens_.size();
        for (std::size_t j = i; j < tokens_.size(); ++j) {
            if (tokens_[j].kind == Kind::Directive) continue;
            if (isPunct(j, ';')) {
                last = j;
                break;
            }
            if (isPunct(j, '{') && previous < tokens_.size() && isPunct(previous, ')')) { // a function body
                last = matching(j);
                break;
            }
            if (isPunct(j, '(') || isPunct(j, '[') || isPunct(j, '{')) j = matching(j);
            previous = j;
        }
        if (last == tokens_.size()) fail(tokens_[i].line, "a declaration that never ends (no ';' after it)");
        declaration(i, last);
        i = last + 1;
    }
}

void Translator::declaration(std::size_t first, std::size_t last) {
    const Prefix p = readPrefix(first, last);
    const int line = tokens_[first].line;
    for (std::size_t k = p.end; k <= last; ++k)
        if (isIdent(k) && (text(k) == "layout" || text(k) == "subroutine"))
            refuse(tokens_[k].line, "`" + std::string(text(k)) + "` here",
                   "the translator rewrites layout and subroutine qualifiers only at the start of a global declaration");
    if (!p.layoutRanges.empty() || p.subroutine || !p.subroutineTypes.empty())
        for (std::size_t k = first; k <= last; ++k)
            if (tokens_[k].kind == Kind::Directive)
                refuse(tokens_[k].line, "a preprocessor directive inside a declaration with a layout or subroutine qualifier",
                       "the translator cannot follow it");
    if (p.subroutine) return subroutineDeclaration(p, first, last);
    if (!p.subroutineTypes.empty()) return subroutineFunction(p, first, last);
    const std::size_t rest = nextCode(p.end);
    const bool block = isIdent(rest) && isPunct(nextCode(rest + 1), '{');
    if (p.uniform && isPunct(rest, ';')) { // `layout(std140) uniform;` sets the default block layout
        for (const LayoutQualifier& q : p.layout) {
            if (q.name == "std140" || q.name == "shared" || q.name == "packed") defaultPacking_ = true;
            else if (q.name != "row_major" && q.name != "column_major")
                refuse(q.line, "layout(" + q.name + ") uniform;", "only block packings and matrix orders have defaults in ES");
        }
        return;
    }
    if (p.uniform) return block ? uniformBlock(p, first) : uniformDeclaration(p, first, last);
    if ((p.in || p.out) && block)
        refuse(line, "an in/out interface block", "GLSL ES 3.00 has blocks only for uniforms: declare the variables one by one");
    if ((p.in || p.out) && isPunct(rest, ';') && !p.layout.empty())
        refuse(line, "a layout(...) in/out default", "it belongs to compute, geometry or tessellation shaders, or to "
                     "fragment-test qualifiers GLSL ES 3.00 lacks");
    if (p.in || p.out) return inOutDeclaration(p, first);
    if (!p.layout.empty())
        refuse(line, "layout(" + p.layout.front().name + ")", "it is on a declaration that is neither a uniform nor an in/out variable");
}

void Translator::uniformDeclaration(const Prefix& p, std::size_t first, std::size_t last) {
    const int line = tokens_[first].line;
    for (std::size_t k = p.end; k <= last; ++k)
        if (isPunct(k, '=')) refuse(tokens_[k].line, "a uniform initializer", "GLSL ES 3.00 uniforms start at 0: set the value from the host");
    std::size_t k = nextCode(p.end);
    if (!isIdent(k) || text(k) == "struct") {
        if (!p.layout.empty()) refuse(line, "a layout qualifier on a uniform struct declaration", "declare the struct first, then the uniform");
        return;
    }
    const std::string type(text(k));
    k = nextCode(k + 1);
    std::optional<std::uint64_t> size = arraySize(k);
    if (!isIdent(k)) {
        if (!p.layout.empty()) fail(line, "a uniform declaration the translator cannot read (expected a name after " + type + ")");
        return;
    }
    const std::string name(text(k));
    k = nextCode(k + 1);
    if (const auto declaratorSize = arraySize(k)) size = declaratorSize;
    if (p.layout.empty()) return;
    if (k != last)
        refuse(line, "several uniforms in one layout-qualified declaration", "give each uniform its own declaration");
    std::optional<int> location, binding; // the last of each wins, as in GLSL
    for (const LayoutQualifier& q : p.layout) {
        if (q.name == "location") location = layoutValue(q);
        else if (q.name == "binding") binding = layoutValue(q);
        else refuse(q.line, "layout(" + q.name + ") on the uniform " + name, "GLSL ES 3.00 has no such uniform qualifier");
    }
    if (location) out_.layout.uniformLocations.push_back({name, *location});
    if (binding) {
        const int unit = *binding;
        if (!isSamplerType(type))
            refuse(line, "layout(binding) on the " + type + " uniform " + name, "only samplers and uniform blocks take a binding in WebGL2");
        if (size && (*size == 0 || *size > 4096))
            refuse(line, "layout(binding) on the sampler array " + name, "its size must be an integer literal up to 4096");
        if (!size) out_.layout.samplerUnits.push_back({name, unit});
        for (std::uint64_t e = 0; size && e < *size; ++e)
            out_.layout.samplerUnits.push_back({name + "[" + std::to_string(e) + "]", unit + static_cast<int>(e)});
    }
    rewriteLayout(p, first, {});
}

void Translator::uniformBlock(const Prefix& p, std::size_t first) {
    const std::size_t nameToken = nextCode(p.end);
    const std::string name(text(nameToken));
    std::size_t k = nextCode(matching(nextCode(nameToken + 1)) + 1);
    std::optional<std::uint64_t> size;
    if (isIdent(k)) {
        k = nextCode(k + 1);
        size = arraySize(k);
    }
    std::vector<std::string> kept;
    bool packing = defaultPacking_;
    for (const LayoutQualifier& q : p.layout) {
        if (q.name == "binding") {
            const int point = layoutValue(q);
            if (size && (*size == 0 || *size > 4096))
                refuse(q.line, "layout(binding) on the block array " + name, "its size must be an integer literal up to 4096");
            if (!size) out_.layout.blockBindings.push_back({name, point});
            for (std::uint64_t e = 0; size && e < *size; ++e)
                out_.layout.blockBindings.push_back({name + "[" + std::to_string(e) + "]", point + static_cast<int>(e)});
        } else if (q.name == "std140" || q.name == "shared" || q.name == "packed") {
            packing = true;
            kept.push_back(q.name);
        } else if (q.name == "row_major" || q.name == "column_major") {
            kept.push_back(q.name);
        } else {
            refuse(q.line, "layout(" + q.name + ") on the uniform block " + name, "GLSL ES 3.00 has no such block qualifier");
        }
    }
    if (!packing) kept.insert(kept.begin(), "std140"); // ES's default is shared; the host writes std140
    rewriteLayout(p, first, kept);
}

void Translator::inOutDeclaration(const Prefix& p, std::size_t first) {
    // ES 3.00 allows a location only on vertex inputs and fragment outputs; varyings match by name.
    const bool keep = (stage_ == GlslStage::Vertex && p.in) || (stage_ == GlslStage::Fragment && p.out);
    std::vector<std::string> kept;
    for (const LayoutQualifier& q : p.layout) {
        if (q.name == "location") {
            const int location = layoutValue(q);
            if (keep) kept.push_back("location = " + std::to_string(location));
        } else if (q.name == "index" && p.out) {
            refuse(q.line, "layout(index) on a fragment output", "dual-source blending is not in WebGL2");
        } else {
            refuse(q.line, "layout(" + q.name + ") on an in/out variable", "GLSL ES 3.00 has only layout(location) there");
        }
    }
    if (!p.layout.empty()) rewriteLayout(p, first, kept);
}

// The parameter tokens [from, to) split around the parameter's name (a name-less one gets a name).
std::pair<std::string, std::string> Translator::parameter(std::size_t from, std::size_t to) const {
    std::size_t k = nextCode(from);
    static const std::unordered_set<std::string_view> kQualifiers = {"const", "in", "out", "inout", "highp", "mediump", "lowp"};
    while (k < to && isIdent(k) && kQualifiers.count(text(k))) k = nextCode(k + 1);
    if (k >= to || !isIdent(k)) fail(tokens_[std::min(k, to - 1)].line, "a subroutine parameter the translator cannot read");
    std::size_t afterType = nextCode(k + 1);
    if (isPunct(afterType, '[')) afterType = nextCode(matching(afterType) + 1);
    std::string before = joinTokens(from, afterType);
    std::size_t rest = afterType;
    if (rest < to && isIdent(rest)) rest = nextCode(rest + 1); // the name, replaced
    std::string after = joinTokens(rest, to);
    return {before, after};
}

void Translator::subroutineDeclaration(const Prefix& p, std::size_t first, std::size_t last) {
    const int line = tokens_[first].line;
    if (p.uniform) { // layout(location = L) subroutine uniform Type name;
        const std::size_t type = nextCode(p.end), name = nextCode(type + 1);
        if (!isIdent(type) || !isIdent(name) || nextCode(name + 1) != last)
            refuse(line, "this subroutine uniform", "the translator reads `layout(location = L) subroutine uniform Type name;`: one name, no array");
        std::optional<int> location;
        for (const LayoutQualifier& q : p.layout) {
            if (q.name != "location") refuse(q.line, "layout(" + q.name + ") on a subroutine uniform", "only location is translated");
            location = layoutValue(q);
        }
        if (!location)
            refuse(line, "a subroutine uniform without layout(location = L)", "the web platform sets subroutine uniforms by location: give it one");
        if (subroutineUniforms_.size() >= kMaxSubroutineUniforms)
            refuse(line, "more than " + std::to_string(kMaxSubroutineUniforms) + " subroutine uniforms", "the translator's limit");
        for (const SubroutineDeclaration& u : subroutineUniforms_)
            if (u.location == *location) fail(line, "two subroutine uniforms at location " + std::to_string(*location));
        subroutineUniforms_.push_back({std::string(text(type)), std::string(text(name)), *location, tokens_[first].begin,
                                       tokens_[last].end, line});
        return;
    }
    // subroutine ReturnType TypeName(parameters);
    if (!p.layout.empty()) refuse(line, "a layout qualifier on a subroutine type", "the translator has no use for it");
    std::size_t open = p.end;
    while (open < last && !isPunct(open, '(')) ++open;
    std::size_t name = open;
    while (name > p.end && tokens_[name - 1].kind == Kind::Directive) --name;
    if (open >= last || name <= p.end || !isIdent(name - 1) || nextCode(matching(open) + 1) != last)
        refuse(line, "this subroutine declaration", "the translator reads `subroutine ReturnType TypeName(parameters);`");
    const std::string typeName(text(name - 1));
    SubroutineType type{joinTokens(p.end, name - 1), {}, line};
    const std::size_t close = matching(open);
    std::size_t from = open + 1;
    for (std::size_t k = open + 1; k <= close; ++k) {
        if (isPunct(k, '(') || isPunct(k, '[')) k = matching(k);
        else if (isPunct(k, ',') || k == close) {
            if (nextCode(from) < k && !(nextCode(from) + 1 == k && text(nextCode(from)) == "void")) type.params.push_back(parameter(from, k));
            from = k + 1;
        }
    }
    if (!subroutineTypes_.emplace(typeName, type).second) fail(line, "a second declaration of the subroutine type " + typeName);
    edits_.push_back({tokens_[first].begin, tokens_[last].end, ""});
}

void Translator::subroutineFunction(const Prefix& p, std::size_t first, std::size_t last) {
    const int line = tokens_[first].line;
    std::optional<int> index;
    for (const LayoutQualifier& q : p.layout) {
        if (q.name != "index") refuse(q.line, "layout(" + q.name + ") on a subroutine function", "only index is translated");
        index = layoutValue(q);
    }
    std::size_t open = p.end;
    while (open < last && !isPunct(open, '(')) ++open;
    std::size_t name = open;
    while (name > p.end && tokens_[name - 1].kind == Kind::Directive) --name;
    if (open >= last || name <= p.end || !isIdent(name - 1))
        refuse(line, "this subroutine function", "the translator reads `layout(index = N) subroutine(Type) ReturnType name(...)`");
    if (!index)
        refuse(line, "the subroutine function " + std::string(text(name - 1)) + " without layout(index = N)",
               "the web platform selects subroutines by index: give it one");
    if (subroutineFunctions_.size() >= kMaxSubroutineFunctions)
        refuse(line, "more than " + std::to_string(kMaxSubroutineFunctions) + " subroutine functions",
               "GL itself guarantees no more (GL_MAX_SUBROUTINES)");
    const bool definition = isPunct(last, '}');
    subroutineFunctions_.push_back({std::string(text(name - 1)), p.subroutineTypes, *index, definition ? tokens_[last].end : 0, line});
    for (const auto& [from, to] : p.layoutRanges) erase(from, to);
    erase(p.subroutineRange.first, p.subroutineRange.second);
}

// The defined functions of the uniform's type by index; lastEnd: the byte after the last body.
std::vector<std::pair<int, std::string>> Translator::subroutineCallees(const SubroutineDeclaration& u, std::size_t& lastEnd) const {
    std::vector<std::pair<int, std::string>> callees;
    lastEnd = 0;
    for (const SubroutineFunction& f : subroutineFunctions_) {
        if (std::find(f.types.begin(), f.types.end(), u.typeName) == f.types.end()) continue;
        bool defined = f.definitionEnd != 0;
        for (const SubroutineFunction& g : subroutineFunctions_) {
            if (g.name != f.name) continue;
            if (g.index != f.index) fail(g.line, "the subroutine function " + f.name + " has two different indices");
            defined = defined || g.definitionEnd != 0;
        }
        if (!defined) fail(f.line, "the subroutine function " + f.name + " is declared but never defined");
        if (f.definitionEnd == 0) continue;
        for (const auto& [index, callee] : callees)
            if (index == f.index)
                fail(f.line, "two subroutine functions of type " + u.typeName + " with index " + std::to_string(index) + ": " +
                                 callee + " and " + f.name);
        callees.emplace_back(f.index, f.name);
        lastEnd = std::max(lastEnd, f.definitionEnd);
    }
    std::sort(callees.begin(), callees.end());
    return callees;
}

// `ReturnType U(params) { if (index == 1) return f1(args); ... return lowestIndexFunction(args); }`: the
// lowest index is also what an unset uniform (0) or an index without a function calls.
std::string Translator::dispatchFunction(const SubroutineDeclaration& u, const SubroutineType& type,
                                         const std::string& indexName,
                                         const std::vector<std::pair<int, std::string>>& callees) {
    std::vector<std::string> params, args;
    for (const auto& [before, after] : type.params) {
        args.push_back(uniqueName("t10Arg" + std::to_string(args.size())));
        params.push_back(before + " " + args.back() + after);
    }
    const bool isVoid = type.returnType == "void";
    const std::string argList = "(" + join(args, ", ") + ")";
    std::string body;
    for (std::size_t i = 1; i < callees.size(); ++i) {
        const std::string call = callees[i].second + argList;
        body += "if (" + indexName + " == " + std::to_string(callees[i].first) + ") " +
                (isVoid ? "{ " + call + "; return; } " : "return " + call + "; ");
    }
    body += (isVoid ? "" : "return ") + callees.front().second + argList + "; ";
    return type.returnType + " " + u.name + "(" + join(params, ", ") + ") { " + body + "}";
}

void Translator::emitSubroutines() {
    for (const SubroutineFunction& f : subroutineFunctions_)
        for (const std::string& t : f.types)
            if (!subroutineTypes_.count(t)) fail(f.line, "the subroutine function " + f.name + " names an undeclared subroutine type " + t);
    for (const SubroutineDeclaration& u : subroutineUniforms_) {
        const auto type = subroutineTypes_.find(u.typeName);
        if (type == subroutineTypes_.end()) fail(u.line, "the subroutine uniform " + u.name + " has an undeclared type " + u.typeName);
        std::size_t lastEnd = 0;
        const auto callees = subroutineCallees(u, lastEnd);
        if (callees.empty())
            refuse(u.line, "the subroutine uniform " + u.name, "no function is defined as layout(index = N) subroutine(" + u.typeName + ")");
        const std::size_t at = std::max(u.end, lastEnd);
        for (const Token& t : tokens_)
            if (t.kind == Kind::Identifier && t.begin < at && (t.begin < u.begin || t.begin >= u.end) && text(t) == u.name)
                refuse(t.line, "this use of " + u.name + " before the last subroutine function of type " + u.typeName,
                       "the translator defines " + u.name + " after those functions: move them above it");
        const std::string indexName = uniqueName(u.name.find("__") == std::string::npos ? "t10SubroutineIndex" + u.name : "t10SubroutineIndex");
        edits_.push_back({u.begin, u.end, "uniform int " + indexName + ";"});
        edits_.push_back({at, at, " " + dispatchFunction(u, type->second, indexName, callees)});
        std::vector<NamedValue> functions;
        for (const auto& [index, name] : callees) functions.push_back({name, index});
        out_.layout.subroutineUniforms.push_back({stage_, u.location, indexName, functions});
    }
}

// GLSL 4.30 converts an integer bias or level of detail to float; ES 3.00 has no implicit conversions.
void Translator::convertTextureLiterals() {
    // Literals inside what a rewrite removes (a subroutine type's parameters) stay as they are.
    std::vector<std::pair<std::size_t, std::size_t>> removed;
    for (const Edit& e : edits_)
        if (e.end > e.begin) removed.emplace_back(e.begin, e.end);
    std::sort(removed.begin(), removed.end());
    const auto isRemoved = [&](std::size_t at) {
        auto after = std::upper_bound(removed.begin(), removed.end(), std::make_pair(at, std::string::npos));
        return after != removed.begin() && std::prev(after)->second > at;
    };
    static const std::unordered_map<std::string_view, std::size_t> kFloatArgument = {
        {"texture", 2}, {"textureProj", 2}, {"textureLod", 2}, {"textureProjLod", 2}, {"textureLodOffset", 2},
        {"textureProjLodOffset", 2}, {"textureOffset", 3}, {"textureProjOffset", 3}};
    for (std::size_t i = 0; i < tokens_.size(); ++i) {
        if (!isIdent(i)) continue;
        const auto found = kFloatArgument.find(text(i));
        const std::size_t open = nextCode(i + 1);
        if (found == kFloatArgument.end() || !isPunct(open, '(')) continue;
        const std::size_t close = matching(open);
        std::vector<std::vector<std::size_t>> args(1);
        for (std::size_t k = open + 1; k < close; ++k) {
            if (tokens_[k].kind == Kind::Directive) continue;
            if (isPunct(k, ',')) {
                args.emplace_back();
                continue;
            }
            args.back().push_back(k);
            if (isPunct(k, '(') || isPunct(k, '[') || isPunct(k, '{')) k = matching(k);
        }
        if (args.size() <= found->second) continue;
        const std::vector<std::size_t>& arg = args[found->second];
        const bool signedLiteral = arg.size() == 2 && (isPunct(arg[0], '-') || isPunct(arg[0], '+'));
        if (arg.size() != 1 && !signedLiteral) continue;
        const std::size_t literal = arg.back();
        if (tokens_[literal].kind != Kind::Number || isRemoved(tokens_[literal].begin)) continue;
        if (const auto value = parseIntLiteral(text(literal)))
            edits_.push_back({tokens_[literal].begin, tokens_[literal].end, std::to_string(*value) + ".0"});
    }
}

std::string Translator::uniqueName(std::string base) {
    std::string name = base;
    for (int n = 1; names_.count(name); ++n) name = base + std::to_string(n);
    names_.insert(name);
    return name;
}

// Line 1 is `#version 300 es`; the precisions take the version's line when it was not the first
// (only comments came before it), else their own line followed by `#line 2` (ES: the next line is 2).
std::string Translator::assemble(int versionLine, std::size_t versionEnd) const {
    std::string out = "#version 300 es";
    if (versionLine >= 2) out += std::string(static_cast<std::size_t>(versionLine - 1), '\n') + kPrecisions;
    else out += std::string("\n") + kPrecisions + "\n#line 2";
    std::vector<Edit> edits = edits_;
    std::stable_sort(edits.begin(), edits.end(), [](const Edit& a, const Edit& b) {
        return a.begin != b.begin ? a.begin < b.begin : a.end - a.begin < b.end - b.begin;
    });
    std::size_t cursor = versionEnd;
    for (const Edit& e : edits) {
        if (e.begin < cursor) throw Error(file_ + ": internal error in the GLSL ES translator (overlapping rewrites)");
        out.append(text_, cursor, e.begin - cursor);
        out += e.text;
        out.append(static_cast<std::size_t>(std::count(text_.begin() + static_cast<std::ptrdiff_t>(e.begin),
                                                       text_.begin() + static_cast<std::ptrdiff_t>(e.end), '\n')),
                   '\n');
        cursor = e.end;
    }
    out.append(text_, cursor, std::string::npos);
    return out;
}

GlslEsShader Translator::run() {
    readVersion();
    checkBrackets();
    checkDirectives();
    checkIdentifiers();
    for (const Token& t : tokens_) {
        if (t.kind == Kind::Identifier) names_.emplace(text(t));
        if (t.kind == Kind::Directive)
            for (const Token& w : lex(t.begin + 1, t.end, t.line))
                if (w.kind == Kind::Identifier) names_.emplace(text(w));
    }
    scanDeclarations(1);
    emitSubroutines();
    convertTextureLiterals();
    out_.source = assemble(tokens_[0].line, tokens_[0].end);
    return std::move(out_);
}

// --- Loops a page can bound (unboundedLoops, glsl_es.hpp) -------------------------------------------

constexpr std::uint64_t kSaturated = std::uint64_t{1} << 40; // iteration counts stop growing here
// The for loops read in one source (each reads its body: quadratic); the course's shaders have none.
constexpr std::size_t kMaxLoops = 128;
constexpr std::size_t kMaxListed = 50; // refusals listed, then how many more

std::uint64_t times(std::uint64_t a, std::uint64_t b) {
    if (a == 0 || b == 0) return 0;
    return a > kSaturated / b ? kSaturated : std::min(a * b, kSaturated);
}

std::string countText(std::uint64_t n) { return n >= kSaturated ? "more than " + std::to_string(kSaturated) : std::to_string(n); }

const std::string kWhy = "so that a shader cannot hang the browser";

// The loops of one source, read from the translator's tokens: each for loop's head and body, the
// functions and the calls between them, the macros. Iterative throughout (hostile input).
class LoopBounds {
public:
    explicit LoopBounds(const Translator& source) : source_(source), text_(source.prepared()), tokens_(source.tokens()) {}
    std::vector<ShaderMessage> run();

private:
    struct Function {
        std::string name;
        std::size_t open, close; // its body's braces
        bool outParameters;      // an out or inout parameter: an argument may be changed
    };
    struct Call {
        std::string caller, callee;
        std::uint64_t around; // the iterations of the caller's loops around the call
        int line;
    };
    struct Head {
        std::string counter;
        std::uint64_t count; // kSaturated when the head is not one the page can bound
    };

    std::string_view word(std::size_t i) const {
        return i < tokens_.size() && tokens_[i].kind == Kind::Identifier
                   ? std::string_view(text_).substr(tokens_[i].begin, tokens_[i].end - tokens_[i].begin) : std::string_view();
    }
    bool punct(std::size_t i, char c) const {
        return i < tokens_.size() && tokens_[i].kind == Kind::Punct && text_[tokens_[i].begin] == c;
    }
    // tokens_[i] then tokens_[i + 1] with nothing between them ("++", "<=")
    bool pair(std::size_t i, char a, char b) const {
        return punct(i, a) && punct(i + 1, b) && tokens_[i].end == tokens_[i + 1].begin;
    }
    std::size_t next(std::size_t i) const { // the next token that is not a directive
        while (i < tokens_.size() && tokens_[i].kind == Kind::Directive) ++i;
        return i;
    }
    void refuse(int line, std::string message) { found_.push_back({line, std::move(message)}); }

    void macros();
    void functions();
    Head head(std::size_t open, std::size_t close) const;
    std::size_t statementEnd(std::size_t i) const;
    bool counterChanged(const std::string& counter, std::size_t from, std::size_t to) const;
    bool macroSpells(const std::string& macro, const std::string& counter) const;
    void loops();
    void calls();

    const Translator& source_;
    const std::string& text_;
    const std::vector<Token>& tokens_;
    std::vector<ShaderMessage> found_;
    std::unordered_map<std::string, std::vector<std::string>> macroWords_; // a #define's name: its body's identifiers
    std::vector<std::pair<std::string, std::vector<Token>>> macroBodies_; // a #define's name, then its words
    std::vector<Function> functions_;                                     // in the order of the source
    std::unordered_map<std::string, std::vector<std::size_t>> byName_;    // overloads share a name
    std::unordered_map<std::string, std::uint64_t> cost_; // per function name: the most iterations for a call of it
    std::vector<Call> calls_;
};

// Token pasting could spell a loop; a macro could hold one, or hide a call of a function with loops.
void LoopBounds::macros() {
    int line = 1;
    for (std::size_t i = 0; i + 1 < text_.size(); ++i) {
        if (text_[i] == '\n') ++line;
        if (text_[i] == '#' && text_[i + 1] == '#') {
            refuse(line, "token pasting (##): it could build a loop the page cannot bound, so the page refuses it, " + kWhy);
            ++i;
        }
    }
    for (const Token& t : tokens_) {
        if (t.kind != Kind::Directive) continue;
        std::vector<Token> words = source_.words(t);
        auto spelt = [&](std::size_t k) { return std::string_view(text_).substr(words[k].begin, words[k].end - words[k].begin); };
        if (words.size() < 2 || spelt(0) != "define") continue;
        const std::string name(spelt(1));
        std::vector<std::string>& spelling = macroWords_[name]; // every definition of the name together
        // A function-like macro's parameters: `#define F(a, b)` with no space before "(".
        std::unordered_set<std::string_view> parameters;
        std::size_t k = 2;
        if (words.size() > 2 && spelt(2) == "(" && words[2].begin == words[1].end) {
            for (k = 3; k < words.size() && spelt(k) != ")"; ++k)
                if (words[k].kind == Kind::Identifier) parameters.insert(spelt(k));
            ++k;
        }
        for (std::size_t j = k; j < words.size(); ++j) {
            const std::string_view w = spelt(j);
            if (w == "for" || w == "while" || w == "do") {
                refuse(t.line, "a loop inside the macro " + name + ": the page cannot bound a loop that a macro spells, " +
                                   "so it refuses it, " + kWhy);
                break;
            }
            if (parameters.count(w) && j + 1 < words.size() && spelt(j + 1) == "(") {
                refuse(t.line, "the macro " + name + " calls its parameter " + std::string(w) + ": the page follows calls " +
                                   "to bound their loops, not macros, so it refuses it, " + kWhy);
                break;
            }
        }
        macroBodies_.emplace_back(name, std::vector<Token>(words.begin() + static_cast<std::ptrdiff_t>(std::min(k, words.size())), words.end()));
        for (const Token& w : macroBodies_.back().second)
            if (w.kind == Kind::Identifier) spelling.emplace_back(text_.substr(w.begin, w.end - w.begin));
    }
}

// The functions defined at the top level: `NAME (...) {` with the brace at depth 0.
void LoopBounds::functions() {
    int depth = 0;
    std::vector<std::size_t> parens;
    std::size_t lastOpen = 0, lastClose = tokens_.size();
    for (std::size_t i = 0; i < tokens_.size(); ++i) {
        if (tokens_[i].kind != Kind::Punct) continue;
        const char c = text_[tokens_[i].begin];
        if (c == '(') parens.push_back(i);
        if (c == ')' && !parens.empty()) {
            lastOpen = parens.back();
            parens.pop_back();
            lastClose = i;
        }
        if (c == '{' && depth++ == 0 && lastClose < i && next(lastClose + 1) == i && lastOpen > 0 &&
            !word(lastOpen - 1).empty()) {
            const std::string name(word(lastOpen - 1));
            bool out = false;
            for (std::size_t k = lastOpen; k < lastClose; ++k) out = out || word(k) == "out" || word(k) == "inout";
            byName_[name].push_back(functions_.size());
            functions_.push_back({name, i, std::min(source_.closing(i), tokens_.size() - 1), out});
            if (macroWords_.count(name))
                refuse(tokens_[i].line, "the function " + name + " is named by a macro: the page follows calls to bound " +
                                            "their loops, not macros, so it refuses it, " + kWhy);
        }
        if (c == '}') --depth;
    }
    for (const auto& [macro, body] : macroBodies_) {
        for (const Token& w : body) {
            const std::string spelt = text_.substr(w.begin, w.end - w.begin);
            if (w.kind != Kind::Identifier || !byName_.count(spelt)) continue;
            refuse(w.line, "the macro " + macro + " names the function " + spelt + ": the page follows calls to bound " +
                               "their loops, not macros, so it refuses it, " + kWhy);
            break;
        }
    }
}

// `for (int i = A; i < B; ++i)` read between the head's parentheses; count kSaturated when it is not
// that shape, or counts away from B, or leaves int on its way.
LoopBounds::Head LoopBounds::head(std::size_t open, std::size_t close) const {
    Head h{"", kSaturated};
    std::size_t k = next(open + 1);
    auto literal = [&](std::int64_t& value) {
        const bool negative = punct(k, '-');
        if (negative) k = next(k + 1);
        if (k >= tokens_.size() || tokens_[k].kind != Kind::Number) return false;
        const auto parsed = parseIntLiteral(std::string_view(text_).substr(tokens_[k].begin, tokens_[k].end - tokens_[k].begin));
        if (!parsed) return false;
        value = negative ? -static_cast<std::int64_t>(*parsed) : static_cast<std::int64_t>(*parsed);
        k = next(k + 1);
        return true;
    };
    auto take = [&](std::size_t n) { k = next(k + n); };
    std::int64_t from = 0, to = 0, step = 0;
    if (word(k) != "int") return h;
    take(1);
    const std::string counter(word(k));
    if (counter.empty() || macroWords_.count(counter)) return h; // a macro could make it another variable
    take(1);
    if (!punct(k, '=')) return h;
    take(1);
    if (!literal(from) || !punct(k, ';')) return h;
    take(1);
    if (word(k) != counter) return h;
    take(1);
    const bool up = punct(k, '<');
    if (!up && !punct(k, '>')) return h;
    const bool inclusive = pair(k, up ? '<' : '>', '=');
    take(inclusive ? 2 : 1);
    if (!literal(to) || !punct(k, ';')) return h;
    take(1);
    if ((pair(k, '+', '+') || pair(k, '-', '-')) && word(k + 2) == counter) {
        step = punct(k, '+') ? 1 : -1;
        take(3);
    } else if (word(k) == counter && (pair(k + 1, '+', '+') || pair(k + 1, '-', '-'))) {
        step = punct(k + 1, '+') ? 1 : -1;
        take(3);
    } else if (word(k) == counter && (pair(k + 1, '+', '=') || pair(k + 1, '-', '='))) {
        const bool plus = punct(k + 1, '+');
        take(3);
        if (punct(k, '-') || !literal(step)) return h;
        step = plus ? step : -step;
    } else {
        return h;
    }
    if (k != close || step == 0 || (step > 0) != up) return h;
    const std::int64_t span = (up ? to - from : from - to) + (inclusive ? 1 : 0);
    const std::int64_t n = span <= 0 ? 0 : (span + std::abs(step) - 1) / std::abs(step);
    const std::int64_t last = from + n * step; // the value it leaves with: every value before lies between
    constexpr std::int64_t kIntMin = -2147483648LL, kIntMax = 2147483647LL;
    if (from < kIntMin || from > kIntMax || last < kIntMin || last > kIntMax) return h;
    return {counter, static_cast<std::uint64_t>(n)};
}

// The last token of the statement starting at token i (a loop's body): a block's "}", a simple
// statement's ";", or where the if, else, for, while, switch or do that starts there ends. The last
// token of the source when it is not well formed (a body taken too long only refuses more).
std::size_t LoopBounds::statementEnd(std::size_t i) const {
    const std::size_t last = tokens_.size() - 1;
    std::vector<bool> pending; // open if (true: an else may follow) and do (false: `while (...);` follows)
    for (;;) {
        i = next(i);
        if (i >= tokens_.size()) return last;
        const std::string_view w = word(i);
        std::size_t end = i;
        if (punct(i, '{')) {
            end = source_.closing(i);
        } else if (w == "for" || w == "while" || w == "switch" || w == "if") {
            const std::size_t open = next(i + 1);
            if (!punct(open, '(')) return last;
            if (w == "if") pending.push_back(true);
            i = source_.closing(open) + 1;
            continue;
        } else if (w == "do") {
            pending.push_back(false);
            ++i;
            continue;
        } else {
            while (end < tokens_.size() && !punct(end, ';')) {
                if (punct(end, '(') || punct(end, '[') || punct(end, '{')) end = source_.closing(end);
                else if (punct(end, ')') || punct(end, ']') || punct(end, '}')) return last;
                ++end;
            }
        }
        if (end >= tokens_.size()) return last;
        bool elseFollows = false;
        while (!pending.empty() && !elseFollows) {
            const std::size_t after = next(end + 1);
            const bool isIf = pending.back();
            pending.pop_back();
            if (isIf) {
                elseFollows = word(after) == "else";
                i = after + 1;
                continue;
            }
            const std::size_t open = next(after + 1);
            if (word(after) != "while" || !punct(open, '(')) return last;
            end = next(source_.closing(open) + 1);
            if (!punct(end, ';')) return last;
        }
        if (!elseFollows) return end;
    }
}

// Whether the macro's body, or that of a macro it names (and so on), holds the identifier `counter`.
bool LoopBounds::macroSpells(const std::string& macro, const std::string& counter) const {
    std::vector<std::string> toExpand{macro};
    std::unordered_set<std::string> seen{macro};
    while (!toExpand.empty()) {
        const auto found = macroWords_.find(toExpand.back());
        toExpand.pop_back();
        if (found == macroWords_.end()) continue;
        for (const std::string& w : found->second) {
            if (w == counter) return true;
            if (macroWords_.count(w) && seen.insert(w).second) toExpand.push_back(w);
        }
    }
    return false;
}

// Whether tokens [from, to] assign, step or pass to an out parameter the counter, or use a macro that
// names it or takes it as an argument (which could do either).
bool LoopBounds::counterChanged(const std::string& counter, std::size_t from, std::size_t to) const {
    for (std::size_t j = from; j <= to && j < tokens_.size(); ++j) {
        const std::string_view w = word(j);
        if (!w.empty() && macroWords_.count(std::string(w))) {
            if (macroSpells(std::string(w), counter)) return true;
            const std::size_t open = next(j + 1);
            for (std::size_t a = open, close = punct(open, '(') ? source_.closing(open) : open; a < close && a < tokens_.size(); ++a)
                if (word(a) == counter) return true;
        }
        if (!w.empty() && punct(next(j + 1), '(') && byName_.count(std::string(w))) {
            const auto& overloads = byName_.at(std::string(w));
            const bool out = std::any_of(overloads.begin(), overloads.end(), [&](std::size_t f) { return functions_[f].outParameters; });
            const std::size_t open = next(j + 1), close = source_.closing(open);
            for (std::size_t a = open; out && a < close && a < tokens_.size(); ++a)
                if (word(a) == counter) return true;
        }
        if (w != counter) continue;
        if (j >= 2 && (pair(j - 2, '+', '+') || pair(j - 2, '-', '-'))) return true;
        if (pair(j + 1, '+', '+') || pair(j + 1, '-', '-')) return true;
        if (punct(j + 1, '=') && !pair(j + 1, '=', '=')) return true;
        for (char op : {'+', '-', '*', '/', '%', '&', '|', '^'})
            if (pair(j + 1, op, '=')) return true;
        if ((pair(j + 1, '<', '<') && pair(j + 2, '<', '=')) || (pair(j + 1, '>', '>') && pair(j + 2, '>', '='))) return true;
    }
    return false;
}

// Every loop on its line, its iterations multiplied by the bounded loops around it; the calls of the
// file's functions with the iterations around them.
void LoopBounds::loops() {
    struct Open {
        std::size_t end;
        std::uint64_t total; // its iterations times those of the loops around it
    };
    std::vector<Open> around;
    std::size_t f = 0, read = 0; // the function whose body may hold token i; the for loops read
    for (std::size_t i = 0; i < tokens_.size(); ++i) {
        while (!around.empty() && i > around.back().end) around.pop_back();
        while (f < functions_.size() && functions_[f].close < i) ++f;
        const bool inFunction = f < functions_.size() && functions_[f].open < i;
        const std::uint64_t outer = around.empty() ? 1 : around.back().total;
        const std::string_view w = word(i);
        if (w == "while" || w == "do") {
            refuse(tokens_[i].line, "a " + std::string(w) + " loop: the page runs only for loops with a fixed count " +
                                        "(for (int i = 0; i < N; ++i), N at most " + std::to_string(kGlslMaxLoopIterations) +
                                        "), " + kWhy);
        } else if (w == "for" && ++read > kMaxLoops) {
            refuse(tokens_[i].line, "more than " + std::to_string(kMaxLoops) + " for loops: the page bounds the loops of a " +
                                        "shader with at most " + std::to_string(kMaxLoops) + ", " + kWhy);
        } else if (w == "for") {
            const std::size_t open = next(i + 1);
            const std::size_t close = punct(open, '(') ? source_.closing(open) : tokens_.size();
            const Head h = close < tokens_.size() ? head(open, close) : Head{"", kSaturated};
            if (h.count > kGlslMaxLoopIterations) {
                refuse(tokens_[i].line, "a for loop whose count the page cannot bound: write it as for (int i = 0; i < N; ++i) "
                                        "with a number N of at most " + std::to_string(kGlslMaxLoopIterations) + ", " + kWhy);
                continue;
            }
            const std::size_t end = statementEnd(close + 1);
            if (counterChanged(h.counter, close + 1, end)) {
                refuse(tokens_[i].line, "a for loop whose counter " + h.counter + " is changed inside it: the page cannot " +
                                            "bound its count, so it refuses it, " + kWhy);
                continue;
            }
            const std::uint64_t total = times(outer, h.count);
            if (total > kGlslMaxLoopIterations)
                refuse(tokens_[i].line, "nested loops that run " + countText(total) + " times for a pixel: the page runs at most " +
                                            std::to_string(kGlslMaxLoopIterations) + ", " + kWhy);
            if (inFunction) {
                std::uint64_t& cost = cost_.try_emplace(functions_[f].name, 1).first->second;
                cost = std::max(cost, total);
            }
            around.push_back({end, total});
        } else if (!w.empty() && inFunction && byName_.count(std::string(w)) && punct(next(i + 1), '(')) {
            calls_.push_back({functions_[f].name, std::string(w), outer, tokens_[i].line});
        }
    }
}

// Each function's iterations with those of the functions it calls, by name (overloads together: a
// walk without recursion; a cycle, which GLSL forbids, saturates), then each call inside loops checked.
void LoopBounds::calls() {
    std::unordered_map<std::string, std::vector<std::pair<std::string, std::uint64_t>>> edges; // callee, around
    for (const Call& c : calls_) edges[c.caller].emplace_back(c.callee, c.around);
    enum class State { Busy, Done };
    std::unordered_map<std::string, State> state;
    std::vector<std::pair<std::string, std::size_t>> stack; // function, its next call
    for (const auto& [root, ignored] : byName_) {
        if (state.count(root)) continue;
        stack.emplace_back(root, 0);
        state[root] = State::Busy;
        while (!stack.empty()) {
            const std::string f = stack.back().first;
            const std::size_t e = stack.back().second;
            const auto& out = edges[f];
            std::uint64_t& cost = cost_.try_emplace(f, 1).first->second;
            if (e == out.size()) {
                state[f] = State::Done;
                stack.pop_back();
                continue;
            }
            const auto& [g, around] = out[e];
            if (!state.count(g)) {
                state[g] = State::Busy;
                stack.emplace_back(g, 0);
                continue;
            }
            cost = std::max(cost, state[g] == State::Busy ? kSaturated : times(around, cost_.try_emplace(g, 1).first->second));
            ++stack.back().second;
        }
    }
    for (const Call& c : calls_) {
        const std::uint64_t callee = cost_.try_emplace(c.callee, 1).first->second;
        const std::uint64_t total = times(c.around, callee);
        if (c.around > 1 && callee > 1 && total > kGlslMaxLoopIterations)
            refuse(c.line, "a call of " + c.callee + ", whose loops run " + countText(callee) + " times, inside loops that run " +
                               countText(c.around) + " times: " + countText(total) + " times for a pixel; the page runs at most " +
                               std::to_string(kGlslMaxLoopIterations) + ", " + kWhy);
    }
}

std::vector<ShaderMessage> LoopBounds::run() {
    if (tokens_.empty()) return {};
    macros();
    functions();
    loops();
    calls();
    std::stable_sort(found_.begin(), found_.end(), [](const ShaderMessage& a, const ShaderMessage& b) { return a.line < b.line; });
    if (found_.size() > kMaxListed) { // a list a reader can take in; fixing these shows the next
        const std::size_t more = found_.size() - kMaxListed;
        found_.resize(kMaxListed);
        found_.push_back({0, std::to_string(more) + " more loops or macros are refused as well (the first " +
                                 std::to_string(kMaxListed) + " are listed)"});
    }
    return found_;
}

} // namespace

GlslEsShader translateToGlslEs(std::string_view source, const std::string& fileName, GlslStage stage) {
    if (stage == GlslStage::Compute)
        throw Error(fileName + ": a compute shader cannot be translated to GLSL ES 3.00 (WebGL2 has no compute shaders)");
    if (stage == GlslStage::Other)
        throw Error(fileName + ": only vertex and fragment shaders can be translated to GLSL ES 3.00 (WebGL2 has no "
                               "geometry or tessellation stages)");
    return Translator(source, fileName, stage).run();
}

std::vector<ShaderMessage> unboundedLoops(std::string_view source, const std::string& fileName) {
    const Translator translator(source, fileName, GlslStage::Fragment);
    return LoopBounds(translator).run();
}

} // namespace t10
