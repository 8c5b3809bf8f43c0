#pragma once
// Packs a scene, its render volume and camera into the std430 struct the viewing pass reads, and
// decides which field texture slot each material samples (one slot per distinct field).
#include <string>
#include <vector>

#include "core/camera.h"
#include "core/dense_grid.h"
#include "core/scene.h"
#include "shaders/shared/gpu_types.h"

namespace eikon {

struct ViewSetup {
    shared::GpuViewParams params{};
    std::vector<std::string> slotFields;  // slot -> field name, the textures to bind in order
};

ViewSetup makeViewSetup(const Scene& scene, const RenderVolume& volume, const CameraFrame& camera);

}  // namespace eikon
