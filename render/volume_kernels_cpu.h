#pragma once
// The shared GPU code (shaders/shared/*.h), compiled as C++ for the CPU twins. The shared
// functions are included inside struct bodies, so that what the shaders read as globals —
// `params`, `fetchVolume`, `fetchPreviousSlice` — are members here and the code needs no change
// between the two sides.
#include <atomic>
#include <cmath>
#include <cstddef>

#include "core/ray_integrator.h"
#include "render/constant_bricks.h"
#include "render/empty_bricks.h"

#include "shaders/shared/gpu_types.h"
#include "shaders/shared/material_index.h"  // at file scope: fresnel.h calls it

// The lights' highlights on sharp surfaces (view_march.h): always compiled here, skipped at run
// time where no material has them (the GPU compiles them only into a variant of its own).
#define EK_SPECULAR
// Steps through empty space without sampling it (view_march.h; render/empty_bricks.h): only here,
// where the empty bricks are found. The GPU takes every step in full, with the same result.
#define EK_SKIP_EMPTY_SPACE
// Takes a trilinear sample in a brick where its volume holds one value without fetching the eight
// corners (shaders/shared/sampling.h; render/constant_bricks.h): only here, with the same floats.
#define EK_CONSTANT_BRICKS
// volumeVoxelSize (sampling.h) returns the kernel's voxelSize, computed once when it is made.
#define EK_VOXEL_SIZE_MEMBER

EK_NAMESPACE_BEGIN

// What volume_bindings.glsl gives the shaders: field values and light transmittances by slot.
struct VolumeAccessCpu {
    const GpuViewParams& params;
    const float* fields[EK_MAX_MATERIALS] = {};
    const vec4* lights[EK_MAX_LIGHTS] = {};
    const vec4* gradient = nullptr;  // the ∇n volume, for curved rays
    // The output contract's fluence and mean-direction volumes (render/light_transport.h), when
    // the view reads them (readsFluence).
    const vec4* fluence = nullptr;
    const vec4* fluenceDirection = nullptr;
    // The plane sweep's interleaved view (render/transport/plane_sweep/plane_sweep_view.h) keeps
    // of the fluence volumes only the last `slices` slices swept across `axis`, slice k at plane
    // k % slices of them (u fastest); lookups elsewhere along the axis take the nearest held.
    // axis < 0: whole volumes.
    struct FluenceWindow {
        int axis = -1, u = 0, w = 0;
        int slices = 2;
        int first = 0, last = 0;  // the slices held (first ≤ last)
        size_t planeTexels = 0;
        // The sweep: toward +axis (order 1) or −axis; `swept` slices so far.
        int order = 1, swept = 0;
        // Samples taken from slices already dropped (a view ray that turned back against the
        // sweep), read from the nearest slice held; counted.
        std::atomic<int64_t>* behind = nullptr;
    };
    FluenceWindow window = {};

    size_t fluenceIndex(ivec3 v) const {
        if (window.axis < 0) return voxelIndex(v);
        const int k = v[window.axis] < window.first  ? window.first
                      : v[window.axis] > window.last ? window.last
                                                     : v[window.axis];
        return size_t(k % window.slices) * window.planeTexels +
               size_t(v[window.w]) * size_t(params.resolution[window.u]) + size_t(v[window.u]);
    }

    // Where the volumes hold one value over a brick (render/constant_bricks.h); null: nowhere,
    // every sample fetches its eight corners.
    const ConstantBricks* constantBricks = nullptr;
    // Whether slot `slot` holds one value, set in `value`, over every voxel a sample with lower
    // corner voxel `corner` (clamped into the volume) reads.
    EK_FORCE_INLINE bool constantBrickValue(int slot, ivec3 corner, vec4& value) const {
        if (!constantBricks) return false;
        const size_t brick = constantBricks->brickIndex(corner);
        if (!(constantBricks->mask[brick] >> slot & 1)) return false;
        const size_t column = size_t(constantBricks->column[slot]);
        value = constantBricks->values[column * constantBricks->mask.size() + brick];
        return true;
    }

    size_t voxelIndex(ivec3 v) const {
        return (size_t(v.z) * size_t(params.resolution.y) + size_t(v.y)) *
                   size_t(params.resolution.x) +
               size_t(v.x);
    }
    // One volume per kind, for the shared slot switch (shaders/shared/volume_slots.h).
    vec4 fetchFieldVoxel(int field, ivec3 v) const {
        return vec4(fields[field][voxelIndex(v)], 0.0f, 0.0f, 0.0f);
    }
    vec4 fetchLightVoxel(int light, ivec3 v) const { return lights[light][voxelIndex(v)]; }
    vec4 fetchGradientVoxel(ivec3 v) const { return gradient[voxelIndex(v)]; }
    vec4 fetchFluenceVoxel(ivec3 v) const { return fluence[fluenceIndex(v)]; }
    vec4 fetchFluenceDirectionVoxel(ivec3 v) const { return fluenceDirection[fluenceIndex(v)]; }

    // The shared files are order-sensitive in GLSL; keep their order here too.
    // clang-format off
#include "shaders/shared/volume_slots.h"
#include "shaders/shared/sampling.h"
#include "shaders/shared/optics.h"
#include "shaders/shared/receivers.h"
#include "shaders/shared/ray_equation.h"
    // clang-format on

