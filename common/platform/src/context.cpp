// Context creation for the backends: a GLFW window everywhere, EGL and OSMesa on Linux, a WGL pbuffer
// on Windows (context_wgl.cpp). Each makes a GL 4.3 core context current, gives it a default
// framebuffer of the requested size and loads the glad entry points through its own
// get-proc-address function.
#include "t10/context.hpp"

#include "context_detail.hpp"

#include "t10/contract.hpp"
#include "t10/error.hpp"
#include "t10/gl.hpp"

#include <GLFW/glfw3.h>
#ifdef T10_HAVE_EGL
#include <EGL/egl.h>
#include <EGL/eglext.h>
#endif
#ifdef T10_HAVE_X11
#include <X11/Xlib.h>
#endif
#ifdef T10_HAVE_OSMESA
#include <GL/osmesa.h>
#endif

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <vector>

namespace t10 {

namespace {

using detail::hasExtension;
using detail::kGlMajor;
using detail::kGlMinor;
using detail::loadGl;

// ---------------------------------------------------------------------------------------------
// GLFW window

#ifdef T10_HAVE_X11
// Xlib's default error handler ends the process ("BadDrawable") when another client destroys our
// window. This one only records that an X request failed; the window context then reports itself
// closed, and the run ends like any other. Xlib's handler takes no user pointer, hence the flag.
std::atomic<bool>& xRequestFailed() {
    static std::atomic<bool> failed{false};
    return failed;
}

int onXError(Display*, XErrorEvent*) {
    xRequestFailed() = true;
    return 0;
}

void guardX() { XSetErrorHandler(onXError); }
bool xFailed() { return xRequestFailed(); }
#else
// No X server here (Windows): a window closed from outside goes through GLFW's close flag.
void guardX() {}
bool xFailed() { return false; }
#endif

class WindowContext final : public Context {
public:
    explicit WindowContext(const ContextOptions& options) {
        glfwSetErrorCallback([](int code, const char* message) {
            std::cerr << "GLFW error " << code << ": " << message << "\n";
        });
        if (glfwInit() == GLFW_FALSE) throw Error("window: GLFW could not initialise (is there a display?)");
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, kGlMajor);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, kGlMinor);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
        glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, options.debug ? GLFW_TRUE : GLFW_FALSE);
        glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
        window_ = glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
        if (window_ == nullptr) {
            glfwTerminate();
            throw Error("window: could not create a window with an OpenGL 4.3 core context");
        }
        glfwSetWindowSizeLimits(window_, contract::kMinFramebufferSide, contract::kMinFramebufferSide, GLFW_DONT_CARE, GLFW_DONT_CARE);
        glfwMakeContextCurrent(window_);
        glfwSwapInterval(1);
        loadGl(glfwGetProcAddress, "window");
        guardX();
    }
    ~WindowContext() override {
        guardX();
        glfwDestroyWindow(window_);
        glfwTerminate();
    }
    Backend backend() const override { return Backend::Window; }
    std::string description() const override { return "GLFW window"; }
    bool isWindow() const override { return true; }
    GLFWwindow* window() const override { return window_; }
    // GLFW 3.3 puts Xlib's default handler back after some of its own calls: ours is installed
    // again before every call that talks to the X server.
    void swapBuffers() override {
        guardX();
        glfwSwapBuffers(window_);
    }
    void pollEvents() override {
        guardX();
        glfwPollEvents();
        guardX();
    }
    bool shouldClose() const override {
        if (xFailed() && !glfwWindowShouldClose(window_)) {
            std::cerr << "window: an X request failed (the window was destroyed from outside?); closing\n";
            glfwSetWindowShouldClose(window_, GLFW_TRUE);
        }
        return glfwWindowShouldClose(window_) == GLFW_TRUE;
    }
    void framebufferSize(int& width, int& height) const override {
        guardX();
        glfwGetFramebufferSize(window_, &width, &height);
        if (xFailed()) width = height = 0; // the window is gone: nothing to render into
    }
    void requestSize(int width, int height) override {
        guardX();
        if (width == 0 || height == 0) {
            glfwIconifyWindow(window_);
        } else {
            glfwRestoreWindow(window_);
            glfwSetWindowSize(window_, width, height);
        }
    }
    void setTitle(const std::string& title) override {
        guardX();
        glfwSetWindowTitle(window_, title.c_str());
    }

private:
    GLFWwindow* window_ = nullptr;
};

// ---------------------------------------------------------------------------------------------
// EGL: a pbuffer surface is the default framebuffer.

