// First-person camera (WASD to move, mouse to look, scroll for field of view) and named presets
// that give reproducible frames for headless renders and golden images.
#pragma once
#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <vector>

namespace t10 {

struct CameraPreset {
    std::string name;
    std::string description;
    glm::vec3 position;
    float yawDegrees;   // 0 looks down -Z, positive turns right (towards +X)
    float pitchDegrees; // positive looks up
    float fovDegrees;   // vertical field of view
};

class Camera {
public:
    Camera() = default;
    explicit Camera(const CameraPreset& preset);

    glm::mat4 view() const;
    glm::mat4 projection(float aspect) const;
    glm::vec3 position() const { return position_; }
    glm::vec3 forward() const;
    glm::vec3 right() const;
    float fovDegrees() const { return fov_; }

    // Movement in camera space: x right, y up, z forward, already scaled by speed and time.
    void move(const glm::vec3& delta);
    // Mouse motion in pixels; pitch is clamped short of straight up/down.
    void look(float dxPixels, float dyPixels);
    // Scroll steps; field of view stays within [kMinFov, kMaxFov].
    void zoom(float steps);

    static constexpr float kMinFov = 20.0f;
    static constexpr float kMaxFov = 90.0f;
    static constexpr float kNear = 0.05f;
    static constexpr float kFar = 100.0f;
    static constexpr float kMouseDegreesPerPixel = 0.1f;
    static constexpr float kMaxPitch = 89.0f;

private:
    glm::vec3 position_{0.0f, 1.5f, 5.0f};
    float yaw_ = 0.0f;
    float pitch_ = 0.0f;
    float fov_ = 60.0f;
};

// All presets; the first is the default. At least one frames the lights and the POM surfaces.
const std::vector<CameraPreset>& cameraPresets();
std::optional<CameraPreset> findCameraPreset(const std::string& name);

} // namespace t10
