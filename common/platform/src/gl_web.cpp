// The browser build's GL layer: the desktop GL calls common/ and the stages make that WebGL 2 lacks,
// emulated where WebGL 2 can answer them and refused with a message naming the call where it cannot;
// and the explicit uniform locations of the shaders, which GLSL ES 3.00 cannot declare, mapped to the
// locations WebGL assigns (see common/platform/web/include/glad/gl.h and gl_web.hpp).
#define T10_WEB_GL_IMPLEMENTATION
#include "t10/gl_web.hpp"

#include "t10/error.hpp"
#include "t10/gl.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace {

// Locations handed out by glGetUniformLocation for uniforms without an explicit location: far above
// any explicit one (GL_MAX_UNIFORM_LOCATIONS is 1024 at least and the shaders use < 64).
constexpr GLint kLookedUpBase = 1 << 20;

struct ProgramMap {
    std::unordered_map<GLint, GLint> locations;           // our location -> WebGL's
    std::unordered_map<std::string, GLint> explicitNames; // uniform (array) name -> its explicit location
    std::unordered_map<std::string, GLint> lookedUp;      // name -> the location we handed out
    std::vector<t10::SubroutineUniform> subroutines;
    std::vector<GLint> subroutineLocations;               // WebGL's location of each subroutine's int
    std::vector<GLuint> subroutineValues;                 // the index each was last set to (glGetUniformSubroutineuiv)
    GLint next = kLookedUpBase;
};

struct TextureInfo {
    GLenum format = 0; // as the caller asked (GL_R16 also when emulated)
    int width = 0;
    int height = 0;
    int levels = 0;
    bool emulatedR16 = false; // GL_R16 stored as GL_R32F (see emulateR16Write)
};

std::unordered_map<GLuint, ProgramMap>& programs() {
    static std::unordered_map<GLuint, ProgramMap> map;
    return map;
}
std::unordered_map<GLuint, TextureInfo>& textures() {
    static std::unordered_map<GLuint, TextureInfo> map;
    return map;
}
GLuint g_current = 0;
t10::web::DrawHook g_drawHook = nullptr;
void* g_drawHookContext = nullptr;
bool g_norm16 = false;
bool g_r16Emulation = false;

[[noreturn]] void unavailable(const std::string& call, const std::string& why) {
    throw t10::Error(call + " is not available in the web build (WebGL 2 has no " + why + ")");
}

t10::GlslStage glslStage(GLenum shadertype) {
    return shadertype == GL_VERTEX_SHADER ? t10::GlslStage::Vertex
           : shadertype == GL_FRAGMENT_SHADER ? t10::GlslStage::Fragment
                                              : t10::GlslStage::Other;
}

// "name[3]" -> ("name", 3); "name" -> ("name", 0).
std::pair<std::string, int> splitIndex(const std::string& name) {
    const std::size_t open = name.rfind('[');
    if (open == std::string::npos || name.back() != ']') return {name, 0};
    const std::string digits = name.substr(open + 1, name.size() - open - 2);
    if (digits.empty() || !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return {name, 0};
    return {name.substr(0, open), std::stoi(digits)};
}

GLint webLocation(GLuint program, GLint location) {
    if (location < 0) return -1;
    const auto p = programs().find(program);
    if (p == programs().end()) return location; // not made by ShaderManager: WebGL's own locations
    const auto it = p->second.locations.find(location);
    return it == p->second.locations.end() ? -1 : it->second;
}

GLint current(GLint location) { return webLocation(g_current, location); }

GLuint boundTexture2D() {
    GLint texture = 0;
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture);
    return static_cast<GLuint>(texture);
}

