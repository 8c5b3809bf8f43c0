#include <algorithm>
#include <atomic>
#include <cmath>
#include <optional>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/error.h"
#include "render/light_transport.h"
#include "render/transport/plane_sweep/plane_sweep_view.h"
#include "render/volume_kernels_cpu.h"

namespace eikon {
namespace {

const char* axisName(int axis) {
    return axis == 0 ? "x" : axis == 1 ? "y" : "z";
}

glm::vec3 volumeCentre(const shared::GpuViewParams& p) {
    return 0.5f * (glm::vec3(p.volumeMin) + glm::vec3(p.volumeMax));
}

// One pixel's view ray while the planes pass: curved or straight (the scene's), or none where it
// misses the volume.
struct PixelRay {
    shared::ViewKernelCpu::CurvedRay curved;
    shared::ViewKernelCpu::StraightRay straight;
    glm::vec3 missDir{0.0f};  // the pixel's direction (what a straight ray or a miss sees)
    bool inVolume = false;
    bool ended = false;
};

// The two slices of the fluence and mean-direction volumes held across `axis`.
size_t windowBytes(const shared::GpuViewParams& p, const SweepAxis& axis) {
    const glm::ivec3 res(p.resolution);
    return 2 * 2 * size_t(res[(axis.axis + 1) % 3]) * size_t(res[(axis.axis + 2) % 3]) *
           sizeof(glm::vec4);
}

}  // namespace

size_t interleavedViewBytes(const ViewSetup& setup) {
    const shared::GpuViewParams& p = setup.params;
    return windowBytes(p, interleavedSweepAxis(setup)) +
           size_t(p.image.x) * size_t(p.image.y) * sizeof(PixelRay);
}

SweepAxis interleavedSweepAxis(const ViewSetup& setup) {
    const shared::GpuViewParams& p = setup.params;
    return dominantAxis(volumeCentre(p) - glm::vec3(p.cameraOrigin));
}

void checkInterleavedView(const ViewSetup& setup, const PlaneSweepSettings& settings,
                          const std::string& where) {
    const shared::GpuViewParams& p = setup.params;
    const SweepAxis axis = interleavedSweepAxis(setup);
    const std::string name = axisName(axis.axis);
    const float camera = p.cameraOrigin[axis.axis];
    const float entry = axis.order > 0 ? p.volumeMin[axis.axis] : p.volumeMax[axis.axis];
    if (axis.order > 0 ? camera > entry : camera < entry)
        throw Error(where, "the interleaved view sweeps planes across " + name +
                               ", the axis the camera looks along, and needs the camera outside "
                               "the face its rays enter through (" +
                               name + (axis.order > 0 ? " <= " : " >= ") + std::to_string(entry) +
                               "; the camera is at " + name + " = " + std::to_string(camera) + ")");
    if (shared::receiverCount(p) > 0)
        throw Error(where,
                    "the interleaved view does not show receivers yet (their maps fill as "
                    "the planes pass them); use \"view\": \"volume\"");
    if (dispersesView(setup))
        throw Error(where, "the interleaved view does not disperse yet; use \"view\": \"volume\"");
    for (int l = 0; l < shared::lightCount(p); ++l) {
        if (!shared::lightInFluence(p, l)) continue;
        const shared::GpuLight& light = p.lights[l];
        if (shared::lightType(light) == EK_LIGHT_DIRECTIONAL) {
            const glm::vec3 d = glm::normalize(glm::vec3(light.direction));
            const float cosine = d[axis.axis] * float(axis.order);
            if (!(cosine >= settings.minCosine))
                throw Error(where, "light " + std::to_string(l) + " crosses the planes across " +
                                       name + " at cosine " + std::to_string(cosine) +
                                       ", below min_cosine " + std::to_string(settings.minCosine) +
                                       ": the interleaved view needs light from the camera's side");
        }
        planPlaneSweep(setup, l, settings, &axis);  // a point or spot light on the wrong side
    }
}

InterleavedViewCpu renderInterleavedCpu(const ViewSetup& setup,
                                        const std::vector<const DenseGrid*>& slotGrids,
                                        const RefractionVolumeCpu& gradient,
                                        const PlaneSweepSettings& settings,
                                        const Image* environment, GpuStageTimer* timer) {
    const shared::GpuViewParams& p = setup.params;
    const SweepAxis axis = interleavedSweepAxis(setup);
    InterleavedViewCpu out;
    SweepReceiversCpu receivers(setup, settings);
    std::vector<std::unique_ptr<LightSweepCpu>> sweeps;
    for (const LightSweepSpec& spec : lightSweepSpecs(setup, gradient, settings, nullptr, &axis))
        sweeps.push_back(
            std::make_unique<LightSweepCpu>(setup, slotGrids, spec, settings, receivers));
    for (const auto& sweep : sweeps) out.sweep.memory.bufferBytes += sweep->bufferBytes();

    // The two slices of the fluence and mean-direction volumes held, slice k at plane k & 1.
    const glm::ivec3 res(p.resolution);
    const int u = (axis.axis + 1) % 3, w = (axis.axis + 2) % 3;
    const size_t planeTexels = size_t(res[u]) * size_t(res[w]);
    std::vector<glm::vec4> fluence(2 * planeTexels), direction(2 * planeTexels);
    out.windowBytes = windowBytes(p, axis);

    std::atomic<int64_t> behind{0};
    shared::ViewKernelCpu kernel{{p}};
    for (size_t s = 0; s < slotGrids.size(); ++s) kernel.fields[s] = slotGrids[s]->values.data();
    if (!gradient.empty()) kernel.gradient = gradient.data();
    kernel.fluence = fluence.data();
    kernel.fluenceDirection = direction.data();
    if (shared::environmentType(p) == EK_ENVIRONMENT_IMAGE)
        kernel.environment = environment->pixels.data();
    kernel.window.axis = axis.axis;
    kernel.window.u = u;
    kernel.window.w = w;
    kernel.window.order = axis.order;
    kernel.window.planeTexels = planeTexels;
    kernel.window.behind = &behind;

    // Every pixel's ray, started where it enters the volume (view_march.h, integrateViewRay).
    std::optional<StageScope> starting(std::in_place, timer, "view");
    const int width = p.image.x, height = p.image.y;
    std::vector<PixelRay> rays(size_t(width) * size_t(height));
    out.rayBytes = rays.size() * sizeof(PixelRay);
    const bool curved = shared::curvedRays(p);
    const auto forEachPixel = [&](const auto& perPixel) {
        tbb::parallel_for(tbb::blocked_range<int>(0, height),
                          [&](const tbb::blocked_range<int>& r) {
                              for (int y = r.begin(); y != r.end(); ++y)
                                  for (int x = 0; x < width; ++x)
                                      perPixel(x, y, rays[size_t(y) * size_t(width) + size_t(x)]);
                          });
    };
    forEachPixel([&](int x, int y, PixelRay& ray) {
        const glm::vec3 origin(p.cameraOrigin);
        const glm::vec3 dir = kernel.pixelRayDirection(x, y);
        ray.missDir = dir;
        const glm::vec2 span = kernel.intersectVolume(origin, dir);
        ray.inVolume = span.x < span.y;
        ray.ended = !ray.inVolume;
        if (!ray.inVolume) return;
        if (curved)
            ray.curved = kernel.curvedRayStart(origin + dir * span.x, dir, true, 0.0f, 0,
                                               glm::vec3(0.0f), glm::vec3(1.0f));
        else
            ray.straight = kernel.straightRayStart(origin, dir, span);
    });
    starting.reset();
    std::atomic<int64_t> steps{0};
    const auto advanceRays = [&](shared::ViewKernelCpu& k) {
        forEachPixel([&](int, int, PixelRay& ray) {
            if (ray.ended) return;
            const int before = curved ? ray.curved.steps : ray.straight.step;
            const int state =
                curved ? k.curvedRayAdvance(ray.curved) : k.straightRayAdvance(ray.straight);
            ray.ended = state == EK_RAY_ENDED;
            const int64_t taken = (curved ? ray.curved.steps : ray.straight.step) - before;
            steps.fetch_add(taken, std::memory_order_relaxed);
        });
    };

    // The planes, the light first: each voxel-centre plane becomes the newest slice held, the
    // sweeps adding into it in the order the volume path adds them (the same bits), and then
    // every view ray takes the steps whose samples it completes.
    const int planes = sweeps.empty() ? 0 : sweeps.front()->plan().planes;
    int swept = 0, previousSlice = -1;
    for (int j = 0; j < planes; ++j) {
        const int slice = planeSweepSlice(sweeps.front()->plan(), j);
        const size_t base = size_t(slice & 1) * planeTexels;
        {
            StageScope stage(timer, "plane_sweep");
            for (const auto& sweep : sweeps) sweep->advance(j);
            if (slice < 0) continue;
            std::fill(fluence.begin() + base, fluence.begin() + base + planeTexels,
                      glm::vec4(0.0f));
            std::fill(direction.begin() + base, direction.begin() + base + planeTexels,
                      glm::vec4(0.0f));
            for (const auto& sweep : sweeps)
                sweep->deposit(fluence.data() + base, direction.data() + base, 1, size_t(res[u]));
        }
        StageScope stage(timer, "view");
        ++swept;
        shared::ViewKernelCpu k = kernel;
        k.window.first = previousSlice < 0 ? slice : std::min(previousSlice, slice);
        k.window.last = previousSlice < 0 ? slice : std::max(previousSlice, slice);
        k.window.swept = swept;
        advanceRays(k);
        previousSlice = slice;
    }
    StageScope stage(timer, "view");
    // With no light to sweep the rays read no fluence: they finish in one go.
    if (planes == 0) {
        shared::ViewKernelCpu k = kernel;
        k.window.axis = -1;
        advanceRays(k);
    }
    for (const auto& sweep : sweeps) countSweep(*sweep, out.sweep);
    out.samplesBehind = behind.load();
    out.viewSteps = steps.load();

    // What each ray sees where it leaves (integrateViewRay's last line), alpha the mean
    // transmittance (renderPixel's).
    out.image = Image(width, height);
    forEachPixel([&](int x, int y, PixelRay& ray) {
        glm::vec3 radiance, transmittance;
        if (!ray.inVolume) {
            radiance = kernel.environmentRadiance(ray.missDir);
            transmittance = glm::vec3(1.0f);
        } else if (curved) {
            transmittance = ray.curved.transmittance;
            radiance = ray.curved.radiance +
                       transmittance * kernel.environmentRadiance(ray.curved.exitDir);
        } else {
            transmittance = ray.straight.transmittance;
            radiance =
                ray.straight.radiance + transmittance * kernel.environmentRadiance(ray.missDir);
        }
        out.image.at(x, y) =
            glm::vec4(radiance, (transmittance.x + transmittance.y + transmittance.z) / 3.0f);
    });
    return out;
}

}  // namespace eikon
