// Restoring a new context's GL state between runs of one process; see gl_defaults.hpp. The values
// are the initial values of the OpenGL 4.3 core specification's state tables (chapter 23).
#include "t10/gl_defaults.hpp"

#include "t10/gl.hpp"

#include <initializer_list>
#include <utility>

namespace t10 {

namespace {

GLint getInt(GLenum name) {
    GLint value = 0;
    glGetIntegerv(name, &value);
    return value;
}

void unbindTextures() {
    static constexpr GLenum kTargets[] = {GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_1D_ARRAY,
                                          GL_TEXTURE_2D_ARRAY, GL_TEXTURE_RECTANGLE, GL_TEXTURE_CUBE_MAP,
                                          GL_TEXTURE_CUBE_MAP_ARRAY, GL_TEXTURE_BUFFER, GL_TEXTURE_2D_MULTISAMPLE,
                                          GL_TEXTURE_2D_MULTISAMPLE_ARRAY};
    const GLint units = getInt(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS);
    for (GLint unit = 0; unit < units; ++unit) {
        glActiveTexture(GLenum(GL_TEXTURE0 + unit));
        for (GLenum target : kTargets) glBindTexture(target, 0);
        glBindSampler(GLuint(unit), 0);
    }
    glActiveTexture(GL_TEXTURE0);
    const GLint images = getInt(GL_MAX_IMAGE_UNITS);
    for (GLint unit = 0; unit < images; ++unit) glBindImageTexture(GLuint(unit), 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R8);
}

void unbindBuffers() {
    for (GLenum target : {GL_ARRAY_BUFFER, GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, GL_PIXEL_PACK_BUFFER,
                          GL_PIXEL_UNPACK_BUFFER, GL_DRAW_INDIRECT_BUFFER, GL_DISPATCH_INDIRECT_BUFFER, GL_TEXTURE_BUFFER})
        glBindBuffer(target, 0);
    // The indexed bindings (and with them each generic binding).
    const std::initializer_list<std::pair<GLenum, GLenum>> indexed = {
        {GL_UNIFORM_BUFFER, GL_MAX_UNIFORM_BUFFER_BINDINGS},
        {GL_SHADER_STORAGE_BUFFER, GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS},
        {GL_ATOMIC_COUNTER_BUFFER, GL_MAX_ATOMIC_COUNTER_BUFFER_BINDINGS}};
    for (const auto& [target, count] : indexed) {
        const GLint bindings = getInt(count);
        for (GLint i = 0; i < bindings; ++i) glBindBufferBase(target, GLuint(i), 0);
        glBindBuffer(target, 0);
    }
    glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, 0);
}

void restoreCapabilities() {
    for (GLenum capability :
         {GL_BLEND, GL_COLOR_LOGIC_OP, GL_CULL_FACE, GL_DEPTH_CLAMP, GL_DEPTH_TEST, GL_FRAMEBUFFER_SRGB, GL_LINE_SMOOTH,
          GL_POLYGON_OFFSET_FILL, GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_POINT, GL_POLYGON_SMOOTH,
          GL_PRIMITIVE_RESTART, GL_PRIMITIVE_RESTART_FIXED_INDEX, GL_RASTERIZER_DISCARD, GL_SAMPLE_ALPHA_TO_COVERAGE,
          GL_SAMPLE_ALPHA_TO_ONE, GL_SAMPLE_COVERAGE, GL_SAMPLE_SHADING, GL_SAMPLE_MASK, GL_SCISSOR_TEST,
          GL_STENCIL_TEST, GL_TEXTURE_CUBE_MAP_SEAMLESS, GL_PROGRAM_POINT_SIZE})
        glDisable(capability);
    const GLint clipDistances = getInt(GL_MAX_CLIP_DISTANCES);
    for (GLint i = 0; i < clipDistances; ++i) glDisable(GLenum(GL_CLIP_DISTANCE0 + i));
    glEnable(GL_DITHER);
    glEnable(GL_MULTISAMPLE);
}

void restoreFragmentState(const GlDefaults& defaults) {
    glDepthRange(0.0, 1.0);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE); // every draw buffer
    glStencilFunc(GL_ALWAYS, 0, GLuint(defaults.stencilValueMask)); // both faces
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glStencilMask(GLuint(defaults.stencilWriteMask));
    glBlendFunc(GL_ONE, GL_ZERO); // every draw buffer
    glBlendEquation(GL_FUNC_ADD);
    glBlendColor(0.0f, 0.0f, 0.0f, 0.0f);
    glLogicOp(GL_COPY);
    glSampleCoverage(1.0f, GL_FALSE);
    glSampleMaski(0, ~0u);
    glMinSampleShading(0.0f);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClearDepth(1.0);
    glClearStencil(0);
    glClampColor(GL_CLAMP_READ_COLOR, GL_FIXED_ONLY);
}

void restoreRasterState() {
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glPolygonOffset(0.0f, 0.0f);
    glLineWidth(1.0f);
    glPointSize(1.0f);
    glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, 1.0f);
    glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_UPPER_LEFT);
    glProvokingVertex(GL_LAST_VERTEX_CONVENTION);
    glPrimitiveRestartIndex(0);
    glPatchParameteri(GL_PATCH_VERTICES, 3);
    for (GLenum hint : {GL_LINE_SMOOTH_HINT, GL_POLYGON_SMOOTH_HINT, GL_TEXTURE_COMPRESSION_HINT,
                        GL_FRAGMENT_SHADER_DERIVATIVE_HINT})
        glHint(hint, GL_DONT_CARE);
}

void restorePixelStore() {
    for (GLenum name : {GL_PACK_SWAP_BYTES, GL_PACK_LSB_FIRST, GL_UNPACK_SWAP_BYTES, GL_UNPACK_LSB_FIRST})
        glPixelStorei(name, GL_FALSE);
    for (GLenum name : {GL_PACK_ROW_LENGTH, GL_PACK_IMAGE_HEIGHT, GL_PACK_SKIP_ROWS, GL_PACK_SKIP_PIXELS,
                        GL_PACK_SKIP_IMAGES, GL_UNPACK_ROW_LENGTH, GL_UNPACK_IMAGE_HEIGHT, GL_UNPACK_SKIP_ROWS,
                        GL_UNPACK_SKIP_PIXELS, GL_UNPACK_SKIP_IMAGES})
        glPixelStorei(name, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
}

} // namespace

GlDefaults readGlDefaults() {
    GlDefaults defaults;
    defaults.drawBuffer = getInt(GL_DRAW_BUFFER);
    defaults.readBuffer = getInt(GL_READ_BUFFER);
    defaults.stencilWriteMask = getInt(GL_STENCIL_WRITEMASK);
    defaults.stencilValueMask = getInt(GL_STENCIL_VALUE_MASK);
    return defaults;
}

void restoreGlDefaults(const GlDefaults& defaults, int width, int height) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDrawBuffer(GLenum(defaults.drawBuffer));
    glReadBuffer(GLenum(defaults.readBuffer));
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    glUseProgram(0);
    glBindProgramPipeline(0);
    glBindVertexArray(0);
    unbindBuffers();
    unbindTextures();
    const GLint attributes = getInt(GL_MAX_VERTEX_ATTRIBS);
    for (GLint i = 0; i < attributes; ++i) glVertexAttrib4f(GLuint(i), 0.0f, 0.0f, 0.0f, 1.0f);
    restoreCapabilities();
    restoreFragmentState(defaults);
    restoreRasterState();
    restorePixelStore();
    glViewport(0, 0, width, height);
    glScissor(0, 0, width, height);
}

} // namespace t10
