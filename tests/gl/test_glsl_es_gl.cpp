// The GLSL ES translation (t10::translateToGlslEs) run on a real GL: Mesa compiles GLSL ES 3.00 in a
// desktop context (ARB_ES3_compatibility), so the desktop shader and its translation can be drawn side
// by side. The translation, with its samplers, blocks and subroutine int set from what the translator
// reports (what the web ShaderManager does), draws the same pixels as the desktop shader with
// glUniformSubroutinesuiv, for every subroutine index.
#include "gl_context.hpp"

#include "t10/error.hpp"
#include "t10/gl.hpp"
#include "t10/glsl_es.hpp"

#include "t10_catch.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>
#include <vector>

namespace {

constexpr int kProbeSide = 8;

// One triangle covering the viewport, from gl_VertexID alone (no vertex buffer).
const char* kVertex = "#version 430 core\n"
                      "void main() {\n"
                      "    gl_Position = vec4(float((gl_VertexID & 1) * 4 - 1), float((gl_VertexID >> 1) * 4 - 1), 0.0, 1.0);\n"
                      "}\n";

GLuint compile(GLenum type, const std::string& source) {
    const GLuint shader = glCreateShader(type);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[2048] = {};
        glGetShaderInfoLog(shader, sizeof log, nullptr, log);
        throw t10::Error(std::string("compile failed: ") + log + "\n" + source);
    }
    return shader;
}

GLuint link(const std::string& vertex, const std::string& fragment) {
    const GLuint program = glCreateProgram();
    const GLuint v = compile(GL_VERTEX_SHADER, vertex), f = compile(GL_FRAGMENT_SHADER, fragment);
    glAttachShader(program, v);
    glAttachShader(program, f);
    glLinkProgram(program);
    glDeleteShader(v);
    glDeleteShader(f);
    GLint ok = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) throw t10::Error("link failed");
    return program;
}

// A program of the desktop shaders and one of their translations, with the translation's uniforms set
// from what the translator reported.
struct Programs {
    GLuint desktop = 0;
    GLuint es = 0;
    t10::GlslEsShader fragment;
};

Programs programs(const std::string& fragment) {
    Programs p;
    p.desktop = link(kVertex, fragment);
    const t10::GlslEsShader vertex = t10::translateToGlslEs(kVertex, "quad.vert", t10::GlslStage::Vertex);
    p.fragment = t10::translateToGlslEs(fragment, "test.frag", t10::GlslStage::Fragment);
    p.es = link(vertex.source, p.fragment.source);
    glUseProgram(p.es);
    for (const auto& s : p.fragment.layout.samplerUnits) glUniform1i(glGetUniformLocation(p.es, s.name.c_str()), s.value);
    for (const auto& b : p.fragment.layout.blockBindings)
        glUniformBlockBinding(p.es, glGetUniformBlockIndex(p.es, b.name.c_str()), static_cast<GLuint>(b.value));
    return p;
}

// Draws with `program` selecting subroutine `index` (desktop: glUniformSubroutinesuiv; ES: the int
// uniform the translator declared) and reads the RGBA32F target back.
std::vector<float> draw(GLuint program, bool es, const t10::GlslEsShader& fragment, GLuint index) {
    glUseProgram(program);
    if (es) glUniform1i(glGetUniformLocation(program, fragment.layout.subroutineUniforms.at(0).uniformName.c_str()), static_cast<GLint>(index));
    else glUniformSubroutinesuiv(GL_FRAGMENT_SHADER, 1, &index); // after glUseProgram: it resets them
    glClearColor(-1.0f, -1.0f, -1.0f, -1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    std::vector<float> pixels(kProbeSide * kProbeSide * 4);
    glReadPixels(0, 0, kProbeSide, kProbeSide, GL_RGBA, GL_FLOAT, pixels.data());
    REQUIRE(glGetError() == GL_NO_ERROR);
    return pixels;
}

// An 8x8 RGBA32F render target, an empty vertex array, and the cleanup.
struct Target {
    GLuint fbo = 0, colour = 0, vao = 0;
    Target() {
        glGenRenderbuffers(1, &colour);
        glBindRenderbuffer(GL_RENDERBUFFER, colour);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA32F, kProbeSide, kProbeSide);
        glGenFramebuffers(1, &fbo);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour);
        glGenVertexArrays(1, &vao);
        glBindVertexArray(vao);
        glViewport(0, 0, kProbeSide, kProbeSide);
    }
    ~Target() {
        glDeleteVertexArrays(1, &vao);
        glDeleteFramebuffers(1, &fbo);
        glDeleteRenderbuffers(1, &colour);
    }
};

