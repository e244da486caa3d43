// UI glue for extras/; see Panel.hpp.
#include "t10/panel.hpp"

#include "t10/error.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <sstream>

namespace t10::ui {

// --- Dear ImGui ------------------------------------------------------------------------------

namespace {

void shortcutHint(const char* shortcut) {
    if (shortcut == nullptr || *shortcut == '\0') return;
    ImGui::SameLine();
    ImGui::TextDisabled("(%s)", shortcut);
}
} // namespace

void ImGuiPanel::create(GLFWwindow* window) {
    if (window_ != nullptr || window == nullptr) return;
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr; // nothing written into the working directory
    io.LogFilename = nullptr;
    ImGui::StyleColorsDark();
    ImGui::GetStyle().Alpha = 0.92f;
    // install_callbacks: ImGui's callbacks call the ones common/ set before (Esc, scroll) and
    // ImGui_ImplGlfw_Shutdown puts those back.
    if (!ImGui_ImplGlfw_InitForOpenGL(window, true)) throw t10::Error("Dear ImGui: the GLFW backend failed to start");
    if (!ImGui_ImplOpenGL3_Init("#version 430 core")) {
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
        throw t10::Error("Dear ImGui: the OpenGL 3 backend failed to start");
    }
    // Sticky keys: a key pressed and released between two polls still reads as pressed once, so a
    // quick tap is not lost when a software-rendered frame takes 100 ms or more.
    previousStickyKeys_ = glfwGetInputMode(window, GLFW_STICKY_KEYS);
    glfwSetInputMode(window, GLFW_STICKY_KEYS, GLFW_TRUE);
    window_ = window;
}

void ImGuiPanel::destroy() {
    if (window_ == nullptr) return;
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwSetInputMode(window_, GLFW_STICKY_KEYS, previousStickyKeys_);
    window_ = nullptr;
}

void ImGuiPanel::begin(const char* title) {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    // Bottom left, over the floor: the scene's lamps and window are in the upper half of every
    // preset's view, and a panel in the corner above would hide the red lamp of the default view.
    ImGui::SetNextWindowPos(ImVec2(8.0f, ImGui::GetIO().DisplaySize.y - 8.0f), ImGuiCond_FirstUseEver, ImVec2(0.0f, 1.0f));
    ImGui::Begin(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize);
}

void ImGuiPanel::end() {
    ImGui::End();
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

bool ImGuiPanel::wantsKeyboard() const { return window_ != nullptr && ImGui::GetIO().WantTextInput; }

bool sliderFloat(const char* label, float* value, float lo, float hi, const char* shortcut, const char* format,
                 bool logarithmic) {
    ImGui::SetNextItemWidth(180.0f);
    const bool changed = ImGui::SliderFloat(label, value, lo, hi, format,
                                            ImGuiSliderFlags_AlwaysClamp |
                                                (logarithmic ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None));
    shortcutHint(shortcut);
    return changed;
}

bool sliderInt(const char* label, int* value, int lo, int hi, const char* shortcut) {
    ImGui::SetNextItemWidth(180.0f);
    const bool changed = ImGui::SliderInt(label, value, lo, hi, "%d", ImGuiSliderFlags_AlwaysClamp);
    shortcutHint(shortcut);
    return changed;
}

bool checkbox(const char* label, bool* value, const char* shortcut) {
    const bool changed = ImGui::Checkbox(label, value);
    shortcutHint(shortcut);
    return changed;
}

void heading(const char* text) {
    ImGui::Spacing();
    ImGui::TextColored(ImVec4(0.55f, 0.8f, 1.0f, 1.0f), "%s", text);
}

void warning(const std::string& text) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.3f, 1.0f));
    ImGui::TextWrapped("%s", text.c_str());
    ImGui::PopStyleColor();
}

// --- Keys --------------------------------------------------------------------------------------

bool KeyEdges::pressed(GLFWwindow* window, int key) {
    if (window == nullptr || key < 0 || key >= static_cast<int>(down_.size())) return false;
    const bool down = glfwGetKey(window, key) == GLFW_PRESS;
    const bool edge = down && !down_[static_cast<std::size_t>(key)];
    down_[static_cast<std::size_t>(key)] = down;
    return edge;
}