void recordExplicitLocations(GLuint program, ProgramMap& map, const std::vector<t10::NamedValue>& explicitLocations) {
    for (const auto& entry : explicitLocations) map.explicitNames[entry.name] = entry.value;
    GLint count = 0;
    glGetProgramiv(program, GL_ACTIVE_UNIFORMS, &count);
    for (GLint i = 0; i < count; ++i) {
        char name[256];
        GLsizei length = 0;
        GLint size = 0;
        GLenum type = 0;
        glGetActiveUniform(program, static_cast<GLuint>(i), sizeof name, &length, &size, &type, name);
        const auto [base, index] = splitIndex(std::string(name, static_cast<std::size_t>(length)));
        const auto found = map.explicitNames.find(base);
        if (found == map.explicitNames.end() || index != 0) continue;
        for (GLint k = 0; k < size; ++k) {
            const std::string element = size > 1 ? base + "[" + std::to_string(k) + "]" : base;
            const GLint location = glGetUniformLocation(program, element.c_str());
            if (location >= 0) map.locations[found->second + k] = location;
        }
    }
}

// GL_R16 where the browser lacks EXT_texture_norm16 (Chromium on SwiftShader, for one): stored as
// GL_R32F, and what a GL_R16 texture would hold is made before every glGenerateMipmap of it (the
// stages' luminance texture gets its mipmaps right after its pass): level 0 clamped to [0, 1] and
// rounded to a multiple of 1/65535, as writing to a 16-bit normalised target does (NaN becomes 0).
// The mipmaps are then averaged in float rather than in 16 bits: within 1/65535 of GL_R16's.
constexpr const char* kR16Vertex = R"(#version 300 es
void main() {
    gl_Position = vec4(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0, 0.0, 1.0);
})";
constexpr const char* kR16Fragment = R"(#version 300 es
precision highp float;
uniform highp sampler2D s2Level0;
out vec4 v4Out;
void main() {
    float v = texelFetch(s2Level0, ivec2(gl_FragCoord.xy), 0).r;
    v = v >= 0.0 ? min(v, 1.0) : 0.0;
    v4Out = vec4(floor(v * 65535.0 + 0.5) / 65535.0, 0.0, 0.0, 1.0);
})";

GLuint compileR16Program() {
    const GLuint program = glCreateProgram();
    for (const auto& [type, text] : {std::pair<GLenum, const char*>{GL_VERTEX_SHADER, kR16Vertex},
                                     std::pair<GLenum, const char*>{GL_FRAGMENT_SHADER, kR16Fragment}}) {
        const GLuint shader = glCreateShader(type);
        glShaderSource(shader, 1, &text, nullptr);
        glCompileShader(shader);
        glAttachShader(program, shader);
        glDeleteShader(shader);
    }
    glLinkProgram(program);
    GLint linked = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    if (linked != GL_TRUE) throw t10::Error("the GL_R16 emulation's program did not link");
    return program;
}

// Every piece of state the pass below changes, put back afterwards.
class SavedState {
public:
    SavedState() {
        glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw_);
        glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read_);
        glGetIntegerv(GL_VIEWPORT, viewport_);
        glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vao_);
        glGetIntegerv(GL_ACTIVE_TEXTURE, &active_);
        glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture_);
        for (std::size_t i = 0; i < kCaps.size(); ++i) enabled_[i] = glIsEnabled(kCaps[i]);
    }
    ~SavedState() {
        glUseProgram(static_cast<GLuint>(program_));
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(draw_));
        glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(read_));
        glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
        glBindVertexArray(static_cast<GLuint>(vao_));
        glActiveTexture(static_cast<GLenum>(active_));
        glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(texture_));
        for (std::size_t i = 0; i < kCaps.size(); ++i) (enabled_[i] ? glEnable : glDisable)(kCaps[i]);
    }
    SavedState(const SavedState&) = delete;
    SavedState& operator=(const SavedState&) = delete;

private:
    static constexpr std::array<GLenum, 5> kCaps{GL_DEPTH_TEST, GL_BLEND, GL_SCISSOR_TEST, GL_CULL_FACE, GL_STENCIL_TEST};
    GLint program_ = 0, draw_ = 0, read_ = 0, vao_ = 0, active_ = 0, texture_ = 0;
    GLint viewport_[4] = {};
    std::array<GLboolean, 5> enabled_{};
};

