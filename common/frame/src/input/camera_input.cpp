// The window's camera controls; see camera_input.hpp.
#include "t10/camera_input.hpp"

// Input only: no GL header from GLFW, which in a unity build would come before glad's.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace t10 {

namespace {
constexpr float kMoveSpeed = 3.0f;      // metres per second
constexpr float kFastMultiplier = 4.0f; // with Shift held
} // namespace

CameraInput::CameraInput(GLFWwindow* window, Camera& camera) : window_(window), camera_(camera) {
    glfwSetWindowUserPointer(window_, this);
    glfwSetScrollCallback(window_, [](GLFWwindow* w, double, double dy) {
        static_cast<CameraInput*>(glfwGetWindowUserPointer(w))->camera_.zoom(static_cast<float>(dy));
    });
    glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int) {
        if (key == GLFW_KEY_ESCAPE && action == GLFW_PRESS) glfwSetWindowShouldClose(w, GLFW_TRUE);
    });
}

void CameraInput::update(double seconds) {
    glm::vec3 move(0.0f);
    if (glfwGetKey(window_, GLFW_KEY_W) == GLFW_PRESS) move.z += 1.0f;
    if (glfwGetKey(window_, GLFW_KEY_S) == GLFW_PRESS) move.z -= 1.0f;
    if (glfwGetKey(window_, GLFW_KEY_D) == GLFW_PRESS) move.x += 1.0f;
    if (glfwGetKey(window_, GLFW_KEY_A) == GLFW_PRESS) move.x -= 1.0f;
    if (glfwGetKey(window_, GLFW_KEY_E) == GLFW_PRESS) move.y += 1.0f;
    if (glfwGetKey(window_, GLFW_KEY_Q) == GLFW_PRESS) move.y -= 1.0f;
    float speed = kMoveSpeed * static_cast<float>(seconds);
    if (glfwGetKey(window_, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS) speed *= kFastMultiplier;
    if (move != glm::vec3(0.0f)) camera_.move(glm::normalize(move) * speed);

    // Mouse look while the right button is held, so the cursor stays free for the window otherwise.
    double x = 0.0;
    double y = 0.0;
    glfwGetCursorPos(window_, &x, &y);
    bool looking = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
#ifdef __EMSCRIPTEN__
    // A page: the left button (and a finger, which emscripten's GLFW reports as it) looks too.
    looking = looking || glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
#endif
    if (looking && lookActive_) camera_.look(static_cast<float>(x - lastCursorX_), static_cast<float>(y - lastCursorY_));
    lookActive_ = looking;
    lastCursorX_ = x;
    lastCursorY_ = y;
}

} // namespace t10