#ifdef T10_HAVE_EGL
class EglContext final : public Context {
public:
    explicit EglContext(const ContextOptions& options) : width_(options.width), height_(options.height) {
        const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
        auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
            eglGetProcAddress("eglGetPlatformDisplayEXT"));
        if (getPlatformDisplay == nullptr) throw Error("egl: eglGetPlatformDisplayEXT is not available");

        // A hardware device (e.g. NVIDIA's EGL device platform) is preferred; Mesa lists its
        // software rasteriser as a device too, which the surfaceless platform reaches anyway.
        if (hasExtension(clientExtensions, "EGL_EXT_platform_device")) {
            display_ = openHardwareDevice(getPlatformDisplay);
        }
        if (display_ == EGL_NO_DISPLAY && hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")) {
            display_ = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
            if (display_ != EGL_NO_DISPLAY && eglInitialize(display_, nullptr, nullptr) == EGL_TRUE) {
                platform_ = "EGL surfaceless (Mesa)";
            } else {
                display_ = EGL_NO_DISPLAY;
            }
        }
        if (display_ == EGL_NO_DISPLAY) {
            throw Error("egl: no EGL device or surfaceless platform could be initialised");
        }
        if (eglBindAPI(EGL_OPENGL_API) != EGL_TRUE) throw Error("egl: desktop OpenGL is not supported");

        const EGLint configAttributes[] = {
            EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
            EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8,
            EGL_DEPTH_SIZE, 24, EGL_NONE};
        EGLint count = 0;
        if (eglChooseConfig(display_, configAttributes, &config_, 1, &count) != EGL_TRUE || count < 1) {
            throw Error("egl: no RGBA8 pbuffer configuration with OpenGL support");
        }
        const EGLint contextAttributes[] = {
            EGL_CONTEXT_MAJOR_VERSION, kGlMajor, EGL_CONTEXT_MINOR_VERSION, kGlMinor,
            EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
            EGL_CONTEXT_OPENGL_DEBUG, options.debug ? EGL_TRUE : EGL_FALSE, EGL_NONE};
        context_ = eglCreateContext(display_, config_, EGL_NO_CONTEXT, contextAttributes);
        if (context_ == EGL_NO_CONTEXT) throw Error("egl: could not create an OpenGL 4.3 core context");
        createSurface(width_, height_);
        loadGl(eglGetProcAddress, "egl");
    }
    ~EglContext() override {
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (surface_ != EGL_NO_SURFACE) eglDestroySurface(display_, surface_);
        if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
        eglTerminate(display_);
    }
    Backend backend() const override { return Backend::Egl; }
    std::string description() const override { return platform_; }
    void framebufferSize(int& width, int& height) const override { width = width_; height = height_; }
    void requestSize(int width, int height) override {
        width_ = width;
        height_ = height;
        // A zero-sized pbuffer is not allowed; the app renders nothing at 0 x 0 anyway.
        if (width > 0 && height > 0) createSurface(width, height);
    }

private:
    EGLDisplay openHardwareDevice(PFNEGLGETPLATFORMDISPLAYEXTPROC getPlatformDisplay) {
        auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
        auto queryDeviceString = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(
            eglGetProcAddress("eglQueryDeviceStringEXT"));
        if (queryDevices == nullptr || queryDeviceString == nullptr) return EGL_NO_DISPLAY;
        EGLDeviceEXT devices[16];
        EGLint count = 0;
        if (queryDevices(16, devices, &count) != EGL_TRUE) return EGL_NO_DISPLAY;
        for (EGLint i = 0; i < count; ++i) {
            const char* extensions = queryDeviceString(devices[i], EGL_EXTENSIONS);
            if (hasExtension(extensions, "EGL_MESA_device_software")) continue;
            // Mesa also lists DRM render nodes; only take devices that are not Mesa's.
            if (hasExtension(extensions, "EGL_EXT_device_drm") && !hasExtension(extensions, "EGL_NV_device_cuda")) {
                continue;
            }
            EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
            if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr) == EGL_TRUE) {
                platform_ = "EGL device platform";
                return display;
            }
        }
        return EGL_NO_DISPLAY;
    }
    void createSurface(int width, int height) {
        const EGLint attributes[] = {EGL_WIDTH, width, EGL_HEIGHT, height, EGL_NONE};
        EGLSurface surface = eglCreatePbufferSurface(display_, config_, attributes);
        if (surface == EGL_NO_SURFACE) {
            throw Error("egl: could not create a " + std::to_string(width) + "x" + std::to_string(height) + " pbuffer");
        }
        if (eglMakeCurrent(display_, surface, surface, context_) != EGL_TRUE) {
            eglDestroySurface(display_, surface);
            throw Error("egl: could not make the context current");
        }
        if (surface_ != EGL_NO_SURFACE) eglDestroySurface(display_, surface_);
        surface_ = surface;
    }

    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLConfig config_ = nullptr;
    EGLContext context_ = EGL_NO_CONTEXT;
    EGLSurface surface_ = EGL_NO_SURFACE;
    std::string platform_;
    int width_;
    int height_;
};
#endif

