// The GL state a new context starts with, restored between the runs of one process (--then): each
// run of a stage then starts as the first frame of a process of its own would, whatever the run
// before it left enabled, bound or set. Desktop GL 4.3 core only (the browser build has no --then).
#pragma once

namespace t10 {

// What a context's default framebuffer starts with; read once, right after the context is made.
struct GlDefaults {
    int drawBuffer = 0; // GL_DRAW_BUFFER of framebuffer 0
    int readBuffer = 0; // GL_READ_BUFFER of framebuffer 0
    // The stencil masks' "all ones", as this driver gives them back (Mesa: the stencil bits, 255).
    int stencilWriteMask = -1;
    int stencilValueMask = -1;
};

// Reads the defaults that depend on the context (call before anything draws).
GlDefaults readGlDefaults();

// Restores the rasterisation, fragment, pixel-store, binding and vertex-attribute state of the GL
// 4.3 core state tables to their initial values; the viewport and scissor box become 0, 0, width,
// height (what the first eglMakeCurrent gives a surface of that size). Objects are not deleted
// (GL_Quit and the frame loop's destructors do that), and GL_DEBUG_OUTPUT is the frame loop's.
void restoreGlDefaults(const GlDefaults& defaults, int width, int height);

} // namespace t10
