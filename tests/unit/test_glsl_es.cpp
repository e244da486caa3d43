// The GLSL 4.30 -> GLSL ES 3.00 translator (common/content glsl_es.cpp) without a compiler: every
// shader of the repository translates with its bindings, locations and line count; the subroutine
// dispatch calls the function of each index; hostile inputs give an error naming the file and line,
// never a crash, a hang or a silent drop. test_glsl_es_validate.cpp compiles the output with
// glslangValidator.
#include "t10/contract.hpp"
#include "t10/error.hpp"
#include "t10/glsl_es.hpp"

#include "repository_shaders.hpp"
#include "t10_catch.hpp"

#include <algorithm>
#include <filesystem>
#include <random>
#include <regex>
#include <sstream>

namespace fs = std::filesystem;
using namespace std::string_literals;
using t10::test::readText;
using t10::test::repositoryShaders;
using t10::test::stageOf;

namespace {

t10::GlslEsShader translate(const std::string& source, t10::GlslStage stage = t10::GlslStage::Fragment) {
    return t10::translateToGlslEs(source, "in.frag", stage);
}

// The error message of a translation that must fail (empty if it did not fail).
std::string errorOf(const std::string& source, t10::GlslStage stage = t10::GlslStage::Fragment) {
    try {
        translate(source, stage);
    } catch (const t10::Error& e) {
        return e.what();
    }
    return "";
}

int lineCount(const std::string& text) { return static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

int valueOf(const std::vector<t10::NamedValue>& list, const std::string& name) {
    for (const auto& b : list)
        if (b.name == name) return b.value;
    return -1;
}

} // namespace

TEST_CASE("every shader of the repository translates, line for line", "[glsl_es]") {
    const auto shaders = repositoryShaders();
    REQUIRE(shaders.size() >= 15); // the stages' 11, common's 4, the bench's: a failed search finds none
    for (const fs::path& file : shaders) {
        INFO(file.string());
        const std::string source = readText(file);
        const t10::GlslEsShader es = t10::translateToGlslEs(source, file.string(), stageOf(file));
        CHECK(es.source.rfind("#version 300 es\n", 0) == 0);
        CHECK(lineCount(es.source) == lineCount(source));
        CHECK(es.source.find("layout(binding") == std::string::npos);
        CHECK(es.source.find("subroutine") == std::string::npos);
        CHECK(es.source.find("//") == std::string::npos); // comments are blanked
    }
    // The exact key's compute pass has no WebGL2 form: refused by name.
    const fs::path compute = fs::path(T10_SOURCE_ROOT) / "common/optional/shaders/ExactKey.comp";
    CHECK_THROWS_WITH(t10::translateToGlslEs(readText(compute), "ExactKey.comp", t10::GlslStage::Compute),
                      Catch::StartsWith("ExactKey.comp: a compute shader cannot be translated to GLSL ES 3.00"));
}

TEST_CASE("the post-process shaders report the contract's units, binding and locations", "[glsl_es]") {
    const fs::path root(T10_SOURCE_ROOT);
    const auto post = translate(readText(root / "extras/PostProcess.frag"));
    CHECK(valueOf(post.layout.samplerUnits, "s2AccumulationTexture") == int(t10::contract::kAccumulationUnit));
    CHECK(valueOf(post.layout.samplerUnits, "s2LuminanceKeyTexture") == int(t10::contract::kLuminanceKeyUnit));
    CHECK(valueOf(post.layout.samplerUnits, "s2BloomTexture") == int(t10::contract::kBloomUnit));
    CHECK(valueOf(post.layout.blockBindings, "InvResolution") == int(t10::contract::kInvResolutionBinding));
    CHECK(valueOf(post.layout.uniformLocations, "fYwhite") == t10::contract::extras::kWhitePointLocation);
    CHECK(valueOf(post.layout.uniformLocations, "bBloom") == t10::contract::extras::kBloomSwitchLocation);
    CHECK(valueOf(post.layout.uniformLocations, "fBloomStrength") == t10::contract::extras::kBloomStrengthLocation);
    CHECK(valueOf(post.layout.uniformLocations, "bRangeMapping") == t10::contract::extras::kRangeMappingLocation);
    CHECK(post.layout.samplerUnits.size() == 3);
    CHECK(post.layout.uniformLocations.size() == 4);
    // The block gets std140 (ES would make it shared); the fragment output keeps its location.
    CHECK_THAT(post.source, Catch::Contains("layout(std140) uniform InvResolution"));
    CHECK_THAT(post.source, Catch::Contains("layout(location = 0) out vec3 v3ColourOut;"));
    // The integer bias 1024 (GLSL 4.30 converts it) is a float literal.
    CHECK_THAT(post.source, Catch::Contains("texture(s2LuminanceKeyTexture, v2UV, 1024.0)"));

    const auto scene = t10::translateToGlslEs(readText(root / "common/shaders/Scene.vert"), "Scene.vert", t10::GlslStage::Vertex);
    CHECK_THAT(scene.source, Catch::Contains("layout(location = 5) in vec4 v4VertexUVBounds;")); // vertex input: kept
    CHECK_THAT(scene.source, Catch::Contains("\nflat out vec4 v4UVBounds;"));                      // varying: stripped
    CHECK_THAT(scene.source, Catch::Contains("layout(std140) uniform Camera"));
    CHECK(valueOf(scene.layout.blockBindings, "Camera") == 0);
}

TEST_CASE("a subroutine becomes an int uniform and a dispatch calling the function of each index", "[glsl_es]") {
    // Indices out of declaration order, a void type and two uniforms of one type.
    const std::string source = "// a comment first: no #line\n#version 430 core\n"
                               "subroutine float Pick(in float x, out vec2 y[2]);\n"
                               "layout(location = 1) subroutine uniform Pick PickA;\n"
                               "layout(location = 0) subroutine uniform Pick PickB;\n"
                               "layout(index = 2) subroutine(Pick) float two(in float x, out vec2 y[2]) { y[0] = vec2(x); return 2.0; }\n"
                               "layout(index = 0) subroutine(Pick) float zero(in float x, out vec2 y[2]) { return 0.0; }\n"
                               "layout(index = 1) subroutine(Pick) float one(in float x, out vec2 y[2]) { return 1.0; }\n"
                               "out vec4 c;\n"
                               "void main() { vec2 y[2]; c = vec4(PickA(1.0, y), PickB(2.0, y), 0.0, 1.0); }\n";
    const auto es = translate(source);
    REQUIRE(es.layout.subroutineUniforms.size() == 2);
    CHECK(es.layout.subroutineUniforms[0].location == 1);
    CHECK(es.layout.subroutineUniforms[1].location == 0);
    // The stage the platform's glUniformSubroutinesuiv matches them by (gl_web.cpp).
    CHECK(es.layout.subroutineUniforms[0].stage == t10::GlslStage::Fragment);
    CHECK(es.layout.subroutineUniforms[1].stage == t10::GlslStage::Fragment);
    const std::string a = es.layout.subroutineUniforms[0].uniformName, b = es.layout.subroutineUniforms[1].uniformName;
    CHECK(a != b);
    CHECK_THAT(es.source, Catch::Contains("uniform int " + a + ";"));
    CHECK_THAT(es.source, Catch::Contains("uniform int " + b + ";"));
    // Each index calls its own function; anything else (0 included) calls the lowest index.
    for (const std::string& u : {std::string("PickA"), std::string("PickB")}) {
        const std::string index = u == "PickA" ? a : b;
        const std::regex dispatch("float " + u + R"(\(in float (\w+), out vec2 (\w+)\[2\]\) \{ if \()" + index +
                                  R"( == 1\) return one\(\1, \2\); if \()" + index +
                                  R"( == 2\) return two\(\1, \2\); return zero\(\1, \2\); \})");
        CHECK(std::regex_search(es.source, dispatch));
    }
    CHECK(lineCount(es.source) == lineCount(source));
    // The dispatch is defined after the last function (line 8), before main uses it.
    const auto lineOf = [&](const std::string& what) {
        return lineCount(es.source.substr(0, es.source.find(what))) + 1;
    };
    CHECK(lineOf("float PickA(") == 8);
}

TEST_CASE("generated names never collide with the shader's own", "[glsl_es]") {
    const std::string source = "#version 430 core\n"
                               "uniform float t10SubroutineIndexU; uniform float t10Arg0;\n"
                               "subroutine void S(float);\n"
                               "layout(location = 0) subroutine uniform S U;\n"
                               "layout(index = 0) subroutine(S) void f(float x) {}\n"
                               "void main() { U(t10Arg0 + t10SubroutineIndexU); }\n";
    const auto es = translate(source);
    REQUIRE(es.layout.subroutineUniforms.size() == 1);
    const std::string name = es.layout.subroutineUniforms[0].uniformName;
    CHECK(name != "t10SubroutineIndexU");
    CHECK(name.find("__") == std::string::npos);
    CHECK(name.rfind("gl_", 0) != 0);
    CHECK_THAT(es.source, Catch::Contains("void U(float t10Arg01) { f(t10Arg01); }"));
}

TEST_CASE("comments do not fool the translator", "[glsl_es]") {
    const auto es = translate("#version 430 core\n"
                              "// layout(binding = 1) uniform sampler2D fake;\n"
                              "/* layout(binding = 2)\n uniform sampler2D fake2; double d; */\n"
                              "layout(binding = 3) /* binding = 9 */ uniform sampler2D real; // binding = 8\n"
                              "out vec4 c; void main() { c = texture(real, vec2(0)); }\n");
    REQUIRE(es.layout.samplerUnits.size() == 1);
    CHECK(es.layout.samplerUnits[0].name == "real");
    CHECK(es.layout.samplerUnits[0].value == 3);
}

TEST_CASE("layouts split over lines keep every line where it was", "[glsl_es]") {
    const std::string source = "// a comment first: no #line\n#version 430 core\n"
                               "layout(\n  binding\n  =\n  4)\nuniform sampler2D s[2];\n"
                               "layout(location = 2,\n location = 3) uniform float f;\n" // the last location wins in GLSL
                               "out vec4 c;\nvoid main() { c = texture(s[1], vec2(f)); }\n";
    const auto es = translate(source);
    CHECK(lineCount(es.source) == lineCount(source));
    CHECK(valueOf(es.layout.samplerUnits, "s[0]") == 4);
    CHECK(valueOf(es.layout.samplerUnits, "s[1]") == 5);
    CHECK(valueOf(es.layout.uniformLocations, "f") == 3);
    CHECK(es.layout.uniformLocations.size() == 1);
    const auto lines = [](const std::string& text) {
        std::vector<std::string> out;
        std::istringstream in(text);
        for (std::string line; std::getline(in, line);) out.push_back(line);
        return out;
    }(es.source);
    CHECK(lines.at(6) == "uniform sampler2D s[2];"); // line 7 of the source
    CHECK(lines.at(8) == "uniform float f;");
    CHECK(lines.at(10) == "void main() { c = texture(s[1], vec2(f)); }");
}

TEST_CASE("#version on the first line: the precisions get a line and #line restores the numbering", "[glsl_es]") {
    const std::string source = "#version 430 core\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n";
    const auto es = translate(source);
    CHECK(lineCount(es.source) == lineCount(source) + 2);
    CHECK(es.source.rfind("#version 300 es\nprecision highp float;", 0) == 0);
    CHECK_THAT(es.source, Catch::Contains("\n#line 2\nout vec4 c;"));
}

TEST_CASE("integer texture biases and levels become float literals, other arguments do not", "[glsl_es]") {
    const auto es = translate("#version 430 core\nuniform sampler2D s; out vec4 c;\n"
                              "void main() { c = texture(s, vec2(0), -2) + textureLod(s, vec2(1), 0x10) +"
                              " textureOffset(s, vec2(0), ivec2(1, 2), 3u) + texelFetch(s, ivec2(0), 0) +"
                              " texture(s, vec2(texture(s, vec2(0), 1).x)); }\n");
    CHECK_THAT(es.source, Catch::Contains("texture(s, vec2(0), -2.0)"));
    CHECK_THAT(es.source, Catch::Contains("textureLod(s, vec2(1), 16.0)"));
    CHECK_THAT(es.source, Catch::Contains("textureOffset(s, vec2(0), ivec2(1, 2), 3.0)"));
    CHECK_THAT(es.source, Catch::Contains("texelFetch(s, ivec2(0), 0)")); // an int lod stays int
    CHECK_THAT(es.source, Catch::Contains("texture(s, vec2(texture(s, vec2(0), 1.0).x))"));
}

TEST_CASE("constructs without an ES 3.00 form are errors naming the file, the line and the construct", "[glsl_es]") {
    const std::string head = "#version 430 core\n\n";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"double d;", "in.frag:3: `double` cannot be translated to GLSL ES 3.00"},
        {"layout(binding = 0, rgba8) uniform image2D img;", "in.frag:3: `image2D` cannot be translated"},
        {"layout(std430, binding = 0) buffer B { float x[]; };", "in.frag:3: `buffer` cannot be translated"},
        {"layout(binding = 0) uniform atomic_uint a;", "in.frag:3: `atomic_uint`"},
        {"void main() { int n = textureQueryLevels(s); }", "in.frag:3: `textureQueryLevels`"},
        {"void main() { gl_ClipDistance[0] = 1.0; }", "in.frag:3: `gl_ClipDistance`"},
        {"float f = 1.0lf;", "in.frag:3: the double-precision literal 1.0lf"},
        {"noperspective in float f;", "in.frag:3: `noperspective`"},
        {"out Block { vec2 uv; } vs;", "in.frag:3: an in/out interface block"},
        {"layout(binding = UNIT) uniform sampler2D s;", "in.frag:3: layout(binding = UNIT...) cannot be translated"},
        {"layout(location = 0, index = 1) out vec4 c;", "in.frag:3: layout(index) on a fragment output"},
        {"layout(early_fragment_tests) in;", "in.frag:3: a layout(...) in/out default"},
        {"layout(binding = 1) uniform float f;", "in.frag:3: layout(binding) on the float uniform f"},
        {"uniform float f = 1.0;", "in.frag:3: a uniform initializer"},
        {"layout(location = 0) uniform float a, b;", "in.frag:3: several uniforms in one layout-qualified declaration"},
        {"#define TEX layout(binding = 2) uniform sampler2D\nTEX s;", "in.frag:3: #define TEX (a macro containing `layout`)"},
        {"#extension GL_ARB_shading_language_420pack : enable", "in.frag:3: #extension cannot be translated"},
        {"#include \"x.glsl\"", "in.frag:3: character '\"'"},
        {"subroutine void S();\nsubroutine uniform S u;", "in.frag:4: a subroutine uniform without layout(location = L)"},
        {"subroutine void S();\nlayout(location = 0) subroutine uniform S u;\nsubroutine(S) void f() {}",
         "in.frag:5: the subroutine function f without layout(index = N)"},
        {"subroutine void S();\nlayout(location = 0) subroutine uniform S u;\nvoid main() { u(); }",
         "in.frag:4: the subroutine uniform u cannot be translated"},
        {"subroutine void S();\nlayout(location = 0) subroutine uniform S u;\nvoid g() { u(); }\n"
         "layout(index = 0) subroutine(S) void f() {}",
         "in.frag:5: this use of u before the last subroutine function of type S"},
        {"subroutine void S();\nlayout(location = 0) subroutine uniform S u;\n"
         "layout(index = 0) subroutine(S) void f() {}\nlayout(index = 0) subroutine(S) void g() {}",
         "two subroutine functions of type S with index 0: f and g"},
        {"void main() { float x = (1.0; }", "in.frag:3: unmatched '}'"},
    };
    for (const auto& [body, expected] : cases) {
        INFO(body);
        CHECK_THAT(errorOf(head + body + "\n"), Catch::Contains(expected));
    }
}

