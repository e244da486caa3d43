// Edge-triggered keys for a stage's shortcuts: pressed() is true once per press, on the frame the
// key goes down.
#pragma once
#include <array>

struct GLFWwindow;

namespace t10 {

class KeyEdges {
public:
    bool pressed(GLFWwindow* window, int key);

private:
    std::array<bool, 512> down_{};
};

} // namespace t10
