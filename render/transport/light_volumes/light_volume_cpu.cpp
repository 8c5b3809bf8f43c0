#include <tbb/blocked_range2d.h>
#include <tbb/blocked_range3d.h>
#include <tbb/parallel_for.h>

#include <optional>

#include "core/error.h"
#include "render/transport/light_volumes/light_volume.h"
#include "render/volume_kernels_cpu.h"

namespace eikon {

std::vector<LightVolumeCpu> computeLightVolumesCpu(const ViewSetup& setup,
                                                   const std::vector<const DenseGrid*>& slotGrids) {
    const shared::GpuViewParams& p = setup.params;
    const glm::ivec3 res(p.resolution.x, p.resolution.y, p.resolution.z);
    shared::LightKernelCpu kernel{{p}};
    for (size_t s = 0; s < slotGrids.size(); ++s) kernel.fields[s] = slotGrids[s]->values.data();
    // The fields where they hold one value (render/constant_bricks.h): the extinction's samples
    // there fetch no corners.
    std::optional<ConstantBricks> constant;
    if (constantBricksEnabled()) {
        constant.emplace(res);
        for (size_t s = 0; s < slotGrids.size(); ++s) constant->addField(int(s), kernel.fields[s]);
        kernel.constantBricks = &*constant;
    }

    std::vector<LightVolumeCpu> volumes(size_t(shared::lightCount(p)));
    for (int l = 0; l < shared::lightCount(p); ++l) {
        LightVolumeCpu& out = volumes[size_t(l)];
        out.assign(size_t(res.x) * size_t(res.y) * size_t(res.z), glm::vec4(1.0f));
        // A light that comes through the fluence has a volume neither computed nor read.
        if (shared::lightInFluence(p, l)) continue;
        shared::LightKernelCpu k = kernel;
        k.sweepSlices = out.data();
        if (!k.sweepsLight(l)) {
            tbb::parallel_for(tbb::blocked_range3d<int>(0, res.z, 0, res.y, 0, res.x),
                              [&](const tbb::blocked_range3d<int>& r) {
                                  for (int z = r.pages().begin(); z != r.pages().end(); ++z)
                                      for (int y = r.rows().begin(); y != r.rows().end(); ++y)
                                          for (int x = r.cols().begin(); x != r.cols().end(); ++x) {
                                              const glm::ivec3 v(x, y, z);
                                              out[k.voxelIndex(v)] = glm::vec4(
                                                  k.marchedLightTransmittance(l, v), 1.0f);
                                          }
                              });
            continue;
        }
        const glm::vec3 d(p.lights[l].direction);
        const int axis = k.sweepAxis(d);
        const int order = k.sweepOrder(d, axis);
        const int u = (axis + 1) % 3, w = (axis + 2) % 3;
        for (int n = 0; n < res[axis]; ++n) {
            const int slice = order > 0 ? n : res[axis] - 1 - n;
            tbb::parallel_for(tbb::blocked_range2d<int>(0, res[w], 0, res[u]),
                              [&](const tbb::blocked_range2d<int>& r) {
                                  for (int b = r.rows().begin(); b != r.rows().end(); ++b)
                                      for (int a = r.cols().begin(); a != r.cols().end(); ++a) {
                                          glm::ivec3 v;
                                          v[axis] = slice;
                                          v[u] = a;
                                          v[w] = b;
                                          out[k.voxelIndex(v)] =
                                              glm::vec4(k.sweptLightTransmittance(l, v), 1.0f);
                                      }
                              });
        }
    }
    return volumes;
}

}  // namespace eikon
