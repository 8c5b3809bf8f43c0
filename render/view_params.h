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
    // slot -> field name (or "<field>|<material>" for a material's transfer function,
    // core/transfer_function.h), the textures to bind in order
    std::vector<std::string> slotFields;
    // Dispersion (core/dispersion.h): per material, n − 1 per unit of its field in the red, green
    // and blue channels, when any material of a scene with curved rays disperses; empty when none
    // does. params holds the green channel's (the d line's, ior − 1).
    std::vector<glm::vec3> channelIndexSlopes;
};

// Whether view rays trace each colour channel with its own n (channelViewParams).
inline bool dispersesView(const ViewSetup& setup) {
    return !setup.channelIndexSlopes.empty();
}
// setup.params for the rays of colour channel `channel` (0, 1, 2: red, green, blue) under
// dispersion: every material's n − 1 that channel's, and viewChannel = channel.
shared::GpuViewParams channelViewParams(const ViewSetup& setup, int channel);

// environmentSize: the width and height of the environment image (render/environment_map.h)
// when scene.environment asks for one. The light-transport method writes its own part
// (LightTransport::configure): which lights come through the fluence, how shadows are found.
ViewSetup makeViewSetup(const Scene& scene, const RenderVolume& volume, const CameraFrame& camera,
                        glm::ivec2 environmentSize = glm::ivec2(0));

// The smallest voxel edge of the render volume the params describe, in scene units.
float smallestVoxelEdge(const shared::GpuViewParams& params);

}  // namespace eikon