// --- Command line ------------------------------------------------------------------------------

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

CLI::Validator inRange(double lo, double hi, bool integer) {
    const std::string range = "from " + number(lo) + " to " + number(hi);
    return CLI::Validator(
        [lo, hi, integer, range](std::string& text) -> std::string {
            std::size_t used = 0;
            double value = 0.0;
            try {
                value = std::stod(text, &used);
            } catch (const std::exception&) {
                used = 0;
            }
            const bool isNumber = used > 0 && used == text.size();
            const bool isInteger = isNumber && text.find_first_not_of("+-0123456789") == std::string::npos;
            if (!isNumber || (integer && !isInteger)) {
                return "'" + text + "' is not " + (integer ? "a whole number" : "a number") + "; it must be " + range;
            }
            // Written this way round, NaN is rejected too.
            if (!(value >= lo && value <= hi)) return "must be " + range + " (got " + text + ")";
            return std::string();
        },
        range);
}

// --- GPU timing ---------------------------------------------------------------------------------

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

// --- Benchmark table ----------------------------------------------------------------------------

namespace {
struct Stats {
    double median = 0.0;
    double min = 0.0;
    double max = 0.0;
};

Stats stats(std::vector<double> samples) {
    Stats s;
    if (samples.empty()) return s;
    std::sort(samples.begin(), samples.end());
    const std::size_t n = samples.size();
    s.median = n % 2 == 1 ? samples[n / 2] : 0.5 * (samples[n / 2 - 1] + samples[n / 2]);
    s.min = samples.front();
    s.max = samples.back();
    return s;
}
} // namespace

void BenchTable::add(const std::vector<PassTime>& passes, double frameWallMs) {
    double post = 0.0;
    for (const PassTime& pass : passes) {
        auto row = std::find_if(passes_.begin(), passes_.end(), [&](const Row& r) { return r.name == pass.name; });
        if (row == passes_.end()) row = passes_.insert(passes_.end(), Row{pass.name, {}});
        row->samples.push_back(pass.ms);
        if (pass.name != "scene") post += pass.ms;
    }
    post_.push_back(post);
    frame_.push_back(frameWallMs);
}

std::vector<BenchTable::Row> BenchTable::rows() const {
    std::vector<Row> all = passes_;
    all.push_back(Row{"post-process", post_});
    all.push_back(Row{"frame", frame_});
    return all;
}

void BenchTable::print(std::ostream& out) const {
    const std::ios::fmtflags flags = out.flags();
    out << std::left << std::setw(14) << "pass" << std::right << std::setw(11) << "median ms" << std::setw(11) << "min ms"
        << std::setw(11) << "max ms" << "\n";
    out << std::fixed << std::setprecision(3);
    for (const Row& row : rows()) {
        const Stats s = stats(row.samples);
        if (row.name == "post-process") out << std::string(47, '-') << "\n";
        out << std::left << std::setw(14) << row.name << std::right << std::setw(11) << s.median << std::setw(11) << s.min
            << std::setw(11) << s.max << "\n";
    }
    out << "(GPU times from GL_TIME_ELAPSED queries; post-process = every pass but the scene, summed per frame;\n"
           " frame = wall clock of render + glFinish, including the key read-back)\n";
    out.flags(flags);
}

void BenchTable::writeCsv(const std::string& path) const {
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    std::error_code error;
    if (!parent.empty()) std::filesystem::create_directories(parent, error);
    std::ofstream file(path);
    if (!file) throw t10::Error(path + ": cannot write the benchmark CSV");
    file << "pass,median_ms,min_ms,max_ms,frames\n" << std::fixed << std::setprecision(4);
    for (const Row& row : rows()) {
        const Stats s = stats(row.samples);
        file << row.name << "," << s.median << "," << s.min << "," << s.max << "," << row.samples.size() << "\n";
    }
    if (!file) throw t10::Error(path + ": cannot write the benchmark CSV");
}

} // namespace t10::ui
