// The UI host a stage's panel draws with (window mode only). The frame loop creates it once per
// window through Stage::makeUi, so it survives resizes and rebuilds of the stage, and brackets the
// stage's panel with beginFrame() / endFrame() over the finished frame. common/ knows only this
// interface; the Dear ImGui host is in t10_panel (imgui_host.hpp), which only extras links.
#pragma once

namespace t10 {

class UiHost {
public:
    virtual ~UiHost() = default;
    // Starts a UI frame (input, display size).
    virtual void beginFrame() = 0;
    // Draws what the panel added into the current framebuffer.
    virtual void endFrame() = 0;
    // True while a text field has the keyboard (the stage's shortcuts are then not called).
    virtual bool wantsKeyboard() const = 0;
};

} // namespace t10
