// The browser build's context (compiled instead of context.cpp and context_detail.cpp): a WebGL 2
// context on the page's canvas through emscripten's GLFW (its 3.2 API), standing for the window of
// the desktop build, so that the camera's keys and mouse work as there. The frame loop is the
// browser's (App::run in app_web.cpp); swapping is the browser's too.
#include "t10/context.hpp"

#include "t10/contract.hpp"
#include "t10/error.hpp"
#include "t10/gl.hpp"
#include "t10/gl_web.hpp"

#include <GLFW/glfw3.h>
#include <emscripten.h>
#include <emscripten/html5.h>

#include <iostream>
#include <string>

// The page says so too: document.body.dataset.t10R16 = "emulated".
EM_JS(void, markR16Emulated, (), { document.body.dataset.t10R16 = "emulated"; });

namespace t10 {

namespace {

class WebContext final : public Context {
public:
    explicit WebContext(const ContextOptions& options) : width_(options.width), height_(options.height) {
        if (glfwInit() == GLFW_FALSE) throw Error("web: GLFW could not initialise");
        glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
        glfwWindowHint(GLFW_DEPTH_BITS, 24);
        // An opaque canvas: the post-process writes colour only, and the page must not show through.
        glfwWindowHint(GLFW_ALPHA_BITS, 0);
        window_ = glfwCreateWindow(width_, height_, options.title.c_str(), nullptr, nullptr);
        if (window_ == nullptr) throw Error("this browser offers no WebGL 2 context (the stages need WebGL 2)");
        glfwMakeContextCurrent(window_);
        const EMSCRIPTEN_WEBGL_CONTEXT_HANDLE context = emscripten_webgl_get_current_context();
        // The HDR targets (GL_RGBA16F, GL_R11F_G11F_B10F, GL_R16F) must be renderable.
        if (!emscripten_webgl_enable_extension(context, "EXT_color_buffer_float"))
            throw Error("this browser's WebGL 2 has no EXT_color_buffer_float: the stages render into "
                        "floating-point targets (GL_RGBA16F), which it cannot");
        // GL_R16, the tutorial's luminance texture: EXT_texture_norm16, else emulated with GL_R32F,
        // which needs OES_texture_float_linear to be filtered (gl_web.cpp); else refused when used.
        const bool norm16 = emscripten_webgl_enable_extension(context, "EXT_texture_norm16") == EM_TRUE;
        const bool floatLinear = emscripten_webgl_enable_extension(context, "OES_texture_float_linear") == EM_TRUE;
        web::setTextureNorm16(norm16, floatLinear);
        if (!norm16 && floatLinear) {
            std::cout << "note: this browser's WebGL 2 has no EXT_texture_norm16: GL_R16 is emulated (GL_R32F, "
                         "clamped to [0, 1] and rounded to 16 bits before its mipmaps are made)\n";
            markR16Emulated();
        }
    }
    ~WebContext() override {
        glfwDestroyWindow(window_);
        glfwTerminate();
    }
    Backend backend() const override { return Backend::Window; }
    std::string description() const override { return "WebGL 2 (emscripten GLFW)"; }
    bool isWindow() const override { return true; }
    GLFWwindow* window() const override { return window_; }
    void framebufferSize(int& width, int& height) const override { glfwGetFramebufferSize(window_, &width, &height); }
    void requestSize(int width, int height) override {
        width_ = width;
        height_ = height;
        glfwSetWindowSize(window_, width, height);
    }
    void setTitle(const std::string& title) override { glfwSetWindowTitle(window_, title.c_str()); }

private:
    GLFWwindow* window_ = nullptr;
    int width_;
    int height_;
};

} // namespace

bool Context::displayAvailable() { return true; }

std::unique_ptr<Context> Context::create(const ContextOptions& options) {
    if (options.backend != Backend::Auto && options.backend != Backend::Window)
        throw UsageError("--backend: the web build has only the page's canvas (WebGL 2); leave --backend out");
    return std::make_unique<WebContext>(options);
}

} // namespace t10
