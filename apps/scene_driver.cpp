#include "apps/scene_driver.h"

namespace eikon::app {

SceneDriver::SceneDriver(const Scene& scene)
    : animation_(scene), clock_(scene.time.fps, 1.0) {}

void SceneDriver::prepareFrame(FrameRenderer& renderer, int frame) const {
    if (!animation_.empty()) animation_.apply(clock_.timeOfFrame(frame), renderer.scene());
}

}  // namespace eikon::app
