#pragma once
// The receiver map: the irradiance photons bring to each plane receiver (shaders/shared/
// receivers.h), texel by texel, every receiver's texels one after the other. Photon tracing sums
// the flux landing on each texel as int64 fixed point (3 per texel: r, g, b, at the totals' scale
// 2^40 / Φ_c of render/transport/photons/photon_tracing.h); this turns the sums into irradiance,
// the same on both backends.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "shaders/shared/gpu_types.h"

namespace eikon {

// Texels of every receiver's map (receiverCount(params) receivers, receiverMapWidth ×
// receiverMapHeight each).
size_t receiverMapTexels(const shared::GpuViewParams& params);

// rgb = Σ flux / texel area (power per area) from the fixed-point sums (3 per texel) and their
// per-channel scales, smoothed in the plane like the photon volumes (render/smoothing.h); w = 0.
std::vector<glm::vec4> receiverMapFromFixed(const shared::GpuViewParams& params,
                                            const std::vector<int64_t>& sums, glm::dvec3 scale);

}  // namespace eikon
