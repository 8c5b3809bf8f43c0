#include "sim/jelly_from_scene.h"

namespace eikon::sim {

JellySettings jellySettingsFor(const JellySpec& spec, double fps) {
    JellySettings s;
    s.mass = spec.mass;
    s.stiffness = spec.stiffness;
    s.bendStiffness = spec.bendStiffness;
    s.volumeStiffness = spec.volumeStiffness;
    s.damping = spec.damping;
    s.gravity = spec.gravity;
    s.floor = spec.floorY.has_value();
    s.floorY = spec.floorY.value_or(0.0f);
    s.friction = spec.friction;
    s.substeps = spec.substeps;
    s.fps = fps;
    for (const JellyPokeSpec& p : spec.pokes)
        s.pokes.push_back({p.time, p.position, p.radius, p.velocity});
    return s;
}

}  // namespace eikon::sim
