// First-person camera maths (yaw/pitch angles, right-handed view and projection matrices) and the
// named presets that headless renders, golden images and `--camera NAME` use.
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
      fov_(clampFov(preset.fovDegrees)) {}

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
    return glm::perspective(glm::radians(fov_), aspect, kNear, kFar);
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

const std::vector<CameraPreset>& cameraPresets() {
    // The room spans x [-4.5, 4.5], y [0, 3.5], z [-8, 2]; see scene.cpp for the lights and boxes.
    static const std::vector<CameraPreset> presets{
        {"default", "Looks into the room: the window, the lamps, the brick walls, the tiled floor and the crates",
         {0.0f, 1.6f, 1.5f}, 0.0f, -6.0f, 60.0f},
        {"floor", "Low grazing view along the tiled floor, where parallax occlusion depth is most visible",
         {-3.2f, 0.35f, 0.8f}, 28.0f, -3.0f, 55.0f},
        {"lights", "Closer to the lamps: the white one, the warm one on the crate, the blue one and the window",
         {1.2f, 1.9f, -1.6f}, 4.0f, -3.0f, 60.0f},
        {"crates", "Three-quarter view of the crates, showing POM edges trimmed at the faces",
         {0.4f, 1.8f, -1.4f}, -12.0f, -19.0f, 55.0f},
        {"dark", "Turned away from the window and the lamps, towards the unlit end of the room: the exposure opens up",
         {0.5f, 1.6f, -3.0f}, 172.0f, -4.0f, 60.0f},
    };
    return presets;
}

std::optional<CameraPreset> findCameraPreset(const std::string& name) {
    const auto& presets = cameraPresets();
    const auto it = std::find_if(presets.begin(), presets.end(),
                                 [&](const CameraPreset& p) { return p.name == name; });
    if (it == presets.end()) return std::nullopt;
    return *it;
}

} // namespace t10
