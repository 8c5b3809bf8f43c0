#pragma once
// A scene's ARAP deformer over time (core/scene.h ArapSpec): the vertices of each handle's region
// picked once from the rest mesh, one factorization for that handle set, and each frame's shape
// solved from the previous frame's with the handles where that frame puts them, as a user's drag
// would be. Frame f is always reached through frames 0 … f (going back restarts from rest), so a
// frame is the same however it is reached, like the jelly and the water.
#include <functional>
#include <string>
#include <vector>

#include "core/scene.h"
#include "sim/arap_deformer.h"

namespace eikon::sim {

class ArapDrag {
public:
    // `what` names the mesh in errors (the scene file and its JSON path). Throws eikon::Error
    // when a handle's region holds no vertex, a vertex lies in two handles' regions, or a piece
    // of the mesh has no handle.
    ArapDrag(const TriangleMesh& rest, const ArapSpec& spec, const std::string& what);

    // The deformer's spec (its handles' motion) at frame k.
    using SpecAtFrame = std::function<ArapSpec(int frame)>;
    void advanceToFrame(int frame, const SpecAtFrame& specAt);

    // A drag while the frame stands still (eikon view's mouse): the handles go where `spec` puts
    // them and spec.iterations more iterations run from the current shape, so a run of small
    // drags converges on the dragged pose as the paper's interactive editing does. The result
    // depends on the drags' history (how many iterations each got), unlike a frame reached by
    // advanceToFrame. Needs a frame reached by advanceToFrame; returns E after each iteration.
    std::vector<double> dragCurrentFrame(const ArapSpec& spec);

    // Where the handle vertices go for `spec`'s handle motions: about each region's centre,
    // rotated then translated.
    std::vector<glm::vec3> handleTargets(const ArapSpec& spec) const;

    TriangleMesh mesh() const { return deformer_.deformedMesh(); }
    const std::vector<glm::vec3>& positions() const { return deformer_.positions(); }
    int frame() const { return frame_; }
    double energy() const { return deformer_.energy(); }
    // Per handle, the rest mesh's vertices it moves.
    const std::vector<std::vector<std::uint32_t>>& handleVertices() const { return handles_; }

private:
    // Throws unless `spec` has the handles the deformer was built with.
    void checkHandles(const ArapSpec& spec) const;

    ArapDeformer deformer_;
    std::vector<std::vector<std::uint32_t>> handles_;
    std::string what_;
    int frame_ = -1;  // -1: the rest shape
};

}  // namespace eikon::sim