    // volumeVoxelSize's value, once: declared after params, so initialized after it. params
    // must not change while the kernel lives (every kernel is made for one pass).
    const vec3 voxelSize = EK_VOXEL_SIZE_OF(params);
};

struct ViewKernelCpu : VolumeAccessCpu {
    // The environment image (environmentWidth × environmentHeight texels, row 0 at the top),
    // when environmentType(params) asks for it.
    const vec4* environment = nullptr;
    vec4 fetchEnvironment(ivec2 t) const {
        return environment[size_t(t.y) * size_t(environmentWidth(params)) + size_t(t.x)];
    }
    // The receiver map (render/receiver_map.h), when a receiver reads the fluence.
    const vec4* receiverMap = nullptr;
    vec4 fetchReceiverTexel(int index) const { return receiverMap[size_t(index)]; }
    // Whether a view ray may shade a sample at volume index position p (view_march.h): always,
    // but in the plane sweep's interleaved view, where the two slices its fluence lookups read
    // (sampleVolume's) must have been swept. Counts the samples that read a slice dropped.
    bool viewSampleReady(vec3 p) const {
        if (window.axis < 0) return true;
        const int last = params.resolution[window.axis] - 1;
        const int base = int(std::floor(p[window.axis] - 0.5f));
        const int k0 = base < 0 ? 0 : base > last ? last : base;
        const int k1 = base + 1 < 0 ? 0 : base + 1 > last ? last : base + 1;
        // The place of a slice in the sweep's order.
        const int r0 = window.order > 0 ? k0 : last - k0;
        const int r1 = window.order > 0 ? k1 : last - k1;
        if ((r0 > r1 ? r0 : r1) >= window.swept) return false;
        if ((r0 < r1 ? r0 : r1) < window.swept - window.slices && window.behind)
            window.behind->fetch_add(1, std::memory_order_relaxed);
        return true;
    }
    // A view ray's hit on a receiver, kept to be shaded once the receiver's irradiance is complete
    // (the interleaved view: a plane receiver's map fills as the planes pass it, after the rays
    // that see it). receiver < 0: none.
    struct ReceiverHit {
        int receiver = -1;
        vec3 x = vec3(0.0f);
        bool front = false;
        vec3 weight = vec3(0.0f);  // the ray's transmittance where it met the receiver
    };
    // Where receiverDeferred keeps the hit of the ray being advanced; null: none is deferred.
    ReceiverHit* deferredReceiverHit = nullptr;
    bool receiverDeferred(int r, vec3 x, bool front, vec3 weight) const {
        if (!deferredReceiverHit) return false;
        *deferredReceiverHit = ReceiverHit{r, x, front, weight};
        return true;
    }

    // The empty bricks (render/empty_bricks.h) the view may step through without sampling them;
    // null where none is empty: every step is taken in full.
    const uint8_t* emptyBricks = nullptr;
    ivec3 emptyBrickCount = ivec3(0);
    bool anyEmptyBricks() const { return emptyBricks != nullptr; }
    // The index of the empty brick that holds volume index position p; −1 where that brick is not
    // empty, or p is outside the volume (or NaN).
    int emptyBrickAt(vec3 p) const {
        if (!emptyBricks) return -1;
        if (!(p.x >= 0.0f && p.y >= 0.0f && p.z >= 0.0f && p.x < float(params.resolution.x) &&
              p.y < float(params.resolution.y) && p.z < float(params.resolution.z)))
            return -1;
        const ivec3 b = ivec3(p) >> kEmptyBrickShift;  // truncation is floor here: p ≥ 0
        const int i = (b.z * emptyBrickCount.y + b.y) * emptyBrickCount.x + b.x;
        return emptyBricks[i] ? i : -1;
    }
    // Where the ray o + d·t (volume index space) leaves the run of empty bricks it is in at t
    // (render/empty_bricks.h).
    float emptyRunEnd(vec3 o, vec3 d, float t) const {
        return eikon::emptyRunEnd(emptyBricks, emptyBrickCount, o, d, t);
    }
    // Whether every sample a view ray takes may be shaded at once: all but the interleaved view
    // (viewSampleReady).
    bool viewSamplesAllReady() const { return window.axis < 0; }

    // clang-format off
#include "shaders/shared/environment.h"
#include "shaders/shared/fresnel.h"
#include "shaders/shared/specular.h"
#include "shaders/shared/view_march.h"
    // clang-format on
};

struct LightKernelCpu : VolumeAccessCpu {
    const vec4* sweepSlices = nullptr;  // the volume being swept; earlier slices are complete
    vec4 fetchPreviousSlice(ivec3 v) const { return sweepSlices[voxelIndex(v)]; }

#include "shaders/shared/light_volume.h"
};

EK_NAMESPACE_END

// The scene's integrator names are the shaders' EK_RAY_* values (core/ray_integrator.h).
static_assert(int(eikon::RayIntegrator::Euler) == EK_RAY_EULER &&
                  int(eikon::RayIntegrator::Midpoint) == EK_RAY_MIDPOINT &&
                  int(eikon::RayIntegrator::Rk4) == EK_RAY_RK4 &&
                  int(eikon::RayIntegrator::Verlet) == EK_RAY_VERLET,
              "core/ray_integrator.h and shaders/shared/ray_equation.h disagree");
