#include "core/mesh_placement.h"

#include "core/mesh_primitives.h"

namespace eikon {

TriangleMesh meshShape(const MeshObjectSpec& spec) {
    switch (spec.shape) {
        case MeshShapeType::Icosphere:
            return icosphere(glm::vec3(0.0f), spec.radius, spec.subdivisions);
        case MeshShapeType::Box:
            return boxMesh(spec.boxMin, spec.boxMax);
        case MeshShapeType::File:
            break;
    }
    return {};
}

TriangleMesh placeMesh(const TriangleMesh& local, const MeshObjectSpec& spec) {
    TriangleMesh world = local;
    for (glm::vec3& p : world.positions) p = spec.translation + spec.rotation * (spec.scale * p);
    return world;
}

}  // namespace eikon
