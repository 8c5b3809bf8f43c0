#pragma once
// A scene mesh that something moves frame by frame: a water surface, a jelly, an ARAP deformer's
// handles. One interface, so that the scene driver (pipeline/scene_driver.h) holds a list of them
// built by one factory instead of a field and a branch per kind; a new kind of moving mesh is a
// class here and a line in makeMovingMesh.
//
// Every kind reaches frame f through frames 0 … f (going back restarts), so a frame is the same
// however it is reached.
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/scene.h"
#include "sim/arap_drag.h"

namespace eikon::sim {

// The scene as its tracks put it at an earlier frame k (a copy): what a deformer whose handles
// are animated reads when it is solved frame by frame from its start.
using SceneAtFrame = std::function<Scene(int frame)>;

class MovingMesh {
public:
    virtual ~MovingMesh() = default;
    // The index of the scene mesh it moves.
    virtual std::size_t meshIndex() const = 0;
    // Brings it to `frame`. `now` is the scene at that frame; `earlier` the scene at an earlier
    // one, null when no track animates the scene (every frame then reads `now`).
    virtual void advanceToFrame(int frame, const Scene& now, const SceneAtFrame& earlier) = 0;
    // Its shape at the frame it was advanced to, in object space for `now`'s placement of the
    // mesh (what the renderer takes, core/mesh_placement.h).
    virtual TriangleMesh objectSpaceMesh(const Scene& now) const = 0;
};

// The moving mesh that scene mesh `m`, of object-space shape `local`, needs; null for one that
// nothing moves. Throws eikon::Error for a deformer that cannot be built (an ARAP handle region
// with no vertex, ...).
std::unique_ptr<MovingMesh> makeMovingMesh(const Scene& scene, std::size_t m,
                                           const TriangleMesh& local);

// An ARAP deformer (sim/arap_drag.h) whose handles follow their tracks and, on top, the user's
// drags (eikon view): a drag moves a handle at every frame, so playing or stepping frames keeps it.
class ArapMovingMesh final : public MovingMesh {
public:
    ArapMovingMesh(std::size_t mesh, const TriangleMesh& local, const ArapSpec& spec,
                   const std::string& what);

    std::size_t meshIndex() const override { return mesh_; }
    void advanceToFrame(int frame, const Scene& now, const SceneAtFrame& earlier) override;
    TriangleMesh objectSpaceMesh(const Scene&) const override { return drag_.mesh(); }

    // The deformer's spec in `scene` (its tracks applied) with the drags added.
    ArapSpec withDrags(const Scene& scene) const;
    // Adds an object-space motion to handle `handle` and re-solves the current frame's shape
    // from where it is (sim/arap_drag.h dragCurrentFrame; throws before any frame was reached).
    void drag(std::size_t handle, glm::vec3 objectMotion, const Scene& now);
    std::size_t handleCount() const { return dragOffsets_.size(); }
    const ArapDrag& deformer() const { return drag_; }

private:
    std::size_t mesh_;
    ArapDrag drag_;
    std::vector<glm::vec3> dragOffsets_;  // per handle, object space, from the user
};

}  // namespace eikon::sim
