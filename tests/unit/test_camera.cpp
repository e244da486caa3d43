// Camera maths without a GL context: view direction conventions (yaw 0 looks down -Z, positive yaw
// turns right), pitch and field-of-view clamping, camera-space movement, the projection's aspect,
// and the named presets.
#include "t10/camera.hpp"

#include "t10_catch.hpp"
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <set>
#include <string>

namespace {

// Float maths through sin/cos of degrees: a few ulps of error, far below anything visible.
constexpr double kEps = 1e-5;

t10::CameraPreset preset(glm::vec3 position, float yaw, float pitch, float fov) {
    return {"test", "a test camera", position, yaw, pitch, fov};
}

// Where a world point lands in view space.
glm::vec3 toView(const t10::Camera& camera, glm::vec3 world) {
    return glm::vec3(camera.view() * glm::vec4(world, 1.0f));
}

void requireVec(glm::vec3 actual, glm::vec3 expected) {
    CHECK(actual.x == Approx(expected.x).margin(kEps));
    CHECK(actual.y == Approx(expected.y).margin(kEps));
    CHECK(actual.z == Approx(expected.z).margin(kEps));
}

} // namespace

TEST_CASE("default camera looks down -Z with +X to the right", "[camera]") {
    const t10::Camera camera;
    requireVec(camera.forward(), {0, 0, -1});
    requireVec(camera.right(), {1, 0, 0});
    // A point straight ahead lies on the view-space -Z axis (OpenGL's right-handed eye space).
    const glm::vec3 eye = camera.position();
    requireVec(toView(camera, eye + glm::vec3(0, 0, -2)), {0, 0, -2});
    requireVec(toView(camera, eye + glm::vec3(1, 0, 0)), {1, 0, 0});
    requireVec(toView(camera, eye + glm::vec3(0, 1, 0)), {0, 1, 0});
}

TEST_CASE("yaw 90 looks down +X; yaw -90 down -X", "[camera]") {
    const t10::Camera right(preset({0, 0, 0}, 90.0f, 0.0f, 60.0f));
    requireVec(right.forward(), {1, 0, 0});
    requireVec(right.right(), {0, 0, 1});
    requireVec(toView(right, {3, 0, 0}), {0, 0, -3});

    const t10::Camera left(preset({0, 0, 0}, -90.0f, 0.0f, 60.0f));
    requireVec(left.forward(), {-1, 0, 0});
    requireVec(toView(left, {-3, 0, 0}), {0, 0, -3});
}

TEST_CASE("positive pitch looks up", "[camera]") {
    const t10::Camera camera(preset({0, 0, 0}, 0.0f, 30.0f, 60.0f));
    const glm::vec3 f = camera.forward();
    CHECK(f.y == Approx(0.5).margin(kEps));
    CHECK(f.z == Approx(-std::sqrt(3.0) / 2.0).margin(kEps));
    CHECK(glm::length(f) == Approx(1.0).margin(kEps));
}

TEST_CASE("mouse motion turns and tilts the camera", "[camera]") {
    t10::Camera camera;
    // Moving the mouse right turns right: 100 px at 0.1 degree per pixel is 10 degrees.
    camera.look(100.0f, 0.0f);
    CHECK(camera.forward().x == Approx(std::sin(glm::radians(10.0))).margin(kEps));
    CHECK(camera.forward().y == Approx(0.0).margin(kEps));
    // Moving the mouse up (window y decreases) looks up.
    camera.look(0.0f, -100.0f);
    CHECK(camera.forward().y == Approx(std::sin(glm::radians(10.0))).margin(kEps));
}

TEST_CASE("pitch is clamped short of straight up and down", "[camera]") {
    const double maxY = std::sin(glm::radians(static_cast<double>(t10::Camera::kMaxPitch)));
    t10::Camera camera;
    camera.look(0.0f, -1.0e6f);
    CHECK(camera.forward().y == Approx(maxY).margin(kEps));
    camera.look(0.0f, 2.0e6f);
    CHECK(camera.forward().y == Approx(-maxY).margin(kEps));
    // The view matrix stays finite at the clamp (lookAt would degenerate at exactly +-90).
    const glm::mat4 v = camera.view();
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) CHECK(std::isfinite(v[c][r]));

    const t10::Camera fromPreset(preset({0, 0, 0}, 0.0f, 120.0f, 60.0f));
    CHECK(fromPreset.forward().y == Approx(maxY).margin(kEps));
}

