#pragma once
// A level set read from a VDB or NanoVDB file as a solid: OpenVDB's sphere.vdb, Houdini's "VDB
// from Polygons", Blender's mesh-to-volume SDF. Its surface is where the signed distance crosses
// zero, negative inside. A scene places it as a mesh object (core/scene.h
// MeshShapeType::LevelSet); its coverage of each render voxel comes from the distance
// (coverage), and the index blur, ∇n, overlap rule and optics are the meshes'
// (render/mesh_fields.h). A smoke simulation takes its inside as an obstacle (inside).
#include <memory>
#include <string>

#include "core/bounds.h"
#include "core/dense_grid.h"
#include "core/mesh_voxelize.h"
#include "core/scene.h"

namespace eikon {

class LevelSet {
public:
    // Reads the grid `choice` picks: by name, by index, or the file's one grid of class "level
    // set". A grid chosen by name or index that is not of that class is taken as a signed
    // distance when it has values below zero (zeno writes its SDFs unnamed and unclassed).
    // Throws eikon::Error(path, reason) for a file that cannot be read, no level set or several
    // (the reason lists the grids with their index and class), a chosen grid that is missing,
    // not float, has NaN/Inf values or nothing inside.
    static LevelSet read(const std::string& path, const GridChoice& choice);

    // "'surface' (grid 0)" or "unnamed grid 1", for messages.
    const std::string& label() const;
    // The box around the solid in the grid's world: the object space a mesh's scale, rotation and
    // translation place.
    Bounds3 bounds() const;

    // The fraction of each voxel of `volume` (x fastest) inside the solid placed by `placement`.
    // Where the surface crosses a voxel: the distance d to it and its normal from the sampled
    // field's gradient, and the exact fraction of the voxel a plane at d cuts off (so a flat face
    // at any angle is covered exactly; a curved one to second order). When the render voxel is
    // coarser than the level set's, the same over sub-voxels as fine as the set's (up to 4³),
    // so that detail the render voxel spans is averaged rather than point-sampled.
    std::vector<float> coverage(const RenderVolume& volume, const MeshObjectSpec& placement) const;

    // Cells whose centre is inside (the distance below zero), as voxelizeInsideCpu gives them for
    // a triangle mesh: the smoke solver's obstacle cells.
    InsideBits inside(glm::vec3 gridMin, glm::vec3 cellSize, glm::ivec3 resolution,
                      const MeshObjectSpec& placement) const;

private:
    struct Impl;
    std::shared_ptr<const Impl> impl_;
};

}  // namespace eikon
