#pragma once
// A photon-tracing test scene: one material on one field over [-1, 1]^3, lit by one light
// (directional unless given), with its refraction volumes from the CPU twins. Shared by the CPU
// and GPU photon tests.
#include <functional>

#include "core/camera.h"
#include "core/scene.h"
#include "render/refraction_volume.h"
#include "render/transport/photons/photon_tracing.h"
#include "render/view_params.h"

namespace eikon::test {

struct PhotonScene {
    Scene scene;
    DenseGrid field;
    ViewSetup setup;
    RefractionVolumeCpu gradient;
    RefractionVolumeCpu octree;

    PhotonScene(int res, float ior, glm::vec3 absorption, glm::vec3 lightDir,
                const std::function<float(glm::vec3)>& f, glm::vec3 lightColor = glm::vec3(1.0f),
                const OctreeSettings& octreeSettings = {})
        : PhotonScene(res, ior, absorption, directionalLight(lightDir, lightColor), f,
                      octreeSettings) {}

    PhotonScene(int res, float ior, glm::vec3 absorption, const LightSpec& light,
                const std::function<float(glm::vec3)>& f,
                const OctreeSettings& octreeSettings = {}) {
        MaterialSpec m;
        m.name = "medium";
        m.ior = ior;
        m.absorption = absorption;
        scene.materials.push_back(m);
        scene.lights.push_back(light);
        scene.render.width = scene.render.height = 4;
        field.field = "density";
        field.volume = {{glm::vec3(-1.0f), glm::vec3(1.0f)}, glm::ivec3(res)};
        field.values.resize(field.volume.voxelCount());
        for (int k = 0; k < res; ++k)
            for (int j = 0; j < res; ++j)
                for (int i = 0; i < res; ++i)
                    field.values[field.index(i, j, k)] = f(field.volume.voxelCenter(i, j, k));
        setup = makeViewSetup(scene, field.volume,
                              makeCameraFrame(scene.camera, field.volume.bounds, 4, 4));
        gradient = computeIndexGradientCpu(setup, {&field});
        octree = computeOctreeCpu(setup, gradient, octreeSettings, {&field});
    }

    // The material's index is graded (a GRIN lens, a Luneburg lens): its edge is no sharp surface
    // and reflects nothing (MaterialSpec::fresnel).
    void markGraded() {
        scene.materials[0].fresnel = false;
        setup = makeViewSetup(scene, field.volume,
                              makeCameraFrame(scene.camera, field.volume.bounds, 4, 4));
    }

    static LightSpec directionalLight(glm::vec3 direction, glm::vec3 color) {
        LightSpec light;
        light.type = LightType::Directional;
        light.direction = direction;
        light.color = color;
        return light;
    }

    // Radiant intensity color (per steradian) from position, in every direction.
    static LightSpec pointLight(glm::vec3 position, glm::vec3 color) {
        LightSpec light;
        light.type = LightType::Point;
        light.position = position;
        light.color = color;
        return light;
    }

    // A point light limited to a cone around direction: full intensity up to coneDeg −
    // softnessDeg from the axis, nothing beyond coneDeg.
    static LightSpec spotLight(glm::vec3 position, glm::vec3 direction, glm::vec3 color,
                               float coneDeg, float softnessDeg) {
        LightSpec light = pointLight(position, color);
        light.type = LightType::Spot;
        light.direction = direction;
        light.coneAngleDeg = coneDeg;
        light.coneSoftnessDeg = softnessDeg;
        return light;
    }

    PhotonResultCpu trace(const PhotonSettings& s) const {
        return traceLightPhotonsCpu(setup, {&field}, gradient, octree, s);
    }
};

}  // namespace eikon::test
