// restoreGlDefaults (gl_defaults.hpp, between the runs of --then): every state it restores is first
// changed away from a new context's value, the change seen, then restored and compared with the
// value the context started with. A state it forgot fails both ways: still changed after the reset.
#include "gl_context.hpp"

#include "t10/context.hpp"
#include "t10/gl.hpp"
#include "t10/gl_defaults.hpp"

#include "t10_catch.hpp"

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace {

// One piece of state: how to read it (up to four integers) and how to change it.
struct Probe {
    std::string name;
    std::function<std::array<GLint, 4>()> read;
    std::function<void()> change;
};

std::array<GLint, 4> getInts(GLenum name) {
    std::array<GLint, 4> v{};
    glGetIntegerv(name, v.data());
    return v;
}

std::array<GLint, 4> getFloats(GLenum name) {
    GLfloat f[4] = {};
    glGetFloatv(name, f);
    return {GLint(f[0] * 1000.0f), GLint(f[1] * 1000.0f), GLint(f[2] * 1000.0f), GLint(f[3] * 1000.0f)};
}

Probe enabled(GLenum capability, const char* name) {
    return {name, [capability] { return std::array<GLint, 4>{glIsEnabled(capability) ? 1 : 0, 0, 0, 0}; },
            [capability] { glIsEnabled(capability) ? glDisable(capability) : glEnable(capability); }};
}

Probe ints(GLenum what, const char* name, std::function<void()> change) { return {name, [what] { return getInts(what); }, std::move(change)}; }
Probe floats(GLenum what, const char* name, std::function<void()> change) { return {name, [what] { return getFloats(what); }, std::move(change)}; }

// `texture` and `buffer`: objects the binding probes bind (made by the test, deleted after it).
std::vector<Probe> probes(GLuint texture, GLuint buffer) {
    std::vector<Probe> list{
        enabled(GL_BLEND, "GL_BLEND"), enabled(GL_CULL_FACE, "GL_CULL_FACE"), enabled(GL_DEPTH_TEST, "GL_DEPTH_TEST"),
        enabled(GL_SCISSOR_TEST, "GL_SCISSOR_TEST"), enabled(GL_STENCIL_TEST, "GL_STENCIL_TEST"),
        enabled(GL_FRAMEBUFFER_SRGB, "GL_FRAMEBUFFER_SRGB"), enabled(GL_DEPTH_CLAMP, "GL_DEPTH_CLAMP"),
        enabled(GL_POLYGON_OFFSET_FILL, "GL_POLYGON_OFFSET_FILL"), enabled(GL_RASTERIZER_DISCARD, "GL_RASTERIZER_DISCARD"),
        enabled(GL_PRIMITIVE_RESTART, "GL_PRIMITIVE_RESTART"), enabled(GL_TEXTURE_CUBE_MAP_SEAMLESS, "GL_TEXTURE_CUBE_MAP_SEAMLESS"),
        enabled(GL_PROGRAM_POINT_SIZE, "GL_PROGRAM_POINT_SIZE"), enabled(GL_SAMPLE_ALPHA_TO_COVERAGE, "GL_SAMPLE_ALPHA_TO_COVERAGE"),
        enabled(GL_COLOR_LOGIC_OP, "GL_COLOR_LOGIC_OP"), enabled(GL_CLIP_DISTANCE0, "GL_CLIP_DISTANCE0"),
        enabled(GL_DITHER, "GL_DITHER"), enabled(GL_MULTISAMPLE, "GL_MULTISAMPLE"),
        ints(GL_VIEWPORT, "GL_VIEWPORT", [] { glViewport(1, 2, 3, 4); }),
        ints(GL_SCISSOR_BOX, "GL_SCISSOR_BOX", [] { glScissor(1, 2, 3, 4); }),
        ints(GL_DEPTH_FUNC, "GL_DEPTH_FUNC", [] { glDepthFunc(GL_GEQUAL); }),
        ints(GL_DEPTH_WRITEMASK, "GL_DEPTH_WRITEMASK", [] { glDepthMask(GL_FALSE); }),
        floats(GL_DEPTH_RANGE, "GL_DEPTH_RANGE", [] { glDepthRange(0.25, 0.5); }),
        ints(GL_COLOR_WRITEMASK, "GL_COLOR_WRITEMASK", [] { glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE); }),
        ints(GL_BLEND_SRC_RGB, "GL_BLEND_SRC_RGB", [] { glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA); }),
        ints(GL_BLEND_DST_ALPHA, "GL_BLEND_DST_ALPHA", [] { glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE); }),
        ints(GL_BLEND_EQUATION_RGB, "GL_BLEND_EQUATION_RGB", [] { glBlendEquation(GL_MAX); }),
        floats(GL_BLEND_COLOR, "GL_BLEND_COLOR", [] { glBlendColor(0.5f, 0.5f, 0.5f, 0.5f); }),
        ints(GL_STENCIL_FUNC, "GL_STENCIL_FUNC", [] { glStencilFunc(GL_EQUAL, 3, 0x0f); }),
        ints(GL_STENCIL_BACK_FAIL, "GL_STENCIL_BACK_FAIL", [] { glStencilOpSeparate(GL_BACK, GL_ZERO, GL_KEEP, GL_KEEP); }),
        ints(GL_STENCIL_WRITEMASK, "GL_STENCIL_WRITEMASK", [] { glStencilMask(0x0f); }),
        ints(GL_STENCIL_BACK_VALUE_MASK, "GL_STENCIL_BACK_VALUE_MASK", [] { glStencilFuncSeparate(GL_BACK, GL_ALWAYS, 0, 0x03); }),
        ints(GL_LOGIC_OP_MODE, "GL_LOGIC_OP_MODE", [] { glLogicOp(GL_XOR); }),
        ints(GL_CULL_FACE_MODE, "GL_CULL_FACE_MODE", [] { glCullFace(GL_FRONT); }),
        ints(GL_FRONT_FACE, "GL_FRONT_FACE", [] { glFrontFace(GL_CW); }),
        ints(GL_POLYGON_MODE, "GL_POLYGON_MODE", [] { glPolygonMode(GL_FRONT_AND_BACK, GL_LINE); }),
        floats(GL_POLYGON_OFFSET_FACTOR, "GL_POLYGON_OFFSET_FACTOR", [] { glPolygonOffset(2.0f, 3.0f); }),
        floats(GL_POINT_SIZE, "GL_POINT_SIZE", [] { glPointSize(4.0f); }),
        ints(GL_PROVOKING_VERTEX, "GL_PROVOKING_VERTEX", [] { glProvokingVertex(GL_FIRST_VERTEX_CONVENTION); }),
        ints(GL_PRIMITIVE_RESTART_INDEX, "GL_PRIMITIVE_RESTART_INDEX", [] { glPrimitiveRestartIndex(7); }),
        ints(GL_PATCH_VERTICES, "GL_PATCH_VERTICES", [] { glPatchParameteri(GL_PATCH_VERTICES, 4); }),
        floats(GL_COLOR_CLEAR_VALUE, "GL_COLOR_CLEAR_VALUE", [] { glClearColor(0.25f, 0.5f, 0.75f, 1.0f); }),
        floats(GL_DEPTH_CLEAR_VALUE, "GL_DEPTH_CLEAR_VALUE", [] { glClearDepth(0.5); }),
        ints(GL_STENCIL_CLEAR_VALUE, "GL_STENCIL_CLEAR_VALUE", [] { glClearStencil(5); }),
        ints(GL_UNPACK_ALIGNMENT, "GL_UNPACK_ALIGNMENT", [] { glPixelStorei(GL_UNPACK_ALIGNMENT, 1); }),
        ints(GL_PACK_ALIGNMENT, "GL_PACK_ALIGNMENT", [] { glPixelStorei(GL_PACK_ALIGNMENT, 8); }),
        ints(GL_UNPACK_ROW_LENGTH, "GL_UNPACK_ROW_LENGTH", [] { glPixelStorei(GL_UNPACK_ROW_LENGTH, 16); }),
        ints(GL_PACK_SKIP_PIXELS, "GL_PACK_SKIP_PIXELS", [] { glPixelStorei(GL_PACK_SKIP_PIXELS, 2); }),
        ints(GL_ACTIVE_TEXTURE, "GL_ACTIVE_TEXTURE", [] { glActiveTexture(GL_TEXTURE3); }),
        ints(GL_DRAW_BUFFER, "GL_DRAW_BUFFER", [] { glDrawBuffer(GL_NONE); }),
        ints(GL_READ_BUFFER, "GL_READ_BUFFER", [] { glReadBuffer(GL_NONE); }),
    };
    // Objects bound: a texture on unit 15 (the accumulation's), a buffer on uniform binding 7.
    list.push_back({"GL_TEXTURE_BINDING_2D on unit 15",
                    [] {
                        GLint active = 0;
                        glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
                        glActiveTexture(GL_TEXTURE15);
                        const auto v = getInts(GL_TEXTURE_BINDING_2D);
                        glActiveTexture(GLenum(active));
                        return v;
                    },
                    [texture] {
                        GLint active = 0;
                        glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
                        glActiveTexture(GL_TEXTURE15);
                        glBindTexture(GL_TEXTURE_2D, texture);
                        glActiveTexture(GLenum(active));
                    }});
    list.push_back({"GL_UNIFORM_BUFFER_BINDING 7",
                    [] {
                        std::array<GLint, 4> v{};
                        glGetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, 7, v.data());
                        return v;
                    },
                    [buffer] { glBindBufferBase(GL_UNIFORM_BUFFER, 7, buffer); }});
    list.push_back(ints(GL_ARRAY_BUFFER_BINDING, "GL_ARRAY_BUFFER_BINDING", [buffer] { glBindBuffer(GL_ARRAY_BUFFER, buffer); }));
    return list;
}

} // namespace

TEST_CASE("restoreGlDefaults gives back every state a new context starts with", "[gl_defaults]") {
    const std::unique_ptr<t10::Context> context = t10::test::makeTestContext();
    int width = 0;
    int height = 0;
    context->framebufferSize(width, height);
    const t10::GlDefaults defaults = t10::readGlDefaults();
    GLuint texture = 0;
    GLuint buffer = 0;
    glGenTextures(1, &texture);
    glGenBuffers(1, &buffer);
    const std::vector<Probe> list = probes(texture, buffer);
    std::vector<std::array<GLint, 4>> initial;
    for (const Probe& probe : list) initial.push_back(probe.read());
    for (const Probe& probe : list) probe.change();
    for (std::size_t i = 0; i < list.size(); ++i) {
        INFO(list[i].name << " changed");
        CHECK(list[i].read() != initial[i]);
    }
    t10::restoreGlDefaults(defaults, width, height);
    for (std::size_t i = 0; i < list.size(); ++i) {
        INFO(list[i].name << " restored");
        CHECK(list[i].read() == initial[i]);
    }
    CHECK(glGetError() == GL_NO_ERROR);
    glDeleteBuffers(1, &buffer);
    glDeleteTextures(1, &texture);
}
