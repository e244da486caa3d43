// The Windows headless backend: a WGL_ARB_pbuffer surface as the default framebuffer and a 4.3 core
// context from WGL_ARB_create_context. A hidden GLFW window is no substitute: Windows clamps a
// window to the screen, so a 3840x2160 frame on a smaller screen would come out smaller. A pbuffer
// has exactly the size asked for, or its creation fails and the run is refused with the reason.
//
// WGL's extensions are reached through a context, so a legacy context on a hidden helper window
// comes first; it only serves to look up the ARB functions and is deleted once the core context is
// current. The helper window (never shown) stays: the pbuffer was created from its device context.
#include "context_detail.hpp"

#include "t10/context.hpp"

#include "t10/error.hpp"

#include <windows.h>

#include <string>

namespace t10::detail {

namespace {

// From the WGL_ARB_pixel_format, WGL_ARB_pbuffer and WGL_ARB_create_context(_profile) specifications
// (Khronos' wglext.h is no MinGW or Windows SDK header).
constexpr int kDrawToPbuffer = 0x202D;
constexpr int kMaxPbufferWidth = 0x202F;
constexpr int kMaxPbufferHeight = 0x2030;
constexpr int kPbufferWidth = 0x2034;
constexpr int kPbufferHeight = 0x2035;
constexpr int kSupportOpenGl = 0x2010;
constexpr int kPixelType = 0x2013;
constexpr int kTypeRgba = 0x202B;
constexpr int kAcceleration = 0x2003;
constexpr int kRedBits = 0x2015;
constexpr int kGreenBits = 0x2017;
constexpr int kBlueBits = 0x2019;
constexpr int kDepthBits = 0x2022;
constexpr int kContextMajorVersion = 0x2091;
constexpr int kContextMinorVersion = 0x2092;
constexpr int kContextFlags = 0x2094;
constexpr int kContextProfileMask = 0x9126;
constexpr int kContextCoreProfileBit = 0x00000001;
constexpr int kContextDebugBit = 0x00000001;
constexpr int kContextForwardCompatibleBit = 0x00000002;

DECLARE_HANDLE(HPBUFFER);
using GetExtensionsStringArb = const char*(WINAPI*)(HDC);
using ChoosePixelFormatArb = BOOL(WINAPI*)(HDC, const int*, const FLOAT*, UINT, int*, UINT*);
using GetPixelFormatAttribivArb = BOOL(WINAPI*)(HDC, int, int, UINT, const int*, int*);
using CreatePbufferArb = HPBUFFER(WINAPI*)(HDC, int, int, int, const int*);
using GetPbufferDcArb = HDC(WINAPI*)(HPBUFFER);
using ReleasePbufferDcArb = int(WINAPI*)(HPBUFFER, HDC);
using DestroyPbufferArb = BOOL(WINAPI*)(HPBUFFER);
using QueryPbufferArb = BOOL(WINAPI*)(HPBUFFER, int, int*);
using CreateContextAttribsArb = HGLRC(WINAPI*)(HDC, HGLRC, const int*);

constexpr wchar_t kHelperClass[] = L"t10 WGL helper";

// wglGetProcAddress knows only extension and post-1.1 functions (and some drivers answer 1, 2, 3 or
// -1 for "none"); the GL 1.1 core is exported by opengl32.dll itself.
GLADapiproc getProcAddress(const char* name) {
    PROC proc = wglGetProcAddress(name);
    const auto value = reinterpret_cast<INT_PTR>(proc);
    if (value == 0 || value == 1 || value == 2 || value == 3 || value == -1) {
        static HMODULE openGl = LoadLibraryW(L"opengl32.dll");
        proc = openGl != nullptr ? GetProcAddress(openGl, name) : nullptr;
    }
    return reinterpret_cast<GLADapiproc>(proc);
}

template <typename Function>
Function lookUp(const char* name) {
    return reinterpret_cast<Function>(reinterpret_cast<void*>(wglGetProcAddress(name)));
}

std::string lastError() {
    return "Windows error " + std::to_string(GetLastError());
}

class WglContext final : public Context {
public:
    explicit WglContext(const ContextOptions& options) : width_(options.width), height_(options.height) {
        try {
            create(options.debug);
        } catch (...) {
            release();
            throw;
        }
    }
    ~WglContext() override { release(); }
    WglContext(const WglContext&) = delete;
    WglContext& operator=(const WglContext&) = delete;

