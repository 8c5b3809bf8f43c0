#pragma once
// Evaluation of one keyframe track (core/scene.h AnimationTrack) at a time: step, linear (slerp for
// rotations), Catmull-Rom (tangents from the neighbouring keys) and glTF 2.0's CUBICSPLINE
// (Hermite with the track's own tangents). Before the first key the first value holds, after the
// last the last. Rotations come out normalized; clamping to a target's valid range is the
// writer's job (core/animation_targets.h).
#include "core/scene.h"

namespace eikon::sim {

// Writes track.width numbers of the track's value at `seconds` to `out`.
void evaluateTrack(const AnimationTrack& track, bool rotation, double seconds, float* out);

}  // namespace eikon::sim
