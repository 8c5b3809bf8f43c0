// The "receivers" array of a scene, read as strictly as the rest (see scene.cpp): every error
// names "<file>:/receivers/<i>/...". Keep in step with docs/scene-format.md#receivers.
#include "core/scene_receivers.h"

namespace eikon {
namespace {

using json::Object;
using json::Range;
using json::Value;

// Texels per voxel edge of a plane receiver's map: 8 already gives 64 texels per voxel face,
// far below a photon's spacing at any usable photon count.
constexpr int kMaxTexelsPerVoxel = 8;

ReceiverSpec readReceiver(const Value& value) {
    Object object(value, "a receiver");
    ReceiverSpec r;
    r.jsonPath = value.pointer();
    object.required("type", "\"plane\"").choice({"plane"});
    const std::string axis =
        object.required("axis", "\"x\", \"y\" or \"z\"").choice({"x", "y", "z"});
    r.axis = axis == "x" ? 0 : axis == "y" ? 1 : 2;
    r.position = object.required("position", "a number").floatNumber();
    if (auto facing = object.optional("facing"))
        r.facing = facing->choice({"+", "-"}) == "+" ? 1 : -1;
    if (auto albedo = object.optional("albedo")) r.albedo = albedo->vec3(Range::closed(0.0, 1.0));
    if (auto method = object.optional("method"))
        r.method = method->choice({"plane", "voxels"}) == "plane" ? ReceiverMethod::Plane
                                                                  : ReceiverMethod::Voxels;
    if (auto texels = object.optional("texels_per_voxel"))
        r.texelsPerVoxel = int(texels->integer(1, kMaxTexelsPerVoxel));
    object.finish();
    return r;
}

}  // namespace

std::vector<ReceiverSpec> readReceivers(const Value& value) {
    std::vector<ReceiverSpec> receivers;
    for (const Value& element : value.elements("an array of receivers", kMaxReceivers))
        receivers.push_back(readReceiver(element));
    return receivers;
}

}  // namespace eikon
