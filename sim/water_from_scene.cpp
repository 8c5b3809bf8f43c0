#include "sim/water_from_scene.h"

namespace eikon::sim {

WaterSettings waterSettingsFor(const WaterSpec& spec, double fps) {
    WaterSettings s;
    s.cells = spec.cells;
    s.size = spec.size;
    s.depth = spec.depth;
    s.waveSpeed = spec.waveSpeed;
    s.damping = spec.damping;
    s.fps = fps;
    for (const WaterDropletSpec& d : spec.droplets)
        s.droplets.push_back({d.time, d.position, d.radius, d.depth});
    return s;
}

}  // namespace eikon::sim
