#include "core/mesh_placement.h"

#include <cmath>

#include "core/mesh_primitives.h"

namespace eikon {

TriangleMesh meshShape(const MeshObjectSpec& spec) {
    switch (spec.shape) {
        case MeshShapeType::Icosphere:
            return icosphere(glm::vec3(0.0f), spec.radius, spec.subdivisions);
        case MeshShapeType::Box:
            return boxMesh(spec.boxMin, spec.boxMax);
        case MeshShapeType::Water: {
            // The pool's room: its rest body with headroom for every droplet's dent above and
            // below the rest surface, so that the render volume does not follow the waves.
            float headroom = 0.0f;
            for (const WaterDropletSpec& d : spec.water.droplets) headroom += std::abs(d.depth);
            const glm::vec2 half = 0.5f * spec.water.size;
            return boxMesh({-half.x, 0.0f, -half.y}, {half.x, spec.water.depth + headroom, half.y});
        }
        case MeshShapeType::File:
        case MeshShapeType::Liquid:
        case MeshShapeType::LevelSet:
            break;
    }
    return {};
}

const MeshObjectSpec& placementOf(const Scene& scene, size_t index) {
    const MeshObjectSpec& mesh = scene.meshes[index];
    return mesh.shape == MeshShapeType::Liquid ? scene.meshes[size_t(mesh.container)] : mesh;
}

glm::vec3 placePoint(glm::vec3 local, const MeshObjectSpec& spec) {
    return spec.translation + spec.rotation * (spec.scale * local);
}

glm::vec3 unplaceMotion(glm::vec3 world, const MeshObjectSpec& spec) {
    return (glm::conjugate(spec.rotation) * world) / spec.scale;
}

TriangleMesh placeMesh(const TriangleMesh& local, const MeshObjectSpec& spec) {
    TriangleMesh world = local;
    for (glm::vec3& p : world.positions) p = placePoint(p, spec);
    return world;
}

TriangleMesh unplaceMesh(const TriangleMesh& world, const MeshObjectSpec& spec) {
    TriangleMesh local = world;
    for (glm::vec3& p : local.positions) p = unplaceMotion(p - spec.translation, spec);
    return local;
}

}  // namespace eikon