void emulateR16Write(GLuint texture, const TextureInfo& info) {
    static GLuint program = 0, vao = 0, fbos[2] = {}, scratch = 0;
    static int scratchWidth = 0, scratchHeight = 0;
    if (program == 0) {
        program = compileR16Program();
        glGenVertexArrays(1, &vao);
        glGenFramebuffers(2, fbos);
    }
    const SavedState saved;
    // The texture stays bound on the caller's unit; the scratch texture and the pass use unit 0's
    // binding only while the pass runs (restored by SavedState on the caller's active unit).
    glActiveTexture(GL_TEXTURE0);
    const SavedState unit0; // unit 0's binding and everything else, put back first
    if (scratch == 0 || scratchWidth != info.width || scratchHeight != info.height) {
        if (scratch != 0) glDeleteTextures(1, &scratch);
        glGenTextures(1, &scratch);
        glBindTexture(GL_TEXTURE_2D, scratch);
        glTexStorage2D(GL_TEXTURE_2D, 1, GL_R32F, info.width, info.height);
        scratchWidth = info.width;
        scratchHeight = info.height;
    }
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbos[0]);
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, scratch, 0);
    glBindTexture(GL_TEXTURE_2D, texture);
    for (GLenum cap : {GL_DEPTH_TEST, GL_BLEND, GL_SCISSOR_TEST, GL_CULL_FACE, GL_STENCIL_TEST}) glDisable(cap);
    glViewport(0, 0, info.width, info.height);
    glUseProgram(program);
    glUniform1i(glGetUniformLocation(program, "s2Level0"), 0);
    glBindVertexArray(vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    // The clamped copy back into level 0.
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbos[0]);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbos[1]);
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
    glBlitFramebuffer(0, 0, info.width, info.height, 0, 0, info.width, info.height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 0, 0);
}

} // namespace

namespace t10::web {

void configureProgram(unsigned program, const ProgramLayout& layout) {
    ProgramMap map;
    GLint previous = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &previous);
    glUseProgram(program);
    for (const NamedValue& sampler : layout.samplerUnits) {
        const GLint location = glGetUniformLocation(program, sampler.name.c_str());
        if (location >= 0) glUniform1i(location, sampler.value);
    }
    for (const NamedValue& block : layout.blockBindings) {
        const GLuint index = glGetUniformBlockIndex(program, block.name.c_str());
        if (index != GL_INVALID_INDEX) glUniformBlockBinding(program, index, static_cast<GLuint>(block.value));
    }
    recordExplicitLocations(program, map, layout.uniformLocations);
    for (const SubroutineUniform& subroutine : layout.subroutineUniforms) {
        map.subroutines.push_back(subroutine);
        map.subroutineLocations.push_back(glGetUniformLocation(program, subroutine.uniformName.c_str()));
        map.subroutineValues.push_back(0);
    }
    // Linked again (the page's shader editing): the locations handed out before keep their numbers.
    if (const auto old = programs().find(program); old != programs().end()) {
        map.next = old->second.next;
        for (const auto& [name, ours] : old->second.lookedUp) {
            map.lookedUp[name] = ours;
            const GLint location = glGetUniformLocation(program, name.c_str());
            if (location >= 0) map.locations[ours] = location;
        }
    }
    glUseProgram(static_cast<GLuint>(previous));
    programs()[program] = std::move(map);
}

std::pair<DrawHook, void*> setDrawHook(DrawHook hook, void* context) {
    const std::pair<DrawHook, void*> previous{g_drawHook, g_drawHookContext};
    g_drawHook = hook;
    g_drawHookContext = context;
    return previous;
}

void setTextureNorm16(bool available, bool emulation) {
    g_norm16 = available;
    g_r16Emulation = emulation;
}
bool textureNorm16() { return g_norm16; }

} // namespace t10::web

