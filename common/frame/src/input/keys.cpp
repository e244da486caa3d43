// Edge-triggered keys; see keys.hpp.
#include "t10/keys.hpp"

// Input only: no GL header from GLFW, which in a unity build would come before glad's.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace t10 {

bool KeyEdges::pressed(GLFWwindow* window, int key) {
    if (window == nullptr || key < 0 || key >= static_cast<int>(down_.size())) return false;
    const bool down = glfwGetKey(window, key) == GLFW_PRESS;
    const bool edge = down && !down_[static_cast<std::size_t>(key)];
    down_[static_cast<std::size_t>(key)] = down;
    return edge;
}

} // namespace t10
