#include <algorithm>

#include <tbb/blocked_range.h>
#include <tbb/blocked_range3d.h>
#include <tbb/parallel_for.h>

#include "render/refraction_volume.h"
#include "render/volume_kernels_cpu.h"
#include "shaders/shared/material_index.h"  // at file scope: refraction.h calls it

EK_NAMESPACE_BEGIN

// What shaders/refraction_gradient.comp sees: the field volumes and the params; and n at every
// voxel centre, refractiveIndexAtVoxel's floats computed once a voxel into w of a volume
// (computeIndexGradientCpu).
struct RefractionKernelCpu : VolumeAccessCpu {
    const vec4* indexVolume = nullptr;
    float indexVolumeAt(ivec3 v) const { return indexVolume[voxelIndex(v)].w; }
#define EK_INDEX_VOLUME
#include "shaders/shared/refraction.h"
#undef EK_INDEX_VOLUME
};

// What the octree shaders see: the pyramid SSBO, n, and κ at voxel centres (none without fields).
struct OctreeKernelCpu {
    const vec4* pyramid = nullptr;
    const vec4* gradient = nullptr;  // w: n
    VolumeAccessCpu* fields = nullptr;
    ivec3 res = ivec3(0);
    vec4 fetchPyramid(int index) const { return pyramid[index]; }
    float fetchIndex(ivec3 v) const {
        return gradient[(size_t(v.z) * size_t(res.y) + size_t(v.y)) * size_t(res.x) + size_t(v.x)]
            .w;
    }
    glm::vec2 fetchKappaRange(ivec3 v) const {
        return fields ? fields->voxelExtinctionRange(v) : glm::vec2(0.0f);
    }

#define EK_OCTREE_LEAF_RANGE
#include "shaders/shared/octree.h"
#undef EK_OCTREE_LEAF_RANGE
};

EK_NAMESPACE_END

