// The Dear ImGui UI host and widgets; see imgui_host.hpp.
#include "t10/imgui_host.hpp"

#include "t10/error.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

namespace t10::ui {

namespace {

class ImGuiHost final : public UiHost {
public:
    explicit ImGuiHost(GLFWwindow* window) : window_(window) {
        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr; // nothing written into the working directory
        io.LogFilename = nullptr;
        ImGui::StyleColorsDark();
        ImGui::GetStyle().Alpha = 0.92f;
        // install_callbacks: ImGui's callbacks call the ones common/ set before (Esc, scroll) and
        // ImGui_ImplGlfw_Shutdown puts those back.
        if (!ImGui_ImplGlfw_InitForOpenGL(window, true)) {
            ImGui::DestroyContext();
            throw Error("Dear ImGui: the GLFW backend failed to start");
        }
        if (!ImGui_ImplOpenGL3_Init("#version 430 core")) {
            ImGui_ImplGlfw_Shutdown();
            ImGui::DestroyContext();
            throw Error("Dear ImGui: the OpenGL 3 backend failed to start");
        }
        // Sticky keys: a key pressed and released between two polls still reads as pressed once, so
        // a quick tap is not lost when a software-rendered frame takes 100 ms or more.
        previousStickyKeys_ = glfwGetInputMode(window, GLFW_STICKY_KEYS);
        glfwSetInputMode(window, GLFW_STICKY_KEYS, GLFW_TRUE);
    }

    ~ImGuiHost() override {
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
        glfwSetInputMode(window_, GLFW_STICKY_KEYS, previousStickyKeys_);
    }

    ImGuiHost(const ImGuiHost&) = delete;
    ImGuiHost& operator=(const ImGuiHost&) = delete;

    void beginFrame() override {
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
    }

    void endFrame() override {
        ImGui::Render();
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    }

    bool wantsKeyboard() const override { return ImGui::GetIO().WantTextInput; }

private:
    GLFWwindow* window_;
    int previousStickyKeys_ = 0;
};

void shortcutHint(const char* shortcut) {
    if (shortcut == nullptr || *shortcut == '\0') return;
    ImGui::SameLine();
    ImGui::TextDisabled("(%s)", shortcut);
}

} // namespace

std::unique_ptr<UiHost> makeImGuiHost(GLFWwindow* window) {
    if (window == nullptr) throw Error("Dear ImGui: no window to attach to");
    return std::make_unique<ImGuiHost>(window);
}

void beginPanel(const char* title) {
    // Bottom left, over the floor: the scene's lamps and window are in the upper half of every
    // preset's view, and a panel in the corner above would hide the red lamp of the default view.
    ImGui::SetNextWindowPos(ImVec2(8.0f, ImGui::GetIO().DisplaySize.y - 8.0f), ImGuiCond_FirstUseEver, ImVec2(0.0f, 1.0f));
    ImGui::Begin(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize);
}

void endPanel() { ImGui::End(); }

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

} // namespace t10::ui
