/* The browser build's stand-in for the glad GL 4.3 loader header (common/platform/web/README.md):
   OpenGL ES 3.0 as WebGL 2 offers it, plus what common/ and the stages use that ES 3.0 lacks.
   - Desktop enums that WebGL 2 has under an extension keep their values (GL_R16 is EXT_texture_norm16's
     R16_EXT); the others are defined so that code naming them compiles, and the calls that take them
     fail at run time with a message (gl_web.cpp).
   - Uniform calls go through the platform (t10Web*), which maps the shaders' explicit locations
     (layout(location = N), which GLSL ES 3.00 lacks for uniforms) to the locations WebGL assigns, and
     sets Part 3's subroutine uniform (an int uniform in the translated shader).
   - Texture storage is recorded, so that glGetTexLevelParameteriv and glGetTexImage can be answered,
     and GL_R16 emulated where EXT_texture_norm16 is missing (glGenerateMipmap; gl_web.cpp). */
#ifndef T10_WEB_GL_H
#define T10_WEB_GL_H

#include <GLES3/gl3.h>
#include <GLES2/gl2ext.h>

#define GLAPIENTRY
#define GLAD_API_PTR

/* Desktop enums: EXT_texture_norm16 (same values as desktop GL) and the rest. */
#ifndef GL_R16
#define GL_R16 0x822A
#endif
#ifndef GL_RG16
#define GL_RG16 0x822C
#endif
#ifndef GL_RGBA16
#define GL_RGBA16 0x805B
#endif
#define GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER 0x8CDB
#define GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER 0x8CDC
#define GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS 0x8DA8
#define GL_TEXTURE_WIDTH 0x1000
#define GL_TEXTURE_HEIGHT 0x1001
#define GL_TEXTURE_INTERNAL_FORMAT 0x1003
#define GL_TEXTURE_SWIZZLE_RGBA 0x8E46
#define GL_DEBUG_OUTPUT 0x92E0
#define GL_DEBUG_OUTPUT_SYNCHRONOUS 0x8242
#define GL_DEBUG_SEVERITY_NOTIFICATION 0x826B
#define GL_DEBUG_SEVERITY_HIGH 0x9146
#define GL_DEBUG_TYPE_ERROR 0x824C
#define GL_GEOMETRY_SHADER 0x8DD9
#define GL_COMPUTE_SHADER 0x91B9
#define GL_TESS_CONTROL_SHADER 0x8E88
#define GL_TESS_EVALUATION_SHADER 0x8E87
#define GL_SHADER_STORAGE_BUFFER 0x90D2
#define GL_SHADER_STORAGE_BARRIER_BIT 0x00002000
#define GL_PIXEL_BUFFER_BARRIER_BIT 0x00000080
#define GL_BUFFER_UPDATE_BARRIER_BIT 0x00000200
#define GL_TIME_ELAPSED 0x88BF
#define GL_TIMESTAMP 0x8E28
#define GL_ACTIVE_SUBROUTINE_UNIFORMS 0x8DE6
#define GL_READ_ONLY 0x88B8
#define GL_QUERY_RESULT_NO_WAIT 0x9194
#define GL_CLAMP_TO_BORDER 0x812D
#define GL_TEXTURE_BORDER_COLOR 0x1004