namespace eikon {

namespace {

glm::ivec3 resolutionOf(const ViewSetup& setup) {
    return glm::ivec3(setup.params.resolution);
}

// Calls f(voxel, flat index) for every voxel, in parallel; each voxel is written by one call.
template <typename F>
void forEachVoxel(glm::ivec3 res, const F& f) {
    tbb::parallel_for(tbb::blocked_range3d<int>(0, res.z, 0, res.y, 0, res.x),
                      [&](const tbb::blocked_range3d<int>& r) {
                          for (int z = r.pages().begin(); z != r.pages().end(); ++z)
                              for (int y = r.rows().begin(); y != r.rows().end(); ++y)
                                  for (int x = r.cols().begin(); x != r.cols().end(); ++x) {
                                      const size_t i =
                                          (size_t(z) * size_t(res.y) + size_t(y)) * size_t(res.x) +
                                          size_t(x);
                                      f(glm::ivec3(x, y, z), i);
                                  }
                      });
}

// Folds s into a leaf range: x, y the min and max of n over the ±2 window, z, w those of κ over
// the ±1 window (`inner`: s lies in it too). glm::min keeps the first of equal values (+0 before
// −0), so the fold's order is pyramidLeafRange's: increasing offsets.
inline void foldLeafRange(glm::vec4& range, const glm::vec4& s, bool inner) {
    range.x = glm::min(range.x, s.x);
    range.y = glm::max(range.y, s.y);
    if (inner) {
        range.z = glm::min(range.z, s.z);
        range.w = glm::max(range.w, s.w);
    }
}

// One separable pass of the leaf ranges along `axis`: x, y the min and max over ±2 voxels, z, w
// over ±1, the window clamped at the faces as pyramidLeafRange clamps its voxels. Min and max are
// exact and the windows are boxes, so three passes give the 5³ and 3³ windows' very floats. A
// clamped voxel repeats the face's, which changes neither a min nor a max nor which of equal
// values comes first: the window is cut at the face instead. Row by row along x; across rows
// (axis 1, 2) each row of the window is folded into the whole output row in turn, a loop over
// contiguous voxels (a voxel at a time, with a clamp per offset, took 3/4 of the octree stage).
void leafRangePass(glm::ivec3 res, int axis, const std::vector<glm::vec4>& from,
                   std::vector<glm::vec4>& to) {
    const ptrdiff_t stride = axis == 0   ? 1
                             : axis == 1 ? ptrdiff_t(res.x)
                                         : ptrdiff_t(res.x) * ptrdiff_t(res.y);
    const glm::vec4 empty(EK_UNLIMITED_STEP, -EK_UNLIMITED_STEP, EK_UNLIMITED_STEP,
                          -EK_UNLIMITED_STEP);
    const int n = res[axis];
    tbb::parallel_for(tbb::blocked_range<int>(0, res.z), [&](const tbb::blocked_range<int>& r) {
        for (int z = r.begin(); z != r.end(); ++z)
            for (int y = 0; y < res.y; ++y) {
                const size_t row = (size_t(z) * size_t(res.y) + size_t(y)) * size_t(res.x);
                const glm::vec4* in = from.data() + row;
                glm::vec4* out = to.data() + row;
                if (axis == 0) {
                    for (int x = 0; x < res.x; ++x) {
                        glm::vec4 range = empty;
                        for (int at = std::max(x - 2, 0); at <= std::min(x + 2, n - 1); ++at)
                            foldLeafRange(range, in[at], at >= x - 1 && at <= x + 1);
                        out[x] = range;
                    }
                    continue;
                }
                const int v = axis == 1 ? y : z;
                std::fill(out, out + res.x, empty);
                for (int at = std::max(v - 2, 0); at <= std::min(v + 2, n - 1); ++at) {
                    const glm::vec4* source = in + ptrdiff_t(at - v) * stride;
                    const bool inner = at >= v - 1 && at <= v + 1;
                    for (int x = 0; x < res.x; ++x) foldLeafRange(out[x], source[x], inner);
                }
            }
    });
}

shared::VolumeAccessCpu fieldAccess(const ViewSetup& setup,
                                    const std::vector<const DenseGrid*>& slotGrids) {
    shared::VolumeAccessCpu fields{setup.params};
    for (size_t s = 0; s < slotGrids.size(); ++s) fields.fields[s] = slotGrids[s]->values.data();
    return fields;
}

// Each level from the one below, level by level as the GPU passes do, over level 0 (the leaf
// ranges) already in `pyramid`.
void buildPyramidLevels(glm::ivec3 res, std::vector<glm::vec4>& pyramid) {
    shared::OctreeKernelCpu k;
    const int levels = k.pyramidLevelCount(res);
    k.pyramid = pyramid.data();
    for (int level = 1; level < levels; ++level) {
        const glm::ivec3 size = k.pyramidLevelSize(res, level);
        const size_t offset = size_t(k.pyramidLevelOffset(res, level));
        // Nodes of one level only read the level below: written in parallel, in any order.
        forEachVoxel(size, [&](glm::ivec3 node, size_t i) {
            pyramid[offset + i] = k.pyramidNodeFromChildren(res, level, node);
        });
    }
}

// Level 0 into the first voxel-count entries of `ranges` (at least that long: the octree passes
// the whole pyramid, so that no level-0 copy is made), with `scratch` (as long as the volume) for
// the passes between. The shared code evaluates κ's range at 27 voxels and n at 125 for every
// voxel. Here each voxel's κ range is evaluated once, then three passes of five: the octree stage
// took 1.7-1.8× less time at 64³ and 128³ (BENCHMARKS.md).
void octreeLeafRangesInto(const ViewSetup& setup, const RefractionVolumeCpu& gradient,
                          const std::vector<const DenseGrid*>& slotGrids,
                          std::vector<glm::vec4>& scratch, std::vector<glm::vec4>& ranges) {
    const glm::ivec3 res = resolutionOf(setup);
    shared::VolumeAccessCpu fields = fieldAccess(setup, slotGrids);
    forEachVoxel(res, [&](glm::ivec3 v, size_t i) {
        const float n = gradient[i].w;
        const glm::vec2 kappa =
            slotGrids.empty() ? glm::vec2(0.0f) : fields.voxelExtinctionRange(v);
        scratch[i] = glm::vec4(n, n, kappa.x, kappa.y);
    });
    leafRangePass(res, 0, scratch, ranges);
    leafRangePass(res, 1, ranges, scratch);
    leafRangePass(res, 2, scratch, ranges);
}

}  // namespace

std::vector<glm::vec4> octreeLeafRangesCpu(const ViewSetup& setup,
                                           const RefractionVolumeCpu& gradient,
                                           const std::vector<const DenseGrid*>& slotGrids) {
    std::vector<glm::vec4> scratch(gradient.size()), ranges(gradient.size());
    octreeLeafRangesInto(setup, gradient, slotGrids, scratch, ranges);
    return ranges;
}

std::vector<glm::vec4> octreeLeafRangesPerVoxelCpu(const ViewSetup& setup,
                                                   const RefractionVolumeCpu& gradient,
                                                   const std::vector<const DenseGrid*>& slotGrids) {
    const glm::ivec3 res = resolutionOf(setup);
    shared::VolumeAccessCpu fields = fieldAccess(setup, slotGrids);
    shared::OctreeKernelCpu k;
    k.gradient = gradient.data();
    k.fields = slotGrids.empty() ? nullptr : &fields;
    k.res = res;
    std::vector<glm::vec4> out(gradient.size());
    forEachVoxel(res, [&](glm::ivec3 v, size_t i) { out[i] = k.pyramidLeafRange(res, v); });
    return out;
}

int octreeLevelCount(glm::ivec3 resolution) {
    return shared::OctreeKernelCpu{}.pyramidLevelCount(resolution);
}

glm::ivec3 octreeLevelSize(glm::ivec3 resolution, int level) {
    return shared::OctreeKernelCpu{}.pyramidLevelSize(resolution, level);
}

size_t octreePyramidNodeCount(glm::ivec3 resolution) {
    shared::OctreeKernelCpu k;
    return size_t(k.pyramidLevelOffset(resolution, k.pyramidLevelCount(resolution)));
}

float octreeStepInScene(const ViewSetup& setup, float voxels) {
    shared::VolumeAccessCpu access{setup.params};
    const glm::vec3 h = access.volumeVoxelSize();
    return voxels * std::min(h.x, std::min(h.y, h.z));
}

RefractionVolumeCpu computeIndexGradientCpu(const ViewSetup& setup,
                                            const std::vector<const DenseGrid*>& slotGrids) {
    shared::RefractionKernelCpu kernel{{setup.params}};
    for (size_t s = 0; s < slotGrids.size(); ++s) kernel.fields[s] = slotGrids[s]->values.data();
    const glm::ivec3 res = resolutionOf(setup);
    RefractionVolumeCpu out(size_t(res.x) * size_t(res.y) * size_t(res.z));
    // n once a voxel, for the seven reads of gradientAtVoxel (the ∇n stage at 128³: 1.8× faster),
    // kept in the output's w, which is n: no volume of its own, whose pages would fault in a 64³
    // render as long as the time it saves. The second pass writes x, y, z alone, so the w its
    // neighbours read is never written while read.
    forEachVoxel(res, [&](glm::ivec3 v, size_t i) {
        out[i] = glm::vec4(0.0f, 0.0f, 0.0f, kernel.refractiveIndexAtVoxel(v));
    });
    kernel.indexVolume = out.data();
    forEachVoxel(res, [&](glm::ivec3 v, size_t i) {
        const glm::vec4 g = kernel.gradientAtVoxel(v);
        out[i].x = g.x;
        out[i].y = g.y;
        out[i].z = g.z;
    });
    return out;
}

ChannelGradientsCpu computeChannelGradientsCpu(const ViewSetup& setup,
                                               const std::vector<const DenseGrid*>& slotGrids) {
    ViewSetup channel = setup;
    ChannelGradientsCpu out;
    channel.params = channelViewParams(setup, 0);
    out.red = computeIndexGradientCpu(channel, slotGrids);
    channel.params = channelViewParams(setup, 2);
    out.blue = computeIndexGradientCpu(channel, slotGrids);
    return out;
}

RefractionVolumeCpu computeOctreeCpu(const ViewSetup& setup, const RefractionVolumeCpu& gradient,
                                     const OctreeSettings& settings,
                                     const std::vector<const DenseGrid*>& slotGrids) {
    const glm::ivec3 res = resolutionOf(setup);
    // The labels' volume is the leaf passes' scratch first: two fresh volumes where there were
    // four (page faults were a quarter of a 128³ render's time in this VM).
    RefractionVolumeCpu out(gradient.size());
    std::vector<glm::vec4> pyramid(octreePyramidNodeCount(res));
    octreeLeafRangesInto(setup, gradient, slotGrids, out, pyramid);
    buildPyramidLevels(res, pyramid);
    shared::OctreeKernelCpu k;
    k.pyramid = pyramid.data();
    const float stepLimit = octreeStepInScene(setup, settings.stepLimitVoxels);
    const float minStep = octreeStepInScene(setup, settings.minStepVoxels);
    const float voxelLength = octreeStepInScene(setup, 1.0f);
    // octreeLabel, its walk over the coarser levels taken once for the eight voxels of each
    // level-1 node (level 1 is the pyramid's own: res halved, rounded up).
    forEachVoxel(octreeLevelSize(res, 1), [&](glm::ivec3 node1, size_t) {
        const glm::vec4 above =
            k.octreeLabelAboveLeaves(res, node1, settings.epsilon, settings.epsilonPrime, stepLimit,
                                     settings.kappaTolerance, voxelLength);
        const glm::ivec3 first = node1 * 2;
        const glm::ivec3 last = glm::min(first + 1, res - 1);
        for (int z = first.z; z <= last.z; ++z)
            for (int y = first.y; y <= last.y; ++y)
                for (int x = first.x; x <= last.x; ++x) {
                    const glm::ivec3 v(x, y, z);
                    const size_t i =
                        (size_t(z) * size_t(res.y) + size_t(y)) * size_t(res.x) + size_t(x);
                    out[i] = k.octreeLabelFrom(above, res, v, minStep);
                }
    });
    return out;
}

}  // namespace eikon
