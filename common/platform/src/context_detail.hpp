// What the backends' source files share inside t10_platform (not a public header): the GL version
// every context asks for, the glad loading step and the extension-list test; on Windows the WGL
// backend's factory (context_wgl.cpp). Context is only declared here, so that context.cpp and this
// unit do not include each other.
#pragma once
#include "t10/gl.hpp"

#include <memory>

namespace t10 {
class Context;
struct ContextOptions;
} // namespace t10

namespace t10::detail {

constexpr int kGlMajor = 4;
constexpr int kGlMinor = 3;

// Loads the GL 4.3 entry points through `loader`; throws t10::Error naming `backend` when it cannot.
void loadGl(GLADloadfunc loader, const char* backend);

// True when the space-separated extension `list` holds `name` exactly (not as a prefix of another).
bool hasExtension(const char* list, const char* name);

#ifdef _WIN32
// The headless context of Windows: a WGL_ARB_pbuffer surface of exactly the requested size with a
// 4.3 core context (WGL_ARB_create_context), or t10::Error saying what the driver lacks.
std::unique_ptr<Context> createWglContext(const ContextOptions& options);
#endif

} // namespace t10::detail
