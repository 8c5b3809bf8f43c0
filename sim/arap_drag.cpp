#include "sim/arap_drag.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "core/error.h"

namespace eikon::sim {

namespace {

bool inRegion(const ArapHandleSpec& h, glm::vec3 p) {
    if (h.sphere) return glm::length(p - h.center) <= h.radius;
    return glm::all(glm::greaterThanEqual(p, h.boxMin)) &&
           glm::all(glm::lessThanEqual(p, h.boxMax));
}

}  // namespace

ArapDrag::ArapDrag(const TriangleMesh& rest, const ArapSpec& spec, const std::string& what)
    : deformer_(rest), handles_(spec.handles.size()), what_(what) {
    // Only vertices the triangles use can be handles: the deformer moves nothing else.
    std::vector<bool> used(rest.positions.size(), false);
    for (const glm::uvec3& t : rest.triangles) used[t.x] = used[t.y] = used[t.z] = true;
    std::vector<int> owner(rest.positions.size(), -1);
    std::vector<std::uint32_t> all;
    for (size_t j = 0; j < spec.handles.size(); ++j) {
        const ArapHandleSpec& h = spec.handles[j];
        for (std::uint32_t v = 0; v < rest.positions.size(); ++v) {
            if (!used[v] || !inRegion(h, rest.positions[v])) continue;
            if (owner[v] >= 0)
                throw Error(what + "/deformer/handles/" + std::to_string(j),
                            "handle '" + h.name + "' shares vertex " + std::to_string(v) +
                                " with handle '" + spec.handles[size_t(owner[v])].name +
                                "': regions must not overlap on the mesh");
            owner[v] = int(j);
            handles_[j].push_back(v);
            all.push_back(v);
        }
        if (handles_[j].empty())
            throw Error(what + "/deformer/handles/" + std::to_string(j),
                        "handle '" + h.name +
                            "' holds no vertex of the mesh (its region is in "
                            "the mesh's object space, before scale, rotation and translation)");
    }
    try {
        deformer_.setHandles(all);
    } catch (const Error& e) {
        throw Error(what + "/deformer", e.reason());
    }
}

std::vector<glm::vec3> ArapDrag::handleTargets(const ArapSpec& spec) const {
    std::vector<glm::vec3> targets;
    for (size_t j = 0; j < handles_.size(); ++j) {
        const ArapHandleSpec& h = spec.handles[j];
        for (std::uint32_t v : handles_[j])
            targets.push_back(h.center + h.rotation * (deformer_.rest().positions[v] - h.center) +
                              h.translation);
    }
    return targets;
}

void ArapDrag::checkHandles(const ArapSpec& spec) const {
    if (spec.handles.size() != handles_.size())
        throw Error(what_ + "/deformer", "the handles changed after the deformer was built");
}

void ArapDrag::advanceToFrame(int frame, const SpecAtFrame& specAt) {
    if (frame < frame_) {
        deformer_.reset();
        frame_ = -1;
    }
    while (frame_ < frame) {
        const ArapSpec spec = specAt(frame_ + 1);
        checkHandles(spec);
        deformer_.solve(handleTargets(spec), spec.iterations);
        ++frame_;
    }
}

std::vector<double> ArapDrag::dragCurrentFrame(const ArapSpec& spec) {
    if (frame_ < 0) throw Error(what_ + "/deformer", "a drag needs a frame first (advanceToFrame)");
    checkHandles(spec);
    return deformer_.solve(handleTargets(spec), spec.iterations);
}

}  // namespace eikon::sim
