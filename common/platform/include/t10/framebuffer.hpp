// Framebuffer completeness check: an incomplete framebuffer stops the program with its name and
// the status, instead of rendering nothing silently.
#pragma once
#include "t10/gl.hpp"

#include <string>

namespace t10 {

// Throws t10::Error("<what>: framebuffer incomplete (GL_FRAMEBUFFER_...)") unless the framebuffer
// bound to `target` is complete.
void requireCompleteFramebuffer(GLenum target, const std::string& what);

} // namespace t10
