#pragma once
// The 3×3×3 smoothing of RGBA32F volumes (shaders/shared/smoothing.h), GPU and CPU twin. The
// photon pass's radiance and direction volumes go through it before the viewing pass reads them.
#include <memory>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace eikon {

class ShaderProgram;

// CPU twin: voxels in parallel, each independent, so the thread count does not matter. Voxels
// off the faces take the shared smoothedInteriorVoxel, the same sums without bounds tests (3×
// faster at 128³, BENCHMARKS.md).
std::vector<glm::vec4> smoothVolumeCpu(const std::vector<glm::vec4>& volume, glm::ivec3 res);
// Every voxel through the shared smoothedVoxel, as the GPU smooths: what tests hold
// smoothVolumeCpu to, bit for bit.
std::vector<glm::vec4> smoothVolumePerVoxelCpu(const std::vector<glm::vec4>& volume,
                                               glm::ivec3 res);

class VolumeSmootherGpu {
public:
    VolumeSmootherGpu();
    ~VolumeSmootherGpu();
    VolumeSmootherGpu(const VolumeSmootherGpu&) = delete;
    VolumeSmootherGpu& operator=(const VolumeSmootherGpu&) = delete;
    // Smooths the RGBA32F 3D texture `source` into `target` (both `res`, allocated by the caller).
    void smooth(unsigned source, unsigned target, glm::ivec3 res);

private:
    std::unique_ptr<ShaderProgram> program_;
};

}  // namespace eikon