#ifdef __cplusplus
extern "C" {
#endif

typedef void (*GLDEBUGPROC)(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                            const GLchar* message, const void* userParam);

/* Desktop GL 4.3 entry points common/ names (gl_web.cpp): emulated where WebGL 2 can answer
   (glGetTexLevelParameteriv, glGetTexImage into memory, glProgramUniform*, glUniformSubroutinesuiv),
   otherwise a t10::Error naming the call. */
void glGetTexLevelParameteriv(GLenum target, GLint level, GLenum pname, GLint* params);
void glGetTexImage(GLenum target, GLint level, GLenum format, GLenum type, void* pixels);
void glGetBufferSubData(GLenum target, GLintptr offset, GLsizeiptr size, void* data);
void glTextureView(GLuint texture, GLenum target, GLuint origtexture, GLenum internalformat, GLuint minlevel,
                   GLuint numlevels, GLuint minlayer, GLuint numlayers);
void glDebugMessageCallback(GLDEBUGPROC callback, const void* userParam);
void glDispatchCompute(GLuint x, GLuint y, GLuint z);
void glMemoryBarrier(GLbitfield barriers);
void glGetQueryObjectiv(GLuint id, GLenum pname, GLint* params);
void glGetQueryObjectui64v(GLuint id, GLenum pname, GLuint64* params);
void glQueryCounter(GLuint id, GLenum target);
void glGetProgramStageiv(GLuint program, GLenum shadertype, GLenum pname, GLint* values);
void glGetUniformSubroutineuiv(GLenum shadertype, GLint location, GLuint* params);
void glGetActiveSubroutineName(GLuint program, GLenum shadertype, GLuint index, GLsizei bufsize, GLsizei* length,
                               GLchar* name);
void glUniformSubroutinesuiv(GLenum shadertype, GLsizei count, const GLuint* indices);
void glProgramUniform1f(GLuint program, GLint location, GLfloat v0);
void glProgramUniform1i(GLuint program, GLint location, GLint v0);

/* The uniform calls, through the explicit-location map (gl_web.cpp). */
void t10WebUseProgram(GLuint program);
void t10WebDeleteProgram(GLuint program);
GLint t10WebGetUniformLocation(GLuint program, const GLchar* name);
void t10WebGetUniformfv(GLuint program, GLint location, GLfloat* params);
void t10WebGetUniformiv(GLuint program, GLint location, GLint* params);
void t10WebUniform1f(GLint location, GLfloat v0);
void t10WebUniform2f(GLint location, GLfloat v0, GLfloat v1);
void t10WebUniform3f(GLint location, GLfloat v0, GLfloat v1, GLfloat v2);
void t10WebUniform4f(GLint location, GLfloat v0, GLfloat v1, GLfloat v2, GLfloat v3);
void t10WebUniform1i(GLint location, GLint v0);
void t10WebUniform2i(GLint location, GLint v0, GLint v1);
void t10WebUniform3i(GLint location, GLint v0, GLint v1, GLint v2);
void t10WebUniform4i(GLint location, GLint v0, GLint v1, GLint v2, GLint v3);
void t10WebUniform1ui(GLint location, GLuint v0);
void t10WebUniform1fv(GLint location, GLsizei count, const GLfloat* value);
void t10WebUniform2fv(GLint location, GLsizei count, const GLfloat* value);
void t10WebUniform3fv(GLint location, GLsizei count, const GLfloat* value);
void t10WebUniform4fv(GLint location, GLsizei count, const GLfloat* value);
void t10WebUniform1iv(GLint location, GLsizei count, const GLint* value);
void t10WebUniform2iv(GLint location, GLsizei count, const GLint* value);
void t10WebUniformMatrix3fv(GLint location, GLsizei count, GLboolean transpose, const GLfloat* value);
void t10WebUniformMatrix4fv(GLint location, GLsizei count, GLboolean transpose, const GLfloat* value);
/* Texture storage, recorded for the queries above (and GL_R16 checked against EXT_texture_norm16). */
void t10WebTexStorage2D(GLenum target, GLsizei levels, GLenum internalformat, GLsizei width, GLsizei height);
void t10WebTexImage2D(GLenum target, GLint level, GLint internalformat, GLsizei width, GLsizei height, GLint border,
                      GLenum format, GLenum type, const void* pixels);
void t10WebDeleteTextures(GLsizei n, const GLuint* textures);
void t10WebGenerateMipmap(GLenum target);
/* The draws, which the capture hook observes (gl_web.hpp setDrawHook; draw_observation_web.cpp). */
void t10WebDrawElements(GLenum mode, GLsizei count, GLenum type, const void* indices);
void t10WebDrawArrays(GLenum mode, GLint first, GLsizei count);
/* Uniform buffers padded to 16 bytes (WebGL checks the buffer against the block's std140 size). */
void t10WebBufferData(GLenum target, GLsizeiptr size, const void* data, GLenum usage);

#ifdef __cplusplus
}
#endif

#ifndef T10_WEB_GL_IMPLEMENTATION
#define glUseProgram t10WebUseProgram
#define glDrawElements t10WebDrawElements
#define glDrawArrays t10WebDrawArrays
#define glDeleteProgram t10WebDeleteProgram
#define glGetUniformLocation t10WebGetUniformLocation
#define glGetUniformfv t10WebGetUniformfv
#define glGetUniformiv t10WebGetUniformiv
#define glUniform1f t10WebUniform1f
#define glUniform2f t10WebUniform2f
#define glUniform3f t10WebUniform3f
#define glUniform4f t10WebUniform4f
#define glUniform1i t10WebUniform1i
#define glUniform2i t10WebUniform2i
#define glUniform3i t10WebUniform3i
#define glUniform4i t10WebUniform4i
#define glUniform1ui t10WebUniform1ui
#define glUniform1fv t10WebUniform1fv
#define glUniform2fv t10WebUniform2fv
#define glUniform3fv t10WebUniform3fv
#define glUniform4fv t10WebUniform4fv
#define glUniform1iv t10WebUniform1iv
#define glUniform2iv t10WebUniform2iv
#define glUniformMatrix3fv t10WebUniformMatrix3fv
#define glUniformMatrix4fv t10WebUniformMatrix4fv
#define glTexStorage2D t10WebTexStorage2D
#define glTexImage2D t10WebTexImage2D
#define glDeleteTextures t10WebDeleteTextures
#define glGenerateMipmap t10WebGenerateMipmap
#define glBufferData t10WebBufferData
#endif

#endif