TEST_CASE("hostile files give a clear error, never a crash or a hang", "[glsl_es]") {
    CHECK_THAT(errorOf(""), Catch::Contains("in.frag:1: no #version directive"));
    CHECK_THAT(errorOf("void main() {}\n"), Catch::Contains("in.frag:1: expected #version 430 core"));
    CHECK_THAT(errorOf("// only a comment\n\nout vec4 c;\n"), Catch::Contains("in.frag:3: expected #version 430 core"));
    CHECK_THAT(errorOf("#version 110\n"), Catch::Contains("in.frag:1: `#version 110` cannot be translated"));
    CHECK_THAT(errorOf("#version 430 compatibility\n"), Catch::Contains("`#version 430 compatibility`"));
    CHECK_THAT(errorOf("#version 300 es\n"), Catch::Contains("`#version 300 es`"));
    CHECK_THAT(errorOf("#version 430 core\n#version 430 core\n"), Catch::Contains("in.frag:2: a second #version"));
    CHECK_THAT(errorOf("#version 430 core\n/* never closed\n\n"), Catch::Contains("in.frag:2: a /* comment that is never closed"));
    CHECK_THAT(errorOf("#version 430 core\nfloat a;\0\n"s), Catch::Contains("in.frag:2: a NUL byte"));
    CHECK_THAT(errorOf("#version 430 core\n// a comment \0\n"s), Catch::Contains("in.frag:2: a NUL byte"));
    CHECK_THAT(errorOf("#version 430 core\nfloat \xC3\xA9;\n"), Catch::Contains("in.frag:2: byte 0xC3 outside a comment"));
    CHECK_THAT(errorOf("#version 430 core\nfloat \xff\xfe;\n"), Catch::Contains("in.frag:2: byte 0xFF"));
    CHECK_THAT(errorOf("#version 430 core\n#define A 1 \\\n + 2\n"), Catch::Contains("in.frag:2: a line continuation"));
    CHECK_THAT(errorOf("#version 430 core\n#define A /* a\n b */ 1\n"), Catch::Contains("in.frag:2: a /* comment spanning lines inside"));
    CHECK_THAT(errorOf("#version 430 core\nfloat f() { return 1.0;\n"), Catch::Contains("in.frag:2: a bracket that is never closed"));
    CHECK_THAT(errorOf("#version 430 core\nfloat f\n"), Catch::Contains("in.frag:2: a declaration that never ends"));
    CHECK_THAT(errorOf("#version 430 core\nlayout(binding = 99999999999) uniform sampler2D s;\n"),
               Catch::Contains("in.frag:2: layout(binding = 99999999999...)"));
    CHECK_THAT(errorOf("#version 430 core\nlayout(binding = 2147483647) uniform sampler2D s[4];\n"),
               Catch::Contains("in.frag:2: layout(binding = 2147483647) cannot be translated"));
    CHECK_THAT(errorOf("#version 430 core\n", t10::GlslStage::Compute), Catch::Contains("in.frag: a compute shader cannot be translated"));
    CHECK_THAT(errorOf("#version 430 core\n", t10::GlslStage::Other), Catch::Contains("in.frag: only vertex and fragment shaders"));
}