    Backend backend() const override { return Backend::Wgl; }
    std::string description() const override { return "WGL pbuffer"; }
    void framebufferSize(int& width, int& height) const override { width = width_; height = height_; }
    void requestSize(int width, int height) override {
        width_ = width;
        height_ = height;
        // A zero-sized pbuffer is not allowed; the app renders nothing at 0 x 0 anyway.
        if (width <= 0 || height <= 0) return;
        wglMakeCurrent(nullptr, nullptr);
        destroyPbuffer();
        createPbuffer(width, height);
        if (wglMakeCurrent(pbufferDc_, context_) == FALSE) {
            throw Error("wgl: could not make the context current on the resized pbuffer (" + lastError() + ")");
        }
    }

private:
    void create(bool debug) {
        createHelperWindow();
        // The legacy context that gives access to the ARB functions.
        PIXELFORMATDESCRIPTOR descriptor{};
        descriptor.nSize = sizeof descriptor;
        descriptor.nVersion = 1;
        descriptor.dwFlags = PFD_DRAW_TO_WINDOW | PFD_SUPPORT_OPENGL | PFD_DOUBLEBUFFER;
        descriptor.iPixelType = PFD_TYPE_RGBA;
        descriptor.cColorBits = 24;
        descriptor.cDepthBits = 24;
        const int legacyFormat = ChoosePixelFormat(helperDc_, &descriptor);
        if (legacyFormat == 0 || SetPixelFormat(helperDc_, legacyFormat, &descriptor) == FALSE) {
            throw Error("wgl: no OpenGL pixel format for the helper window (" + lastError() + ")");
        }
        legacy_ = wglCreateContext(helperDc_);
        if (legacy_ == nullptr || wglMakeCurrent(helperDc_, legacy_) == FALSE) {
            throw Error("wgl: could not create a first OpenGL context (" + lastError() + "); is an OpenGL driver installed?");
        }
        lookUpExtensions();
        chooseFormat();
        createPbuffer(width_, height_);
        const int attributes[] = {
            kContextMajorVersion, kGlMajor, kContextMinorVersion, kGlMinor,
            kContextProfileMask, kContextCoreProfileBit,
            kContextFlags, kContextForwardCompatibleBit | (debug ? kContextDebugBit : 0), 0};
        context_ = createContextAttribs_(pbufferDc_, nullptr, attributes);
        if (context_ == nullptr) throw Error("wgl: could not create an OpenGL 4.3 core context (" + lastError() + ")");
        if (wglMakeCurrent(pbufferDc_, context_) == FALSE) {
            throw Error("wgl: could not make the context current on the pbuffer (" + lastError() + ")");
        }
        wglDeleteContext(legacy_);
        legacy_ = nullptr;
        loadGl(getProcAddress, "wgl");
    }

    // Everything create() made, in reverse order; safe on a half-made context.
    void release() {
        wglMakeCurrent(nullptr, nullptr);
        if (context_ != nullptr) wglDeleteContext(context_);
        if (legacy_ != nullptr) wglDeleteContext(legacy_);
        context_ = legacy_ = nullptr;
        destroyPbuffer();
        if (helperDc_ != nullptr) ReleaseDC(helper_, helperDc_);
        if (helper_ != nullptr) DestroyWindow(helper_);
        helperDc_ = nullptr;
        helper_ = nullptr;
    }

    void createHelperWindow() {
        HINSTANCE instance = GetModuleHandleW(nullptr);
        WNDCLASSW windowClass{};
        windowClass.style = CS_OWNDC;
        windowClass.lpfnWndProc = DefWindowProcW;
        windowClass.hInstance = instance;
        windowClass.lpszClassName = kHelperClass;
        // A second context in the same process finds the class registered already.
        if (RegisterClassW(&windowClass) == 0 && GetLastError() != ERROR_CLASS_ALREADY_EXISTS) {
            throw Error("wgl: could not register the helper window class (" + lastError() + ")");
        }
        helper_ = CreateWindowExW(0, kHelperClass, L"t10", WS_OVERLAPPEDWINDOW, 0, 0, 16, 16, nullptr, nullptr, instance, nullptr);
        if (helper_ == nullptr) throw Error("wgl: could not create the hidden helper window (" + lastError() + ")");
        helperDc_ = GetDC(helper_);
        if (helperDc_ == nullptr) throw Error("wgl: the helper window has no device context (" + lastError() + ")");
    }

    void lookUpExtensions() {
        auto getExtensions = lookUp<GetExtensionsStringArb>("wglGetExtensionsStringARB");
        const char* extensions = getExtensions != nullptr ? getExtensions(helperDc_) : nullptr;
        for (const char* needed : {"WGL_ARB_pixel_format", "WGL_ARB_pbuffer", "WGL_ARB_create_context",
                                   "WGL_ARB_create_context_profile"}) {
            if (!hasExtension(extensions, needed)) {
                throw Error(std::string("wgl: the OpenGL driver lacks ") + needed +
                            ", which headless rendering needs (update the graphics driver)");
            }
        }
        choosePixelFormat_ = lookUp<ChoosePixelFormatArb>("wglChoosePixelFormatARB");
        getPixelFormatAttribiv_ = lookUp<GetPixelFormatAttribivArb>("wglGetPixelFormatAttribivARB");
        createPbuffer_ = lookUp<CreatePbufferArb>("wglCreatePbufferARB");
        getPbufferDc_ = lookUp<GetPbufferDcArb>("wglGetPbufferDCARB");
        releasePbufferDc_ = lookUp<ReleasePbufferDcArb>("wglReleasePbufferDCARB");
        destroyPbuffer_ = lookUp<DestroyPbufferArb>("wglDestroyPbufferARB");
        queryPbuffer_ = lookUp<QueryPbufferArb>("wglQueryPbufferARB");
        createContextAttribs_ = lookUp<CreateContextAttribsArb>("wglCreateContextAttribsARB");
        if (choosePixelFormat_ == nullptr || getPixelFormatAttribiv_ == nullptr || createPbuffer_ == nullptr ||
            getPbufferDc_ == nullptr || releasePbufferDc_ == nullptr || destroyPbuffer_ == nullptr ||
            queryPbuffer_ == nullptr || createContextAttribs_ == nullptr) {
            throw Error("wgl: the driver lists the pbuffer extensions but not all of their functions");
        }
    }