extern "C" {

void t10WebUseProgram(GLuint program) {
    g_current = program;
    glUseProgram(program);
}

void t10WebDeleteProgram(GLuint program) {
    programs().erase(program);
    if (g_current == program) g_current = 0;
    glDeleteProgram(program);
}

GLint t10WebGetUniformLocation(GLuint program, const GLchar* name) {
    const auto p = programs().find(program);
    if (p == programs().end()) return glGetUniformLocation(program, name);
    ProgramMap& map = p->second;
    const auto [base, index] = splitIndex(name);
    if (const auto found = map.explicitNames.find(base); found != map.explicitNames.end())
        return map.locations.count(found->second + index) != 0 ? found->second + index : -1;
    if (const auto known = map.lookedUp.find(name); known != map.lookedUp.end()) return known->second;
    const GLint location = glGetUniformLocation(program, name);
    if (location < 0) return -1;
    const GLint ours = map.next++;
    map.locations[ours] = location;
    map.lookedUp[name] = ours;
    return ours;
}

void t10WebGetUniformfv(GLuint program, GLint location, GLfloat* params) {
    glGetUniformfv(program, webLocation(program, location), params);
}
void t10WebGetUniformiv(GLuint program, GLint location, GLint* params) {
    glGetUniformiv(program, webLocation(program, location), params);
}

void t10WebUniform1f(GLint l, GLfloat a) { glUniform1f(current(l), a); }
void t10WebUniform2f(GLint l, GLfloat a, GLfloat b) { glUniform2f(current(l), a, b); }
void t10WebUniform3f(GLint l, GLfloat a, GLfloat b, GLfloat c) { glUniform3f(current(l), a, b, c); }
void t10WebUniform4f(GLint l, GLfloat a, GLfloat b, GLfloat c, GLfloat d) { glUniform4f(current(l), a, b, c, d); }
void t10WebUniform1i(GLint l, GLint a) { glUniform1i(current(l), a); }
void t10WebUniform2i(GLint l, GLint a, GLint b) { glUniform2i(current(l), a, b); }
void t10WebUniform3i(GLint l, GLint a, GLint b, GLint c) { glUniform3i(current(l), a, b, c); }
void t10WebUniform4i(GLint l, GLint a, GLint b, GLint c, GLint d) { glUniform4i(current(l), a, b, c, d); }
void t10WebUniform1ui(GLint l, GLuint a) { glUniform1ui(current(l), a); }
void t10WebUniform1fv(GLint l, GLsizei n, const GLfloat* v) { glUniform1fv(current(l), n, v); }
void t10WebUniform2fv(GLint l, GLsizei n, const GLfloat* v) { glUniform2fv(current(l), n, v); }
void t10WebUniform3fv(GLint l, GLsizei n, const GLfloat* v) { glUniform3fv(current(l), n, v); }
void t10WebUniform4fv(GLint l, GLsizei n, const GLfloat* v) { glUniform4fv(current(l), n, v); }
void t10WebUniform1iv(GLint l, GLsizei n, const GLint* v) { glUniform1iv(current(l), n, v); }
void t10WebUniform2iv(GLint l, GLsizei n, const GLint* v) { glUniform2iv(current(l), n, v); }
void t10WebUniformMatrix3fv(GLint l, GLsizei n, GLboolean t, const GLfloat* v) { glUniformMatrix3fv(current(l), n, t, v); }
void t10WebUniformMatrix4fv(GLint l, GLsizei n, GLboolean t, const GLfloat* v) { glUniformMatrix4fv(current(l), n, t, v); }

// Desktop GL 4.1's glProgramUniform*: WebGL 2 has none, so the program is made current for the call.
void glProgramUniform1f(GLuint program, GLint location, GLfloat v0) {
    const GLuint previous = g_current;
    t10WebUseProgram(program);
    t10WebUniform1f(location, v0);
    t10WebUseProgram(previous);
}
void glProgramUniform1i(GLuint program, GLint location, GLint v0) {
    const GLuint previous = g_current;
    t10WebUseProgram(program);
    t10WebUniform1i(location, v0);
    t10WebUseProgram(previous);
}

// The subroutine uniform at location i of the current program is the int uniform its translation
// declared; it takes the chosen subroutine's layout(index).
void glUniformSubroutinesuiv(GLenum shadertype, GLsizei count, const GLuint* indices) {
    const auto p = programs().find(g_current);
    if (p == programs().end()) throw t10::Error("glUniformSubroutinesuiv: no program made by ShaderManager is current");
    ProgramMap& map = p->second;
    const t10::GlslStage stage = glslStage(shadertype);
    for (std::size_t i = 0; i < map.subroutines.size(); ++i) {
        const auto& subroutine = map.subroutines[i];
        if (subroutine.stage != stage || subroutine.location < 0 || subroutine.location >= count) continue;
        glUniform1i(map.subroutineLocations[i], static_cast<GLint>(indices[subroutine.location]));
        map.subroutineValues[i] = indices[subroutine.location];
    }
}

// The subroutine queries the capture hook's pass capture makes (frame_observer.cpp), answered from the
// program's layout: the subroutine uniforms of a stage, the index one was set to, a function's name.
void glGetProgramStageiv(GLuint program, GLenum shadertype, GLenum pname, GLint* values) {
    if (pname != GL_ACTIVE_SUBROUTINE_UNIFORMS) unavailable("glGetProgramStageiv other than GL_ACTIVE_SUBROUTINE_UNIFORMS", "subroutines");
    const auto p = programs().find(program);
    const t10::GlslStage stage = glslStage(shadertype);
    *values = p == programs().end() ? 0
                                    : static_cast<GLint>(std::count_if(p->second.subroutines.begin(), p->second.subroutines.end(),
                                                                       [&](const t10::SubroutineUniform& s) { return s.stage == stage; }));
}

void glGetUniformSubroutineuiv(GLenum shadertype, GLint location, GLuint* params) {
    const auto p = programs().find(g_current);
    if (p == programs().end()) throw t10::Error("glGetUniformSubroutineuiv: no program made by ShaderManager is current");
    for (std::size_t i = 0; i < p->second.subroutines.size(); ++i) {
        const auto& subroutine = p->second.subroutines[i];
        if (subroutine.stage == glslStage(shadertype) && subroutine.location == location) {
            *params = p->second.subroutineValues[i];
            return;
        }
    }
    throw t10::Error("glGetUniformSubroutineuiv: the current program has no subroutine uniform at location " + std::to_string(location));
}

void glGetActiveSubroutineName(GLuint program, GLenum shadertype, GLuint index, GLsizei bufsize, GLsizei* length, GLchar* name) {
    std::string found;
    const auto p = programs().find(program);
    if (p != programs().end()) {
        for (const auto& subroutine : p->second.subroutines)
            for (const t10::NamedValue& f : subroutine.functions)
                if (subroutine.stage == glslStage(shadertype) && f.value == static_cast<int>(index)) found = f.name;
    }
    if (found.empty()) throw t10::Error("glGetActiveSubroutineName: the program has no subroutine of index " + std::to_string(index));
    const std::size_t copied = bufsize > 0 ? std::min(found.size(), static_cast<std::size_t>(bufsize - 1)) : 0;
    if (bufsize > 0) {
        std::copy_n(found.begin(), copied, name);
        name[copied] = '\0';
    }
    if (length != nullptr) *length = static_cast<GLsizei>(copied);
}

void t10WebDrawElements(GLenum mode, GLsizei count, GLenum type, const void* indices) {
    glDrawElements(mode, count, type, indices);
    if (g_drawHook != nullptr) g_drawHook(g_drawHookContext);
}

void t10WebDrawArrays(GLenum mode, GLint first, GLsizei count) {
    glDrawArrays(mode, first, count);
    if (g_drawHook != nullptr) g_drawHook(g_drawHookContext);
}

void t10WebTexStorage2D(GLenum target, GLsizei levels, GLenum internalformat, GLsizei width, GLsizei height) {
    const bool emulate = internalformat == GL_R16 && !g_norm16;
    if (emulate && !g_r16Emulation) {
        throw t10::Error("GL_R16 textures (the tutorial's luminance texture) need WebGL 2's EXT_texture_norm16 or, to "
                         "emulate it, OES_texture_float_linear; this browser offers neither. The extras page can "
                         "use GL_R16F instead (luminance-format=r16f)");
    }
    glTexStorage2D(target, levels, emulate ? GL_R32F : internalformat, width, height);
    if (target == GL_TEXTURE_2D) textures()[boundTexture2D()] = TextureInfo{internalformat, width, height, levels, emulate};
}

void t10WebGenerateMipmap(GLenum target) {
    if (target == GL_TEXTURE_2D) {
        const GLuint texture = boundTexture2D();
        const auto it = textures().find(texture);
        if (it != textures().end() && it->second.emulatedR16) emulateR16Write(texture, it->second);
    }
    glGenerateMipmap(target);
}

void t10WebTexImage2D(GLenum target, GLint level, GLint internalformat, GLsizei width, GLsizei height, GLint border,
                      GLenum format, GLenum type, const void* pixels) {
    if (internalformat == GL_R16 && !g_norm16)
        unavailable("glTexImage2D with GL_R16 (use glTexStorage2D, as the stages do)", "EXT_texture_norm16 here");
    glTexImage2D(target, level, internalformat, width, height, border, format, type, pixels);
    if (target != GL_TEXTURE_2D) return;
    TextureInfo& info = textures()[boundTexture2D()];
    if (level == 0) info = TextureInfo{static_cast<GLenum>(internalformat), width, height, 1};
    info.levels = std::max(info.levels, level + 1);
}

// A uniform block's size is a multiple of 16 bytes in std140 (InvResolution's one vec2 is 16), and
// WebGL refuses a draw whose bound uniform buffer is smaller than its block; desktop GL reads only
// what the shader uses. The stages fill InvResolution with sizeof(vec2): padded here with zeros.
void t10WebBufferData(GLenum target, GLsizeiptr size, const void* data, GLenum usage) {
    constexpr GLsizeiptr kBlockAlignment = 16;
    if (target != GL_UNIFORM_BUFFER || size % kBlockAlignment == 0) {
        glBufferData(target, size, data, usage);
        return;
    }
    std::vector<std::uint8_t> padded(static_cast<std::size_t>((size / kBlockAlignment + 1) * kBlockAlignment), 0);
    if (data != nullptr) std::copy_n(static_cast<const std::uint8_t*>(data), static_cast<std::size_t>(size), padded.begin());
    glBufferData(target, static_cast<GLsizeiptr>(padded.size()), padded.data(), usage);
}

void t10WebDeleteTextures(GLsizei n, const GLuint* names) {
    for (GLsizei i = 0; i < n; ++i) textures().erase(names[i]);
    glDeleteTextures(n, names);
}

void glGetTexLevelParameteriv(GLenum target, GLint level, GLenum pname, GLint* params) {
    if (target != GL_TEXTURE_2D) unavailable("glGetTexLevelParameteriv on a target other than GL_TEXTURE_2D", "such query");
    const auto it = textures().find(boundTexture2D());
    const bool defined = it != textures().end() && level >= 0 && level < it->second.levels;
    switch (pname) {
    case GL_TEXTURE_WIDTH: *params = defined ? std::max(1, it->second.width >> level) : 0; return;
    case GL_TEXTURE_HEIGHT: *params = defined ? std::max(1, it->second.height >> level) : 0; return;
    case GL_TEXTURE_INTERNAL_FORMAT: *params = defined ? static_cast<GLint>(it->second.format) : GL_RGBA; return;
    default: unavailable("glGetTexLevelParameteriv(" + std::to_string(pname) + ")", "texture level queries");
    }
}

// glGetTexImage into memory, through a framebuffer and glReadPixels: float formats as RGBA floats,
// GL_R16 as RGBA unsigned shorts (EXT_texture_norm16), 8-bit formats as RGBA bytes.
void glGetTexImage(GLenum target, GLint level, GLenum format, GLenum type, void* pixels) {
    GLint pack = 0;
    glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &pack);
    if (target != GL_TEXTURE_2D || type != GL_FLOAT || pack != 0)
        unavailable("glGetTexImage (other than GL_TEXTURE_2D as floats into memory)", "glGetTexImage");
    const GLuint texture = boundTexture2D();
    const auto it = textures().find(texture);
    if (it == textures().end() || level >= it->second.levels) throw t10::Error("glGetTexImage: the texture level is undefined");
    const int width = std::max(1, it->second.width >> level);
    const int height = std::max(1, it->second.height >> level);
    const std::size_t count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    GLint previousRead = 0;
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &previousRead);
    GLuint fbo = 0;
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, level);
    std::vector<float> rgba(count * 4);
    const GLenum internal = it->second.format;
    if (internal == GL_R16 && !it->second.emulatedR16) {
        std::vector<std::uint16_t> raw(count * 4);
        glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_SHORT, raw.data());
        for (std::size_t i = 0; i < raw.size(); ++i) rgba[i] = static_cast<float>(raw[i]) / 65535.0f;
    } else if (internal == GL_RGBA8 || internal == GL_SRGB8_ALPHA8 || internal == GL_RGB8 || internal == GL_R8) {
        std::vector<std::uint8_t> raw(count * 4);
        glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, raw.data());
        for (std::size_t i = 0; i < raw.size(); ++i) rgba[i] = static_cast<float>(raw[i]) / 255.0f;
    } else {
        glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, rgba.data());
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(previousRead));
    glDeleteFramebuffers(1, &fbo);
    const int channels = format == GL_RED ? 1 : (format == GL_RGB ? 3 : 4);
    auto* out = static_cast<float*>(pixels);
    for (std::size_t i = 0; i < count; ++i)
        for (int c = 0; c < channels; ++c) out[i * static_cast<std::size_t>(channels) + static_cast<std::size_t>(c)] = rgba[i * 4 + static_cast<std::size_t>(c)];
}

