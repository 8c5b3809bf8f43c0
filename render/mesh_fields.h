#pragma once
// The fields a scene's meshes write (core/scene.h MeshObjectSpec): each mesh placed in the world,
// voxelized into coverage at the render resolution (render/voxelize.h; on the GPU when given a
// voxelizer, else by the CPU twin), overlaps resolved (a later mesh displaces earlier ones), and
// the coverage blurred for n. A mesh is voxelized again only when its triangles (setMesh), its
// placement or the render volume changed; the others keep their coverage.
//
// The blur and the overlap rule run on the host for both backends, and the GPU's coverage is read
// back for them: host stages (the index check, the photon bookkeeping, the upload) read the dense
// grids. Keeping the fields on the GPU end to end is left to do.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/dense_grid.h"
#include "core/level_set.h"
#include "core/scene.h"
#include "core/triangle_mesh.h"

namespace eikon {

class MeshVoxelizerGpu;

class MeshFields {
public:
    // Generates the shapes' meshes and reads the level sets (core/level_set.h; errors name the
    // mesh's "file"); meshes from files wait for setMesh.
    explicit MeshFields(const Scene& scene);

    // The object-space triangles of mesh `index` (a file's, or a deformer's output each frame).
    // Throws eikon::Error for an index out of range or an unusable mesh (NaN, bad indices).
    void setMesh(const Scene& scene, size_t index, TriangleMesh objectSpace);

    // World bounds of every mesh, in the scene's order (for the render volume). Throws
    // eikon::Error naming the mesh's JSON path when a file mesh was never set.
    std::vector<Bounds3> worldBounds(const Scene& scene);

    // Brings both fields of every mesh up to date in `dense` (by field name).
    void update(const Scene& scene, const RenderVolume& volume, MeshVoxelizerGpu* gpu,
                std::map<std::string, DenseGrid>& dense);

    // Meshes voxelized since construction (a camera or light change adds none).
    int voxelizations() const { return voxelizations_; }

private:
    struct Mesh {
        TriangleMesh local;
        bool loaded = false;
        std::uint64_t version = 0;  // of `local`
        std::vector<unsigned char> placedKey;
        TriangleMesh placed;
        std::vector<unsigned char> coverageKey;
        std::vector<float> coverage;       // before the overlap rule
        std::optional<LevelSet> levelSet;  // a LevelSet shape: its coverage from the distance
    };
    const TriangleMesh& placed(const Scene& scene, size_t index);

    std::vector<Mesh> meshes_;
    std::uint64_t composed_ = 0;             // version of the fields written to `dense`
    std::vector<unsigned char> composeKey_;  // what they were made from
    int voxelizations_ = 0;
};

}  // namespace eikon
