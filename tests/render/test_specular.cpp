// Specular highlights of the lights on sharp surfaces (shaders/shared/specular.h, view_march.h
// surfaceHighlights; Magnus's thesis §4.3): the Cook–Torrance BRDF with GGX against its closed
// form on a flat glass face, through the light-transport method's fluence as well as straight,
// and the GPU against the CPU twin.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/gtc/constants.hpp>

#include "core/camera.h"
#include "core/error.h"
#include "core/scene.h"
#include "render/frame_renderer.h"
#include "render/image.h"
#include "render/refraction_volume.h"
#include "render/view_params.h"
#include "render/volume_kernels_cpu.h"
#include "support/fresnel_exact.h"
#include "support/light_transport_setup.h"
#include "support/scene_builders.h"

using namespace eikon;
using eikon::test::fresnelExact;

namespace {

// The closed form: f_r (n·l) E = D F G / (4 n·v) E with D the GGX distribution (α =
// roughness²), G UE4's Schlick-GGX (k = (roughness + 1)²/8) and F the exact unpolarized
// reflectance from air into n = 1.5 at the halfway vector, in double; v, l unit, in the xy plane
// over a face of normal +y.
double ggxClosedForm(glm::dvec3 v, glm::dvec3 l, double roughness) {
    const glm::dvec3 n(0.0, 1.0, 0.0);
    const double nv = glm::dot(n, v), nl = glm::dot(n, l);
    if (nl <= 0.0) return 0.0;
    const glm::dvec3 h = glm::normalize(v + l);
    const double alpha2 = std::pow(roughness, 4.0);
    const double d = glm::dot(n, h) * glm::dot(n, h) * (alpha2 - 1.0) + 1.0;
    const double distribution = alpha2 / (glm::pi<double>() * d * d);
    const double k = (roughness + 1.0) * (roughness + 1.0) / 8.0;
    const double geometry = nl / (nl * (1.0 - k) + k) * nv / (nv * (1.0 - k) + k);
    const double fresnel = fresnelExact(1.0, 1.5, std::acos(glm::dot(v, h)));
    return distribution * fresnel * geometry / (4.0 * nv);
}

// A direction in the xy plane at `degrees` from +y, toward +x.
glm::dvec3 fromVertical(double degrees) {
    const double a = glm::radians(degrees);
    return {std::sin(a), std::cos(a), 0.0};
}

// Glass (n = 1.5, roughness 0.3) filling a wide box below y = 0.25 with a 2-voxel linear rim,
// under a black environment, lit by a directional light of irradiance 1: a view ray that meets
// the face sees nothing but the light's highlight (its reflection sees the black sky, the ray
// through the glass leaves the box through its bottom with no face to cross).
struct GlassFace {
    static constexpr float kVoxel = 2.0f / 32;
    Scene scene;
    DenseGrid field;
    ViewSetup setup;
    std::vector<glm::vec4> gradient;

    GlassFace(glm::vec3 lightTravel, float roughness) {
        MaterialSpec glass;
        glass.name = "glass";
        glass.ior = 1.5f;
        glass.roughness = roughness;
        scene.materials.push_back(glass);
        LightSpec light;
        light.type = LightType::Directional;
        light.direction = lightTravel;
        light.color = glm::vec3(1.0f);
        light.intensity = 1.0f;
        scene.lights.push_back(light);
        scene.environment.type = EnvironmentType::Gradient;
        scene.environment.zenith = scene.environment.horizon = scene.environment.ground =
            glm::vec3(0.0f);
        field.field = "density";
        field.version = 1;
        field.volume =
            RenderVolume{{glm::vec3(-5.0f, -1.0f, -0.125f), glm::vec3(5.0f, 1.0f, 0.125f)},
                         glm::ivec3(160, 32, 4)};
        field.values.resize(field.volume.voxelCount());
        for (int k = 0; k < field.volume.resolution.z; ++k)
            for (int j = 0; j < field.volume.resolution.y; ++j)
                for (int i = 0; i < field.volume.resolution.x; ++i) {
                    const float y = field.volume.voxelCenter(i, j, k).y;
                    field.values[field.index(i, j, k)] =
                        std::clamp((0.25f - y) / (2.0f * kVoxel) + 0.5f, 0.0f, 1.0f);
                }
        scene.render.width = scene.render.height = 4;
        setup = makeViewSetup(scene, field.volume,
                              makeCameraFrame(scene.camera, field.volume.bounds, 4, 4));
        // The light straight to the face, its transmittance marched (through air: 1).
        shared::setShadowMode(setup.params, EK_SHADOWS_MARCHED);
        gradient = computeIndexGradientCpu(setup, {&field});
    }

