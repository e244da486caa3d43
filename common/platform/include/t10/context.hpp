// The OpenGL 4.3 core context a stage renders with: a GLFW window, or headless through EGL
// (Mesa's surfaceless platform, or the EGL device platform for a hardware GPU) or OSMesa on Linux,
// through a WGL pbuffer on Windows. Headless contexts render into an off-screen default framebuffer
// (an EGL or WGL pbuffer, an OSMesa buffer) of exactly the requested size, so stage code draws to
// framebuffer 0 the same way in every mode.
#pragma once
#include <memory>
#include <string>

struct GLFWwindow;

namespace t10 {

enum class Backend { Auto, Window, Egl, OsMesa, Wgl };

struct ContextOptions {
    Backend backend = Backend::Auto;
    bool headless = false;   // with Backend::Auto: skip the window even if there is a display
    int width = 1280;
    int height = 720;
    bool sizeGiven = false;  // --size was given (an --input image must then have that size)
    std::string title;
    bool debug = false;      // request a debug context (KHR_debug output)
};

class Context {
public:
    virtual ~Context() = default;

    // Creates the context, makes it current and loads the GL entry points. Throws t10::Error
    // naming the backend and the reason when it cannot.
    static std::unique_ptr<Context> create(const ContextOptions& options);
    // True when a window can be opened here (an X11 or Wayland display is set; always on Windows).
    static bool displayAvailable();

    virtual Backend backend() const = 0;
    // A short description of the platform, e.g. "EGL surfaceless (Mesa)".
    virtual std::string description() const = 0;
    virtual bool isWindow() const { return false; }
    virtual GLFWwindow* window() const { return nullptr; }
    virtual void swapBuffers() {}
    virtual void pollEvents() {}
    virtual bool shouldClose() const { return false; }
    // Current default-framebuffer size in pixels (0 x 0 while a window is minimised).
    virtual void framebufferSize(int& width, int& height) const = 0;
    // Requests a new size: a window is resized, a headless surface is recreated at once.
    virtual void requestSize(int width, int height) = 0;
    virtual void setTitle(const std::string&) {}
};

} // namespace t10
