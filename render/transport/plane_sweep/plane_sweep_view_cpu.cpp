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
#include "render/transport/plane_sweep/plane_sweep_view_window.h"
#include "render/view_params.h"
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
using ReceiverHit = shared::ViewKernelCpu::ReceiverHit;

// The bytes of one pixel's ray, and of its receiver hit where there are receivers.
size_t rayBytes(const shared::GpuViewParams& p) {
    return sizeof(PixelRay) +
           (shared::curvedRays(p) ? sizeof(CurvedRayCpu) : sizeof(StraightRayCpu)) +
           (shared::receiverCount(p) > 0 ? sizeof(ReceiverHit) : 0);
}

constexpr int kWindowSlices = kInterleavedWindowSlices;  // plane_sweep_view_window.h

// The slices held across `axis`, fluence and direction.
size_t windowBytes(const shared::GpuViewParams& p, const SweepAxis& axis) {
    const glm::ivec3 res(p.resolution);
    return 2 * size_t(kWindowSlices) * size_t(res[(axis.axis + 1) % 3]) *
           size_t(res[(axis.axis + 2) % 3]) * sizeof(glm::vec4);
}

}  // namespace

size_t interleavedViewBytes(const ViewSetup& setup) {
    const shared::GpuViewParams& p = setup.params;
    const size_t channels = shared::curvedRays(p) && dispersesView(setup) ? 3 : 1;
    return windowBytes(p, interleavedSweepAxis(setup)) +
           size_t(p.image.x) * size_t(p.image.y) * channels * rayBytes(p);
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

InterleavedViewCpu renderInterleavedCpu(
    const ViewSetup& setup, const std::vector<const DenseGrid*>& slotGrids,
    const RefractionVolumeCpu& gradient, const PlaneSweepSettings& settings,
    const Image* environment, const ChannelGradientsCpu* channelGradients, GpuStageTimer* timer) {
    const shared::GpuViewParams& p = setup.params;
    const SweepAxis axis = interleavedSweepAxis(setup);
    const bool curved = shared::curvedRays(p);
    const bool dispersed = curved && dispersesView(setup);
    if (dispersed && (!channelGradients || channelGradients->red.size() != gradient.size() ||
                      channelGradients->blue.size() != gradient.size()))
        throw Error("interleaved view (CPU)",
                    "dispersion needs the red and blue channels' gradient volumes");
    InterleavedViewCpu out;
    SweepReceiversCpu receivers(setup, settings);
    std::vector<std::unique_ptr<LightSweepCpu>> sweeps;
    for (const LightSweepSpec& spec :
         lightSweepSpecs(setup, gradient, settings, dispersed ? channelGradients : nullptr, &axis))
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

    // One kernel a ray per pixel: under dispersion red, green and blue, each bending with its
    // own n (channelViewParams, the view pass's three), else the scene's.
    const int channels = dispersed ? 3 : 1;
    std::vector<shared::GpuViewParams> channelParams;
    for (int c = 0; c < channels; ++c)
        channelParams.push_back(dispersed ? channelViewParams(setup, c) : p);
    std::atomic<int64_t> behind{0};
    std::vector<shared::ViewKernelCpu> kernels;
    kernels.reserve(size_t(channels));
    for (int c = 0; c < channels; ++c) {
        shared::ViewKernelCpu kernel{{channelParams[size_t(c)]}};
        for (size_t s = 0; s < slotGrids.size(); ++s)
            kernel.fields[s] = slotGrids[s]->values.data();
        const RefractionVolumeCpu& channelGradient = !dispersed || c == 1 ? gradient
                                                     : c == 0             ? channelGradients->red
                                                                          : channelGradients->blue;
        if (!channelGradient.empty()) kernel.gradient = channelGradient.data();
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
        kernels.push_back(kernel);
    }
    // The kernels with the window of a turn.
    const auto kernelsWith = [&](const shared::ViewKernelCpu::FluenceWindow& window) {
        std::vector<shared::ViewKernelCpu> turn(kernels);
        for (shared::ViewKernelCpu& k : turn) k.window = window;
        return turn;
    };

    // Every ray, started where it enters the volume (view_march.h, integrateViewRay); ray
    // i·channels + c is pixel i's in channel c.
    std::optional<StageScope> starting(std::in_place, timer, "view");
    const int width = p.image.x, height = p.image.y;
    const size_t pixels = size_t(width) * size_t(height);
    const size_t count = pixels * size_t(channels);
    std::vector<PixelRay> rays(count);
    std::vector<CurvedRayCpu> curvedRays(curved ? count : 0);
    std::vector<StraightRayCpu> straightRays(curved ? 0 : count);
    out.rayBytes = count * rayBytes(p);
    const auto forEachPixel = [&](const auto& perPixel) {
        tbb::parallel_for(tbb::blocked_range<int>(0, height),
                          [&](const tbb::blocked_range<int>& r) {
                              for (int y = r.begin(); y != r.end(); ++y)
                                  for (int x = 0; x < width; ++x)
                                      perPixel(x, y, size_t(y) * size_t(width) + size_t(x));
                          });
    };
    forEachPixel([&](int x, int y, size_t pixel) {
        for (int c = 0; c < channels; ++c) {
            shared::ViewKernelCpu& kernel = kernels[size_t(c)];
            const size_t i = pixel * size_t(channels) + size_t(c);
            PixelRay& ray = rays[i];
            const glm::vec3 origin(kernel.params.cameraOrigin);
            const glm::vec3 dir = kernel.pixelRayDirection(x, y);
            const glm::vec2 span = kernel.intersectVolume(origin, dir);
            ray.inVolume = span.x < span.y;
            ray.ended = !ray.inVolume;
            if (!ray.inVolume) continue;
            if (curved)
                curvedRays[i] = kernel.curvedRayStart(origin + dir * span.x, dir, true, 0.0f, 0,
                                                      glm::vec3(0.0f), glm::vec3(1.0f));
            else
                straightRays[i] = kernel.straightRayStart(origin, dir, span);
        }
    });
    starting.reset();
    // The receiver hits waiting for their irradiance, one a ray (none without receivers).
    std::vector<ReceiverHit> hits(shared::receiverCount(p) > 0 ? count : 0);
    std::atomic<int64_t> steps{0};
    const auto advanceRays = [&](const std::vector<shared::ViewKernelCpu>& turn) {
        tbb::parallel_for(
            tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& r) {
                // This block's: they point at each ray's receiver hit.
                std::vector<shared::ViewKernelCpu> block(turn);
                int64_t taken = 0;
                for (int y = r.begin(); y != r.end(); ++y)
                    for (int x = 0; x < width; ++x)
                        for (int c = 0; c < channels; ++c) {
                            const size_t i =
                                (size_t(y) * size_t(width) + size_t(x)) * size_t(channels) +
                                size_t(c);
                            PixelRay& ray = rays[i];
                            if (ray.ended) continue;
                            shared::ViewKernelCpu& k = block[size_t(c)];
                            if (!hits.empty()) k.deferredReceiverHit = &hits[i];
                            // Reflections at sharp surfaces see the environment: none is kept.
                            shared::ViewKernelCpu::KeptReflection none, unused;
                            const int before = curved ? curvedRays[i].steps : straightRays[i].step;
                            const int state = curved
                                                  ? k.curvedRayAdvance(curvedRays[i], none, unused)
                                                  : k.straightRayAdvance(straightRays[i]);
                            ray.ended = state == EK_RAY_ENDED;
                            taken += (curved ? curvedRays[i].steps : straightRays[i].step) - before;
                        }
                steps.fetch_add(taken, std::memory_order_relaxed);
            });
    };
    // Shades the receiver hits whose irradiance is complete: a voxel receiver's once the fluence
    // slices it reads (1.5 voxels in front of it, receiverFluenceIrradiance) are held; with
    // `all`, every hit, the plane receivers' maps being complete. The ray's radiance gets what
    // the view pass would have added where the ray met the receiver: the same bits.
    const auto shadeReceiverHits = [&](std::vector<shared::ViewKernelCpu>& turn, bool all) {
        if (hits.empty()) return;
        forEachPixel([&](int, int, size_t pixel) {
            for (int c = 0; c < channels; ++c) {
                const size_t i = pixel * size_t(channels) + size_t(c);
                ReceiverHit& hit = hits[i];
                if (hit.receiver < 0) continue;
                shared::ViewKernelCpu& k = turn[size_t(c)];
                if (!all) {
                    if (shared::receiverKind(p.receivers[hit.receiver]) != EK_RECEIVER_VOXELS)
                        continue;
                    const glm::vec3 read =
                        k.worldToVolumeIndex(hit.x) + 1.5f * k.receiverNormal(hit.receiver);
                    if (!k.viewSampleReady(read)) continue;
                }
                glm::vec3& radiance = curved ? curvedRays[i].radiance : straightRays[i].radiance;
                radiance += hit.weight * k.receiverRadiance(hit.receiver, hit.x, hit.front);
                hit.receiver = -1;
            }
        });
    };

    // The planes, the light first: each voxel-centre plane becomes the newest slice held, the
    // sweeps adding into it in the order the volume path adds them (the same bits). At each turn
    // (interleavedViewTurn) every view ray takes the steps whose samples the slices held
    // complete.
    const int planes = sweeps.empty() ? 0 : sweeps.front()->plan().planes;
    shared::ViewKernelCpu::FluenceWindow window = kernels.front().window;
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
        if (!interleavedViewTurn(swept, depth)) continue;
        StageScope stage(timer, "view");
        // The slices held, by their place in the sweep: swept − kWindowSlices … swept − 1.
        const int oldest = std::max(swept - kWindowSlices, 0), newest = swept - 1;
        const auto sliceAt = [&](int rank) { return axis.order > 0 ? rank : depth - 1 - rank; };
        window.first = std::min(sliceAt(oldest), sliceAt(newest));
        window.last = std::max(sliceAt(oldest), sliceAt(newest));
        window.swept = swept;
        std::vector<shared::ViewKernelCpu> turn = kernelsWith(window);
        advanceRays(turn);
        shadeReceiverHits(turn, false);
    }
    StageScope stage(timer, "view");
    // With no light to sweep the rays read no fluence: they finish in one go.
    if (planes == 0) window.axis = -1;
    std::vector<shared::ViewKernelCpu> last = kernelsWith(window);
    if (planes == 0) advanceRays(last);
    // The receivers' maps are complete: the hits left see them.
    out.sweep.receiverMap = receivers.map(setup);
    for (shared::ViewKernelCpu& k : last) k.receiverMap = out.sweep.receiverMap.data();
    shadeReceiverHits(last, true);
    for (const auto& sweep : sweeps) countSweep(*sweep, out.sweep);
    out.samplesBehind = behind.load();
    out.viewSteps = steps.load();

    // What each ray sees where it leaves (integrateViewRay's last line), alpha the mean
    // transmittance (renderPixel's); under dispersion each channel's ray gives its channel, in
    // renderPixelChannel's order of operations.
    out.image = Image(width, height);
    forEachPixel([&](int x, int y, size_t pixel) {
        glm::vec4 colour(0.0f);
        for (int c = 0; c < channels; ++c) {
            shared::ViewKernelCpu& kernel = kernels[size_t(c)];
            const size_t i = pixel * size_t(channels) + size_t(c);
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
            if (!dispersed) {
                colour = glm::vec4(radiance,
                                   (transmittance.x + transmittance.y + transmittance.z) / 3.0f);
                continue;
            }
            colour[c] = radiance[c];
            colour.w = c == 0 ? transmittance[c] : colour.w + transmittance[c];
            if (c == 2) colour.w = colour.w / 3.0f;
        }
        out.image.at(x, y) = colour;
    });
    return out;
}

}  // namespace eikon
