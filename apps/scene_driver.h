#pragma once
// What the commands that render a scene do to the renderer before each frame, so that `eikon
// render` and `eikon view` show the same state at the same frame: the scene's keyframe tracks
// evaluated at the frame's time on the one clock (sim/clock.h, the scene's fps).
#include "render/frame_renderer.h"
#include "sim/animation.h"
#include "sim/clock.h"

namespace eikon::app {

class SceneDriver {
public:
    explicit SceneDriver(const Scene& scene);

    // Sets the renderer's scene to frame `frame`'s state.
    void prepareFrame(FrameRenderer& renderer, int frame) const;

private:
    sim::SceneAnimation animation_;
    SimulationClock clock_;
};

}  // namespace eikon::app
