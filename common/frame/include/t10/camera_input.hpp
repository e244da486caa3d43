// The window's camera controls, the same in every stage: WASD / Q / E move (Shift is faster), the
// right mouse button held looks around, the wheel zooms, Esc closes the window.
#pragma once
#include "t10/camera.hpp"

struct GLFWwindow;

namespace t10 {

class CameraInput {
public:
    // Installs the scroll and Esc callbacks on `window` (which must outlive this object).
    CameraInput(GLFWwindow* window, Camera& camera);
    CameraInput(const CameraInput&) = delete;
    CameraInput& operator=(const CameraInput&) = delete;

    // Moves and turns the camera for the keys and mouse state after `seconds` of frame time.
    void update(double seconds);

private:
    GLFWwindow* window_;
    Camera& camera_;
    bool lookActive_ = false;
    double lastCursorX_ = 0.0;
    double lastCursorY_ = 0.0;
};

} // namespace t10