    // The radiance of a view ray going down along unit `dir` to the face's centre.
    glm::vec3 radiance(glm::vec3 dir) const {
        shared::ViewKernelCpu k{{setup.params}};
        k.fields[0] = field.values.data();
        k.gradient = gradient.data();
        glm::vec3 transmittance;
        return k.integrateViewRay(glm::vec3(0.0f, 0.25f, 0.0f) - 20.0f * dir, dir, transmittance);
    }
};

}  // namespace

TEST_CASE("a light's highlight on a glass face is Cook-Torrance with GGX, as in closed form",
          "[view][specular]") {
    // Measured: worst relative error 1.5e-6, at the mirror angle and off it.
    constexpr double kTolerance = 1e-4;
    for (const double roughness : {0.2, 0.5}) {
        for (const double viewDegrees : {0.0, 30.0, 60.0}) {
            for (const double offset : {0.0, 4.0, -10.0, 25.0}) {
                const double lightDegrees = viewDegrees + offset;  // from the vertical, toward −x
                const glm::dvec3 toLight = fromVertical(-lightDegrees);
                const GlassFace face(-glm::vec3(toLight), float(roughness));
                const glm::dvec3 v = fromVertical(viewDegrees);  // toward the camera, +x side
                const double expected = ggxClosedForm(v, toLight, roughness);
                const glm::vec3 got = face.radiance(-glm::vec3(v));
                INFO("roughness " << roughness << ", view " << viewDegrees << " deg, light "
                                  << lightDegrees << " deg: " << got.x << " against " << expected);
                REQUIRE(expected > 0.0);
                CHECK(std::abs(got.x - expected) <= kTolerance * expected);
                CHECK(got.x == got.y);
                CHECK(got.x == got.z);
            }
        }
        // The light below the face's horizon: no highlight.
        const GlassFace below(-glm::vec3(fromVertical(95.0)), float(roughness));
        CHECK(below.radiance(-glm::vec3(fromVertical(-30.0))).x == 0.0f);
    }
    // No roughness: no highlight at all, to the bit.
    const GlassFace smooth(-glm::vec3(fromVertical(-30.0)), 0.0f);
    CHECK(smooth.radiance(-glm::vec3(fromVertical(30.0))) == glm::vec3(0.0f));
}

TEST_CASE("a highlight lit through the fluence, and on the GPU as on the CPU twin",
          "[view][specular][gpu]") {
    // The lens in fog (scene_builders.h) with a sharp rough glass ball, lit from the camera's side
    // so that highlights face it: the plane sweep's fluence brings the light.
    Scene scene = test::glassSphereInFog();
    scene.lights[0].direction = glm::normalize(glm::vec3(0.3f, -0.4f, -1.0f));
    scene.materials[0].scattering = glm::vec3(0.05f);  // thin fog: the light arrives strong
    scene.sources[1].falloff = 0.02f;
    test::setTransportMethod(scene, "plane_sweep");
    Scene smooth = scene;
    scene.materials[1].roughness = 0.3f;
    const Image rough = FrameRenderer(scene, Backend::Cpu).render(0);
    const Image plain = FrameRenderer(smooth, Backend::Cpu).render(0);
    // Highlights only add light, and some pixel gains much.
    float gain = 0.0f;
    for (size_t i = 0; i < rough.pixels.size(); ++i) {
        REQUIRE(rough.pixels[i].x >= plain.pixels[i].x);
        gain = std::max(gain, rough.pixels[i].x - plain.pixels[i].x);
    }
    CHECK(gain > 0.05f);
    const Image gpu = FrameRenderer(scene, Backend::Gpu).render(0);
    const ImageDifference d = compareImages(gpu, rough);
    // Measured on llvmpipe: 2.8e-4 of 4.8, at a highlight.
    INFO("max |GPU - CPU| " << d.maxAbs << " of " << d.referenceMax);
    CHECK(d.maxAbs < 1e-4 * d.referenceMax);
}

TEST_CASE("roughness is refused where there is no sharp surface", "[view][specular]") {
    const auto parse = [](const std::string& material) {
        return parseScene(
            R"({"sources": [{"type": "sphere", "field": "density", "center": [0, 0, 0],
            "radius": 0.5, "value": 1}], "materials": [)" +
                material + R"(]})",
            "scene.json");
    };
    CHECK(parse(R"({"name": "glass", "ior": 1.5, "roughness": 0.3})").materials[0].roughness ==
          0.3f);
    CHECK_THROWS_WITH(parse(R"({"name": "glass", "ior": 1.5, "roughness": 1.5})"),
                      Catch::Contains("/materials/0/roughness"));
    CHECK_THROWS_WITH(parse(R"({"name": "fog", "roughness": 0.3})"),
                      Catch::Contains("needs a refracting material"));
    CHECK_THROWS_WITH(parse(R"({"name": "glass", "ior": 1.5, "fresnel": false, "roughness": 0.3})"),
                      Catch::Contains("needs a refracting material"));
}
