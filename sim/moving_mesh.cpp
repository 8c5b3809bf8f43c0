#include "sim/moving_mesh.h"

#include "core/mesh_placement.h"
#include "sim/jelly.h"
#include "sim/water_surface.h"

namespace eikon::sim {
namespace {

// A pool of water under the damped wave equation: its surface mesh is made in object space.
class WaterMovingMesh final : public MovingMesh {
public:
    WaterMovingMesh(std::size_t mesh, const WaterSettings& settings)
        : mesh_(mesh), water_(settings) {}
    std::size_t meshIndex() const override { return mesh_; }
    void advanceToFrame(int frame, const Scene&, const SceneAtFrame&) override {
        water_.advanceToFrame(frame);
    }
    TriangleMesh objectSpaceMesh(const Scene&) const override { return water_.mesh(); }

private:
    std::size_t mesh_;
    WaterSurface water_;
};

// A jelly lives in the world, starting where the mesh is placed; the renderer places it again,
// so its shape goes back to object space through the current placement.
class JellyMovingMesh final : public MovingMesh {
public:
    JellyMovingMesh(std::size_t mesh, const TriangleMesh& world, const JellySettings& settings)
        : mesh_(mesh), jelly_(world, settings) {}
    std::size_t meshIndex() const override { return mesh_; }
    void advanceToFrame(int frame, const Scene&, const SceneAtFrame&) override {
        jelly_.advanceToFrame(frame);
    }
    TriangleMesh objectSpaceMesh(const Scene& now) const override {
        return unplaceMesh(jelly_.mesh(), now.meshes[mesh_]);
    }

private:
    std::size_t mesh_;
    Jelly jelly_;
};

}  // namespace

std::unique_ptr<MovingMesh> makeMovingMesh(const Scene& scene, std::size_t m,
                                           const TriangleMesh& local) {
    const MeshObjectSpec& spec = scene.meshes[m];
    if (spec.shape == MeshShapeType::Water)
        return std::make_unique<WaterMovingMesh>(m, waterSettings(spec.water, scene.time.fps));
    if (spec.jelly)
        return std::make_unique<JellyMovingMesh>(m, placeMesh(local, spec),
                                                 jellySettings(*spec.jelly, scene.time.fps));
    // Dragged in object space: the placement still applies (and may be animated).
    if (spec.arap)
        return std::make_unique<ArapMovingMesh>(m, local, *spec.arap,
                                                scene.path + ":" + spec.jsonPath);
    return nullptr;
}

ArapMovingMesh::ArapMovingMesh(std::size_t mesh, const TriangleMesh& local, const ArapSpec& spec,
                               const std::string& what)
    : mesh_(mesh), drag_(local, spec, what), dragOffsets_(spec.handles.size(), glm::vec3(0.0f)) {}

ArapSpec ArapMovingMesh::withDrags(const Scene& scene) const {
    ArapSpec spec = *scene.meshes[mesh_].arap;
    for (std::size_t j = 0; j < spec.handles.size() && j < dragOffsets_.size(); ++j)
        spec.handles[j].translation += dragOffsets_[j];
    return spec;
}

void ArapMovingMesh::advanceToFrame(int frame, const Scene& now, const SceneAtFrame& earlier) {
    // Frames before this one need their own handle positions: the tracks evaluated on a copy of
    // the scene at each frame's time.
    drag_.advanceToFrame(frame, [&](int k) {
        if (k == frame || !earlier) return withDrags(now);
        return withDrags(earlier(k));
    });
}

void ArapMovingMesh::drag(std::size_t handle, glm::vec3 objectMotion, const Scene& now) {
    dragOffsets_[handle] += objectMotion;
    drag_.dragCurrentFrame(withDrags(now));
}

}  // namespace eikon::sim
