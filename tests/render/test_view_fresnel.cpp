// Fresnel reflection toward the camera where curved view rays cross a sharp surface
// (shaders/shared/view_march.h traceCurvedRayReflecting, fresnel.h), against closed forms. The
// environment is a sky of one colour (blue) over a ground of another (red), so that each pixel's
// two channels say how much of the ray went up and how much went down. Through a slab of n = 1.5,
// with R the exact unpolarized reflectance at the ray's angle and T = 1 − R: the ray goes through
// both faces to the ground (T²); its reflection off the top face goes up to the sky (R); its
// reflection off the inside of the bottom face, traced, goes up through the top face to the sky
// (T·R·T) and reflects there once more, seeing the ground (T·R·R, the environment in its mirror
// direction: kept reflections are not followed further). From inside glass, past the critical
// angle the ray turns back whole (total internal reflection) and below it the ground shows with R.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/gtc/constants.hpp>

#include "core/camera.h"
#include "render/refraction_volume.h"
#include "render/view_params.h"
#include "render/volume_kernels_cpu.h"

#include "support/fresnel_exact.h"

using namespace eikon;
using eikon::test::fresnelExact;

namespace {

// A flat box, wide along x so that rays at 80° from the vertical enter through its top and
// leave through its bottom: x in [-5, 5], y in [-1, 1], z in [-0.125, 0.125], cubic voxels.
constexpr float kVoxel = 2.0f / 32;
const RenderVolume kBox{{glm::vec3(-5.0f, -1.0f, -0.125f), glm::vec3(5.0f, 1.0f, 0.125f)},
                        glm::ivec3(160, 32, 4)};
const glm::vec3 kSky(0.0f, 0.0f, 1.0f);
const glm::vec3 kGround(1.0f, 0.0f, 0.0f);

// How the glass field rises from 0 to 1 across its face, over `width` scene units centred on it.
enum class Rim { Linear, Smooth };

float rimProfile(Rim rim, float t) {  // t: signed distance into the glass over the rim's width
    const float u = std::clamp(t + 0.5f, 0.0f, 1.0f);
    return rim == Rim::Linear ? u : u * u * (3.0f - 2.0f * u);
}

// Glass (n = 1.5) between y = bottom and y = top, across the whole box, under the
// sky-and-ground environment; `fresnel` is the material's flag, `viewFresnel` the render's.
struct GlassView {
    Scene scene;
    DenseGrid field;
    ViewSetup setup;
    std::vector<glm::vec4> gradient;

    GlassView(float top, float bottom, Rim rim, float rimVoxels, bool fresnel = true,
              bool viewFresnel = true) {
        MaterialSpec glass;
        glass.name = "glass";
        glass.ior = 1.5f;
        glass.fresnel = fresnel;
        scene.materials.push_back(glass);
        scene.render.fresnel = viewFresnel;
        scene.render.width = scene.render.height = 4;
        scene.environment.type = EnvironmentType::Gradient;
        scene.environment.zenith = scene.environment.horizon = kSky;
        scene.environment.ground = kGround;
        field.field = "density";
        field.version = 1;
        field.volume = kBox;
        field.values.resize(field.volume.voxelCount());
        const float width = rimVoxels * kVoxel;
        for (int k = 0; k < kBox.resolution.z; ++k)
            for (int j = 0; j < kBox.resolution.y; ++j)
                for (int i = 0; i < kBox.resolution.x; ++i) {
                    const float y = field.volume.voxelCenter(i, j, k).y;
                    field.values[field.index(i, j, k)] =
                        rimProfile(rim, std::min(top - y, y - bottom) / width);
                }
        setup = makeViewSetup(scene, field.volume,
                              makeCameraFrame(scene.camera, field.volume.bounds, 4, 4));
        gradient = computeIndexGradientCpu(setup, {&field});
    }

    // The radiance of a view ray from `origin` along unit `dir`, traced by the shared code.
    glm::vec3 radiance(glm::vec3 origin, glm::vec3 dir, glm::vec3& transmittance) const {
        shared::ViewKernelCpu k{{setup.params}};
        k.fields[0] = field.values.data();
        k.gradient = gradient.data();
        return k.integrateViewRay(origin, dir, transmittance);
    }
};

// A ray in the xy plane through the origin, going down at `degrees` from the vertical.
glm::vec3 downAt(double degrees) {
    const float a = float(glm::radians(degrees));
    return {std::sin(a), -std::cos(a), 0.0f};
}

}  // namespace