// The views (--view, Module.t10Set("view", ...)) sample one level of a target through a texture view;
// WebGL 2 has none, so `view` becomes a copy of that level (the views are drawn after the frame, when
// the level no longer changes), blitted through two framebuffers.
void glTextureView(GLuint view, GLenum target, GLuint original, GLenum, GLuint minLevel, GLuint numLevels, GLuint,
                   GLuint) {
    const auto it = textures().find(original);
    if (target != GL_TEXTURE_2D || numLevels != 1 || it == textures().end() ||
        static_cast<int>(minLevel) >= it->second.levels)
        unavailable("glTextureView of anything but one defined level of a 2D texture", "texture views");
    TextureInfo info = it->second;
    const int width = std::max(1, info.width >> minLevel);
    const int height = std::max(1, info.height >> minLevel);
    const GLenum storage = info.emulatedR16 ? GL_R32F : info.format;
    const SavedState saved;
    // A level outside the original's base..max range cannot be attached (Part 3 leaves the bloom
    // texture at base level 1): the range is opened for the copy and put back.
    glBindTexture(GL_TEXTURE_2D, original);
    GLint base = 0;
    GLint max = 0;
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, &base);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, &max);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, static_cast<GLint>(minLevel));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, static_cast<GLint>(minLevel));
    glBindTexture(GL_TEXTURE_2D, view);
    glTexStorage2D(GL_TEXTURE_2D, 1, storage, width, height);
    GLuint fbos[2] = {};
    glGenFramebuffers(2, fbos);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbos[0]);
    glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, original, static_cast<GLint>(minLevel));
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbos[1]);
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, view, 0);
    glDisable(GL_SCISSOR_TEST);
    glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glDeleteFramebuffers(2, fbos);
    glBindTexture(GL_TEXTURE_2D, original);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, base);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, max);
    info.width = width;
    info.height = height;
    info.levels = 1;
    textures()[view] = info;
}
void glDebugMessageCallback(GLDEBUGPROC, const void*) {} // no debug output in WebGL 2: nothing to remove
void glDispatchCompute(GLuint, GLuint, GLuint) { unavailable("glDispatchCompute (--key exact)", "compute shaders"); }
void glMemoryBarrier(GLbitfield) { unavailable("glMemoryBarrier (--key exact)", "compute shaders"); }
void glGetQueryObjectiv(GLuint, GLenum, GLint*) { unavailable("GPU timer queries (--bench)", "GL_TIME_ELAPSED queries"); }
void glGetQueryObjectui64v(GLuint, GLenum, GLuint64*) { unavailable("GPU timer queries (--bench)", "GL_TIME_ELAPSED queries"); }
void glQueryCounter(GLuint, GLenum) { unavailable("GPU timer queries (--bench)", "GL_TIMESTAMP queries"); }

} // extern "C"
