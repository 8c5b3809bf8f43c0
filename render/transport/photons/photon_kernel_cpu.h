#pragma once
// The photon shaders' world for the CPU twin (shaders/shared/photons.h inside a struct body): the
// field and ∇n volumes, the octree volume, and the deposit volumes as 64-bit integer
// accumulators; with the fixed-point rule of render/transport/photons/photon_tracing.h. Shared by
// the photon tracer and the wavefront tracer (render/transport/wavefront/), which deposits
// through the same functions.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>

#include "render/transport/fixed_point.h"
#include "render/transport/photons/deposit_buffers_cpu.h"
// First: the photon types at namespace scope, before photons.h is included in the kernel below.
#include "render/transport/photons/photon_tracing.h"
#include "render/volume_kernels_cpu.h"

EK_NAMESPACE_BEGIN

// What the photon shaders will see: the field and ∇n volumes, the octree volume, and the
// radiance volume as integer accumulators (kDepositChannels per voxel: r, g, b, then the
// weighted direction x, y, z).
struct PhotonKernelCpu : VolumeAccessCpu {
    static constexpr int kDepositChannels = 6;
    const vec4* octree = nullptr;
    ::eikon::DepositBuffersCpu* deposits = nullptr;
    dvec4 scale = dvec4(0.0);                          // rgb: flux·length channels; w: direction
    std::atomic<int64_t>* receiverDeposits = nullptr;  // 3 per receiver map texel: r, g, b
    dvec3 receiverScale = dvec3(0.0);                  // the totals' per-channel scales
    // The colour channels deposited (photons.h): all, or one per pass under dispersion.
    vec3 photonChannels = vec3(1.0f);

    vec4 fetchOctree(ivec3 v) const { return octree[voxelIndex(v)]; }

    static int64_t toFixed(double value, double scale) {
        return ::eikon::toFixedPoint(value, scale);
    }

    void depositVoxel(ivec3 v, vec3 fluxLength, vec3 weightedDir) const {
        int64_t cell[kDepositChannels];
        for (int c = 0; c < 3; ++c) {
            cell[c] = toFixed(fluxLength[c], scale[c]);
            cell[3 + c] = toFixed(weightedDir[c], scale.w);
        }
        // Integer addition commutes exactly: the sum is the same in any order, on any thread.
        deposits->add(voxelIndex(v) * kDepositChannels, cell, kDepositChannels);
    }

    void depositReceiverTexel(int index, vec3 flux) const {
        std::atomic<int64_t>* texel = receiverDeposits + size_t(index) * 3;
        for (int c = 0; c < 3; ++c)
            texel[c].fetch_add(toFixed(flux[c], receiverScale[c]), std::memory_order_relaxed);
    }

    // clang-format off
#include "shaders/shared/photons.h"
    // clang-format on
};

EK_NAMESPACE_END

namespace eikon {

// Order-independent totals: per-particle values in fixed point, summed as integers.
struct FixedTotals {
    std::atomic<int64_t> escaped[3] = {};
    std::atomic<int64_t> extinguished[3] = {};
    std::atomic<int64_t> dropped[3] = {};
    std::atomic<int64_t> received[3] = {};
    std::atomic<int64_t> removed[3] = {};    // of dropped
    std::atomic<int64_t> reflected[3] = {};  // at surfaces (Fresnel), not followed
    std::atomic<int64_t> steps{0};
    std::atomic<int64_t> cut{0};
};

}  // namespace eikon