TEST_CASE("inputs beyond the limits: size and nesting", "[glsl_es]") {
    const std::string big = "#version 430 core\n" + std::string(t10::kGlslEsMaxSourceBytes, ' ');
    CHECK_THAT(errorOf(big), Catch::Contains("in.frag: " + std::to_string(big.size()) + " bytes is more than the"));
    const std::string deep = "#version 430 core\nfloat f = " + std::string(100000, '(') + "1.0" + std::string(100000, ')') + ";\n";
    CHECK_THAT(errorOf(deep), Catch::Contains("in.frag:2: brackets nested more than 256 deep"));
    const std::string fine = "#version 430 core\nfloat f = " + std::string(200, '(') + "1.0" + std::string(200, ')') + ";\n";
    CHECK(errorOf(fine).empty());
    // A large valid shader is translated in linear time (a quadratic scan would take minutes).
    std::string many = "#version 430 core\n";
    while (many.size() < t10::kGlslEsMaxSourceBytes - 64) many += "layout(location = 1) uniform float f;\n";
    CHECK(errorOf(many).empty());
    // Subroutine counts are bounded (their checks are quadratic in them).
    std::string uniforms = "#version 430 core\nsubroutine void S();\n";
    for (int i = 0; i < 65; ++i) uniforms += "layout(location = " + std::to_string(i) + ") subroutine uniform S u" + std::to_string(i) + ";\n";
    CHECK_THAT(errorOf(uniforms), Catch::Contains("in.frag:67: more than 64 subroutine uniforms cannot be translated"));
    std::string functions = "#version 430 core\nsubroutine void S();\n";
    while (functions.size() < t10::kGlslEsMaxSourceBytes - 64) functions += "layout(index = 0) subroutine(S) void f();\n";
    CHECK_THAT(errorOf(functions), Catch::Contains("in.frag:259: more than 256 subroutine functions cannot be translated"));
    // A texture call inside what a rewrite removes is left alone, not rewritten twice.
    CHECK(errorOf("#version 430 core\nuniform sampler2D s;\nsubroutine float T(float x[int(texture(s, vec2(0), 1).x)]);\n").empty());
}

TEST_CASE("random damage to a real shader gives a translation or a t10::Error", "[glsl_es]") {
    const std::string gauss = readText(fs::path(T10_SOURCE_ROOT) / "tutorial10_part3_gaussian/Gauss.frag");
    std::mt19937 random(36);
    int translated = 0, refused = 0;
    for (int round = 0; round < 3000; ++round) {
        std::string damaged = gauss;
        const int edits = 1 + static_cast<int>(random() % 4);
        for (int e = 0; e < edits; ++e) {
            const std::size_t at = random() % damaged.size();
            switch (random() % 3) {
            case 0: damaged[at] = static_cast<char>(random() % 256); break;
            case 1: damaged.erase(at, 1 + random() % 16); break;
            default: damaged.insert(at, damaged.substr(random() % damaged.size(), 1 + random() % 32)); break;
            }
            if (damaged.empty()) damaged = "x";
        }
        try {
            translate(damaged);
            ++translated;
        } catch (const t10::Error& e) {
            CHECK_THAT(e.what(), Catch::StartsWith("in.frag:"));
            ++refused;
        }
    }
    CHECK(translated > 100); // the damage does not only produce errors...
    CHECK(refused > 100);    // ...nor only translations
}
