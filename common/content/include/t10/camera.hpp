// First-person camera (WASD to move, mouse to look, scroll for field of view) and the preset it
// starts from (a camera of the scene: see gltf_scene.hpp).
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
    float nearPlane = 0.05f; // clip distances in metres (a glTF camera's znear and zfar)
    float farPlane = 100.0f;
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
    float yawDegrees() const { return yaw_; }
    float pitchDegrees() const { return pitch_; }

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
    float near_ = kNear;
    float far_ = kFar;
};

// Yaw and pitch (degrees, as in CameraPreset) of a view direction; roll is not representable.
glm::vec2 yawPitchOf(const glm::vec3& forward);

} // namespace t10
