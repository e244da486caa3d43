// First-person camera maths (yaw/pitch angles, right-handed view and projection matrices) and the
// start from a scene camera (`--camera NAME`).
#include "t10/camera.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace t10 {

namespace {

// One scroll step changes the vertical field of view by this many degrees.
constexpr float kFovDegreesPerStep = 2.0f;
const glm::vec3 kWorldUp{0.0f, 1.0f, 0.0f};

float clampPitch(float degrees) {
    return std::clamp(degrees, -Camera::kMaxPitch, Camera::kMaxPitch);
}

float clampFov(float degrees) {
    return std::clamp(degrees, Camera::kMinFov, Camera::kMaxFov);
}

} // namespace

Camera::Camera(const CameraPreset& preset)
    : position_(preset.position),
      yaw_(preset.yawDegrees),
      pitch_(clampPitch(preset.pitchDegrees)),
      fov_(clampFov(preset.fovDegrees)),
      near_(preset.nearPlane),
      far_(preset.farPlane) {}

glm::vec3 Camera::forward() const {
    const float yaw = glm::radians(yaw_);
    const float pitch = glm::radians(pitch_);
    // yaw 0 gives -Z; yaw +90 gives +X (a turn to the right when +Y is up).
    return glm::vec3(std::sin(yaw) * std::cos(pitch), std::sin(pitch), -std::cos(yaw) * std::cos(pitch));
}

glm::vec3 Camera::right() const {
    // Independent of pitch, so it never degenerates; pitch stays short of +-90 anyway.
    const float yaw = glm::radians(yaw_);
    return glm::vec3(std::cos(yaw), 0.0f, std::sin(yaw));
}

glm::mat4 Camera::view() const {
    return glm::lookAt(position_, position_ + forward(), kWorldUp);
}

glm::mat4 Camera::projection(float aspect) const {
    return glm::perspective(glm::radians(fov_), aspect, near_, far_);
}

void Camera::move(const glm::vec3& delta) {
    const glm::vec3 f = forward();
    const glm::vec3 r = right();
    const glm::vec3 u = glm::cross(r, f); // the camera's own up, tilted with the pitch
    position_ += r * delta.x + u * delta.y + f * delta.z;
}

void Camera::look(float dxPixels, float dyPixels) {
    yaw_ += dxPixels * kMouseDegreesPerPixel;
    // Keep yaw in (-360, 360) so long sessions do not lose float precision.
    yaw_ = std::fmod(yaw_, 360.0f);
    // Window y grows downwards: moving the mouse up (negative dy) looks up.
    pitch_ = clampPitch(pitch_ - dyPixels * kMouseDegreesPerPixel);
}

void Camera::zoom(float steps) {
    // Scrolling forward (positive steps) narrows the view, i.e. zooms in.
    fov_ = clampFov(fov_ - steps * kFovDegreesPerStep);
}

glm::vec2 yawPitchOf(const glm::vec3& forward) {
    const glm::vec3 f = glm::normalize(forward);
    // The inverse of Camera::forward(): yaw from the horizontal part, pitch from the height.
    return {glm::degrees(std::atan2(f.x, -f.z)), glm::degrees(std::asin(std::clamp(f.y, -1.0f, 1.0f)))};
}

} // namespace t10
