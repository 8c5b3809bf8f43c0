#pragma once
// The shared GPU code (shaders/shared/*.h), compiled as C++ for the CPU twins. The shared
// functions are included inside struct bodies, so that what the shaders read as globals —
// `params`, `fetchVolume`, `fetchPreviousSlice` — are members here and the code needs no change
// between the two sides.
#include <cstddef>

#include "core/ray_integrator.h"

#include "shaders/shared/gpu_types.h"
#include "shaders/shared/material_index.h"  // at file scope: fresnel.h calls it

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
    vec4 fetchFluenceVoxel(ivec3 v) const { return fluence[voxelIndex(v)]; }
    vec4 fetchFluenceDirectionVoxel(ivec3 v) const { return fluenceDirection[voxelIndex(v)]; }

    // The shared files are order-sensitive in GLSL; keep their order here too.
    // clang-format off
#include "shaders/shared/volume_slots.h"
#include "shaders/shared/sampling.h"
#include "shaders/shared/optics.h"
#include "shaders/shared/receivers.h"
#include "shaders/shared/ray_equation.h"
    // clang-format on
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

    // clang-format off
#include "shaders/shared/environment.h"
#include "shaders/shared/fresnel.h"
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