    // RGB8 without alpha: no frame needs it, and under Wine with Xvfb an alpha channel selects a 32-bit
    // visual whose drawing fails (X BadMatch).
    void chooseFormat() {
        const int attributes[] = {
            kDrawToPbuffer, TRUE, kSupportOpenGl, TRUE, kPixelType, kTypeRgba,
            kRedBits, 8, kGreenBits, 8, kBlueBits, 8, kDepthBits, 24, 0};
        UINT count = 0;
        if (choosePixelFormat_(helperDc_, attributes, nullptr, 1, &format_, &count) == FALSE || count == 0) {
            throw Error("wgl: no RGB8 pixel format with a 24-bit depth buffer for a pbuffer");
        }
        const int limits[] = {kMaxPbufferWidth, kMaxPbufferHeight};
        int values[2] = {0, 0};
        if (getPixelFormatAttribiv_(helperDc_, format_, 0, 2, limits, values) == TRUE) {
            maxWidth_ = values[0];
            maxHeight_ = values[1];
        }
    }

    // Exactly width x height: larger than the driver allows is refused by name, and a pbuffer that
    // came out another size (WGL_PBUFFER_LARGEST_ARB is not asked for, so it should not) too.
    void createPbuffer(int width, int height) {
        const std::string size = std::to_string(width) + "x" + std::to_string(height);
        if ((maxWidth_ > 0 && width > maxWidth_) || (maxHeight_ > 0 && height > maxHeight_)) {
            throw Error("wgl: a " + size + " pbuffer is larger than the driver allows (" + std::to_string(maxWidth_) +
                        "x" + std::to_string(maxHeight_) + ")");
        }
        const int attributes[] = {0};
        pbuffer_ = createPbuffer_(helperDc_, format_, width, height, attributes);
        if (pbuffer_ == nullptr) throw Error("wgl: could not create a " + size + " pbuffer (" + lastError() + ")");
        pbufferDc_ = getPbufferDc_(pbuffer_);
        if (pbufferDc_ == nullptr) {
            destroyPbuffer();
            throw Error("wgl: the " + size + " pbuffer has no device context (" + lastError() + ")");
        }
        int gotWidth = 0;
        int gotHeight = 0;
        queryPbuffer_(pbuffer_, kPbufferWidth, &gotWidth);
        queryPbuffer_(pbuffer_, kPbufferHeight, &gotHeight);
        if (gotWidth != width || gotHeight != height) {
            destroyPbuffer();
            throw Error("wgl: asked for a " + size + " pbuffer, the driver made it " + std::to_string(gotWidth) + "x" +
                        std::to_string(gotHeight) + "; refusing to render another size");
        }
    }

    void destroyPbuffer() {
        if (pbufferDc_ != nullptr) releasePbufferDc_(pbuffer_, pbufferDc_);
        if (pbuffer_ != nullptr) destroyPbuffer_(pbuffer_);
        pbufferDc_ = nullptr;
        pbuffer_ = nullptr;
    }

    HWND helper_ = nullptr;
    HDC helperDc_ = nullptr;
    int format_ = 0;
    int maxWidth_ = 0;
    int maxHeight_ = 0;
    HPBUFFER pbuffer_ = nullptr;
    HDC pbufferDc_ = nullptr;
    HGLRC legacy_ = nullptr;
    HGLRC context_ = nullptr;
    int width_;
    int height_;
    ChoosePixelFormatArb choosePixelFormat_ = nullptr;
    GetPixelFormatAttribivArb getPixelFormatAttribiv_ = nullptr;
    CreatePbufferArb createPbuffer_ = nullptr;
    GetPbufferDcArb getPbufferDc_ = nullptr;
    ReleasePbufferDcArb releasePbufferDc_ = nullptr;
    DestroyPbufferArb destroyPbuffer_ = nullptr;
    QueryPbufferArb queryPbuffer_ = nullptr;
    CreateContextAttribsArb createContextAttribs_ = nullptr;
};

} // namespace

std::unique_ptr<Context> createWglContext(const ContextOptions& options) {
    return std::make_unique<WglContext>(options);
}

} // namespace t10::detail
