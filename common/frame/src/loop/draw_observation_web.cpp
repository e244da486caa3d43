// The capture hook's draw observation in the browser build (compiled instead of draw_observation.cpp,
// common/CMakeLists.txt): WebGL 2's calls go through no loader whose entry points could be swapped.
#include "t10/frame_observer.hpp"

#include "t10/error.hpp"

namespace t10 {

DrawObservation::DrawObservation(FrameObserver&) {
    throw Error("--capture-passes is not available in the web build (WebGL 2's calls cannot be observed)");
}
DrawObservation::~DrawObservation() = default;

} // namespace t10
