#include "sim/smoke_publish.h"

#include <cmath>

#include <openvdb/openvdb.h>

#include "core/field_registry.h"
#include "core/vdb_export.h"
#include "core/vdb_import.h"

namespace eikon::sim {
namespace {

// Index (i, j, k) -> world origin + (i+½, j+½, k+½)·h: OpenVDB index space is cell-centred.
openvdb::math::Transform::Ptr domainTransform(const Domain& d) {
    auto xform = openvdb::math::Transform::createLinearTransform(double(d.voxelSize));
    const glm::vec3 centre0 = d.cellCenter(0, 0, 0);
    xform->postTranslate(openvdb::Vec3d(centre0.x, centre0.y, centre0.z));
    return xform;
}

// Values below kExportPruneTolerance stay background, as `eikon simulate` writes them
// (core/vdb_export.h): a frame rendered live and the same frame rendered from the cache are then
// the same fields, so the same bytes (a farm renders from the cache, a workstation live).
openvdb::FloatGrid::Ptr scalarGrid(const Array3& a, const Domain& d, const std::string& name) {
    auto grid = openvdb::FloatGrid::create(0.0f);
    grid->setName(name);
    grid->setTransform(domainTransform(d));
    auto acc = grid->getAccessor();
    const glm::ivec3 n = a.size();
    for (int k = 0; k < n.z; ++k)
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i < n.x; ++i) {
                const float v = a(i, j, k);
                if (std::abs(v) >= kExportPruneTolerance) acc.setValue(openvdb::Coord(i, j, k), v);
            }
    return grid;
}

openvdb::Vec3SGrid::Ptr staggeredGrid(const MacGrid& g, const std::string& name) {
    auto grid = openvdb::Vec3SGrid::create(openvdb::Vec3s(0.0f));
    grid->setName(name);
    grid->setTransform(domainTransform(g.domain));
    grid->setGridClass(openvdb::GRID_STAGGERED);
    grid->setVectorType(openvdb::VEC_CONTRAVARIANT_RELATIVE);
    auto acc = grid->getAccessor();
    const glm::ivec3 n = g.resolution();
    // Voxels up to n on each axis: the +x faces of the last cells live in voxel (n.x, j, k).
    for (int k = 0; k <= n.z; ++k)
        for (int j = 0; j <= n.y; ++j)
            for (int i = 0; i <= n.x; ++i) {
                openvdb::Vec3s v(0.0f);
                for (int a = 0; a < 3; ++a) {
                    const Array3& face = g.velocity[std::size_t(a)];
                    const glm::ivec3 s = face.size();
                    if (i < s.x && j < s.y && k < s.z) v[a] = face(i, j, k);
                }
                if (v != openvdb::Vec3s(0.0f)) acc.setValue(openvdb::Coord(i, j, k), v);
            }
    return grid;
}

}  // namespace

void publishSmoke(const MacGrid& grid, FieldRegistry& registry, const std::string& origin,
                  const std::string& label) {
    ensureOpenVdbInitialized();
    const auto name = [&](const char* kind) {
        return label.empty() ? std::string(kind) : std::string(kind) + "." + label;
    };
    registry.set(name(field::kDensity),
                 scalarGrid(grid.density, grid.domain, name(field::kDensity)), origin + ":density");
    registry.set(name(field::kTemperature),
                 scalarGrid(grid.temperature, grid.domain, name(field::kTemperature)),
                 origin + ":temperature");
    registry.set(name(field::kVelocity), staggeredGrid(grid, name(field::kVelocity)),
                 origin + ":velocity");
}

}  // namespace eikon::sim
