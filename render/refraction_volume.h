#pragma once
// Refraction volumes, pipeline stages 2 and 3 of Sun et al. 2008 (docs: shaders/shared/
// refraction.h, shaders/shared/octree.h), on the GPU and in the CPU twin. Both are RGBA32F
// volumes at the render resolution, x fastest like DenseGrid:
//  - gradient: xyz = ∇n in scene units, w = n, at each voxel centre;
//  - octree:   x = label (pyramid level, as a float), y = Δs_max in scene units
//              (kUnlimitedStep where the labelled node is flat within ε), z, w = n_min, n_max of
//              the labelled node.
#include <cstddef>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/dense_grid.h"
#include "render/view_params.h"

namespace eikon {

class GpuStageTimer;
class ParamsBuffer;
class ShaderProgram;
class VolumeTextures;

// The octree's tolerances and step bounds (paper defaults, §5.3). Steps are in voxels of the
// render volume's smallest edge, converted to scene units when the labels are written.
struct OctreeSettings {
    float epsilon = 0.005f;        // a node flatter than this is a leaf with unlimited steps
    float epsilonPrime = 0.02f;    // a node flatter than this is a leaf with steps capped...
    float stepLimitVoxels = 8.0f;  // ...at this
    float minStepVoxels = 1.0f;    // Δs_max where no node of level ≥ 1 is within epsilonPrime
    // Optical depth a node's extinction may vary by across it and still be a leaf (not in the
    // paper: shaders/shared/octree.h); ≤ 0: κ does not limit steps.
    float kappaTolerance = 0.0f;
};

// Δs_max of a node flat within ε (EK_UNLIMITED_STEP in shaders/shared/octree.h).
constexpr float kUnlimitedStep = 1e30f;

using RefractionVolumeCpu = std::vector<glm::vec4>;  // x fastest, like DenseGrid

// Levels of the min/max pyramid for a volume of `resolution` voxels (0 = voxels .. coarsest).
int octreeLevelCount(glm::ivec3 resolution);
// Nodes per axis at a pyramid level, and the nodes of all levels together.
glm::ivec3 octreeLevelSize(glm::ivec3 resolution, int level);
size_t octreePyramidNodeCount(glm::ivec3 resolution);
// Δs in scene units for `voxels` voxels of the render volume's smallest edge.
float octreeStepInScene(const ViewSetup& setup, float voxels);

// CPU twins, parallel over voxels; results do not depend on the thread count.
RefractionVolumeCpu computeIndexGradientCpu(const ViewSetup& setup,
                                            const std::vector<const DenseGrid*>& slotGrids);
// Under dispersion (dispersesView(setup)): the red and blue channels' ∇n volumes, each from its
// channel's indices (channelViewParams); the green channel's is computeIndexGradientCpu's.
struct ChannelGradientsCpu {
    RefractionVolumeCpu red, blue;
};
ChannelGradientsCpu computeChannelGradientsCpu(const ViewSetup& setup,
                                               const std::vector<const DenseGrid*>& slotGrids);
// Level 0 of the octree's min/max pyramid: per voxel (n_min, n_max, κ_min, κ_max) over the
// windows of shaders/shared/octree.h pyramidLeafRange (n within two voxels, κ within one, clamped
// at the faces), from the gradient volume's n and the field volumes' extinction (slotGrids; none:
// κ ≡ 0). The twin computes them in separable passes, the same floats as pyramidLeafRange's
// voxel by voxel, which octreeLeafRangesPerVoxelCpu runs (the tests' oracle; the GPU's way).
std::vector<glm::vec4> octreeLeafRangesCpu(const ViewSetup& setup,
                                           const RefractionVolumeCpu& gradient,
                                           const std::vector<const DenseGrid*>& slotGrids);
std::vector<glm::vec4> octreeLeafRangesPerVoxelCpu(const ViewSetup& setup,
                                                   const RefractionVolumeCpu& gradient,
                                                   const std::vector<const DenseGrid*>& slotGrids);
// From the gradient volume's n (w) and, for settings.kappaTolerance, the extinction of the field
// volumes (slotGrids, as for computeIndexGradientCpu; none: κ ≡ 0).
RefractionVolumeCpu computeOctreeCpu(const ViewSetup& setup, const RefractionVolumeCpu& gradient,
                                     const OctreeSettings& settings = {},
                                     const std::vector<const DenseGrid*>& slotGrids = {});

class RefractionVolumesGpu {
public:
    // The gradient reads voxel values only (texelFetch), so there is no sampling path to choose.
    RefractionVolumesGpu();
    ~RefractionVolumesGpu();
    RefractionVolumesGpu(const RefractionVolumesGpu&) = delete;
    RefractionVolumesGpu& operator=(const RefractionVolumesGpu&) = delete;

    // Recomputes the gradient volume from the field textures (already uploaded) and the params
    // SSBO (already bound at EK_SSBO_VIEW_PARAMS), then the octree from its n. Timer stages:
    // "gradient", "octree". withOctree = false computes the gradient only (the viewing pass needs
    // no octree).
    void compute(const ViewSetup& setup, VolumeTextures& fields,
                 const OctreeSettings& settings = {}, GpuStageTimer* timer = nullptr,
                 bool withOctree = true);

    // Under dispersion (dispersesView(setup)), after compute: the red and blue channels' ∇n
    // volumes, uploading each channel's params (channelViewParams) to `params` for its pass and
    // setup.params again at the end. Timer stage "gradient".
    void computeChannelGradients(const ViewSetup& setup, VolumeTextures& fields,
                                 ParamsBuffer& params, GpuStageTimer* timer = nullptr);

    unsigned gradientTexture() const { return gradient_; }
    // Channel 0, 1, 2 (red, green, blue): green is gradientTexture(), the others are
    // computeChannelGradients'.
    unsigned channelGradientTexture(int channel) const;
    unsigned octreeTexture() const { return octree_; }
    // Read back for tests (compared with the CPU twins).
    RefractionVolumeCpu downloadGradient() const;
    RefractionVolumeCpu downloadOctree() const;

private:
    void allocate(glm::ivec3 resolution);
    void computeGradient(unsigned texture, glm::ivec3 resolution);
    void deleteChannelGradients();
    void computeOctree(const ViewSetup& setup, const OctreeSettings& settings);
    RefractionVolumeCpu download(unsigned texture) const;

    std::unique_ptr<ShaderProgram> gradientProgram_;
    std::unique_ptr<ShaderProgram> minMaxProgram_;
    std::unique_ptr<ShaderProgram> labelProgram_;
    unsigned gradient_ = 0;
    unsigned channelGradients_[2] = {0, 0};  // red, blue: dispersion only
    unsigned octree_ = 0;
    unsigned pyramid_ = 0;  // SSBO: every level's (n_min, n_max), see shaders/shared/octree.h
    glm::ivec3 resolution_{0};
};

}  // namespace eikon
