#include "core/mesh_voxelize.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/error.h"
#include "shaders/shared/platform.h"

EK_NAMESPACE_BEGIN

// The shared voxelization code with its hooks: flips land in `toggles` through atomic XOR (so
// triangles can run in parallel and the result does not depend on their order); the count reads
// the scanned words.
struct VoxelizeKernelCpu {
    std::uint32_t* toggles;
    const std::uint32_t* inside;
    int wordsPerColumn;

    void toggleSample(int column, int k) const {
        __atomic_fetch_xor(&toggles[size_t(column) * size_t(wordsPerColumn) + size_t(k / 32)],
                           std::uint32_t(1) << (k % 32), __ATOMIC_RELAXED);
    }
    uint fetchInsideWord(int index) const { return inside[index]; }

#include "shaders/shared/voxelize.h"
};

EK_NAMESPACE_END

namespace eikon {

void checkMeshForVoxelization(const TriangleMesh& mesh, const std::string& what) {
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int c = 0; c < 3; ++c) {
            const unsigned index = mesh.triangles[t][c];
            if (index >= mesh.positions.size())
                throw Error(what, "triangle " + std::to_string(t) + " uses vertex " +
                                      std::to_string(index) + " of " +
                                      std::to_string(mesh.positions.size()));
            const glm::vec3 p = mesh.positions[index];
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                throw Error(what, "vertex " + std::to_string(index) + " is not finite");
        }
}

void checkMeshFitsVoxelGrid(const TriangleMesh& mesh, const std::string& what, glm::vec3 gridMin,
                            glm::vec3 cellSize, glm::ivec3 resolution) {
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        const glm::vec3 p = mesh.positions[v];
        for (int axis = 0; axis < 3; ++axis) {
            // Cells from the grid's nearer face, in double so that nothing overflows.
            const double cell = (double(p[axis]) - double(gridMin[axis])) / double(cellSize[axis]);
            const double outside = std::max(-cell, cell - double(resolution[axis]));
            if (std::isfinite(cell) && outside <= kMaxVoxelsFromGrid) continue;
            std::ostringstream reason;
            reason << "vertex " << v << " at (" << p.x << ", " << p.y << ", " << p.z << ") lies "
                   << outside << " voxels (of " << cellSize[axis] << " along " << char('x' + axis)
                   << ") outside the grid; the voxelizer resolves at most " << kMaxVoxelsFromGrid
                   << ": the mesh's scale or placement, or the volume's "
                   << "size, is far off";
            throw Error(what, reason.str());
        }
    }
}

InsideBits voxelizeInsideCpu(const TriangleMesh& mesh, glm::vec3 gridMin, glm::vec3 cellSize,
                             glm::ivec3 resolution) {
    using shared::VoxelizeKernelCpu;
    VoxelizeKernelCpu kernel{nullptr, nullptr, 0};
    InsideBits out;
    out.resolution = resolution;
    out.wordsPerColumn = kernel.voxelizeWordsPerColumn(resolution.z);
    const int words = out.wordsPerColumn;
    const size_t columns = size_t(resolution.x) * size_t(resolution.y);
    out.words.assign(columns * size_t(words), 0u);
    std::vector<std::uint32_t>& bits = out.words;
    kernel = VoxelizeKernelCpu{bits.data(), bits.data(), words};

    tbb::parallel_for(tbb::blocked_range<size_t>(0, mesh.triangles.size(), 256),
                      [&](const tbb::blocked_range<size_t>& r) {
                          for (size_t t = r.begin(); t != r.end(); ++t) {
                              const glm::uvec3 tri = mesh.triangles[t];
                              kernel.voxelizeTriangle(mesh.positions[tri.x], mesh.positions[tri.y],
                                                      mesh.positions[tri.z], gridMin, cellSize,
                                                      resolution);
                          }
                      });
    tbb::parallel_for(
        tbb::blocked_range<size_t>(0, columns), [&](const tbb::blocked_range<size_t>& r) {
            for (size_t c = r.begin(); c != r.end(); ++c) {
                std::uint32_t carry = 0;
                for (int w = 0; w < words; ++w)
                    bits[c * size_t(words) + size_t(w)] =
                        kernel.voxelizePrefixXor(bits[c * size_t(words) + size_t(w)], carry);
            }
        });
    return out;
}

int voxelizeSupersample() {
    return shared::VoxelizeKernelCpu::EK_VOXELIZE_SUPERSAMPLE;
}

int voxelizeWordsPerColumn(int fineResolutionZ) {
    return shared::VoxelizeKernelCpu{nullptr, nullptr, 0}.voxelizeWordsPerColumn(fineResolutionZ);
}

std::vector<float> voxelizeCoverageCpu(const TriangleMesh& mesh, const RenderVolume& volume) {
    using shared::VoxelizeKernelCpu;
    const glm::ivec3 res = volume.resolution;
    const glm::ivec3 fineRes = res * VoxelizeKernelCpu::EK_VOXELIZE_SUPERSAMPLE;
    const glm::vec3 fineVoxel =
        volume.voxelSize() / float(VoxelizeKernelCpu::EK_VOXELIZE_SUPERSAMPLE);
    const InsideBits fine = voxelizeInsideCpu(mesh, volume.bounds.min, fineVoxel, fineRes);
    VoxelizeKernelCpu kernel{nullptr, fine.words.data(), fine.wordsPerColumn};
    std::vector<float> coverage(volume.voxelCount());
    tbb::parallel_for(tbb::blocked_range<int>(0, res.z), [&](const tbb::blocked_range<int>& r) {
        for (int z = r.begin(); z != r.end(); ++z)
            for (int y = 0; y < res.y; ++y)
                for (int x = 0; x < res.x; ++x)
                    coverage[(size_t(z) * size_t(res.y) + size_t(y)) * size_t(res.x) + size_t(x)] =
                        kernel.voxelizeCoverage(glm::ivec3(x, y, z), fineRes);
    });
    return coverage;
}

}  // namespace eikon
