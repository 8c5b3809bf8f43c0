#include "render/light_transport.h"

#include <cstring>

#include <glm/vector_relational.hpp>

#include "core/error.h"
#include "render/gpu_timer.h"
#include "render/input_key.h"
#include "render/volume_kernels_cpu.h"

namespace eikon {

StageScope::StageScope(GpuStageTimer* timer, const char* stage) : timer_(timer) {
    if (timer_) timer_->begin(stage);
}

StageScope::~StageScope() {
    if (timer_) timer_->end();
}

Image LightTransport::runWithViewCpu(const TransportInputsCpu&, const Image*) {
    throw Error("light transport \"" + name() + "\"", "renders no view of its own");
}

Image LightTransport::runWithViewGpu(const TransportInputsGpu&, unsigned) {
    throw Error("light transport \"" + name() + "\"", "renders no view of its own");
}

TransportOutputCpu fluenceOutputOf(const std::vector<glm::vec4>& fluence,
                                   const std::vector<glm::vec4>& direction,
                                   const std::vector<glm::vec4>& receiverMap) {
    TransportOutputCpu out;
    if (fluence.empty()) return out;
    out.fluence = fluence.data();
    out.direction = direction.data();
    out.fluenceVoxels = fluence.size();
    out.receiverMap = receiverMap.data();
    out.receiverTexels = receiverMap.size();
    return out;
}

bool viewReadsLightTransmittance(const ViewSetup& setup) {
    const shared::GpuViewParams& p = setup.params;
    if (shared::lightCount(p) == 0 || shared::shadowMode(p) == EK_SHADOWS_MARCHED) return false;
    if (shared::allLightsInFluence(p)) return false;
    if (shared::receiverCount(p) > 0) return true;  // receivers are lit through them
    for (int m = 0; m < shared::materialCount(p); ++m) {
        const glm::vec4& s = p.materials[m].scattering;
        if (s.x > 0.0f || s.y > 0.0f || s.z > 0.0f) return true;
    }
    return false;
}

std::vector<glm::vec3> fluenceRateCpu(const ViewSetup& setup, const TransportOutputCpu& out) {
    const shared::GpuViewParams& p = setup.params;
    const RenderVolume volume{{glm::vec3(p.volumeMin), glm::vec3(p.volumeMax)},
                              glm::ivec3(p.resolution.x, p.resolution.y, p.resolution.z)};
    const size_t voxels = volume.voxelCount();
    std::vector<glm::vec3> rate(voxels, glm::vec3(0.0f));
    if (p.pipeline.y != 0) {
        if (!out.fluence || out.fluenceVoxels != voxels)
            throw Error("fluence rate", "the method gave no fluence volume");
        const glm::vec3 h = volume.voxelSize();
        for (size_t v = 0; v < voxels; ++v) rate[v] = glm::vec3(out.fluence[v]) / (h.x * h.y * h.z);
    }
    shared::VolumeAccessCpu kernel{p};  // the shared lightIrradiance, as the view uses it
    for (int l = 0; l < p.image.z; ++l) {
        if ((p.pipeline.z & (1 << l)) != 0) continue;  // in the fluence
        if (p.image.w == EK_SHADOWS_MARCHED || size_t(l) >= out.lightTransmittance.size())
            throw Error("fluence rate", "light " + std::to_string(l) +
                                            " has no transmittance volume (marched at view time)");
        size_t v = 0;
        for (int k = 0; k < volume.resolution.z; ++k)
            for (int j = 0; j < volume.resolution.y; ++j)
                for (int i = 0; i < volume.resolution.x; ++i, ++v) {
                    glm::vec3 toLight;
                    float distance;
                    const glm::vec3 e =
                        kernel.lightIrradiance(l, volume.voxelCenter(i, j, k), toLight, distance);
                    rate[v] += e * glm::vec3(out.lightTransmittance[size_t(l)][v]);
                }
    }
    return rate;
}

std::vector<unsigned char> transportInputsKey(const ViewSetup& setup,
                                              const std::vector<const DenseGrid*>& slotGrids) {
    shared::GpuViewParams p = setup.params;
    p.cameraOrigin = p.cameraRight = p.cameraUp = p.cameraForward = glm::vec4(0.0f);
    p.image.x = p.image.y = 0;
    p.background = glm::vec4(0.0f);
    p.environment = glm::ivec4(0);
    p.environmentSky = p.environmentHorizon = p.environmentGround = glm::vec4(0.0f);
    // Receivers stop photons but not straight light; their albedo only shades the view. A
    // method whose output depends on them appends them itself.
    shared::setReceiverCount(p, 0);
    for (shared::GpuReceiver& r : p.receivers) r = shared::GpuReceiver{};
    // Particle colours tint only what the view sees (optics.h particleColorOverStep): a new colour
    // map re-traces nothing.
    for (glm::vec4& r : p.particleColorRanges) r = glm::vec4(0.0f);
    for (glm::vec4& c : p.particleColors) c = glm::vec4(0.0f);
    for (glm::vec4& c : p.particleColorIntegrals) c = glm::vec4(0.0f);
    for (shared::GpuMaterial& m : p.materials) m.slot.w = 0;
    // The phase function's g shades only the view too: the methods carry flux and its mean
    // direction, and the view applies the phase function to them.
    for (shared::GpuMaterial& m : p.materials) m.absorption.w = 0.0f;
    // Sized first and copied into, not appended to an empty vector: GCC 12 warns (a false
    // -Wstringop-overflow) on insert() into an empty vector at this size.
    std::vector<unsigned char> key(sizeof(p));
    std::memcpy(key.data(), &p, sizeof(p));
    for (const DenseGrid* g : slotGrids) appendBytes(key, &g->version, sizeof(g->version));
    return key;
}

void appendReceiverMapsKey(const ViewSetup& setup, std::vector<unsigned char>& key) {
    const shared::GpuViewParams& p = setup.params;
    for (int r = 0; r < shared::receiverCount(p); ++r) {
        appendBytes(key, &p.receivers[r].plane, sizeof(glm::vec4));
        appendBytes(key, &p.receivers[r].texels, sizeof(glm::ivec4));
    }
}

bool lightAllThroughFluence(const Scene& scene, ViewSetup& setup) {
    bool scatters = false;
    for (const MaterialSpec& mat : scene.materials)
        scatters = scatters || glm::any(glm::greaterThan(mat.scattering, glm::vec3(0.0f)));
    if (!scatters && scene.receivers.empty()) return false;
    shared::GpuViewParams& p = setup.params;
    for (size_t l = 0; l < scene.lights.size(); ++l) shared::setLightInFluence(p, int(l));
    shared::setReadsFluence(p, shared::anyLightInFluence(p));
    return true;
}

void requireLightsWithoutDisc(const Scene& scene, const std::string& method) {
    for (std::size_t l = 0; l < scene.lights.size(); ++l) {
        if (!(scene.lights[l].angularDiameterDeg > 0.0f)) continue;
        throw Error(scene.path + ":/lights/" + std::to_string(l) + "/angular_diameter_deg",
                    "the " + method +
                        " method draws a light from a single direction; a disc light's soft "
                        "shadows are drawn by \"photons\", \"plane_sweep\" and "
                        "\"light_volumes\"");
    }
}

}  // namespace eikon