// ---------------------------------------------------------------------------------------------
// OSMesa: the legacy software path, rendering into a buffer we own.

#ifdef T10_HAVE_OSMESA
class OsMesaContext final : public Context {
public:
    explicit OsMesaContext(const ContextOptions& options) : width_(options.width), height_(options.height) {
        const int attributes[] = {
            OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_STENCIL_BITS, 0, OSMESA_ACCUM_BITS, 0,
            OSMESA_PROFILE, OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, kGlMajor,
            OSMESA_CONTEXT_MINOR_VERSION, kGlMinor, 0};
        context_ = OSMesaCreateContextAttribs(attributes, nullptr);
        if (context_ == nullptr) throw Error("osmesa: could not create an OpenGL 4.3 core context");
        makeCurrent();
        loadGl(reinterpret_cast<GLADloadfunc>(OSMesaGetProcAddress), "osmesa");
    }
    ~OsMesaContext() override { OSMesaDestroyContext(context_); }
    Backend backend() const override { return Backend::OsMesa; }
    std::string description() const override { return "OSMesa"; }
    void framebufferSize(int& width, int& height) const override { width = width_; height = height_; }
    void requestSize(int width, int height) override {
        width_ = width;
        height_ = height;
        if (width > 0 && height > 0) makeCurrent();
    }

private:
    void makeCurrent() {
        buffer_.assign(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_) * 4, 0);
        if (OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_) == GL_FALSE) {
            throw Error("osmesa: could not make the context current");
        }
    }
    OSMesaContext context_ = nullptr;
    std::vector<unsigned char> buffer_;
    int width_;
    int height_;
};
#endif

} // namespace

bool Context::displayAvailable() {
#ifdef _WIN32
    return true; // a Windows session always has a desktop to open a window on
#else
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (x11 != nullptr && *x11 != '\0') || (wayland != nullptr && *wayland != '\0');
#endif
}

namespace {

// The headless backend of this platform: EGL (then OSMesa) on Linux, a WGL pbuffer on Windows.
std::unique_ptr<Context> createHeadless(const ContextOptions& options) {
#ifdef _WIN32
    return detail::createWglContext(options);
#else
    try {
        return std::make_unique<EglContext>(options);
    } catch (const Error& eglError) {
#ifdef T10_HAVE_OSMESA
        std::cerr << "warning: " << eglError.what() << "; falling back to OSMesa\n";
        return std::make_unique<OsMesaContext>(options);
#else
        throw;
#endif
    }
#endif
}

} // namespace

std::unique_ptr<Context> Context::create(const ContextOptions& options) {
    switch (options.backend) {
    case Backend::Window:
        if (!displayAvailable()) throw Error("window: no display (DISPLAY and WAYLAND_DISPLAY are unset); use --headless");
        return std::make_unique<WindowContext>(options);
    case Backend::Egl:
#ifdef T10_HAVE_EGL
        return std::make_unique<EglContext>(options);
#else
        throw Error("egl: EGL is Linux's headless backend; on Windows use --backend wgl (or --headless)");
#endif
    case Backend::OsMesa:
#ifdef T10_HAVE_OSMESA
        return std::make_unique<OsMesaContext>(options);
#elif defined(_WIN32)
        throw Error("osmesa: OSMesa is a Linux backend; on Windows use --backend wgl (or --headless)");
#else
        throw Error("osmesa: this build has no OSMesa support (libosmesa6-dev was not found at configure time)");
#endif
    case Backend::Wgl:
#ifdef _WIN32
        return detail::createWglContext(options);
#else
        throw Error("wgl: WGL is the Windows headless backend; here use --backend egl (or --headless)");
#endif
    case Backend::Auto:
        break;
    }
    if (!options.headless && displayAvailable()) {
        try {
            return std::make_unique<WindowContext>(options);
        } catch (const Error& error) {
            std::cerr << "warning: " << error.what() << "; rendering headless instead\n";
        }
    }
    return createHeadless(options);
}

} // namespace t10
