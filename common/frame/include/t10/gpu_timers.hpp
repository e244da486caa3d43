// GPU time of each pass of a frame, from GL_TIME_ELAPSED queries that are read back a few frames
// later, so timing never stalls the pipeline. A stage that times its passes (extras/) owns one and
// names it in its Stage description; the frame loop opens and closes every frame and collects the
// results, the bench driver reports them.
#pragma once
#include "t10/gl.hpp"

#include <array>
#include <string>
#include <vector>

namespace t10 {

struct PassTime {
    std::string name;
    double ms = 0.0;
};

// A ring of GL_TIME_ELAPSED query sets, one set per frame in flight. Within a frame, begin(name)
// ends the pass that is running (GL allows one time-elapsed query at a time) and starts timing the
// next; end() ends the last one. collect() reads finished frames without stalling the GPU, or
// waits for the newest one (the benchmark).
class PassTimers {
public:
    void create();
    void destroy();
    void beginFrame();
    void begin(const std::string& name);
    void end();
    void endFrame();
    // Reads every submitted frame whose results are ready (all of them with `wait`); returns true
    // when latest() changed.
    bool collect(bool wait);
    // The passes of the newest frame read so far, in the order they ran.
    const std::vector<PassTime>& latest() const { return latest_; }

private:
    static constexpr int kFramesInFlight = 4;
    static constexpr int kMaxQueries = 32;
    struct Frame {
        std::array<GLuint, kMaxQueries> queries{};
        std::vector<std::string> names;
        bool submitted = false;
        long serial = 0;
    };
    bool readFrame(Frame& frame, bool wait);
    std::array<Frame, kFramesInFlight> frames_{};
    int current_ = -1;
    bool running_ = false;
    bool created_ = false;
    long serial_ = 0;
    long latestSerial_ = -1;
    std::vector<PassTime> latest_;
};

} // namespace t10
