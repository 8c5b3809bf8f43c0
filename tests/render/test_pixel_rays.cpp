// The viewing ray through a pixel (shaders/shared/view_march.h pixelRayDirection, run here as
// the CPU twin compiles it) and the projection the viewer picks and drags with
// (core/camera.h projectToImage) are inverses: a point on a pixel's ray projects to that pixel's
// centre, so a handle marker sits on the handle the picture shows.
#include <catch2/catch.hpp>

#include "core/camera.h"
#include "render/view_params.h"
#include "render/volume_kernels_cpu.h"

using namespace eikon;

TEST_CASE("a point on a pixel's viewing ray projects to the pixel's centre", "[camera][view]") {
    Scene scene;
    scene.render.width = 96;
    scene.render.height = 54;
    scene.camera.automatic = false;
    scene.camera.position = glm::vec3(1.5f, 2.0f, 4.0f);
    scene.camera.lookAt = glm::vec3(-0.2f, 0.1f, 0.3f);
    scene.camera.horizontalFovDeg = 50.0f;
    const RenderVolume volume{{glm::vec3(-1.0f), glm::vec3(1.0f)}, glm::ivec3(4)};
    const CameraFrame camera =
        makeCameraFrame(scene.camera, volume.bounds, scene.render.width, scene.render.height);
    const ViewSetup setup = makeViewSetup(scene, volume, camera);
    shared::ViewKernelCpu kernel{{setup.params}};  // the shared functions are not const
    for (const glm::ivec2 pixel :
         {glm::ivec2(0, 0), glm::ivec2(95, 53), glm::ivec2(17, 40), glm::ivec2(60, 3)})
        for (const float distance : {0.5f, 4.0f}) {
            const glm::vec3 p =
                camera.origin + distance * kernel.pixelRayDirection(pixel.x, pixel.y);
            const auto projected = projectToImage(camera, p, scene.render.width);
            REQUIRE(projected);
            INFO("pixel " << pixel.x << " " << pixel.y << ", distance " << distance);
            CHECK(projected->x == Approx(float(pixel.x) + 0.5f).margin(1e-3));
            CHECK(projected->y == Approx(float(pixel.y) + 0.5f).margin(1e-3));
        }
}
