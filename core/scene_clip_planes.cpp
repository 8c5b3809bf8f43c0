// The "clip_planes" array of a scene, read as strictly as the rest (see scene.cpp): every error
// names "<file>:/clip_planes/<i>/...". Keep in step with docs/scene-format.md#clip-planes.
#include "core/scene_clip_planes.h"

#include <algorithm>
#include <cmath>

namespace eikon {
namespace {

using json::Object;
using json::Value;

ClipPlaneSpec readClipPlane(const Value& value, const Scene& scene) {
    Object object(value, "a clip plane");
    ClipPlaneSpec plane;
    plane.jsonPath = value.pointer();
    plane.point = object.required("point", "a point [x, y, z]").vec3();
    const Value normal = object.required("normal", "a direction [x, y, z], not zero");
    const glm::vec3 n = normal.vec3();
    const float length = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    if (!(length > 1e-12f) || !std::isfinite(length))
        normal.fail("the normal is zero; it gives the side of the plane that stays");
    plane.normal = n / length;
    if (auto materials = object.optional("materials")) {
        const std::string form = "an array of material names";
        for (const Value& name : materials->elements(form, EK_MAX_MATERIALS)) {
            const std::string text = name.nonEmptyString();
            const bool known = std::any_of(scene.materials.begin(), scene.materials.end(),
                                           [&](const MaterialSpec& m) { return m.name == text; });
            if (!known) name.fail("no material is named \"" + text + "\"");
            if (std::find(plane.materials.begin(), plane.materials.end(), text) !=
                plane.materials.end())
                name.fail("material \"" + text + "\" is listed twice");
            plane.materials.push_back(text);
        }
        if (plane.materials.empty())
            materials->fail("the list is empty; leave \"materials\" out to cut every material");
    }
    object.finish();
    return plane;
}

}  // namespace

std::vector<ClipPlaneSpec> readClipPlanes(const Value& value, const Scene& scene) {
    std::vector<ClipPlaneSpec> planes;
    for (const Value& element : value.elements("an array of clip planes", kMaxClipPlanes))
        planes.push_back(readClipPlane(element, scene));
    return planes;
}

}  // namespace eikon
