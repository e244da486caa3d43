// The view selector's list in the extras panel (see views_panel.hpp).
#include "t10/views_panel.hpp"

#include "t10/views.hpp"

#include <imgui.h>

namespace t10::ui {

void viewList(ViewService& views) {
    for (int i = 0; i < kViewCount; ++i) {
        const View view = static_cast<View>(i);
        ImGui::BeginDisabled(!views.available(view));
        if (ImGui::RadioButton(viewName(view), views.current() == view)) views.select(view);
        ImGui::EndDisabled();
        if (i % 3 != 2 && i + 1 < kViewCount) ImGui::SameLine();
    }
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 28.0f);
    ImGui::TextDisabled("%s", views.caption().c_str());
    ImGui::PopTextWrapPos();
}

} // namespace t10::ui
