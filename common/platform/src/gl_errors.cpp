// GL error collection: the KHR_debug callback and glGetError; see gl_errors.hpp.
#include "t10/gl_errors.hpp"

#include "t10/gl.hpp"

#include <cstdio>
#include <iostream>
#include <sstream>

namespace t10 {

namespace {

#ifdef T10_GL_DEBUG
void GLAPIENTRY debugCallback(GLenum, GLenum type, GLuint id, GLenum severity, GLsizei, const GLchar* message,
                              const void* user) {
    if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
    std::ostringstream text;
    text << "GL debug (id " << id << "): " << message;
    if (type == GL_DEBUG_TYPE_ERROR || severity == GL_DEBUG_SEVERITY_HIGH) {
        static_cast<GlErrorLog*>(const_cast<void*>(user))->record(text.str());
    } else {
        std::cerr << "warning: " << text.str() << "\n";
    }
}
#endif

} // namespace

GlErrorLog::~GlErrorLog() {
    if (installed_) glDebugMessageCallback(nullptr, nullptr);
}

void GlErrorLog::installDebugCallback() {
#ifdef T10_GL_DEBUG
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(debugCallback, this);
    installed_ = true;
#endif
}

void GlErrorLog::pollGetError() {
    for (GLenum error = glGetError(); error != GL_NO_ERROR; error = glGetError()) {
        char code[16];
        std::snprintf(code, sizeof code, "0x%04X", error);
        record(std::string("glGetError returned ") + code);
    }
}

std::string GlErrorLog::describe() const {
    std::string all;
    for (const auto& error : errors_) all += "\n  " + error;
    return all;
}

} // namespace t10
