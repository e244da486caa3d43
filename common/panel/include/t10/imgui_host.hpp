// The Dear ImGui UI host and the widgets extras' panel is made of (library t10_panel, linked by
// extras only, so the other stages do not need Dear ImGui). What the settings do, and which widget
// and key change them, is in extras/Tutorial10.cpp.
#pragma once
#include "t10/ui_host.hpp"

#include <memory>
#include <string>

struct GLFWwindow;

namespace t10::ui {

// Dear ImGui with its GLFW and OpenGL 3 backends for one window, for as long as the window lives.
// Its callbacks chain to those common/ installed (Esc, scroll) and the destructor puts them back.
std::unique_ptr<UiHost> makeImGuiHost(GLFWwindow* window);

// A panel window (top left, sized to its contents) between beginPanel() and endPanel().
void beginPanel(const char* title);
void endPanel();
// Widgets that show their keyboard shortcut in grey after them.
bool sliderFloat(const char* label, float* value, float lo, float hi, const char* shortcut, const char* format,
                 bool logarithmic = false);
bool sliderInt(const char* label, int* value, int lo, int hi, const char* shortcut);
bool checkbox(const char* label, bool* value, const char* shortcut);
// A section heading ("Step 37: white point").
void heading(const char* text);
// A line of text in the warning colour.
void warning(const std::string& text);

} // namespace t10::ui
