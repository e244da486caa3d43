// The view selector's list for a Dear ImGui panel (library t10_panel, linked by extras only).
#pragma once

namespace t10 {
class ViewService;
}

namespace t10::ui {

// One radio button per view; the views the stage lacks are greyed out. Shows the view's caption
// (its encoding and numbers) under the list.
void viewList(ViewService& views);

} // namespace t10::ui
