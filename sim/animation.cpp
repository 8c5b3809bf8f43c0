#include "sim/animation.h"

#include "core/error.h"
#include "sim/keyframes.h"

namespace eikon::sim {

SceneAnimation::SceneAnimation(const Scene& scene) {
    for (const AnimationTrack& track : scene.animation) {
        std::string why;
        const auto target = resolveAnimationTarget(scene, track.target, why);
        if (!target) throw Error(scene.path + ":" + track.jsonPath + "/target", why);
        tracks_.push_back({track, *target});
    }
}

void SceneAnimation::apply(double seconds, Scene& scene) const {
    for (const Resolved& r : tracks_) {
        float value[4] = {0, 0, 0, 0};
        evaluateTrack(r.track, r.target.rotation, seconds, value);
        writeAnimationTarget(scene, r.target, value);
    }
}

}  // namespace eikon::sim
