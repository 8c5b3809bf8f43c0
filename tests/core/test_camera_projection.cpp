// Where world points show on the image, and the camera-plane drags the viewer builds on it
// (core/camera.h): the look-at point at the image's centre, the field of view's edges at the
// image's edges, and a drag of (dx, dy) pixels that moves the projected point by exactly that.
#include <catch2/catch.hpp>

#include <cmath>

#include <glm/geometric.hpp>

#include "core/camera.h"

using namespace eikon;

namespace {

// A camera off every axis, so that no component of the test hides in a zero.
CameraFrame obliqueCamera(int width, int height) {
    CameraSpec spec;
    spec.automatic = false;
    spec.position = glm::vec3(1.5f, 2.0f, 4.0f);
    spec.lookAt = glm::vec3(-0.2f, 0.1f, 0.3f);
    spec.horizontalFovDeg = 50.0f;
    return makeCameraFrame(spec, Bounds3{}, width, height);
}

constexpr float kPixelTolerance = 1e-3f;  // float rounding over a few units of distance

}  // namespace

TEST_CASE("a point projects where its viewing ray leaves the camera", "[camera]") {
    const int width = 160, height = 90;
    const CameraFrame camera = obliqueCamera(width, height);
    const auto centre = projectToImage(camera, glm::vec3(-0.2f, 0.1f, 0.3f), width);
    REQUIRE(centre);
    CHECK(centre->x == Approx(80.0f).margin(kPixelTolerance));
    CHECK(centre->y == Approx(45.0f).margin(kPixelTolerance));
    // On the edge of the horizontal field of view: the image's right edge; half the vertical
    // extent up: its top edge.
    const float depth = 3.0f;
    const glm::vec3 ahead = camera.origin + depth * camera.forward;
    const auto right =
        projectToImage(camera, ahead + depth * camera.tanHalfFovX * camera.right, width);
    REQUIRE(right);
    CHECK(right->x == Approx(float(width)).margin(kPixelTolerance));
    CHECK(right->y == Approx(45.0f).margin(kPixelTolerance));
    const auto top = projectToImage(
        camera, ahead + depth * camera.tanHalfFovX / camera.aspect * camera.up, width);
    REQUIRE(top);
    CHECK(top->x == Approx(80.0f).margin(kPixelTolerance));
    CHECK(top->y == Approx(0.0f).margin(kPixelTolerance));
    // Behind the camera, straight or off to the side: nowhere.
    CHECK_FALSE(projectToImage(camera, camera.origin - camera.forward, width));
    CHECK_FALSE(
        projectToImage(camera, camera.origin + camera.right - 0.01f * camera.forward, width));
}

TEST_CASE("a camera-plane drag moves the point's image by the drag and keeps its depth",
          "[camera]") {
    const int width = 160, height = 90;
    const CameraFrame camera = obliqueCamera(width, height);
    for (const glm::vec3 p : {glm::vec3(-0.2f, 0.1f, 0.3f), glm::vec3(0.4f, -0.5f, 1.2f),
                              glm::vec3(-1.0f, 0.8f, -2.0f)})
        for (const glm::vec2 drag :
             {glm::vec2(10.0f, 0.0f), glm::vec2(0.0f, -25.0f), glm::vec2(-7.5f, 13.25f)}) {
            const glm::vec3 motion = cameraPlaneMotion(camera, p, drag, width);
            CHECK(std::abs(glm::dot(motion, camera.forward)) < 1e-5f);
            const auto before = projectToImage(camera, p, width);
            const auto after = projectToImage(camera, p + motion, width);
            REQUIRE(before);
            REQUIRE(after);
            INFO("point " << p.x << " " << p.y << " " << p.z << ", drag " << drag.x << " "
                          << drag.y);
            CHECK(after->x - before->x == Approx(drag.x).margin(kPixelTolerance));
            CHECK(after->y - before->y == Approx(drag.y).margin(kPixelTolerance));
        }
    // A point behind the camera does not move.
    CHECK(cameraPlaneMotion(camera, camera.origin - camera.forward, glm::vec2(5.0f), width) ==
          glm::vec3(0.0f));
}
