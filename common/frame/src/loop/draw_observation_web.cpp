// The capture hook's draw observation in the browser build (compiled instead of draw_observation.cpp,
// common/CMakeLists.txt): WebGL 2's calls go through no loader whose entry points could be swapped, so
// the platform's GL layer calls a hook after each of its draws (gl_web.hpp setDrawHook) instead. The
// page's check (page_capture.hpp) captures Part 3's blur passes through it, as t10-grade's
// --capture-passes does on the desktop.
#include "t10/frame_observer.hpp"

#include "t10/error.hpp"
#include "t10/gl_web.hpp"

namespace t10 {

namespace {

void afterDraw(void* observer) { static_cast<FrameObserver*>(observer)->afterDraw(); }

} // namespace

DrawObservation::DrawObservation(FrameObserver& observer) {
    const auto previous = web::setDrawHook(&afterDraw, &observer);
    if (previous.first != nullptr) {
        web::setDrawHook(previous.first, previous.second);
        throw Error("a draw observation is already installed (one at a time)");
    }
}

DrawObservation::~DrawObservation() { web::setDrawHook(nullptr, nullptr); }

} // namespace t10
