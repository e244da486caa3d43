// Collects GL errors: from the KHR_debug callback (installed in debug builds, T10_GL_DEBUG) and
// from glGetError (always). The frame loop fails the run when the log is not empty after a frame.
#pragma once
#include <string>
#include <vector>

namespace t10 {

class GlErrorLog {
public:
    GlErrorLog() = default;
    // Removes the callback again; the context must still be current.
    ~GlErrorLog();
    GlErrorLog(const GlErrorLog&) = delete; // the debug callback keeps a pointer to this object
    GlErrorLog& operator=(const GlErrorLog&) = delete;

    // Installs the KHR_debug callback on the current context (synchronous output, so the message
    // arrives inside the failing call). Errors and high-severity messages are recorded; other
    // messages except notifications are printed as warnings. Does nothing without T10_GL_DEBUG.
    void installDebugCallback();
    // Records every error glGetError reports until it returns GL_NO_ERROR.
    void pollGetError();

    bool empty() const { return errors_.empty(); }
    // "  <error>" lines, one per recorded error.
    std::string describe() const;
    void clear() { errors_.clear(); }
    void record(std::string error) { errors_.push_back(std::move(error)); }

private:
    std::vector<std::string> errors_;
    bool installed_ = false;
};

} // namespace t10
