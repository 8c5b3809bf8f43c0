#pragma once
// What keyframe tracks may animate, and how a value is written into the scene. A target is a JSON
// pointer into the scene as written ("/lights/0/position"); resolving it against a parsed scene
// checks that the object exists and says how many numbers a key holds and which values are valid.
// Interpolation (sim/keyframes.h) can overshoot the keys, so writeTarget() brings a value back
// into the valid range (and normalizes directions and rotations) rather than failing mid-render.
#include <optional>
#include <string>

#include "core/scene.h"

namespace eikon {

enum class TargetKind {
    MeshTranslate,
    MeshRotation,
    MeshScale,
    HandleTranslate,
    HandleRotation,  // an ARAP deformer's handle
    LightPosition,
    LightDirection,
    LightColor,
    LightIntensity,
    LightCone,
    LightSoftness,
    LightAngularDiameter,
    ClipPoint,
    ClipNormal,
    CameraPosition,
    CameraLookAt,
    CameraFov,
    MaterialAbsorption,
    MaterialScattering,
    MaterialEmission,
    MaterialIor,
    MaterialG,
    SourceCenter,
    SourceVelocity,
    SourceDensityRate,
    SourceTemperatureRate,
    SourceVelocityRate,
};

struct AnimationTarget {
    TargetKind kind = TargetKind::LightIntensity;
    // mesh, light, clip plane, material (in Scene::materials) or smoke source (in
    // simulations[domain].sources) index
    int index = 0;
    int handle = 0;  // HandleTranslate, HandleRotation: the handle's index in the deformer
    int domain = 0;  // Source*: the smoke domain's index in Scene::simulations
    int width = 1;   // numbers per value: 1, 3, or 4 (a quaternion [x, y, z, w])
    double lo = -1e30, hi = 1e30;  // the valid range of each number (quaternions: unit length)
    bool rotation = false;         // a quaternion: slerp, normalized
};

// The target `pointer` names in `scene`, or nothing with `why` set to the reason (unknown path,
// index out of range, an automatic camera, a mesh without that optic).
std::optional<AnimationTarget> resolveAnimationTarget(const Scene& scene,
                                                      const std::string& pointer, std::string& why);

// The pointers a message can list as examples.
const char* animationTargetExamples();

// Writes `value` (target.width numbers) into the scene: clamped to the target's range, a direction
// or rotation normalized.
void writeAnimationTarget(Scene& scene, const AnimationTarget& target, const float* value);

}  // namespace eikon
