// The capture hook's draw observation on the desktop (frame_observer.hpp): the glad loader's two draw
// entry points are swapped for wrappers while a DrawObservation is alive. The browser build compiles
// draw_observation_web.cpp instead (common/CMakeLists.txt).
#include "t10/frame_observer.hpp"

#include "t10/error.hpp"
#include "t10/gl.hpp"

namespace t10 {

namespace {

// The loader's entry points while a DrawObservation is alive, and whom to tell. GL entry points are
// plain function pointers that carry no context, so this is the one per-process slot they can reach.
struct ObservedDraws {
    FrameObserver* observer = nullptr;
    PFNGLDRAWELEMENTSPROC drawElements = nullptr;
    PFNGLDRAWARRAYSPROC drawArrays = nullptr;
};

ObservedDraws& observedDraws() {
    static ObservedDraws slot;
    return slot;
}

void GLAD_API_PTR observedDrawElements(GLenum mode, GLsizei count, GLenum type, const void* indices) {
    ObservedDraws& slot = observedDraws();
    slot.drawElements(mode, count, type, indices);
    slot.observer->afterDraw();
}

void GLAD_API_PTR observedDrawArrays(GLenum mode, GLint first, GLsizei count) {
    ObservedDraws& slot = observedDraws();
    slot.drawArrays(mode, first, count);
    slot.observer->afterDraw();
}

} // namespace

DrawObservation::DrawObservation(FrameObserver& observer) {
    ObservedDraws& slot = observedDraws();
    if (slot.observer != nullptr) throw Error("a draw observation is already installed (one at a time)");
    slot.observer = &observer;
    slot.drawElements = glad_glDrawElements;
    slot.drawArrays = glad_glDrawArrays;
    glad_glDrawElements = &observedDrawElements;
    glad_glDrawArrays = &observedDrawArrays;
}

DrawObservation::~DrawObservation() {
    ObservedDraws& slot = observedDraws();
    glad_glDrawElements = slot.drawElements;
    glad_glDrawArrays = slot.drawArrays;
    slot = ObservedDraws{};
}

} // namespace t10
