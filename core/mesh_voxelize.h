#pragma once
// Which points of a regular grid lie inside a closed triangle mesh, on the CPU: the parity method
// of shaders/shared/voxelize.h (Sun et al. 2008 §4.1), the one implementation both the render
// volume's coverage (render/voxelize.h, whose GPU twin runs the same header) and the smoke
// solver's mesh obstacles (sim/smoke_from_scene.h) use. Core, so that sim needs no render.
//
// The mesh must be closed: an open mesh leaves a column with odd parity, filled from the hole up
// to the grid's top (sim/mesh_check.h rejects open ones before they get here).
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/dense_grid.h"
#include "core/triangle_mesh.h"

namespace eikon {

// The inside bits of a grid: bit k of column (i, j) says whether the centre of cell (i, j, k) is
// inside. Columns x fastest, each `wordsPerColumn` 32-bit words, lowest z first.
struct InsideBits {
    glm::ivec3 resolution{0};
    int wordsPerColumn = 0;
    std::vector<std::uint32_t> words;

    bool inside(int i, int j, int k) const {
        const std::size_t column = std::size_t(j) * std::size_t(resolution.x) + std::size_t(i);
        return (words[column * std::size_t(wordsPerColumn) + std::size_t(k / 32)] >> (k % 32)) & 1u;
    }
};

// Throws eikon::Error naming `what` (the mesh's file or name) when a position the triangles use
// is not finite or an index is out of range.
void checkMeshForVoxelization(const TriangleMesh& mesh, const std::string& what);

// Throws eikon::Error naming `what` when a vertex lies more than kMaxVoxelsFromGrid cells (of
// `cellSize`) outside the grid with corner `gridMin` and `resolution` cells, measured in double:
// the voxelizer works in float cell coordinates, which cannot tell columns apart that far out
// (and overflow beyond float range). A mesh of radius 1e30 around a volume 1e-30 wide wrote
// outside the bit array before the kernel learnt to skip such triangles; this check turns the
// absurd scale into a message instead of an empty or garbled coverage.
constexpr double kMaxVoxelsFromGrid = 16777216.0;  // 2^24: float's last exact integer
void checkMeshFitsVoxelGrid(const TriangleMesh& mesh, const std::string& what, glm::vec3 gridMin,
                            glm::vec3 cellSize, glm::ivec3 resolution);

// Inside bits at the centres of the cells of the grid with corner `gridMin`, cells of
// `cellSize` and `resolution` cells: triangles in parallel with atomic XOR (order-independent,
// so the bits do not depend on the thread count), then a prefix XOR up each column.
InsideBits voxelizeInsideCpu(const TriangleMesh& mesh, glm::vec3 gridMin, glm::vec3 cellSize,
                             glm::ivec3 resolution);

// The fine grid's samples per render voxel and axis (EK_VOXELIZE_SUPERSAMPLE), and the 32-bit
// words of one fine column of `fineResolutionZ` samples, as shaders/shared/voxelize.h defines
// them: the GPU twin sizes its grid and buffers by these, not by copies of the numbers.
int voxelizeSupersample();
int voxelizeWordsPerColumn(int fineResolutionZ);

// Coverage of each render voxel in [0, 1] (x fastest, like DenseGrid): the fraction of its
// 4×4×4 samples inside, from voxelizeInsideCpu on the grid 4 times finer. The CPU twin of
// MeshVoxelizerGpu (render/voxelize.h).
std::vector<float> voxelizeCoverageCpu(const TriangleMesh& mesh, const RenderVolume& volume);

}  // namespace eikon
