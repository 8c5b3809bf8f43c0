#pragma once
// A scene's keyframe tracks, resolved once and applied at any time (sim/keyframes.h evaluates;
// core/animation_targets.h writes). Time comes from the one clock (sim/clock.h timeOfFrame), so
// frame f of a scene always shows the same state: apply() depends on nothing but the time.
#include <vector>

#include "core/animation_targets.h"
#include "core/scene.h"

namespace eikon::sim {

class SceneAnimation {
public:
    // Throws eikon::Error naming the track when a target no longer resolves in `scene`.
    explicit SceneAnimation(const Scene& scene);

    bool empty() const { return tracks_.empty(); }
    // Writes every track's value at `seconds` into `scene` (the scene they were resolved in, or
    // a copy of it); values no track animates are left as they are.
    void apply(double seconds, Scene& scene) const;

private:
    struct Resolved {
        AnimationTrack track;
        AnimationTarget target;
    };
    std::vector<Resolved> tracks_;
};

}  // namespace eikon::sim
