// The ring of GL_TIME_ELAPSED query sets; see gpu_timers.hpp. The browser build compiles
// gpu_timers_web.cpp instead (common/CMakeLists.txt).
#include "t10/gpu_timers.hpp"

#include <algorithm>

namespace t10 {

void PassTimers::create() {
    if (created_) return;
    for (Frame& frame : frames_) {
        glGenQueries(kMaxQueries, frame.queries.data());
        frame.names.clear();
        frame.submitted = false;
    }
    current_ = -1;
    running_ = false;
    created_ = true;
}

void PassTimers::destroy() {
    if (!created_) return;
    if (running_) glEndQuery(GL_TIME_ELAPSED);
    for (Frame& frame : frames_) {
        glDeleteQueries(kMaxQueries, frame.queries.data());
        frame.queries.fill(0);
        frame.names.clear();
        frame.submitted = false;
    }
    running_ = false;
    current_ = -1;
    created_ = false;
}

void PassTimers::beginFrame() {
    if (!created_) return;
    current_ = (current_ + 1) % kFramesInFlight;
    Frame& frame = frames_[static_cast<std::size_t>(current_)];
    // The slot's previous frame must be read before its queries are reused (it is normally long
    // finished: kFramesInFlight frames ago).
    if (frame.submitted) readFrame(frame, true);
    frame.names.clear();
    frame.submitted = false;
}

void PassTimers::begin(const std::string& name) {
    if (!created_ || current_ < 0) return;
    Frame& frame = frames_[static_cast<std::size_t>(current_)];
    if (running_) glEndQuery(GL_TIME_ELAPSED);
    running_ = false;
    if (static_cast<int>(frame.names.size()) >= kMaxQueries) return;
    glBeginQuery(GL_TIME_ELAPSED, frame.queries[frame.names.size()]);
    frame.names.push_back(name);
    running_ = true;
}

void PassTimers::end() {
    if (!created_ || !running_) return;
    glEndQuery(GL_TIME_ELAPSED);
    running_ = false;
}

void PassTimers::endFrame() {
    if (!created_ || current_ < 0) return;
    end();
    Frame& frame = frames_[static_cast<std::size_t>(current_)];
    frame.submitted = !frame.names.empty();
    frame.serial = ++serial_;
}

bool PassTimers::readFrame(Frame& frame, bool wait) {
    if (!frame.submitted) return false;
    const GLuint lastQuery = frame.queries[frame.names.size() - 1];
    if (!wait) {
        GLint available = 0;
        glGetQueryObjectiv(lastQuery, GL_QUERY_RESULT_AVAILABLE, &available);
        if (available == 0) return false;
    }
    std::vector<PassTime> passes;
    for (std::size_t i = 0; i < frame.names.size(); ++i) {
        GLuint64 ns = 0;
        glGetQueryObjectui64v(frame.queries[i], GL_QUERY_RESULT, &ns);
        passes.push_back({frame.names[i], static_cast<double>(ns) * 1e-6});
    }
    frame.submitted = false;
    if (frame.serial > latestSerial_) {
        latestSerial_ = frame.serial;
        latest_ = std::move(passes);
        return true;
    }
    return false;
}

bool PassTimers::collect(bool wait) {
    if (!created_) return false;
    // Oldest first, so that latest() ends with the newest frame read.
    std::array<Frame*, kFramesInFlight> order{};
    for (int i = 0; i < kFramesInFlight; ++i) order[static_cast<std::size_t>(i)] = &frames_[static_cast<std::size_t>(i)];
    std::sort(order.begin(), order.end(), [](const Frame* a, const Frame* b) { return a->serial < b->serial; });
    bool changed = false;
    for (Frame* frame : order) changed = readFrame(*frame, wait) || changed;
    return changed;
}

} // namespace t10
