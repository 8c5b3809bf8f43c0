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

// environmentSize: the width and height of the environment image (render/environment_map.h)
// when scene.environment asks for one.
ViewSetup makeViewSetup(const Scene& scene, const RenderVolume& volume, const CameraFrame& camera,
                        glm::ivec2 environmentSize = glm::ivec2(0));

// Whether the viewing pass takes in-scattered light from photon volumes (scene.render.photons:
// "on" when something scatters or a receiver shows the light; "auto" when, besides, some
// material refracts, so that straight light volumes would be wrong). makeViewSetup then sets
// params.pipeline.y and, in pipeline.z, the lights that emit photons; the others keep their light
// volumes.
bool scenePhotonsWanted(const Scene& scene);
bool lightEmitsPhotons(LightType type);

}  // namespace eikon
