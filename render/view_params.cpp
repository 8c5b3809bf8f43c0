#include "render/view_params.h"

#include <algorithm>
#include <cmath>

#include <glm/trigonometric.hpp>

#include "core/error.h"
#include "core/particle_color.h"
#include "core/transfer_function.h"

namespace eikon {
namespace {

glm::vec4 v4(glm::vec3 v, float w = 0.0f) {
    return glm::vec4(v, w);
}

shared::GpuLight packLight(const LightSpec& l) {
    shared::GpuLight g{};
    float type = EK_LIGHT_POINT;
    if (l.type == LightType::Directional) type = EK_LIGHT_DIRECTIONAL;
    if (l.type == LightType::Spot) type = EK_LIGHT_SPOT;
    // The cones as versines 1 − cos θ = 2 sin²(θ/2), in double (shaders/shared/gpu_types.h).
    const auto versine = [](double degrees) {
        const double s = std::sin(0.5 * glm::radians(degrees));
        return 2.0 * s * s;
    };
    double outer = versine(double(l.coneAngleDeg));
    double inner = versine(std::max(double(l.coneAngleDeg - l.coneSoftnessDeg), 0.0));
    if (l.type == LightType::Directional) {  // no cone: the disc's angular radius
        outer = versine(0.5 * double(l.angularDiameterDeg));
        inner = 0.0;
    }
    g.position = v4(l.position, type);
    g.direction = v4(glm::normalize(l.direction), float(outer));
    // smoothstep(inner, outer, v) needs inner < outer; a hard edge gets a hair of width, 1e-4 of
    // the cone's versine whatever its angle.
    g.radiance =
        v4(l.color * l.intensity,
           float(l.type == LightType::Spot ? std::min(inner, outer * (1.0 - 1e-4)) : inner));
    return g;
}

void packEnvironment(const Scene& scene, glm::ivec2 imageSize, shared::GpuViewParams& p) {
    const EnvironmentSpec& env = scene.environment;
    switch (env.type) {
        case EnvironmentType::Color:
            p.environment = glm::ivec4(EK_ENVIRONMENT_COLOR, 0, 0, 0);
            break;
        case EnvironmentType::Gradient:
            p.environment = glm::ivec4(EK_ENVIRONMENT_GRADIENT, 0, 0, 0);
            p.environmentSky = v4(env.zenith);
            p.environmentHorizon = v4(env.horizon);
            p.environmentGround = v4(env.ground);
            break;
        case EnvironmentType::Image: {
            if (imageSize.x < 1 || imageSize.y < 1)
                throw Error(scene.path + ":/environment/file",
                            "the environment image '" + env.file + "' was not loaded");
            p.environment = glm::ivec4(EK_ENVIRONMENT_IMAGE, imageSize.x, imageSize.y, 0);
            const float angle = glm::radians(env.rotationDeg);
            p.environmentSky = glm::vec4(env.intensity, std::cos(angle), std::sin(angle), 0.0f);
            break;
        }
    }
}

// Receivers: the planes, their map layouts (plane receivers: texelsPerVoxel texels along each
// voxel edge of the two in-plane axes; voxel receivers need no map) and their count in
// receiverCount. A plane must cut the volume, or nothing could ever reach it.
void packReceivers(const Scene& scene, const RenderVolume& volume, shared::GpuViewParams& p) {
    if (scene.receivers.size() > EK_MAX_RECEIVERS)
        throw Error(scene.path + ":/receivers",
                    "at most " + std::to_string(EK_MAX_RECEIVERS) + " receivers are supported");
    int offset = 0;
    for (size_t r = 0; r < scene.receivers.size(); ++r) {
        const ReceiverSpec& spec = scene.receivers[r];
        const float lo = volume.bounds.min[spec.axis];
        const float hi = volume.bounds.max[spec.axis];
        if (!(spec.position > lo && spec.position < hi)) {
            const char* axes = "xyz";
            throw Error(scene.path + ":" + spec.jsonPath + "/position",
                        "expected a position strictly inside the render volume's " +
                            std::string(1, axes[spec.axis]) + " range (" + std::to_string(lo) +
                            ", " + std::to_string(hi) + "), got " + std::to_string(spec.position));
        }
        shared::GpuReceiver& g = p.receivers[r];
        const bool plane = spec.method == ReceiverMethod::Plane;
        g.plane = glm::vec4(float(spec.axis), spec.position, float(spec.facing),
                            plane ? EK_RECEIVER_PLANE : EK_RECEIVER_VOXELS);
        g.albedo = v4(spec.albedo);
        const int tpv = plane ? spec.texelsPerVoxel : 0;
        g.texels = glm::ivec4(volume.resolution[(spec.axis + 1) % 3] * tpv,
                              volume.resolution[(spec.axis + 2) % 3] * tpv, offset, 0);
        offset += shared::receiverMapWidth(g) * shared::receiverMapHeight(g);
    }
    shared::setReceiverCount(p, int(scene.receivers.size()));
}

// Material m's particle colour table and range (GpuViewParams::particleColors, optics.h).
void packParticleColor(const ParticleColorSpec& spec, int m, shared::GpuViewParams& p) {
    const std::vector<glm::vec3> table = particleColorTable(spec, EK_PARTICLE_COLOR_TABLE);
    // The pre-integration table in double, rounded once: ∫ over each linear piece is the mean of
    // its ends.
    glm::dvec3 integral(0.0);
    for (int i = 0; i < EK_PARTICLE_COLOR_TABLE; ++i) {
        if (i > 0)
            integral += 0.5 * (glm::dvec3(table[size_t(i - 1)]) + glm::dvec3(table[size_t(i)]));
        p.particleColors[m * EK_PARTICLE_COLOR_TABLE + i] = v4(table[size_t(i)]);
        p.particleColorIntegrals[m * EK_PARTICLE_COLOR_TABLE + i] = v4(glm::vec3(integral));
    }
    const glm::vec2 range = particleColorRange(spec);
    p.particleColorRanges[m] =
        glm::vec4(range.x, float(EK_PARTICLE_COLOR_TABLE - 1) / (range.y - range.x), 0.0f, 0.0f);
}

// The clip planes as index-space ramps (GpuViewParams::clipPlanes): with h the voxel's extent
// along the unit normal n, Σ|n_i| voxel_i, the ramp at index position q (world x = min + q∘voxel)
// is d(x)/h + 1/2 with d the signed distance n·(x − point), so its coefficients are n∘voxel/h and
// n·(min − point)/h + 1/2. Computed in double: the offset subtracts world coordinates.
void packClipPlanes(const Scene& scene, const RenderVolume& volume, shared::GpuViewParams& p) {
    const glm::dvec3 voxel(volume.voxelSize());
    const glm::dvec3 lo(volume.bounds.min);
    for (size_t k = 0; k < scene.clipPlanes.size(); ++k) {
        const ClipPlaneSpec& c = scene.clipPlanes[k];
        const glm::dvec3 n(c.normal);
        const double h =
            std::abs(n.x) * voxel.x + std::abs(n.y) * voxel.y + std::abs(n.z) * voxel.z;
        // The parser normalises; a scene built in code may not (any length does: d and h scale
        // alike), but a zero or non-finite normal has no side that stays.
        if (!(h > 0.0) || !std::isfinite(h))
            throw Error(scene.path + ":" + (c.jsonPath.empty() ? "/clip_planes" : c.jsonPath),
                        "the normal is zero or not finite; it gives the side of the plane that "
                        "stays");
        p.clipPlanes[k] = glm::vec4(glm::vec3(n * voxel / h),
                                    float(glm::dot(n, lo - glm::dvec3(c.point)) / h + 0.5));
    }
}

// Bit k set: clip plane k cuts material `name` (a plane without a list cuts every material).
int clipMask(const Scene& scene, const std::string& name) {
    int mask = 0;
    for (size_t k = 0; k < scene.clipPlanes.size(); ++k) {
        const std::vector<std::string>& list = scene.clipPlanes[k].materials;
        if (list.empty() || std::find(list.begin(), list.end(), name) != list.end()) mask |= 1 << k;
    }
    return mask;
}

}  // namespace

ViewSetup makeViewSetup(const Scene& scene, const RenderVolume& volume, const CameraFrame& camera,
                        glm::ivec2 environmentSize) {
    if (scene.materials.size() > EK_MAX_MATERIALS)
        throw Error(scene.path + ":/materials",
                    "at most " + std::to_string(EK_MAX_MATERIALS) + " materials are supported");
    if (scene.clipPlanes.size() > EK_MAX_CLIP_PLANES)
        throw Error(scene.path + ":/clip_planes",
                    "at most " + std::to_string(EK_MAX_CLIP_PLANES) + " clip planes are supported");
    if (scene.lights.size() > EK_MAX_LIGHTS)
        throw Error(scene.path + ":/lights",
                    "at most " + std::to_string(EK_MAX_LIGHTS) + " lights are supported");
    ViewSetup setup;
    shared::GpuViewParams& p = setup.params;
    const glm::vec3 voxel = volume.voxelSize();
    const float smallestVoxel = std::min({voxel.x, voxel.y, voxel.z});

    p.cameraOrigin = v4(camera.origin);
    p.cameraRight = v4(camera.right);
    p.cameraUp = v4(camera.up);
    p.cameraForward = v4(camera.forward);
    shared::setTanHalfFovX(p, camera.tanHalfFovX);
    shared::setImageAspect(p, camera.aspect);
    p.volumeMin = v4(volume.bounds.min);
    p.volumeMax = v4(volume.bounds.max);
    shared::setViewStep(p, scene.render.stepVoxels * smallestVoxel);
    shared::setShadowStep(p, 0.0f);  // the light-transport method's (LightTransport::configure)
    p.resolution = glm::ivec4(volume.resolution, 0);
    shared::setMaterialCount(p, int(scene.materials.size()));
    p.image = glm::ivec4(scene.render.width, scene.render.height, 0, 0);
    shared::setLightCount(p, int(scene.lights.size()));
    shared::setShadowMode(p, EK_SHADOWS_VOLUME);  // the light-transport method's
    p.background = v4(scene.environment.color);
    shared::setMinTransmittance(p, scene.render.minTransmittance);
    shared::setViewSurfaceSlope(p, scene.render.fresnel ? scene.render.surfaceSlope : 0.0f);
    packEnvironment(scene, environmentSize, p);

    // Materials reading one field share its slot; one with a transfer function has its own, and
    // its particle colour reads the field's own value from the field's slot.
    const auto slotOf = [&](const std::string& slotName, size_t m) {
        auto slot = std::find(setup.slotFields.begin(), setup.slotFields.end(), slotName);
        if (slot != setup.slotFields.end()) return int(slot - setup.slotFields.begin());
        if (setup.slotFields.size() == EK_MAX_MATERIALS)
            throw Error(scene.path + ":/materials/" + std::to_string(m) + "/particle_color",
                        "its colour reads field '" + scene.materials[m].field +
                            "' as it is, beside its transfer function's amount, and the " +
                            std::to_string(EK_MAX_MATERIALS) +
                            " field slots of the render volume are taken");
        setup.slotFields.push_back(slotName);
        return int(setup.slotFields.size()) - 1;
    };
    for (size_t m = 0; m < scene.materials.size(); ++m) {
        const MaterialSpec& mat = scene.materials[m];
        const int slot = slotOf(materialSlotName(mat), m);
        const int colorSlot = mat.particleColor.empty() ? -1 : slotOf(mat.field, m);
        if (colorSlot >= 0) packParticleColor(mat.particleColor, int(m), p);
        shared::GpuMaterial& g = p.materials[m];
        g.absorption = v4(mat.absorption, mat.g);
        // w: what makes a Gladstone–Dale material's index exact (shaders/shared/material_index.h).
        g.scattering = v4(mat.scattering, mat.inverseAmbient());
        g.emission = v4(mat.emission, mat.indexSlope());
        // y: a sharp surface, only where the material refracts at all (fresnel.h).
        g.slot = glm::ivec4(slot, mat.fresnel && mat.indexSlope() != 0.0f ? 1 : 0,
                            clipMask(scene, mat.name), colorSlot + 1);
        g.surface = glm::vec4(mat.roughness, 0.0f, 0.0f, 0.0f);
    }
    for (size_t l = 0; l < scene.lights.size(); ++l) p.lights[l] = packLight(scene.lights[l]);
    // n ≡ 1 everywhere takes straight rays and needs no ∇n volume.
    bool refracts = false;
    for (const MaterialSpec& mat : scene.materials) refracts = refracts || mat.ior != 1.0f;
    p.pipeline = glm::ivec4(0);
    shared::setCurvedRays(p, refracts ? static_cast<int>(scene.render.integrator) : -1);
    packReceivers(scene, volume, p);
    packClipPlanes(scene, volume, p);
    bool disperses = false;
    for (const MaterialSpec& mat : scene.materials) disperses = disperses || mat.abbe > 0.0f;
    if (refracts && disperses) {
        for (const MaterialSpec& mat : scene.materials) {
            // The green channel is the d line: ior − 1 as params has it, to the bit.
            const glm::vec3 n = mat.channelIor();
            setup.channelIndexSlopes.push_back(
                mat.abbe > 0.0f ? glm::vec3(n.x - 1.0f, mat.indexSlope(), n.z - 1.0f)
                                : glm::vec3(mat.indexSlope()));
        }
    }
    return setup;
}

shared::GpuViewParams channelViewParams(const ViewSetup& setup, int channel) {
    shared::GpuViewParams p = setup.params;
    for (size_t m = 0; m < setup.channelIndexSlopes.size(); ++m)
        p.materials[m].emission.w = setup.channelIndexSlopes[m][channel];
    p.cameraUp.w = float(channel + 1);
    return p;
}

float smallestVoxelEdge(const shared::GpuViewParams& p) {
    // As RenderVolume::voxelSize() computes it, so that steps equal those made from the volume.
    const glm::vec3 voxel = (glm::vec3(p.volumeMax) - glm::vec3(p.volumeMin)) /
                            glm::vec3(p.resolution.x, p.resolution.y, p.resolution.z);
    return std::min({voxel.x, voxel.y, voxel.z});
}

}  // namespace eikon
