#include "render/transport/plane_sweep/plane_sweep_cpu.h"

#include <atomic>
#include <cmath>
#include <memory>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/error.h"
#include "render/receiver_map.h"
#include "render/transport/channel_passes.h"
#include "render/transport/fixed_point.h"
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

    // Receiver map sums: 3 int64 per map texel (r, g, b), power · receiverScale.
    std::atomic<int64_t>* receiverSums = nullptr;
    double receiverScale = 0.0;
    void depositSweepReceiver(int mapTexel, vec3 power) const {
        for (int c = 0; c < 3; ++c)
            receiverSums[size_t(mapTexel) * 3 + size_t(c)].fetch_add(
                toFixedPoint(power[c], receiverScale), std::memory_order_relaxed);
    }

    // The channels the sources send (plane_sweep.h): all, or one per pass under dispersion.
    vec3 sweepChannels = vec3(1.0f);

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

// The variance along one axis of a bilinear fetch at offset x (texels) from a texel centre, as
// a kernel: x² from where it lands, f(1 − f) (f = x − ⌊x⌋) from the two texels it blends.
double bilinearTapVariance(double x) {
    const double f = x - std::floor(x);
    return x * x + f * (1.0 - f);
}

// The radius r (texels along one axis) at which the kernel of three equal taps at 0 and
// ±r (cos θ, ·), turned through every θ, has variance `variance` (texels²) along the axis: the
// mean of ⅔ bilinearTapVariance(r cos θ) over θ, which grows with r, solved by bisection.
double softKernelRadius(double variance) {
    const auto spread = [](double r) {
        const int turns = 256;
        double sum = 0.0;
        for (int i = 0; i < turns; ++i)
            sum += bilinearTapVariance(r * std::cos((i + 0.5) * 2.0 * M_PI / turns));
        return 2.0 / 3.0 * sum / turns;
    };
    double lo = 0.0, hi = 1.0;
    while (spread(hi) < variance) hi *= 2.0;
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (spread(mid) < variance ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

// The soft light's kernel radii, in texels along the plane's u and w ((0, 0) for a light
// without a disc). An edge's shadow from a disc of angular radius α, a distance D behind it, is
// the disc's projection of radius D tan α, whose profile across the edge has variance
// (D tan α)²/4. Each plane the kernel adds its own variance, σ² along either axis (the turns
// make it the same along both), so D/ℓ planes of spacing ℓ (along the light) add (D/ℓ)σ². A
// convolution spreads the variance with the depth, not with its square, so the two agree at one
// depth only: D_ref, half the light's path across the volume, where σ² = ℓ D_ref tan²α / 4.
// Closer to the occluder the penumbra comes out wider than the disc's (√(D_ref/D) × in width),
// farther narrower (docs/methods.md#soft-distant-lights has the measured widths). The taps are
// bilinear fetches, which blend two texels each: that blend is counted in σ²
// (softKernelRadius), and it is most of it for a small disc.
glm::dvec2 softLightRadius(const shared::GpuViewParams& p, const PlaneSweepPlan& plan) {
    const shared::GpuLight& light = p.lights[plan.light];
    const double versine = shared::lightType(light) == EK_LIGHT_DIRECTIONAL
                               ? double(shared::lightDiscVersine(light))
                               : 0.0;
    if (!(versine > 0.0)) return glm::dvec2(0.0);
    const double tangent = std::sqrt(versine * (2.0 - versine)) / (1.0 - versine);
    const glm::dvec3 h = (glm::dvec3(glm::vec3(p.volumeMax)) - glm::dvec3(glm::vec3(p.volumeMin))) /
                         glm::dvec3(glm::ivec3(p.resolution));
    const double cosine = std::abs(double(light.direction[plan.axis]));
    const double spacing = h[plan.axis] / double(plan.perVoxel) / cosine;       // ℓ
    const double reference = 0.5 * double(plan.depth) * h[plan.axis] / cosine;  // D_ref
    const double variance = spacing * reference * tangent * tangent / 4.0;      // σ², world
    return glm::dvec2(softKernelRadius(variance / (h[plan.u] * h[plan.u])),
                      softKernelRadius(variance / (h[plan.w] * h[plan.w])));
}

// Sums one voxel-centre plane of a light into a slice of the fluence and direction volumes
// (sweepDepositTexel): texel (a, b) into element a·strideU + b·strideW.
void depositPlane(const shared::GpuPlaneSweep& sweep, const PlaneSweepPlan& plan,
                  const std::vector<glm::vec4>& light, const std::vector<glm::vec4>& direction,
                  shared::PlaneSweepKernelCpu& k, glm::vec4* fluence, glm::vec4* weighted,
                  size_t strideU, size_t strideW) {
    tbb::parallel_for(tbb::blocked_range<int>(0, plan.size.y),
                      [&](const tbb::blocked_range<int>& r) {
                          for (int b = r.begin(); b != r.end(); ++b)
                              for (int a = 0; a < plan.size.x; ++a) {
                                  const size_t t = size_t(b) * size_t(plan.size.x) + size_t(a);
                                  glm::vec3 f, w;
                                  if (!k.sweepDepositTexel(sweep, light[t], direction[t], f, w))
                                      continue;
                                  const size_t i = size_t(a) * strideU + size_t(b) * strideW;
                                  fluence[i] += glm::vec4(f, 0.0f);
                                  weighted[i] += glm::vec4(w, 0.0f);
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

}  // namespace

SweepAxis dominantAxis(glm::vec3 d) {
    const glm::vec3 a = glm::abs(d);
    SweepAxis s;
    s.axis = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
    s.order = d[s.axis] >= 0.0f ? 1 : -1;
    return s;
}

PlaneSweepPlan planPlaneSweep(const ViewSetup& setup, int l, const PlaneSweepSettings& s,
                              const SweepAxis* forced) {
    const shared::GpuViewParams& p = setup.params;
    const shared::GpuLight& light = p.lights[l];
    const glm::vec3 d = travelDirection(light, p);
    PlaneSweepPlan plan;
    const SweepAxis axis = forced ? *forced : dominantAxis(d);
    plan.axis = axis.axis;
    plan.u = (plan.axis + 1) % 3;
    plan.w = (plan.axis + 2) % 3;
    plan.order = axis.order;
    const glm::ivec3 res(p.resolution);
    plan.size = glm::ivec2(res[plan.u], res[plan.w]);
    plan.depth = res[plan.axis];
    plan.perVoxel = std::max(s.planesPerVoxel, 1);
    plan.planes = (plan.depth - 1) * plan.perVoxel + 1;
    plan.light = l;
    plan.softRadius = softLightRadius(p, plan);
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
    // The soft light's kernel, turned by the golden angle from plane to plane (in double from
    // the plane's index: the same turn on every machine).
    const double turn = double(j) * M_PI * (3.0 - std::sqrt(5.0));
    sweep.limit.y = float(plan.softRadius.x * std::cos(turn));
    sweep.limit.z = float(plan.softRadius.y * std::sin(turn));
    return sweep;
}

int planeSweepSlice(const PlaneSweepPlan& plan, int j) {
    if (j % plan.perVoxel != 0) return -1;
    return plan.order > 0 ? j / plan.perVoxel : plan.depth - 1 - j / plan.perVoxel;
}

double planeSweepReceiverScale(const ViewSetup& setup, const PlaneSweepSettings& settings) {
    const shared::GpuViewParams& p = setup.params;
    const glm::vec3 h = shared::VolumeAccessCpu{p}.volumeVoxelSize();
    const double largestTexel = std::max({double(h.x) * h.y, double(h.y) * h.z, double(h.z) * h.x});
    double bound = 0.0;
    for (int l = 0; l < shared::lightCount(p); ++l)
        if (shared::lightInFluence(p, l))
            bound +=
                double(irradianceCeiling(p, l, planPlaneSweep(setup, l, settings))) * largestTexel;
    return fixedPointScaleFor(bound, 1.0);
}

std::vector<glm::vec4> planeSweepReceiverMap(const ViewSetup& setup, const int64_t* sums,
                                             double scale) {
    const shared::GpuViewParams& p = setup.params;
    std::vector<glm::vec4> map(receiverMapTexels(p), glm::vec4(0.0f));
    shared::PlaneSweepKernelCpu k{{p}};
    for (int r = 0; r < shared::receiverCount(p); ++r) {
        const shared::GpuReceiver& receiver = p.receivers[r];
        const size_t start = size_t(shared::receiverMapStart(receiver));
        const size_t texels = size_t(shared::receiverMapWidth(receiver)) *
                              size_t(shared::receiverMapHeight(receiver));
        const double area = double(k.receiverTexelArea(r));
        for (size_t i = start; i < start + texels; ++i) {
            glm::dvec3 flux;
            for (int c = 0; c < 3; ++c) flux[c] = fromFixedPoint(sums[3 * i + size_t(c)], scale);
            map[i] = glm::vec4(glm::vec3(flux / area), 0.0f);
        }
    }
    return map;
}

struct LightSweepCpu::Impl {
    Impl(const ViewSetup& s, const PlaneSweepPlan& p, const PlaneSweepSettings& ss)
        : setup(s), plan(p), settings(ss), kernel{{s.params}} {}
    const ViewSetup& setup;
    PlaneSweepPlan plan;
    PlaneSweepSettings settings;
    shared::PlaneSweepKernelCpu kernel;
    std::vector<glm::vec4> light, direction, nextLight, nextDirection, trace;
    shared::GpuPlaneSweep sweep{};  // the last plane's
    int64_t texelsLost = 0;
};

LightSweepCpu::LightSweepCpu(const ViewSetup& setup, const std::vector<const DenseGrid*>& slotGrids,
                             const LightSweepSpec& spec, const PlaneSweepSettings& settings,
                             SweepReceiversCpu& receivers)
    : impl_(std::make_unique<Impl>(setup, spec.plan, settings)) {
    const PlaneSweepPlan& plan = spec.plan;
    shared::PlaneSweepKernelCpu& k = impl_->kernel;
    for (size_t s = 0; s < slotGrids.size(); ++s) k.fields[s] = slotGrids[s]->values.data();
    k.gradient = spec.gradient->data();
    k.sweepChannels = spec.channels;
    k.receiverSums = receivers.sums.get();
    k.receiverScale = receivers.scale;
    const size_t texels = size_t(plan.size.x) * size_t(plan.size.y);
    for (auto* buffer : {&impl_->light, &impl_->direction, &impl_->nextLight, &impl_->nextDirection,
                         &impl_->trace})
        buffer->assign(texels, glm::vec4(0.0f));
    k.sweepLight = impl_->light.data();
    k.sweepDirection = impl_->direction.data();
    k.sweepTrace = impl_->trace.data();
    k.planeWidth = plan.size.x;
}

LightSweepCpu::~LightSweepCpu() = default;

const PlaneSweepPlan& LightSweepCpu::plan() const {
    return impl_->plan;
}
int64_t LightSweepCpu::texelsLost() const {
    return impl_->texelsLost;
}
size_t LightSweepCpu::bufferBytes() const {
    return 5 * impl_->trace.size() * sizeof(glm::vec4);
}

void LightSweepCpu::advance(int j) {
    Impl& m = *impl_;
    const PlaneSweepPlan& plan = m.plan;
    m.sweep = planeSweepStep(m.setup, plan, m.settings, j);
    shared::PlaneSweepKernelCpu& k = m.kernel;
    auto rows = [&](auto&& perTexel) {
        tbb::parallel_for(
            tbb::blocked_range<int>(0, plan.size.y), [&](const tbb::blocked_range<int>& r) {
                for (int b = r.begin(); b != r.end(); ++b)
                    for (int a = 0; a < plan.size.x; ++a)
                        perTexel(glm::ivec2(a, b), size_t(b) * size_t(plan.size.x) + size_t(a));
            });
    };
    const shared::GpuPlaneSweep& sweep = m.sweep;
    rows([&](glm::ivec2 t, size_t i) { m.trace[i] = k.sweepBackTrace(sweep, t); });
    rows([&](glm::ivec2 t, size_t i) {
        k.sweepAdvance(sweep, t, m.nextLight[i], m.nextDirection[i]);
    });
    if (shared::receiverCount(m.setup.params) > 0)
        rows([&](glm::ivec2 t, size_t i) { k.sweepStopOnReceivers(sweep, t, m.nextLight[i]); });
    m.light.swap(m.nextLight);
    m.direction.swap(m.nextDirection);
    k.sweepLight = m.light.data();
    k.sweepDirection = m.direction.data();
    for (const glm::vec4& tr : m.trace) m.texelsLost += tr.z > 0.0f ? 0 : 1;
}

void LightSweepCpu::deposit(glm::vec4* fluence, glm::vec4* direction, size_t strideU,
                            size_t strideW) const {
    depositPlane(impl_->sweep, impl_->plan, impl_->light, impl_->direction, impl_->kernel, fluence,
                 direction, strideU, strideW);
}

const std::vector<glm::vec4>& LightSweepCpu::light() const {
    return impl_->light;
}
const std::vector<glm::vec4>& LightSweepCpu::direction() const {
    return impl_->direction;
}

SweepReceiversCpu::SweepReceiversCpu(const ViewSetup& setup, const PlaneSweepSettings& settings)
    : count(3 * receiverMapTexels(setup.params)),
      sums(new std::atomic<int64_t>[count]),
      scale(planeSweepReceiverScale(setup, settings)) {
    for (size_t i = 0; i < count; ++i) sums[i].store(0, std::memory_order_relaxed);
}

std::vector<glm::vec4> SweepReceiversCpu::map(const ViewSetup& setup) const {
    std::vector<int64_t> gathered(count);
    for (size_t i = 0; i < count; ++i) gathered[i] = sums[i].load();
    return planeSweepReceiverMap(setup, gathered.data(), scale);
}

std::vector<LightSweepSpec> lightSweepSpecs(const ViewSetup& setup,
                                            const RefractionVolumeCpu& gradient,
                                            const PlaneSweepSettings& settings,
                                            const ChannelGradientsCpu* channelGradients,
                                            const SweepAxis* forced) {
    const std::vector<const RefractionVolumeCpu*> gradients =
        channelPassGradientsCpu(setup, gradient, channelGradients, "plane sweep");
    const int passes = int(gradients.size());
    std::vector<LightSweepSpec> specs;
    for (int l = 0; l < shared::lightCount(setup.params); ++l) {
        if (!shared::lightInFluence(setup.params, l)) continue;
        const PlaneSweepPlan plan = planPlaneSweep(setup, l, settings, forced);
        for (int pass = 0; pass < passes; ++pass)
            specs.push_back({plan, gradients[pass], channelPassMask(pass, passes)});
    }
    return specs;
}

void countSweep(const LightSweepCpu& sweep, PlaneSweepResultCpu& out) {
    const PlaneSweepPlan& plan = sweep.plan();
    const int64_t texels = int64_t(plan.size.x) * plan.size.y;
    out.texels += texels;
    out.texelSteps += texels * plan.planes;
    out.texelsLost += sweep.texelsLost();
}

PlaneSweepResultCpu sweepLightsCpu(const ViewSetup& setup,
                                   const std::vector<const DenseGrid*>& slotGrids,
                                   const RefractionVolumeCpu& gradient,
                                   const PlaneSweepSettings& settings,
                                   const PlaneSweepObserver& observer,
                                   const ChannelGradientsCpu* channelGradients) {
    const shared::GpuViewParams& p = setup.params;
    const glm::ivec3 res(p.resolution);
    const size_t voxels = size_t(res.x) * size_t(res.y) * size_t(res.z);
    PlaneSweepResultCpu out;
    out.fluence.assign(voxels, glm::vec4(0.0f));
    out.direction.assign(voxels, glm::vec4(0.0f));
    out.memory.outputBytes = 2 * voxels * sizeof(glm::vec4);
    // Power gathered by the receivers' map texels, in fixed point (any order, the same sums).
    SweepReceiversCpu receivers(setup, settings);
    const glm::ivec3 stride(1, res.x, res.x * res.y);
    // One light (and channel) at a time: its buffers go before the next's are made.
    for (const LightSweepSpec& spec :
         lightSweepSpecs(setup, gradient, settings, channelGradients)) {
        const PlaneSweepPlan& plan = spec.plan;
        LightSweepCpu sweep(setup, slotGrids, spec, settings, receivers);
        out.memory.bufferBytes = std::max(out.memory.bufferBytes, sweep.bufferBytes());
        for (int j = 0; j < plan.planes; ++j) {
            sweep.advance(j);
            const int slice = planeSweepSlice(plan, j);
            if (slice < 0) continue;
            const size_t base = size_t(slice) * size_t(stride[plan.axis]);
            sweep.deposit(out.fluence.data() + base, out.direction.data() + base,
                          size_t(stride[plan.u]), size_t(stride[plan.w]));
            if (observer) observer(plan.light, plan, slice, sweep.light(), sweep.direction());
        }
        countSweep(sweep, out);
    }
    out.receiverMap = receivers.map(setup);
    return out;
}

}  // namespace eikon
