#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/error.h"
#include "render/receiver_map.h"
#include "render/view_pass.h"
#include "render/volume_kernels_cpu.h"

namespace eikon {

Image renderViewCpu(const ViewSetup& setup, const std::vector<const DenseGrid*>& slotGrids,
                    const TransportOutputCpu& light, const std::vector<glm::vec4>& gradient,
                    const Image* environment) {
    const shared::GpuViewParams& p = setup.params;
    if (slotGrids.size() != setup.slotFields.size())
        throw Error("view pass (CPU)", "expected " + std::to_string(setup.slotFields.size()) +
                                           " field grids, got " + std::to_string(slotGrids.size()));
    shared::ViewKernelCpu kernel{{p}};
    if (viewReadsLightTransmittance(setup) &&
        int(light.lightTransmittance.size()) != shared::lightCount(p))
        throw Error("view pass (CPU)", "the light volumes were not computed");
    for (size_t l = 0; l < light.lightTransmittance.size(); ++l)
        kernel.lights[l] = light.lightTransmittance[l];
    if (shared::curvedRays(p)) {
        if (gradient.size() !=
            size_t(p.resolution.x) * size_t(p.resolution.y) * size_t(p.resolution.z))
            throw Error("view pass (CPU)", "curved rays need the gradient volume");
        kernel.gradient = gradient.data();
    }
    if (shared::readsFluence(p)) {
        const size_t voxels =
            size_t(p.resolution.x) * size_t(p.resolution.y) * size_t(p.resolution.z);
        if (!light.fluence || !light.direction || light.fluenceVoxels != voxels)
            throw Error("view pass (CPU)", "lighting through the fluence needs its volumes");
        kernel.fluence = light.fluence;
        kernel.fluenceDirection = light.direction;
        if (light.receiverTexels != receiverMapTexels(p))
            throw Error("view pass (CPU)", "the receiver map was not computed");
        kernel.receiverMap = light.receiverMap;
    }
    if (shared::environmentType(p) == EK_ENVIRONMENT_IMAGE) {
        if (!environment || environment->width != shared::environmentWidth(p) ||
            environment->height != shared::environmentHeight(p))
            throw Error("view pass (CPU)", "the environment image was not loaded");
        kernel.environment = environment->pixels.data();
    }
    for (size_t s = 0; s < slotGrids.size(); ++s) {
        const glm::ivec3 res = slotGrids[s]->volume.resolution;
        if (res != glm::ivec3(p.resolution.x, p.resolution.y, p.resolution.z))
            throw Error("view pass (CPU)",
                        "field '" + slotGrids[s]->field + "' was resampled on a different volume");
        kernel.fields[s] = slotGrids[s]->values.data();
    }
    Image image(p.image.x, p.image.y);
    tbb::parallel_for(tbb::blocked_range<int>(0, image.height),
                      [&](const tbb::blocked_range<int>& r) {
                          for (int y = r.begin(); y != r.end(); ++y)
                              for (int x = 0; x < image.width; ++x)
                                  image.at(x, y) = kernel.renderPixel(x, y);
                      });
    return image;
}

}  // namespace eikon