TEST_CASE(
    "view rays through a glass slab see the sky by Fresnel reflection and the ground by "
    "(1 - R)^2, to the second reflection",
    "[view][fresnel]") {
    // Measured: worst |error| 3.5e-7 (linear 2-voxel rim) and 3.1e-7 (smooth 5-voxel rim) over
    // 0°-80°, the angle read from the ray's momentum on the sampled path.
    constexpr double kTolerance = 1e-5;
    for (auto [rim, rimVoxels] : {std::pair{Rim::Linear, 2.0f}, std::pair{Rim::Smooth, 5.0f}}) {
        const GlassView slab(0.25f, -0.25f, rim, rimVoxels);
        REQUIRE(shared::viewSurfaceSlope(slab.setup.params) == RenderSettings{}.surfaceSlope);
        double worst = 0.0;
        for (double degrees : {0.0, 30.0, 45.0, 60.0, 70.0, 80.0}) {
            const glm::vec3 dir = downAt(degrees);
            glm::vec3 transmittance;
            const glm::vec3 got = slab.radiance(-20.0f * dir, dir, transmittance);
            const double r = fresnelExact(1.0, 1.5, glm::radians(degrees));
            INFO((rim == Rim::Linear ? "linear" : "smooth")
                 << " rim, " << degrees << " deg: R = " << r << ", ground " << got.x << ", sky "
                 << got.z);
            const double t = 1.0 - r;
            CHECK(got.x == Approx(t * t + t * r * r).margin(kTolerance));
            CHECK(got.z == Approx(r + t * t * r).margin(kTolerance));
            CHECK(got.y == 0.0f);
            CHECK(transmittance.x == Approx(t * t).margin(kTolerance));
            worst = std::max(
                {worst, std::abs(got.x - (t * t + t * r * r)), std::abs(got.z - (r + t * t * r))});
        }
        WARN((rim == Rim::Linear ? "linear" : "smooth") << " rim: worst error " << worst);
    }
    // Normal incidence exactly: the tangential momentum is 0, R = 0.04.
    const GlassView slab(0.25f, -0.25f, Rim::Linear, 2.0f);
    glm::vec3 transmittance;
    const glm::vec3 normal = slab.radiance({0.0f, 3.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, transmittance);
    CHECK(normal.x == Approx(0.9216 + 0.96 * 0.04 * 0.04).margin(1e-5));
    CHECK(normal.z == Approx(0.04 + 0.9216 * 0.04).margin(1e-5));
}

TEST_CASE("without Fresnel, or with a graded material, view rays see only the ground",
          "[view][fresnel]") {
    const glm::vec3 dir = downAt(60.0);
    for (auto [materialFresnel, viewFresnel] : {std::pair{true, false}, std::pair{false, true}}) {
        const GlassView slab(0.25f, -0.25f, Rim::Linear, 2.0f, materialFresnel, viewFresnel);
        glm::vec3 transmittance;
        const glm::vec3 got = slab.radiance(-20.0f * dir, dir, transmittance);
        CHECK(got.x == Approx(1.0).margin(1e-6));
        CHECK(got.z == 0.0f);
    }
}

TEST_CASE(
    "a view ray inside glass turns back whole past the critical angle and reflects R "
    "below it",
    "[view][fresnel]") {
    // Glass fills the box below y = 0; the ray starts inside it, going up.
    const GlassView below(0.0f, -10.0f, Rim::Linear, 2.0f);
    auto upFromInside = [&](double degrees) {
        const glm::vec3 up = -downAt(degrees);
        glm::vec3 transmittance;
        return below.radiance(glm::vec3(-0.5f * up.x / up.y, -0.5f, 0.0f), up, transmittance);
    };
    // 60°, past asin(1/1.5) = 41.8°: reflected whole, back down to the ground.
    const glm::vec3 tir = upFromInside(60.0);
    CHECK(tir.x == Approx(1.0).margin(1e-6));
    CHECK(tir.z == 0.0f);
    // 30°: R = R(1.5 -> 1, 30°) is reflected down (the mirror direction on the glass side), the
    // rest goes out to the sky.
    const double r = fresnelExact(1.5, 1.0, glm::radians(30.0));
    const glm::vec3 partial = upFromInside(30.0);
    INFO("R = " << r << ", ground " << partial.x << ", sky " << partial.z);
    CHECK(partial.x == Approx(r).margin(1e-5));
    CHECK(partial.z == Approx(1.0 - r).margin(1e-5));
}
