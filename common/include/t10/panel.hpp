// UI glue for extras/ that is not itself an exercise step (library t10_panel, linked by extras only): Dear ImGui's set-up in the window,
// widgets that show their keyboard shortcut, edge-triggered keys, range checks for the command
// line, the pool of GL_TIME_ELAPSED queries that times each pass, and the benchmark's table and
// CSV. The exercises themselves (what the settings do, which widget and key change them) are in
// Tutorial10.cpp and the shaders.
#pragma once
#include "t10/gl.hpp"

#include <CLI/CLI.hpp>

#include <array>
#include <iosfwd>
#include <string>
#include <vector>

struct GLFWwindow;

namespace t10::ui {

// --- Dear ImGui, window mode only ------------------------------------------------------------
// The Dear ImGui panel of a window. create() makes the ImGui context and both backends (GLFW,
// OpenGL 3) for `window`; destroy() undoes it and is a no-op when nothing was created. The stage
// calls them from GL_Init / GL_Quit, so they pair up exactly: common/ turns a resize into GL_Quit +
// GL_Init, which rebuilds the panel's GL objects with the stage's, and the GLFW callbacks that
// common/ installed (Esc, scroll) are chained while the panel exists and restored when it goes.
// Whether the panel is shown lives in the stage's globals, so it survives the rebuild.
class ImGuiPanel {
public:
    ImGuiPanel() = default;
    ~ImGuiPanel() { destroy(); }
    ImGuiPanel(const ImGuiPanel&) = delete;
    ImGuiPanel& operator=(const ImGuiPanel&) = delete;

    void create(GLFWwindow* window);
    void destroy();
    bool active() const { return window_ != nullptr; }
    // Starts an ImGui frame and the panel window (top left, sized to its contents).
    void begin(const char* title);
    // Ends the panel window and draws it into the current framebuffer.
    void end();
    // True while a text field has the keyboard (shortcuts should then be ignored).
    bool wantsKeyboard() const;

private:
    GLFWwindow* window_ = nullptr;
    int previousStickyKeys_ = 0;
};

// Widgets that show their keyboard shortcut in grey after them.
bool sliderFloat(const char* label, float* value, float lo, float hi, const char* shortcut, const char* format,
                 bool logarithmic = false);
bool sliderInt(const char* label, int* value, int lo, int hi, const char* shortcut);
bool checkbox(const char* label, bool* value, const char* shortcut);
// A section heading ("Step 37: white point").
void heading(const char* text);
// A line of text in the warning colour.
void warning(const std::string& text);

// --- Keys --------------------------------------------------------------------------------------
// Edge-triggered keys: pressed() is true once per press, on the frame the key goes down.
class KeyEdges {
public:
    bool pressed(GLFWwindow* window, int key);

private:
    std::array<bool, 512> down_{};
};

// --- Command line ------------------------------------------------------------------------------
// A CLI11 check that accepts numbers from lo to hi (integers only with `integer`); anything else
// is rejected with the allowed range, e.g. "--white-point: must be from 0.05 to 2 (got 9)".
CLI::Validator inRange(double lo, double hi, bool integer = false);
// "0.05", "2", "2.95": numbers as a person writes them.
std::string number(double value);

// --- GPU timing ---------------------------------------------------------------------------------
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

// Collects the pass times of the benchmark's frames and reports the median of each.
class BenchTable {
public:
    // One frame: its passes (from PassTimers::latest()) and its wall-clock time.
    void add(const std::vector<PassTime>& passes, double frameWallMs);
    // Prints the table: one row per pass, then "post-process" (every pass but the scene, summed
    // per frame) and "frame" (wall clock, render + glFinish).
    void print(std::ostream& out) const;
    // The same rows as CSV: pass,median_ms,min_ms,max_ms,frames. Throws t10::Error on failure.
    void writeCsv(const std::string& path) const;

private:
    struct Row {
        std::string name;
        std::vector<double> samples;
    };
    std::vector<Row> rows() const;
    std::vector<Row> passes_;
    std::vector<double> post_;
    std::vector<double> frame_;
};

} // namespace t10::ui
