#include "apps/scene_driver.h"

#include "sim/water_from_scene.h"

namespace eikon::app {

SceneDriver::SceneDriver(const Scene& scene) : animation_(scene), clock_(scene.time.fps, 1.0) {
    for (size_t m = 0; m < scene.meshes.size(); ++m)
        if (scene.meshes[m].shape == MeshShapeType::Water)
            waters_.push_back({m, std::make_unique<sim::WaterSurface>(sim::waterSettingsFor(
                                      scene.meshes[m].water, scene.time.fps))});
}

void SceneDriver::prepareFrame(FrameRenderer& renderer, int frame) {
    if (!animation_.empty()) animation_.apply(clock_.timeOfFrame(frame), renderer.scene());
    for (Water& w : waters_) {
        // Only a new frame changes the surface: a camera move on the same frame re-voxelizes
        // nothing.
        if (w.frameSet == frame) continue;
        w.surface->advanceToFrame(frame);
        renderer.setMesh(w.mesh, w.surface->mesh());
        w.frameSet = frame;
    }
}

}  // namespace eikon::app
