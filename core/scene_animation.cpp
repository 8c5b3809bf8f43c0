// The "animation" array of a scene, read as strictly as the rest (see scene.cpp): every error
// names "<file>:/animation/<i>/...". Keep in step with docs/scene-format.md#animation.
#include "core/scene_animation.h"

#include <cmath>

#include "core/animation_targets.h"

namespace eikon {
namespace {

using json::Object;
using json::Range;
using json::Value;

constexpr std::size_t kMaxKeys = 100000;

std::string keyForm(int width) {
    if (width == 1) return "a number";
    return "an array of " + std::to_string(width) + " numbers" +
           (width == 4 ? " [x, y, z, w] (a unit quaternion)" : " [x, y, z]");
}

// One key's numbers, in the target's range (values) or any finite number (tangents).
void readKey(const Value& value, const AnimationTarget& target, bool tangent,
             std::vector<float>& out) {
    // Unbounded ends (±1e30 in the target table) read as ">= 0" or "any", not "in [0, 1e+30]".
    const bool lo = target.lo > -1e29, hi = target.hi < 1e29;
    const Range range = tangent || (!lo && !hi) ? Range::any()
                        : !hi                   ? Range::atLeast(target.lo)
                        : !lo                   ? Range::closed(-1e30, target.hi)
                                                : Range::closed(target.lo, target.hi);
    if (target.width == 1) {
        out.push_back(value.floatNumber(range));
        return;
    }
    const std::vector<Value> numbers = value.elements(keyForm(target.width), size_t(target.width));
    if (numbers.size() != size_t(target.width)) value.failExpected(keyForm(target.width));
    float length2 = 0.0f;
    for (const Value& n : numbers) {
        const float x = n.floatNumber(target.rotation ? Range::any() : range);
        length2 += x * x;
        out.push_back(x);
    }
    if (target.rotation && !tangent && !(std::abs(std::sqrt(length2) - 1.0f) < 1e-3f))
        value.fail(
            "expected a unit quaternion [x, y, z, w] (length within 1e-3 of 1), got length " +
            std::to_string(std::sqrt(length2)));
}

std::vector<std::vector<float>> readKeys(const Value& value, const AnimationTarget& target,
                                         bool tangent, std::size_t count) {
    const std::string form =
        "an array of " + std::to_string(count) + " keys, each " + keyForm(target.width);
    const std::vector<Value> keys = value.elements(form, kMaxKeys);
    if (keys.size() != count)
        value.fail("expected " + std::to_string(count) + " keys (one per time), got " +
                   std::to_string(keys.size()));
    std::vector<std::vector<float>> out;
    for (const Value& key : keys) {
        out.emplace_back();
        readKey(key, target, tangent, out.back());
    }
    return out;
}

AnimationTrack readTrack(const Value& value, const Scene& scene) {
    Object object(value, "an animation track");
    AnimationTrack track;
    track.jsonPath = value.pointer();
    const Value target = object.required("target", "a JSON pointer such as \"/lights/0/position\"");
    track.target = target.nonEmptyString();
    std::string why;
    const std::optional<AnimationTarget> resolved =
        resolveAnimationTarget(scene, track.target, why);
    if (!resolved) target.fail(why);
    track.width = resolved->width;
    if (auto interpolation = object.optional("interpolation")) {
        const std::string name =
            interpolation->choice({"step", "linear", "catmull_rom", "cubicspline"});
        track.interpolation = name == "step"          ? Interpolation::Step
                              : name == "linear"      ? Interpolation::Linear
                              : name == "catmull_rom" ? Interpolation::CatmullRom
                                                      : Interpolation::CubicSpline;
    }
    const Value times = object.required("times", "a non-empty array of seconds, increasing");
    for (const Value& t : times.elements("a non-empty array of seconds, increasing", kMaxKeys)) {
        const double seconds = t.number(Range::atLeast(0.0));
        if (!track.times.empty() && !(seconds > track.times.back()))
            t.fail("expected times to increase strictly, got " + std::to_string(seconds) +
                   " after " + std::to_string(track.times.back()));
        track.times.push_back(seconds);
    }
    if (track.times.empty()) times.failExpected("a non-empty array of seconds, increasing");
    const std::size_t n = track.times.size();
    const auto values =
        readKeys(object.required("values", "one key per time"), *resolved, false, n);
    const bool cubic = track.interpolation == Interpolation::CubicSpline;
    std::vector<std::vector<float>> in, out;
    if (cubic) {
        in = readKeys(object.required("in_tangents", "one tangent per time (cubicspline)"),
                      *resolved, true, n);
        out = readKeys(object.required("out_tangents", "one tangent per time (cubicspline)"),
                       *resolved, true, n);
    } else {
        for (const char* key : {"in_tangents", "out_tangents"})
            if (object.has(key))
                object.failAt(key, std::string("\"") + key +
                                       "\" belongs to \"interpolation\": \"cubicspline\"");
    }
    for (std::size_t k = 0; k < n; ++k) {  // glTF's CUBICSPLINE layout: in, value, out per key
        if (cubic) track.values.insert(track.values.end(), in[k].begin(), in[k].end());
        track.values.insert(track.values.end(), values[k].begin(), values[k].end());
        if (cubic) track.values.insert(track.values.end(), out[k].begin(), out[k].end());
    }
    object.finish();
    return track;
}

}  // namespace

std::vector<AnimationTrack> readAnimation(const Value& value, const Scene& scene) {
    std::vector<AnimationTrack> tracks;
    const std::vector<Value> elements = value.elements("an array of animation tracks");
    for (std::size_t i = 0; i < elements.size(); ++i) {
        AnimationTrack track = readTrack(elements[i], scene);
        for (std::size_t j = 0; j < tracks.size(); ++j)
            if (tracks[j].target == track.target)
                elements[i].child("target").fail(
                    "\"" + track.target + "\" is animated already by " + elements[j].pointer());
        tracks.push_back(std::move(track));
    }
    return tracks;
}

}  // namespace eikon
