// The headless debug context the GL unit tests run in: EGL (llvmpipe on CI), a WGL pbuffer on Windows;
// 8x8, KHR_debug on.
#pragma once
#include "t10/context.hpp"

#include <memory>

namespace t10::test {

inline std::unique_ptr<Context> makeTestContext() {
    ContextOptions options;
#ifdef _WIN32
    options.backend = Backend::Wgl;
#else
    options.backend = Backend::Egl;
#endif
    options.width = 8;
    options.height = 8;
    options.debug = true;
    return Context::create(options);
}

} // namespace t10::test