TEST_CASE("field of view stays within [kMinFov, kMaxFov]", "[camera]") {
    t10::Camera camera;
    const float start = camera.fovDegrees();
    camera.zoom(1.0f); // scrolling forward zooms in
    CHECK(camera.fovDegrees() < start);
    camera.zoom(1000.0f);
    CHECK(camera.fovDegrees() == Approx(t10::Camera::kMinFov));
    camera.zoom(-1000.0f);
    CHECK(camera.fovDegrees() == Approx(t10::Camera::kMaxFov));

    CHECK(t10::Camera(preset({0, 0, 0}, 0, 0, 5.0f)).fovDegrees() == Approx(t10::Camera::kMinFov));
    CHECK(t10::Camera(preset({0, 0, 0}, 0, 0, 170.0f)).fovDegrees() == Approx(t10::Camera::kMaxFov));
}

TEST_CASE("move() works in camera space", "[camera]") {
    SECTION("yaw 0: z forward is -Z, x right is +X, y up is +Y") {
        t10::Camera camera(preset({1, 2, 3}, 0.0f, 0.0f, 60.0f));
        camera.move({0, 0, 2});
        requireVec(camera.position(), {1, 2, 1});
        camera.move({0.5f, 0, 0});
        requireVec(camera.position(), {1.5f, 2, 1});
        camera.move({0, 1, 0});
        requireVec(camera.position(), {1.5f, 3, 1});
    }
    SECTION("yaw 90: forward is +X and right is +Z") {
        t10::Camera camera(preset({0, 0, 0}, 90.0f, 0.0f, 60.0f));
        camera.move({0, 0, 1});
        requireVec(camera.position(), {1, 0, 0});
        camera.move({1, 0, 0});
        requireVec(camera.position(), {1, 0, 1});
    }
    SECTION("pitched: forward follows the view direction") {
        t10::Camera camera(preset({0, 0, 0}, 0.0f, 30.0f, 60.0f));
        camera.move({0, 0, 2});
        requireVec(camera.position(), {0, 1, -static_cast<float>(std::sqrt(3.0))});
    }
}

TEST_CASE("projection uses the vertical field of view and the aspect ratio", "[camera]") {
    const t10::Camera camera(preset({0, 0, 0}, 0.0f, 0.0f, 60.0f));
    const float aspect = 16.0f / 9.0f;
    const glm::mat4 p = camera.projection(aspect);
    const double focal = 1.0 / std::tan(glm::radians(30.0));
    CHECK(p[1][1] == Approx(focal).epsilon(1e-6));
    CHECK(p[0][0] == Approx(focal / aspect).epsilon(1e-6));
    // Right-handed: a point in front (negative view z) has positive w; near and far map to -1 and 1.
    const glm::vec4 nearPoint = p * glm::vec4(0, 0, -t10::Camera::kNear, 1);
    const glm::vec4 farPoint = p * glm::vec4(0, 0, -t10::Camera::kFar, 1);
    CHECK(nearPoint.w > 0.0f);
    CHECK(nearPoint.z / nearPoint.w == Approx(-1.0).margin(1e-4));
    CHECK(farPoint.z / farPoint.w == Approx(1.0).margin(1e-4));
}

TEST_CASE("yawPitchOf inverts Camera::forward", "[camera]") {
    for (const float yaw : {0.0f, 37.0f, -120.0f, 179.0f}) {
        for (const float pitch : {0.0f, -6.0f, 45.0f, -80.0f}) {
            const t10::Camera camera(preset({0, 0, 0}, yaw, pitch, 60.0f));
            const glm::vec2 yp = t10::yawPitchOf(camera.forward());
            INFO("yaw " << yaw << " pitch " << pitch);
            CHECK(yp.x == Approx(yaw).margin(1e-3));
            CHECK(yp.y == Approx(pitch).margin(1e-3));
        }
    }
}
