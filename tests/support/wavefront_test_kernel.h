#pragma once
// The shared wavefront functions (shaders/shared/wavefront.h) with nothing to deposit into: for
// tests that step single particles and patches themselves.
#include "render/transport/wavefront/wavefront_tracing.h"
#include "render/volume_kernels_cpu.h"
#include "support/photon_scene.h"

EK_NAMESPACE_BEGIN
struct WavefrontTestKernel : VolumeAccessCpu {
    vec4 fetchOctree(ivec3) const { return vec4(0.0f); }
    void depositVoxel(ivec3, vec3, vec3) const {}
    void depositReceiverTexel(int, vec3) const {}
    vec3 photonChannels = vec3(1.0f);
#include "shaders/shared/photons.h"
#include "shaders/shared/wavefront.h"
};
EK_NAMESPACE_END

namespace eikon::test {

// The kernel reading the scene's one field and its ∇n volume.
inline shared::WavefrontTestKernel kernelFor(const PhotonScene& s) {
    shared::WavefrontTestKernel k{{s.setup.params}};
    k.fields[0] = s.field.values.data();
    k.gradient = s.gradient.data();
    return k;
}

}  // namespace eikon::test
