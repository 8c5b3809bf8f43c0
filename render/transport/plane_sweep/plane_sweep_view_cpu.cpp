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

// One pixel's view ray while the planes pass: whether it met the volume, whether it ended. Its
// trace, curved or straight (the scene's), is kept apart: only one kind is allocated.
struct PixelRay {
    bool inVolume = false;
    bool ended = false;
};
using CurvedRayCpu = shared::ViewKernelCpu::CurvedRay;
using StraightRayCpu = shared::ViewKernelCpu::StraightRay;

// The bytes of one pixel's ray.
size_t rayBytes(bool curved) {
    return sizeof(PixelRay) + (curved ? sizeof(CurvedRayCpu) : sizeof(StraightRayCpu));
}

// The slices of the fluence and mean-direction volumes held. Every kWindowSlices − 1 slices the
// view rays advance (the ray states are read and written once for that many planes); a ray may
// turn back kWindowSlices − 2 slices before it reads one dropped.
constexpr int kWindowSlices = 8;

// The slices held across `axis`, fluence and direction.
size_t windowBytes(const shared::GpuViewParams& p, const SweepAxis& axis) {
    const glm::ivec3 res(p.resolution);
    return 2 * size_t(kWindowSlices) * size_t(res[(axis.axis + 1) % 3]) *
           size_t(res[(axis.axis + 2) % 3]) * sizeof(glm::vec4);
}

}  // namespace

size_t interleavedViewBytes(const ViewSetup& setup) {
    const shared::GpuViewParams& p = setup.params;
    return windowBytes(p, interleavedSweepAxis(setup)) +
           size_t(p.image.x) * size_t(p.image.y) * rayBytes(shared::curvedRays(p));
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

    // The slices of the fluence and mean-direction volumes held, slice k at plane k % slices.
    const glm::ivec3 res(p.resolution);
    const int u = (axis.axis + 1) % 3, w = (axis.axis + 2) % 3;
    const size_t planeTexels = size_t(res[u]) * size_t(res[w]);
    std::vector<glm::vec4> fluence(kWindowSlices * planeTexels),
        direction(kWindowSlices * planeTexels);
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
    kernel.window.slices = kWindowSlices;
    kernel.window.planeTexels = planeTexels;
    kernel.window.behind = &behind;

    // Every pixel's ray, started where it enters the volume (view_march.h, integrateViewRay).
    std::optional<StageScope> starting(std::in_place, timer, "view");
    const int width = p.image.x, height = p.image.y;
    const bool curved = shared::curvedRays(p);
    const size_t pixels = size_t(width) * size_t(height);
    std::vector<PixelRay> rays(pixels);
    std::vector<CurvedRayCpu> curvedRays(curved ? pixels : 0);
    std::vector<StraightRayCpu> straightRays(curved ? 0 : pixels);
    out.rayBytes = pixels * rayBytes(curved);
    const auto forEachPixel = [&](const auto& perPixel) {
        tbb::parallel_for(tbb::blocked_range<int>(0, height),
                          [&](const tbb::blocked_range<int>& r) {
                              for (int y = r.begin(); y != r.end(); ++y)
                                  for (int x = 0; x < width; ++x)
                                      perPixel(x, y, size_t(y) * size_t(width) + size_t(x));
                          });
    };
    forEachPixel([&](int x, int y, size_t i) {
        PixelRay& ray = rays[i];
        const glm::vec3 origin(p.cameraOrigin);
        const glm::vec3 dir = kernel.pixelRayDirection(x, y);
        const glm::vec2 span = kernel.intersectVolume(origin, dir);
        ray.inVolume = span.x < span.y;
        ray.ended = !ray.inVolume;
        if (!ray.inVolume) return;
        if (curved)
            curvedRays[i] = kernel.curvedRayStart(origin + dir * span.x, dir, true, 0.0f, 0,
                                                  glm::vec3(0.0f), glm::vec3(1.0f));
        else
            straightRays[i] = kernel.straightRayStart(origin, dir, span);
    });
    starting.reset();
    std::atomic<int64_t> steps{0};
    const auto advanceRays = [&](shared::ViewKernelCpu& k) {
        forEachPixel([&](int, int, size_t i) {
            PixelRay& ray = rays[i];
            if (ray.ended) return;
            // Reflections at sharp surfaces see the environment: none is kept.
            shared::ViewKernelCpu::KeptReflection none, unused;
            const int before = curved ? curvedRays[i].steps : straightRays[i].step;
            const int state = curved ? k.curvedRayAdvance(curvedRays[i], none, unused)
                                     : k.straightRayAdvance(straightRays[i]);
            ray.ended = state == EK_RAY_ENDED;
            const int64_t taken = (curved ? curvedRays[i].steps : straightRays[i].step) - before;
            steps.fetch_add(taken, std::memory_order_relaxed);
        });
    };

    // The planes, the light first: each voxel-centre plane becomes the newest slice held, the
    // sweeps adding into it in the order the volume path adds them (the same bits). Every
    // kWindowSlices − 1 slices, and after the last, every view ray takes the steps whose samples
    // the slices held complete: a sample not ready at one such turn needs a slice swept after it,
    // so at the next its slices are among the kWindowSlices held.
    const int planes = sweeps.empty() ? 0 : sweeps.front()->plan().planes;
    const int depth = res[axis.axis];
    int swept = 0;
    for (int j = 0; j < planes; ++j) {
        const int slice = planeSweepSlice(sweeps.front()->plan(), j);
        {
            StageScope stage(timer, "plane_sweep");
            for (const auto& sweep : sweeps) sweep->advance(j);
            if (slice < 0) continue;
            const size_t base = size_t(slice % kWindowSlices) * planeTexels;
            std::fill(fluence.begin() + base, fluence.begin() + base + planeTexels,
                      glm::vec4(0.0f));
            std::fill(direction.begin() + base, direction.begin() + base + planeTexels,
                      glm::vec4(0.0f));
            for (const auto& sweep : sweeps)
                sweep->deposit(fluence.data() + base, direction.data() + base, 1, size_t(res[u]));
        }
        ++swept;
        if ((swept - 1) % (kWindowSlices - 1) != 0 && swept != depth) continue;
        StageScope stage(timer, "view");
        // The slices held, by their place in the sweep: swept − kWindowSlices … swept − 1.
        const int oldest = std::max(swept - kWindowSlices, 0), newest = swept - 1;
        const auto sliceAt = [&](int rank) { return axis.order > 0 ? rank : depth - 1 - rank; };
        shared::ViewKernelCpu k = kernel;
        k.window.first = std::min(sliceAt(oldest), sliceAt(newest));
        k.window.last = std::max(sliceAt(oldest), sliceAt(newest));
        k.window.swept = swept;
        advanceRays(k);
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
    forEachPixel([&](int x, int y, size_t i) {
        glm::vec3 radiance, transmittance;
        if (!rays[i].inVolume) {
            radiance = kernel.environmentRadiance(kernel.pixelRayDirection(x, y));
            transmittance = glm::vec3(1.0f);
        } else if (curved) {
            transmittance = curvedRays[i].transmittance;
            radiance = curvedRays[i].radiance +
                       transmittance * kernel.environmentRadiance(curvedRays[i].exitDir);
        } else {
            transmittance = straightRays[i].transmittance;
            radiance = straightRays[i].radiance +
                       transmittance * kernel.environmentRadiance(straightRays[i].dir);
        }
        out.image.at(x, y) =
            glm::vec4(radiance, (transmittance.x + transmittance.y + transmittance.z) / 3.0f);
    });
    return out;
}

}  // namespace eikon
