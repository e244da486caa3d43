// PassTimers in the browser build (compiled instead of gpu_timers.cpp, common/CMakeLists.txt):
// WebGL 2 has no GL_TIME_ELAPSED queries in its core, so the passes are not timed (latest() stays
// empty; the page refuses --bench).
#include "t10/gpu_timers.hpp"

namespace t10 {

void PassTimers::create() {}
void PassTimers::destroy() {}
void PassTimers::beginFrame() {}
void PassTimers::begin(const std::string&) {}
void PassTimers::end() {}
void PassTimers::endFrame() {}
bool PassTimers::collect(bool) { return false; }

} // namespace t10
