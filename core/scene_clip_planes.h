#pragma once
// Parser of the scene's "clip_planes" array (docs/scene-format.md#clip-planes). Internal to core:
// scene.cpp calls it after the materials (meshes' included), whose names the planes list.
#include <vector>

#include "core/json_reader.h"
#include "core/scene.h"
#include "shaders/shared/gpu_types.h"

namespace eikon {

// At most as many planes as the GPU parameter block has room for.
constexpr std::size_t kMaxClipPlanes = EK_MAX_CLIP_PLANES;

std::vector<ClipPlaneSpec> readClipPlanes(const json::Value& value, const Scene& scene);

}  // namespace eikon