std::string readText(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

// Over red, green and blue: a vec3 output leaves alpha undefined.
float largestDifference(const std::vector<float>& a, const std::vector<float>& b) {
    float largest = 0.0f;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (i % 4 != 3) largest = std::max(largest, std::fabs(a[i] - b[i]));
    return largest;
}

} // namespace

TEST_CASE("the translated dispatch calls the function of each index, as glUniformSubroutinesuiv does", "[glsl_es]") {
    const std::unique_ptr<t10::Context> context = t10::test::makeTestContext();
    const Target target;
    // Indices out of declaration order: the dispatch must follow layout(index), not the order.
    const std::string fragment = "#version 430 core\n"
                                 "subroutine vec4 Colour(float);\n"
                                 "layout(location = 0) subroutine uniform Colour uColour;\n"
                                 "layout(index = 2) subroutine(Colour) vec4 blue(float a) { return vec4(0.0, 0.0, a, 1.0); }\n"
                                 "layout(index = 0) subroutine(Colour) vec4 red(float a) { return vec4(a, 0.0, 0.0, 1.0); }\n"
                                 "layout(index = 1) subroutine(Colour) vec4 green(float a) { return vec4(0.0, a, 0.0, 1.0); }\n"
                                 "layout(location = 0) out vec4 c;\n"
                                 "void main() { c = uColour(0.5); }\n";
    const Programs p = programs(fragment);
    const float expected[3][4] = {{0.5f, 0.0f, 0.0f, 1.0f}, {0.0f, 0.5f, 0.0f, 1.0f}, {0.0f, 0.0f, 0.5f, 1.0f}};
    for (GLuint index = 0; index < 3; ++index) {
        INFO("index " << index);
        const std::vector<float> desktop = draw(p.desktop, false, p.fragment, index);
        const std::vector<float> es = draw(p.es, true, p.fragment, index);
        for (int channel = 0; channel < 4; ++channel) {
            CHECK(desktop[static_cast<std::size_t>(channel)] == expected[index][channel]);
            CHECK(es[static_cast<std::size_t>(channel)] == expected[index][channel]);
        }
        CHECK(es == desktop);
    }
    glDeleteProgram(p.desktop);
    glDeleteProgram(p.es);
}

TEST_CASE("Part 3's Gauss.frag and its translation blur alike in both directions", "[glsl_es]") {
    const std::unique_ptr<t10::Context> context = t10::test::makeTestContext();
    const Target target;
    const Programs p = programs(readText(T10_SOURCE_ROOT "/tutorial10_part3_gaussian/Gauss.frag"));
    // The input at unit 17 (the shader's binding), InvResolution at binding 7, as the stage sets them.
    std::vector<float> input(kProbeSide * kProbeSide * 4);
    for (std::size_t i = 0; i < input.size(); ++i) input[i] = static_cast<float>((i * 7919u) % 101u) / 100.0f;
    GLuint texture = 0, ubo = 0;
    glGenTextures(1, &texture);
    glActiveTexture(GL_TEXTURE0 + 17);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA32F, kProbeSide, kProbeSide);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kProbeSide, kProbeSide, GL_RGBA, GL_FLOAT, input.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    const float invResolution[2] = {1.0f / kProbeSide, 1.0f / kProbeSide};
    glGenBuffers(1, &ubo);
    glBindBufferBase(GL_UNIFORM_BUFFER, 7, ubo);
    glBufferData(GL_UNIFORM_BUFFER, sizeof invResolution, invResolution, GL_STATIC_DRAW);

    const std::vector<float> horizontal = draw(p.desktop, false, p.fragment, 0);
    const std::vector<float> vertical = draw(p.desktop, false, p.fragment, 1);
    // The check can fail: the two directions differ by far more than the tolerance on this input.
    CHECK(largestDifference(horizontal, vertical) > 0.05f);
    // Same driver, same float arithmetic: equal up to the last bits of the fp32 sums (1e-6 of a
    // texel value of at most 1).
    CHECK(largestDifference(draw(p.es, true, p.fragment, 0), horizontal) < 1e-6f);
    CHECK(largestDifference(draw(p.es, true, p.fragment, 1), vertical) < 1e-6f);
    CHECK(largestDifference(horizontal, std::vector<float>(horizontal.size(), -1.0f)) > 0.5f); // drawn, not the clear colour
    glDeleteBuffers(1, &ubo);
    glDeleteTextures(1, &texture);
    glDeleteProgram(p.desktop);
    glDeleteProgram(p.es);
}
