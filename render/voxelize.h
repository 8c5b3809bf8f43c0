#pragma once
// Voxelization of closed triangle meshes into coverage volumes at the render resolution (Sun et
// al. 2008 §4.1; shaders/shared/voxelize.h has the method), and the Gaussian blur that makes the
// coverage that feeds n smooth (shaders/shared/gaussian_blur.h). GPU and CPU twin; coverage is in
// [0, 1] per voxel, x fastest like DenseGrid.
//
// The mesh must be closed (sim/mesh_check.h rejects open ones before they get here): an open
// mesh leaves a column with odd parity, filled from the hole up to the volume's top. The CPU twin
// of the voxelization (voxelizeCoverageCpu, checkMeshForVoxelization) lives in core
// (core/mesh_voxelize.h), which the smoke solver's mesh obstacles use too.
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/dense_grid.h"
#include "core/mesh_voxelize.h"
#include "core/triangle_mesh.h"

namespace eikon {

class ShaderProgram;

struct IndexBlurSettings {
    float sigmaVoxels = 1.5f;  // Sun et al.: σ = window/6
    int radiusVoxels = 4;      // window 2·radius + 1 = 9; 0 turns the blur off
};

// CPU twin of the separable blur (three passes, each voxel independent).
std::vector<float> blurCoverageCpu(const std::vector<float>& coverage, glm::ivec3 res,
                                   const IndexBlurSettings& settings);

// An R32F 3D texture of coverage that the voxelizer writes and blurs on the GPU, and its read-back,
// for callers that keep the coverage there between the two (`eikon bench voxelize` times each
// on one). Needs a current GL context for its whole life.
class CoverageTextureGpu {
public:
    explicit CoverageTextureGpu(glm::ivec3 resolution);
    ~CoverageTextureGpu();
    CoverageTextureGpu(const CoverageTextureGpu&) = delete;
    CoverageTextureGpu& operator=(const CoverageTextureGpu&) = delete;

    unsigned texture() const { return texture_; }
    glm::ivec3 resolution() const { return resolution_; }
    // The coverage, x fastest like DenseGrid.
    std::vector<float> download() const;

private:
    unsigned texture_ = 0;
    glm::ivec3 resolution_;
};

class MeshVoxelizerGpu {
public:
    MeshVoxelizerGpu();
    ~MeshVoxelizerGpu();
    MeshVoxelizerGpu(const MeshVoxelizerGpu&) = delete;
    MeshVoxelizerGpu& operator=(const MeshVoxelizerGpu&) = delete;

    // Writes the mesh's coverage into `target`, an R32F 3D texture of volume.resolution.
    void voxelize(const TriangleMesh& mesh, const RenderVolume& volume, unsigned target);
    // The same, read back into host memory (x fastest), through a CoverageTextureGpu it keeps.
    std::vector<float> voxelizeToHost(const TriangleMesh& mesh, const RenderVolume& volume);
    // Blurs R32F `texture` in place (through an internal scratch texture of the same size).
    void blur(unsigned texture, glm::ivec3 res, const IndexBlurSettings& settings);

private:
    void ensureScratch(glm::ivec3 res);

    std::unique_ptr<ShaderProgram> toggle_, scan_, coverage_, blur_;
    unsigned positions_ = 0, triangles_ = 0, bits_ = 0;
    size_t bitWords_ = 0;  // the size bits_ was allocated for
    unsigned scratch_ = 0;
    glm::ivec3 scratchRes_{0};
    std::unique_ptr<CoverageTextureGpu> hostTarget_;
};

}  // namespace eikon
