// Move-only RAII owners for OpenGL object names, so common/ never leaks or double-frees GL objects.
// Stage code keeps the tutorial's raw `GLuint g_ui...` handles; these are for common/ and tests.
#pragma once
#include "t10/gl.hpp"

#include <utility>

namespace t10 {

template <void (*Delete)(GLuint)>
class GlObject {
public:
    GlObject() = default;
    explicit GlObject(GLuint name) : name_(name) {}
    ~GlObject() { reset(); }
    GlObject(const GlObject&) = delete;
    GlObject& operator=(const GlObject&) = delete;
    GlObject(GlObject&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
    GlObject& operator=(GlObject&& other) noexcept {
        if (this != &other) {
            reset();
            name_ = std::exchange(other.name_, 0);
        }
        return *this;
    }
    GLuint get() const { return name_; }
    explicit operator bool() const { return name_ != 0; }
    // Gives up ownership: the caller deletes the name.
    GLuint release() { return std::exchange(name_, 0); }
    void reset(GLuint name = 0) {
        if (name_ != 0) Delete(name_);
        name_ = name;
    }

private:
    GLuint name_ = 0;
};

namespace detail {
inline void deleteTexture(GLuint n) { glDeleteTextures(1, &n); }
inline void deleteFramebuffer(GLuint n) { glDeleteFramebuffers(1, &n); }
inline void deleteRenderbuffer(GLuint n) { glDeleteRenderbuffers(1, &n); }
inline void deleteBuffer(GLuint n) { glDeleteBuffers(1, &n); }
inline void deleteVertexArray(GLuint n) { glDeleteVertexArrays(1, &n); }
inline void deleteProgram(GLuint n) { glDeleteProgram(n); }
inline void deleteShader(GLuint n) { glDeleteShader(n); }
inline void deleteQuery(GLuint n) { glDeleteQueries(1, &n); }
} // namespace detail

using Texture = GlObject<detail::deleteTexture>;
using Framebuffer = GlObject<detail::deleteFramebuffer>;
using Renderbuffer = GlObject<detail::deleteRenderbuffer>;
using Buffer = GlObject<detail::deleteBuffer>;
using VertexArray = GlObject<detail::deleteVertexArray>;
using Program = GlObject<detail::deleteProgram>;
using Shader = GlObject<detail::deleteShader>;
using Query = GlObject<detail::deleteQuery>;

inline Texture makeTexture() { GLuint n = 0; glGenTextures(1, &n); return Texture(n); }
inline Framebuffer makeFramebuffer() { GLuint n = 0; glGenFramebuffers(1, &n); return Framebuffer(n); }
inline Renderbuffer makeRenderbuffer() { GLuint n = 0; glGenRenderbuffers(1, &n); return Renderbuffer(n); }
inline Buffer makeBuffer() { GLuint n = 0; glGenBuffers(1, &n); return Buffer(n); }
inline VertexArray makeVertexArray() { GLuint n = 0; glGenVertexArrays(1, &n); return VertexArray(n); }

} // namespace t10
