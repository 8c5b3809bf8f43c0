#include "render/transport/plane_sweep/plane_sweep_cpu.h"

#include <cmath>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/error.h"
#include "render/receiver_map.h"
#include "render/volume_kernels_cpu.h"

EK_NAMESPACE_BEGIN

// The sweep shaders' world: the volumes, and three plane buffers (the previous plane's light and
// direction, this plane's back-traced points), u fastest.
struct PlaneSweepKernelCpu : VolumeAccessCpu {
    const vec4* sweepLight = nullptr;
    const vec4* sweepDirection = nullptr;
    const vec4* sweepTrace = nullptr;
    int planeWidth = 0;

    size_t texelIndex(ivec2 t) const { return size_t(t.y) * size_t(planeWidth) + size_t(t.x); }
    vec4 fetchSweepLight(ivec2 t) const { return sweepLight[texelIndex(t)]; }
    vec4 fetchSweepDirection(ivec2 t) const { return sweepDirection[texelIndex(t)]; }
    vec4 fetchSweepTrace(ivec2 t) const { return sweepTrace[texelIndex(t)]; }

    // clang-format off
#include "shaders/shared/plane_sweep.h"
    // clang-format on
};

EK_NAMESPACE_END

namespace eikon {
namespace {

// The volume axis the light travels most along at the volume's centre, and the direction.
glm::vec3 travelDirection(const shared::GpuLight& light, const shared::GpuViewParams& p) {
    if (shared::lightType(light) == EK_LIGHT_DIRECTIONAL) return glm::vec3(light.direction);
    const glm::vec3 centre = 0.5f * (glm::vec3(p.volumeMin) + glm::vec3(p.volumeMax));
    return centre - glm::vec3(light.position);
}

// Sums one voxel-centre plane of a light into the output volumes (sweepDepositTexel).
void depositPlane(const shared::GpuPlaneSweep& sweep, const PlaneSweepPlan& plan, int slice,
                  const std::vector<glm::vec4>& light, const std::vector<glm::vec4>& direction,
                  shared::PlaneSweepKernelCpu& k, PlaneSweepResultCpu& out) {
    tbb::parallel_for(
        tbb::blocked_range<int>(0, plan.size.y), [&](const tbb::blocked_range<int>& r) {
            for (int b = r.begin(); b != r.end(); ++b)
                for (int a = 0; a < plan.size.x; ++a) {
                    const size_t t = size_t(b) * size_t(plan.size.x) + size_t(a);
                    glm::vec3 fluence, weighted;
                    if (!k.sweepDepositTexel(sweep, light[t], direction[t], fluence, weighted))
                        continue;
                    glm::ivec3 voxel;
                    voxel[plan.axis] = slice;
                    voxel[plan.u] = a;
                    voxel[plan.w] = b;
                    const size_t i = k.voxelIndex(voxel);
                    out.fluence[i] += glm::vec4(fluence, 0.0f);
                    out.direction[i] += glm::vec4(weighted, 0.0f);
                }
        });
}

// The most irradiance a texel may hold: the light's brightest irradiance on the volume's box
// (at the box point nearest a point light) times the box's whole surface in texels, as if all
// the light that can enter were gathered in one texel.
float irradianceCeiling(const shared::GpuViewParams& p, int l, const PlaneSweepPlan& plan) {
    const glm::vec3 nearest =
        glm::clamp(glm::vec3(p.lights[l].position), glm::vec3(p.volumeMin), glm::vec3(p.volumeMax));
    glm::vec3 brightest = glm::vec3(p.lights[l].radiance);
    if (shared::lightType(p.lights[l]) != EK_LIGHT_DIRECTIONAL) {
        const float d = std::max(glm::length(glm::vec3(p.lights[l].position) - nearest), 1e-6f);
        brightest /= d * d;  // the spot's falloff only lowers it
    }
    const double faces =
        double(plan.size.x) * plan.size.y + 2.0 * (double(plan.size.x) + plan.size.y) * plan.depth;
    const double ceiling = double(std::max({brightest.x, brightest.y, brightest.z})) * faces;
    return float(std::min(ceiling, 1e30));
}

// A footprint covers at most this many map texels along an axis: a receiver has at most 8
// texels per voxel edge (core/scene_receivers.cpp), and a voxel wide footprint straddles one more.
constexpr int kMaxFootprintTexels = 10;

// The weights of map texels first, first + 1, ... under a footprint [lo, hi) along one map axis
// (texel i covers [i, i + 1)): each its share of the overlap. Returns how many.
int footprintWeights(float lo, float hi, int& first, float* weight) {
    first = int(std::floor(lo));
    const int last = int(std::ceil(hi)) - 1;
    int count = 0;
    for (int i = first; i <= last && count < kMaxFootprintTexels; ++i)
        weight[count++] = (std::min(hi, float(i + 1)) - std::max(lo, float(i))) / (hi - lo);
    return count;
}

// Takes off the new plane the light of texels whose step crossed a receiver, and adds what
// reaches a plane receiver's front face to its map: the texel's power (irradiance on the plane ×
// the texel's area). On a receiver across the sweep axis (its map's axes are the plane's) the
// power is spread over the texel's own footprint, a voxel square around where it lands, so
// uniform light gives a uniform map whatever the map's texels per voxel; on one along the sweep
// axis it is splatted bilinearly at the landing point. Serial, in texel order: the sums are the
// same whatever the threads did before.
void stopOnReceivers(const shared::GpuPlaneSweep& sweep, const PlaneSweepPlan& plan,
                     shared::PlaneSweepKernelCpu& k, std::vector<glm::vec4>& light,
                     std::vector<glm::dvec3>& flux) {
    const shared::GpuViewParams& p = k.params;
    const glm::vec3 h = k.volumeVoxelSize();
    const double texelArea = double(h[plan.u]) * double(h[plan.w]);
    for (int b = 0; b < plan.size.y; ++b)
        for (int a = 0; a < plan.size.x; ++a) {
            glm::vec2 coord;
            bool front = false;
            glm::vec3 beyond;
            const int r = k.sweepReceiverHit(sweep, glm::ivec2(a, b), coord, front, beyond);
            if (r < 0) continue;
            glm::vec4& texel = light[size_t(b) * size_t(plan.size.x) + size_t(a)];
            // The light as it reached the receiver, not as it would have reached the plane.
            const glm::dvec3 power =
                glm::dvec3(glm::vec3(texel) / glm::max(beyond, glm::vec3(1e-30f))) * texelArea;
            texel = glm::vec4(0.0f);
            if (!front) continue;
            const shared::GpuReceiver& receiver = p.receivers[r];
            const int width = shared::receiverMapWidth(receiver);
            const int height = shared::receiverMapHeight(receiver);
            const size_t start = size_t(shared::receiverMapStart(receiver));
            if (shared::receiverAxis(receiver) != plan.axis) {
                glm::ivec4 index;
                glm::vec4 weight;
                k.receiverBilinear(r, coord, index, weight);
                for (int c = 0; c < 4; ++c) flux[size_t(index[c])] += power * double(weight[c]);
                continue;
            }
            // Half the texel's extent in map texels along the map's u and w.
            const glm::vec2 half(0.5f * float(width) / float(plan.size.x),
                                 0.5f * float(height) / float(plan.size.y));
            int firstU = 0, firstW = 0;
            float weightU[kMaxFootprintTexels], weightW[kMaxFootprintTexels];
            const int countU =
                footprintWeights(coord.x - half.x, coord.x + half.x, firstU, weightU);
            const int countW =
                footprintWeights(coord.y - half.y, coord.y + half.y, firstW, weightW);
            // What falls outside the map falls outside the volume's box: it is not gathered.
            for (int jw = 0; jw < countW; ++jw)
                for (int iu = 0; iu < countU; ++iu) {
                    const int u = firstU + iu, w = firstW + jw;
                    if (u < 0 || w < 0 || u >= width || w >= height) continue;
                    flux[start + size_t(w) * size_t(width) + size_t(u)] +=
                        power * double(weightU[iu] * weightW[jw]);
                }
        }
}

// Irradiance (power per area) of every receiver map texel from the flux it gathered.
std::vector<glm::vec4> receiverIrradiance(const ViewSetup& setup,
                                          const std::vector<glm::dvec3>& flux) {
    const shared::GpuViewParams& p = setup.params;
    std::vector<glm::vec4> map(flux.size(), glm::vec4(0.0f));
    shared::PlaneSweepKernelCpu k{{p}};
    for (int r = 0; r < shared::receiverCount(p); ++r) {
        const shared::GpuReceiver& receiver = p.receivers[r];
        const size_t start = size_t(shared::receiverMapStart(receiver));
        const size_t texels = size_t(shared::receiverMapWidth(receiver)) *
                              size_t(shared::receiverMapHeight(receiver));
        const double area = double(k.receiverTexelArea(r));
        for (size_t i = start; i < start + texels; ++i)
            map[i] = glm::vec4(glm::vec3(flux[i] / area), 0.0f);
    }
    return map;
}

}  // namespace

PlaneSweepPlan planPlaneSweep(const ViewSetup& setup, int l, const PlaneSweepSettings& s) {
    const shared::GpuViewParams& p = setup.params;
    const shared::GpuLight& light = p.lights[l];
    const glm::vec3 d = travelDirection(light, p);
    PlaneSweepPlan plan;
    const glm::vec3 a = glm::abs(d);
    plan.axis = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
    plan.u = (plan.axis + 1) % 3;
    plan.w = (plan.axis + 2) % 3;
    plan.order = d[plan.axis] >= 0.0f ? 1 : -1;
    const glm::ivec3 res(p.resolution);
    plan.size = glm::ivec2(res[plan.u], res[plan.w]);
    plan.depth = res[plan.axis];
    plan.perVoxel = std::max(s.planesPerVoxel, 1);
    plan.planes = (plan.depth - 1) * plan.perVoxel + 1;
    plan.light = l;
    if (shared::lightType(light) != EK_LIGHT_DIRECTIONAL) {
        // Every ray must enter through the face the sweep starts from and cross planes forward.
        const float position = light.position[plan.axis];
        const bool outside =
            plan.order > 0 ? position < p.volumeMin[plan.axis] : position > p.volumeMax[plan.axis];
        if (!outside)
            throw Error("render.light_transport.method \"plane_sweep\"",
                        "light " + std::to_string(l) +
                            " is a point or spot light inside the volume's box or beside it; a "
                            "sweep needs it outside the face its light enters through");
    }
    return plan;
}

shared::GpuPlaneSweep planeSweepStep(const ViewSetup& setup, const PlaneSweepPlan& plan,
                                     const PlaneSweepSettings& settings, int j) {
    shared::GpuPlaneSweep sweep{};
    sweep.axes = glm::ivec4(plan.axis, plan.u, plan.w, plan.order);
    sweep.plane = glm::ivec4(plan.light,
                             (settings.intensityCorrection ? EK_SWEEP_CORRECT_INTENSITY : 0) |
                                 (j > 0 ? EK_SWEEP_PREVIOUS_STORED : 0),
                             plan.size.x, plan.size.y);
    const float offset = 0.5f + float(j) / float(plan.perVoxel);
    sweep.place.x = plan.order > 0 ? offset : float(plan.depth) - offset;
    const float face = plan.order > 0 ? 0.0f : float(plan.depth);
    sweep.place.y = j == 0 ? face : sweep.place.x - float(plan.order) / float(plan.perVoxel);
    sweep.place.z = settings.minCosine;
    sweep.place.w = float(std::max(settings.backTraceRefinements, 0));
    sweep.limit.x = irradianceCeiling(setup.params, plan.light, plan);
    return sweep;
}

int planeSweepSlice(const PlaneSweepPlan& plan, int j) {
    if (j % plan.perVoxel != 0) return -1;
    return plan.order > 0 ? j / plan.perVoxel : plan.depth - 1 - j / plan.perVoxel;
}

PlaneSweepResultCpu sweepLightsCpu(const ViewSetup& setup,
                                   const std::vector<const DenseGrid*>& slotGrids,
                                   const RefractionVolumeCpu& gradient,
                                   const PlaneSweepSettings& settings,
                                   const PlaneSweepObserver& observer) {
    const shared::GpuViewParams& p = setup.params;
    const glm::ivec3 res(p.resolution);
    const size_t voxels = size_t(res.x) * size_t(res.y) * size_t(res.z);
    PlaneSweepResultCpu out;
    out.fluence.assign(voxels, glm::vec4(0.0f));
    out.direction.assign(voxels, glm::vec4(0.0f));
    out.memory.outputBytes = 2 * voxels * sizeof(glm::vec4);

    shared::PlaneSweepKernelCpu kernel{{p}};
    for (size_t s = 0; s < slotGrids.size(); ++s) kernel.fields[s] = slotGrids[s]->values.data();
    kernel.gradient = gradient.data();
    // Flux gathered by the receivers' map texels, summed in one fixed order.
    std::vector<glm::dvec3> receiverFlux(receiverMapTexels(p), glm::dvec3(0.0));

    for (int l = 0; l < shared::lightCount(p); ++l) {
        if (!shared::lightInFluence(p, l)) continue;
        const PlaneSweepPlan plan = planPlaneSweep(setup, l, settings);
        const size_t texels = size_t(plan.size.x) * size_t(plan.size.y);
        out.texels += int64_t(texels);
        std::vector<glm::vec4> light(texels), direction(texels), nextLight(texels),
            nextDirection(texels), trace(texels);
        out.memory.bufferBytes = std::max(out.memory.bufferBytes, 5 * texels * sizeof(glm::vec4));

        for (int j = 0; j < plan.planes; ++j) {
            const shared::GpuPlaneSweep sweep = planeSweepStep(setup, plan, settings, j);
            shared::PlaneSweepKernelCpu k = kernel;
            k.sweepLight = light.data();
            k.sweepDirection = direction.data();
            k.sweepTrace = trace.data();
            k.planeWidth = plan.size.x;
            auto rows = [&](auto&& perTexel) {
                tbb::parallel_for(tbb::blocked_range<int>(0, plan.size.y),
                                  [&](const tbb::blocked_range<int>& r) {
                                      for (int b = r.begin(); b != r.end(); ++b)
                                          for (int a = 0; a < plan.size.x; ++a)
                                              perTexel(glm::ivec2(a, b),
                                                       size_t(b) * size_t(plan.size.x) + size_t(a));
                                  });
            };
            rows([&](glm::ivec2 t, size_t i) { trace[i] = k.sweepBackTrace(sweep, t); });
            rows([&](glm::ivec2 t, size_t i) {
                k.sweepAdvance(sweep, t, nextLight[i], nextDirection[i]);
            });
            if (shared::receiverCount(p) > 0)
                stopOnReceivers(sweep, plan, k, nextLight, receiverFlux);
            light.swap(nextLight);
            direction.swap(nextDirection);
            out.texelSteps += int64_t(texels);
            for (const glm::vec4& tr : trace) out.texelsLost += tr.z > 0.0f ? 0 : 1;
            const int slice = planeSweepSlice(plan, j);
            if (slice < 0) continue;
            depositPlane(sweep, plan, slice, light, direction, k, out);
            if (observer) observer(l, plan, slice, light, direction);
        }
    }
    out.receiverMap = receiverIrradiance(setup, receiverFlux);
    return out;
}

}  // namespace eikon
