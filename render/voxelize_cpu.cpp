#include <cmath>
#include <cstdint>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/error.h"
#include "render/voxelize.h"
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

struct BlurKernelCpu {
    const float* source;
    ivec3 res;
    float fetchUnblurred(ivec3 v) const {
        return source[(size_t(v.z) * size_t(res.y) + size_t(v.y)) * size_t(res.x) + size_t(v.x)];
    }

#include "shaders/shared/gaussian_blur.h"
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

std::vector<float> voxelizeCoverageCpu(const TriangleMesh& mesh, const RenderVolume& volume) {
    using shared::VoxelizeKernelCpu;
    const glm::ivec3 res = volume.resolution;
    const glm::ivec3 fineRes = res * VoxelizeKernelCpu::EK_VOXELIZE_SUPERSAMPLE;
    const glm::vec3 fineVoxel = volume.voxelSize() / float(VoxelizeKernelCpu::EK_VOXELIZE_SUPERSAMPLE);
    const int words = (fineRes.z + 31) / 32;  // voxelizeWordsPerColumn
    const size_t columns = size_t(fineRes.x) * size_t(fineRes.y);
    std::vector<std::uint32_t> bits(columns * size_t(words), 0u);
    VoxelizeKernelCpu kernel{bits.data(), bits.data(), words};

    tbb::parallel_for(tbb::blocked_range<size_t>(0, mesh.triangles.size(), 256),
                      [&](const tbb::blocked_range<size_t>& r) {
                          for (size_t t = r.begin(); t != r.end(); ++t) {
                              const glm::uvec3 tri = mesh.triangles[t];
                              kernel.voxelizeTriangle(mesh.positions[tri.x], mesh.positions[tri.y],
                                                      mesh.positions[tri.z], volume.bounds.min,
                                                      fineVoxel, fineRes);
                          }
                      });
    tbb::parallel_for(tbb::blocked_range<size_t>(0, columns), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t c = r.begin(); c != r.end(); ++c) {
            std::uint32_t carry = 0;
            for (int w = 0; w < words; ++w)
                bits[c * size_t(words) + size_t(w)] =
                    kernel.voxelizePrefixXor(bits[c * size_t(words) + size_t(w)], carry);
        }
    });
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

std::vector<float> blurCoverageCpu(const std::vector<float>& coverage, glm::ivec3 res,
                                   const IndexBlurSettings& settings) {
    if (settings.radiusVoxels <= 0) return coverage;
    std::vector<float> a = coverage, b(coverage.size());
    for (int axis = 0; axis < 3; ++axis) {
        shared::BlurKernelCpu kernel{a.data(), res};
        tbb::parallel_for(tbb::blocked_range<int>(0, res.z), [&](const tbb::blocked_range<int>& r) {
            for (int z = r.begin(); z != r.end(); ++z)
                for (int y = 0; y < res.y; ++y)
                    for (int x = 0; x < res.x; ++x)
                        b[(size_t(z) * size_t(res.y) + size_t(y)) * size_t(res.x) + size_t(x)] =
                            kernel.gaussianBlurAlongAxis(glm::ivec3(x, y, z), res, axis,
                                                         settings.sigmaVoxels,
                                                         settings.radiusVoxels);
        });
        std::swap(a, b);
    }
    return a;
}

}  // namespace eikon
