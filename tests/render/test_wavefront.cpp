// Eikonal wavefront tracing (Ihrke et al. 2007; shaders/shared/wavefront.h), CPU twin, against
// closed forms: straight light and power conservation in n = 1, Beer–Lambert in a homogeneous
// box, the eikonal system's particles on the linear-n² parabola at equal optical time, the
// intensity law E·r² = I for a point light, a ball lens's paraxial focus, the paper's caustic
// rule, Maxwell's fish-eye imaging a point at equal optical time, a parabolic GRIN rod's period,
// the patch budget, and bit-identical results for any thread count.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>

#include <glm/gtc/constants.hpp>

#include <tbb/task_arena.h>

#include "render/gl_context.h"
#include "render/shader_program.h"
#include "render/smoothing.h"
#include "render/transport/wavefront/wavefront_tracing.h"
#include "render/volume_kernels_cpu.h"
#include "support/fluence_peak.h"
#include "support/grin_lens.h"
#include "support/linear_n2_medium.h"
#include "support/photon_scene.h"
#include "support/wavefront_test_kernel.h"

using namespace eikon;
using eikon::test::kernelFor;
using eikon::test::PhotonScene;

namespace {

WavefrontResultCpu trace(const PhotonScene& s, const WavefrontSettings& settings,
                         bool keepPatches = false) {
    return traceWavefrontsCpu(s.setup, {&s.field}, s.gradient, settings, keepPatches);
}

double maxRelativeImbalance(const PhotonTotals& t) {
    double worst = 0.0;
    for (int c = 0; c < 3; ++c) {
        const double sum =
            t.escaped[c] + t.extinguished[c] + t.dropped[c] + t.received[c] + t.reflected[c];
        worst = std::max(worst, std::abs(sum - t.emitted[c]) / t.emitted[c]);
    }
    return worst;
}

}  // namespace

TEST_CASE("a wavefront in n = 1 goes straight, fills every voxel with E, and loses nothing",
          "[wavefront]") {
    // One patch per voxel column (32 per side over the box's 2-unit face): nothing to split.
    const int res = 32;
    const glm::vec3 color(1.0f, 0.5f, 0.25f);
    const PhotonScene s(
        res, 1.0f, glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f), [](glm::vec3) { return 0.0f; },
        color);
    WavefrontSettings settings;
    settings.patchesPerSide = res;
    const WavefrontResultCpu r = trace(s, settings, true);
    CHECK(r.startingPatches == res * res);
    CHECK(r.patchesSplit == 0);
    CHECK(r.patchesCut == 0);
    CHECK(maxRelativeImbalance(r.totals) < 1e-6);
    CHECK(r.totals.escaped.x == Approx(4.0 * color.x).epsilon(1e-6));  // E × the 2 × 2 face
    // Every patch left through the bottom face, unchanged in shape.
    for (const shared::GpuWavefrontPatch& p : r.patches) {
        REQUIRE(int(p.state.x) == EK_PHOTON_ESCAPED);
        CHECK(p.corner[0].z < -1.0f);
        CHECK(glm::length(glm::vec3(p.corner[2] - p.corner[0])) ==
              Approx(std::sqrt(2.0) * 2.0 / res).epsilon(1e-5));
    }
    // Fluence rate = power·length / voxel volume = E in every voxel.
    const double h = 2.0 / res;
    double worst = 0.0;
    for (const glm::vec4& v : r.radiance)
        for (int c = 0; c < 3; ++c)
            worst = std::max(worst, std::abs(v[c] / (h * h * h) / color[c] - 1.0));
    INFO("worst relative error of the fluence rate " << worst);
    CHECK(worst < 1e-5);
}

TEST_CASE("deposited power-length in a homogeneous box equals Beer-Lambert, without noise",
          "[wavefront]") {
    const int res = 32;
    const glm::vec3 kappa(0.5f, 1.0f, 2.0f);
    const glm::vec3 color(1.0f, 0.5f, 0.25f);
    const PhotonScene s(
        res, 1.0f, kappa, glm::vec3(0.0f, 0.0f, -1.0f), [](glm::vec3) { return 1.0f; }, color);
    WavefrontSettings settings;
    settings.patchesPerSide = res;
    const WavefrontResultCpu r = trace(s, settings);
    const double h = 2.0 / res;
    double worst = 0.0;
    for (int k = 0; k < res; ++k)
        for (int j = 0; j < res; ++j)
            for (int i = 0; i < res; ++i) {
                const double s0 = 1.0 - (-1.0 + (k + 1) * h);  // depth where voxel k starts
                const glm::vec4 got = r.radiance[s.field.index(i, j, k)];
                for (int c = 0; c < 3; ++c) {
                    const double want = color[c] * h * h * std::exp(-kappa[c] * s0) *
                                        (1.0 - std::exp(-kappa[c] * h)) / kappa[c];
                    worst = std::max(worst, std::abs(got[c] / want - 1.0));
                }
            }
    INFO("worst relative error " << worst);
    // Measured 6.4e-7. Photons need 1e-3 for their jitter (test_photons.cpp); a wavefront has no
    // noise, only float rounding.
    CHECK(worst < 1e-5);
    CHECK(maxRelativeImbalance(r.totals) < 1e-5);
}

TEST_CASE("particles of the eikonal system follow the linear n^2 parabola at equal optical time",
          "[wavefront]") {
    // n² = n0² + α(y + 1): with dτ = ds/n the path is x(τ) = x0 + p0τ + (α/4)ŷτ², and the optical
    // time t = ∫n ds = ∫n² dτ = n²(y0)τ + α p0y τ²/2 + α²τ³/12. A particle stepped to time T must
    // sit at x(τ(T)).
    const int res = 32;
    const PhotonScene s(res, 2.0f, glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f),
                        eikon::test::linearN2Field);
    shared::WavefrontTestKernel k = kernelFor(s);
    const double alpha = eikon::test::kAlpha, n0 = eikon::test::kN0;
    const glm::dvec3 x0(-0.6, -0.7, -0.2);
    const glm::dvec3 dir = glm::normalize(glm::dvec3(1.0, 0.4, 0.3));
    const double n2y0 = n0 * n0 + alpha * (x0.y + 1.0);
    const glm::dvec3 p0 = std::sqrt(n2y0) * dir;
    auto timeAt = [&](double tau) {
        return n2y0 * tau + alpha * p0.y * tau * tau / 2.0 + alpha * alpha * tau * tau * tau / 12.0;
    };
    const double T = 1.2;  // optical time: about 0.9 units of path
    double lo = 0.0, hi = 2.0;
    for (int i = 0; i < 200; ++i) ((timeAt(0.5 * (lo + hi)) < T) ? lo : hi) = 0.5 * (lo + hi);
    const double tau = 0.5 * (lo + hi);
    const glm::dvec3 want = x0 + p0 * tau + glm::dvec3(0.0, alpha / 4.0, 0.0) * (tau * tau);
    const double h = 2.0 / res;
    auto errorWith = [&](int integrator, int steps) {
        glm::vec3 x(x0);
        glm::vec3 v = k.wavefrontIndexAt(x).w * glm::vec3(dir);
        for (int i = 0; i < steps; ++i)
            REQUIRE(k.wavefrontAdvance(integrator, x, v, float(T / steps)));
        return glm::length(glm::dvec3(x) - want) / h;
    };
    const double rk4 = errorWith(EK_WAVEFRONT_RK4, 40);
    const double midpoint = errorWith(EK_WAVEFRONT_MIDPOINT, 40);
    const double euler = errorWith(EK_WAVEFRONT_EULER, 40);
    const double eulerFine = errorWith(EK_WAVEFRONT_EULER, 160);
    INFO("error in voxels after 40 steps: RK4 " << rk4 << ", midpoint " << midpoint << ", Euler "
                                                << euler << " (160 steps: " << eulerFine << ")");
    // Measured: RK4 4.9e-5 voxels, midpoint 6.4e-5, Euler 0.017 (0.0043 with 4x the steps). The
    // ∇n volume is n's differences sampled trilinearly; here n is nearly linear, so what is left
    // is the integrators' own error.
    CHECK(rk4 < 1e-3);
    CHECK(midpoint < 1e-3);
    CHECK(euler > rk4);
    CHECK(eulerFine < 0.5 * euler);  // first order: 4x the steps, about a quarter the error
}

TEST_CASE("a point light's wavefront keeps the intensity law: E r^2 = I on every patch",
          "[wavefront]") {
    // Eq. 15 in vacuum: a patch of power I·Ω spreads over Ω r², so Φ/A · r² = I wherever it is.
    const int res = 32;
    const glm::vec3 light(0.2f, 2.5f, -0.1f);
    const glm::vec3 intensity(2.0f, 1.0f, 0.5f);
    const PhotonScene s(res, 1.0f, glm::vec3(0.0f), PhotonScene::pointLight(light, intensity),
                        [](glm::vec3) { return 0.0f; });
    shared::WavefrontTestKernel k = kernelFor(s);
    WavefrontSettings settings;
    settings.patchesPerSide = 24;
    const std::vector<shared::GpuWavefrontPatch> patches =
        generatePatchesCpu(s.setup, {&s.field}, s.gradient, settings);
    const WavefrontPlan plan = planWavefronts(s.setup, settings);
    double worst = 0.0;
    int checked = 0;
    for (shared::GpuWavefrontPatch p : patches) {
        if (int(p.state.x) != EK_PHOTON_ACTIVE) continue;
        glm::vec3 lost(0.0f), reflected(0.0f);
        for (int step = 0; step < 40; ++step)
            if (k.patchStep(p, plan.dt, EK_WAVEFRONT_RK4, EK_WAVEFRONT_KEEP, 1, 0.0f, lost,
                            reflected) != EK_PHOTON_ACTIVE)
                break;
        const double r = glm::length(k.patchCentroid(p) - light);
        const glm::vec3 e = k.patchIrradiance(p);
        for (int c = 0; c < 3; ++c)
            worst = std::max(worst, std::abs(e[c] * r * r / intensity[c] - 1.0));
        ++checked;
    }
    INFO(checked << " patches, worst relative error of E r² " << worst);
    CHECK(checked > 100);
    // Measured 1.4e-3: a flat quad against the piece of sphere it spans (its area is short by
    // about its angle squared over 12), and the trilinear n = 1 volume's rounding.
    CHECK(worst < 2e-3);
}

TEST_CASE(
    "a converging lens: on the axis E grows as A(0)/A(t) until the focus, and the energy "
    "account closes with the removed power reported",
    "[wavefront][lens]") {
    // The lens of support/grin_lens.h and its paraxial reference.
    const test::GrinLens grin;
    constexpr int kRes = test::GrinLens::kRes;
    constexpr double kVoxel = test::GrinLens::kVoxel;
    constexpr float kFocal = test::GrinLens::kFocal, kLensY = test::GrinLens::kLensY,
                    kAperture = test::GrinLens::kAperture;
    constexpr float kHalfWidth = test::GrinLens::kHalfWidth;
    const double slope = grin.slope, offset = grin.offset;
    auto paraxialE = [&](double z) { return grin.paraxialE(z); };
    auto lens = &test::GrinLens::field;
    PhotonScene s(kRes, 2.0f, glm::vec3(0.0f), glm::vec3(0.0f, -1.0f, 0.0f), lens);
    s.markGraded();
    const float windowBottom = kLensY - kHalfWidth;
    {
        // One particle in fine steps: the sideways momentum it gains is ∫∂n/∂x ds along its own
        // path, as the ray equation says (with dx/dt = v/n², as eqs. 12-13 are written, the
        // sampled n and ∇n let |v| drift from n inside the lens and it gained 2 % more).
        shared::WavefrontTestKernel k = kernelFor(s);
        glm::vec3 x(0.05f, 0.95f, 0.0f), v(0.0f, -1.0f, 0.0f);
        double pushed = 0.0;
        while (x.y > 0.3f) {
            const glm::vec3 before = x;
            REQUIRE(k.wavefrontAdvance(EK_WAVEFRONT_RK4, x, v, 5e-5f));
            pushed += double(glm::length(x - before)) * k.wavefrontIndexAt(0.5f * (x + before)).x;
        }
        INFO("v.x " << v.x << ", ∫∂n/∂x ds " << pushed);
        CHECK(double(v.x) == Approx(pushed).epsilon(1e-3));
        CHECK(glm::length(v) == Approx(1.0f).epsilon(1e-3));  // n = 1 past the lens
    }

    // The patches near the axis, stepped as the trace steps them: Φ/A from below the window to
    // z = 3f/4 (E ×16).
    WavefrontSettings settings;  // one starting patch per voxel column (64 per side)
    {
        shared::WavefrontTestKernel k = kernelFor(s);
        const WavefrontPlan plan = planWavefronts(s.setup, settings);
        double worst = 0.0, worstAt = 0.0, worstThin = 0.0;
        int checked = 0;
        for (shared::GpuWavefrontPatch p :
             generatePatchesCpu(s.setup, {&s.field}, s.gradient, settings)) {
            const glm::vec3 c = k.patchCentroid(p);
            if (int(p.state.x) != EK_PHOTON_ACTIVE ||
                c.x * c.x + c.z * c.z > 4.0f * kVoxel * kVoxel)
                continue;
            glm::vec3 lost(0.0f), reflected(0.0f);  // the GRIN lens is graded: no surfaces
            while (k.patchStep(p, plan.dt, EK_WAVEFRONT_RK4, EK_WAVEFRONT_KEEP, 1, 0.0f, lost,
                               reflected) == EK_PHOTON_ACTIVE) {
                if (k.patchCentroid(p).y > windowBottom) continue;
                const double z = double(kLensY) - double(k.patchCentroid(p).y);
                if (z > 0.75 * kFocal) break;
                const double e = double(k.patchIrradiance(p).x);
                const double error = std::abs(e / paraxialE(z) - 1.0);
                if (error > worst) worst = error, worstAt = z;
                worstThin = std::max(worstThin, std::abs(e * std::pow(1.0 - z / kFocal, 2) - 1.0));
                ++checked;
            }
        }
        INFO(checked << " patch steps near the axis; Φ/A against the paraxial ray: worst relative "
                     << "error " << worst << " at z = " << worstAt
                     << " (E/E0 = " << paraxialE(worstAt) << "); against the thin lens "
                     << worstThin << "; effective focal length " << -1.0 / slope
                     << ", principal plane " << (offset - 1.0) / -slope << " below the centre");
        CHECK(checked > 100);
        // Measured 2.0 % at E ×10.7 (0.93 % at half the step, 0.91 % at a quarter: what is left is
        // the sampled n and its differences against the analytic lens).
        CHECK(worst < 0.03);
        CHECK(worstThin > 0.1);  // the thick lens's shift is real: the reference matters
    }

    // What the view reads: the deposits smoothed (3×3×3), per axis voxel against the reference
    // averaged over the voxel's height (Simpson). Past the focus the beam spreads and its patches
    // would split to 8 levels; 2 are enough here (the rest tear, their power counted as dropped).
    settings.maxLevel = 2;
    const WavefrontResultCpu kept = trace(s, settings);
    const std::vector<glm::vec4> smoothed = smoothVolumeCpu(kept.radiance, kept.resolution);
    const int axis = kRes / 2;
    auto axisRows = [&](const std::function<void(int, double, double)>& visit) {
        // From the second voxel wholly below the window (the smoothing reaches one voxel).
        for (int j = int(std::floor((windowBottom + 1.0f) / kVoxel)) - 2; j >= 0; --j) {
            const double top = double(kLensY) - (-1.0 + (j + 1) * kVoxel);
            if (top + kVoxel > 0.75 * kFocal) break;
            visit(j, top, top + kVoxel);
        }
    };
    double worstDeposit = 0.0;
    axisRows([&](int j, double top, double bottom) {
        const double want =
            (paraxialE(top) + 4.0 * paraxialE(0.5 * (top + bottom)) + paraxialE(bottom)) / 6.0;
        const double got = smoothed[s.field.index(axis, j, axis)].g / std::pow(kVoxel, 3);
        worstDeposit = std::max(worstDeposit, std::abs(got / want - 1.0));
    });
    INFO("deposited E on the axis, smoothed: worst relative error " << worstDeposit);
    // Measured 16 %: the deposit's sampling, not the wavefront's: 2 × 2 chords per patch land
    // in the axis voxel in whole numbers as the patches shrink (unsmoothed: up to 50 %). A
    // deposit spread over each patch's footprint would do better; not yet done.
    CHECK(worstDeposit < 0.25);
    CHECK(maxRelativeImbalance(kept.totals) < 1e-3);
    CHECK(kept.totals.removed == glm::dvec3(0.0));

    // The paper's rule removes the patches that cross the focus; before it nothing changes, and
    // the power removed is reported apart from the rest of what is dropped.
    settings.atCaustic = EK_WAVEFRONT_REMOVE;
    const WavefrontResultCpu removed = trace(s, settings);
    CHECK(removed.patchesRemoved > 0);
    CHECK(maxRelativeImbalance(removed.totals) < 1e-3);
    CHECK(removed.totals.removed.x <= removed.totals.dropped.x);
    // Only light through the aperture focuses. Not all of it is removed: a patch is mapped
    // through a point focus by a half turn, which keeps its orientation, so only those whose
    // radial and azimuthal extents collapse in different steps (by the lens's aberration) are
    // seen to turn inside out.
    const double throughAperture = glm::pi<double>() * kAperture * kAperture;
    INFO("removed " << removed.totals.removed.x << " of " << throughAperture
                    << " through the aperture");
    CHECK(removed.totals.removed.x > 0.5 * throughAperture);
    CHECK(removed.totals.removed.x < 1.02 * throughAperture);
    axisRows([&](int j, double, double) {
        const size_t i = s.field.index(axis, j, axis);
        CHECK(removed.radiance[i].g == Approx(kept.radiance[i].g).epsilon(1e-6));
    });
}

TEST_CASE(
    "a ball lens focuses a paraxial wavefront at nR / (2(n - 1)), without NaN, and the "
    "paper's rule removes the patches that cross the focus",
    "[wavefront][lens]") {
    constexpr int kRes = 63;  // odd: the axis x = z = 0 runs through a column of voxel centres
    constexpr float kVoxel = 2.0f / float(kRes);
    constexpr float kIor = 1.5f, kRadius = 0.5f;
    const glm::vec3 centre(0.0f, 0.3f, 0.0f);
    const float rim = 2.0f * kVoxel;
    auto ball = [&](glm::vec3 x) {
        return std::clamp(0.5f - (glm::length(x - centre) - kRadius) / rim, 0.0f, 1.0f);
    };
    // A beam of radius R/5 from a spot light far above: its image sits at 1/(1/f − 1/D).
    const float distance = 40.0f;
    const float coneDeg = glm::degrees(std::atan(kRadius / 5.0f / distance));
    const PhotonScene s(kRes, kIor, glm::vec3(0.0f),
                        PhotonScene::spotLight(centre + glm::vec3(0.0f, distance, 0.0f),
                                               glm::vec3(0.0f, -1.0f, 0.0f), glm::vec3(1.0f),
                                               coneDeg, 0.05f * coneDeg),
                        ball);
    WavefrontSettings settings;
    settings.patchesPerSide = 32;
    const WavefrontResultCpu kept = trace(s, settings);
    for (const glm::vec4& v : kept.radiance) REQUIRE(std::isfinite(v.x + v.y + v.z));
    CHECK(maxRelativeImbalance(kept.totals) < 1e-5);
    CHECK(kept.causticCrossings > 0);
    CHECK(kept.patchesRemoved == 0);
    const std::vector<glm::vec4> smoothed = smoothVolumeCpu(kept.radiance, kept.resolution);
    const int axis = kRes / 2;
    auto at = [&](int j) {
        return double(smoothed[(size_t(axis) * kRes + size_t(j)) * kRes + size_t(axis)].g);
    };
    const int top = int(std::floor((centre.y - kRadius - rim + 1.0f) / kVoxel)) - 1;
    bool interior = false;
    const double peak = eikon::test::plateauCentre(at, 1, top, 0.005, interior);
    REQUIRE(interior);
    const double measured = double(centre.y) - (-1.0 + (peak + 0.5) * kVoxel);
    const double f = double(kIor) * kRadius / (2.0 * (double(kIor) - 1.0));
    const double expected = 1.0 / (1.0 / f - 1.0 / double(distance));
    INFO("focus " << measured << " from the centre, expected " << expected << ": "
                  << (measured - expected) / kVoxel << " voxels; " << kept.patchesTraced
                  << " patches, " << kept.patchesSplit << " splits, " << kept.causticCrossings
                  << " caustic crossings");
    // Measured 0.019 voxels (photons at 95³: 0.55, test_ball_lens.cpp); the bound is the issue's.
    CHECK(std::abs(measured - expected) < 1.5 * kVoxel);

    // The paper's rule: patches that turn inside out are removed, their power counted as
    // dropped; nothing below the focus is lit by them.
    settings.atCaustic = EK_WAVEFRONT_REMOVE;
    const WavefrontResultCpu removed = trace(s, settings);
    CHECK(removed.patchesRemoved > 0);
    CHECK(removed.patchesRemoved == removed.causticCrossings);
    CHECK(maxRelativeImbalance(removed.totals) < 1e-5);
    CHECK(removed.totals.dropped.x > 0.5 * removed.totals.emitted.x);
    // The patch count stays bounded: the beam converges, so little splits.
    CHECK(kept.patchesTraced < 64 * kept.startingPatches);
}

TEST_CASE("wavefront results are bit-identical for any thread count", "[wavefront]") {
    // Small (16³, 12² starting patches): still hundreds of independent roots for the threads to
    // interleave, with splits, and seconds rather than minutes under the sanitizers.
    const int res = 16;
    const PhotonScene s(
        res, 1.6f, glm::vec3(0.3f, 0.5f, 0.7f), glm::vec3(0.3f, -1.0f, 0.2f),
        [](glm::vec3 x) { return std::clamp(0.5f - (glm::length(x) - 0.6f) / 0.15f, 0.0f, 1.0f); });
    WavefrontSettings settings;
    settings.patchesPerSide = 12;
    settings.maxLevel = 3;  // splits and tears both happen, without the focus's 10^5 patches
    WavefrontResultCpu one, many;
    tbb::task_arena(1).execute([&] { one = trace(s, settings); });
    tbb::task_arena(4).execute([&] { many = trace(s, settings); });
    REQUIRE(one.patchesSplit > 0);
    REQUIRE(one.patchesTorn > 0);
    REQUIRE(one.totals.reflected.x > 0.0);  // the ball's surface reflects
    CHECK(one.totals.reflected == many.totals.reflected);
    CHECK(one.radiance == many.radiance);
    CHECK(one.direction == many.direction);
    CHECK(one.totals.escaped == many.totals.escaped);
    CHECK(one.totals.extinguished == many.totals.extinguished);
    CHECK(one.steps == many.steps);
    CHECK(one.patchesTraced == many.patchesTraced);
    CHECK(one.patchesTorn == many.patchesTorn);
}

TEST_CASE("the patch budget caps splitting without changing the energy balance", "[wavefront]") {
    // A point light inside the box: its wavefront grows without end, and every patch splits.
    const int res = 24;
    const PhotonScene s(res, 1.0f, glm::vec3(0.2f),
                        PhotonScene::pointLight(glm::vec3(0.1f), glm::vec3(1.0f)),
                        [](glm::vec3) { return 1.0f; });
    WavefrontSettings settings;
    settings.patchesPerSide = 4;
    settings.maxPatches = 6 * 16 * 20;  // 20 per starting patch
    const WavefrontResultCpu r = trace(s, settings);
    CHECK(r.startingPatches == 6 * 16);
    CHECK(r.patchesTraced <= settings.maxPatches);
    CHECK(r.splitsRefused > 0);
    CHECK(maxRelativeImbalance(r.totals) < 1e-5);
    // 4π I emitted, to float rounding of the cells' solid angles.
    CHECK(r.totals.emitted.x == Approx(4.0 * glm::pi<double>()).epsilon(1e-5));
}

TEST_CASE("the shared wavefront code compiles as GLSL 4.30", "[wavefront][gpu]") {
    auto context = eikon::createHeadlessContext();
    CHECK_NOTHROW(eikon::ShaderProgram::compute("test/wavefront_compile.comp"));
}

TEST_CASE(
    "Maxwell's fish-eye: particles from a point meet at its image R^2/r opposite, at equal "
    "optical time",
    "[wavefront][lens]") {
    // n = n0 / (1 + (r/R)²) images every point P perfectly at −(R²/|P|²) P, and every ray from P
    // to the image has the same optical length (Maxwell's perfect instrument): particles leaving
    // P together all reach the image at one optical time T, which the straight ray through the
    // centre gives in closed form, T = n0 R (atan(|P|/R) + atan(|image|/R)).
    const int res = 64;
    const double R = 0.8, n0 = 1.0 + 3.0 * R * R;
    const glm::dvec3 P(0.85, 0.0, 0.0);
    const glm::dvec3 image = -(R * R / glm::dot(P, P)) * P;
    auto n = [&](glm::vec3 x) { return n0 / (1.0 + double(glm::dot(x, x)) / (R * R)); };
    // The field f with n = 1 + f (ior 2); n falls to 1 at |x| = R √(n0 − 1) = 1.1 and is held
    // there beyond (no ray from P within 60° of the centre goes that far).
    const PhotonScene s(res, 2.0f, glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f),
                        [&](glm::vec3 x) { return float(std::max(n(x) - 1.0, 0.0)); });
    shared::WavefrontTestKernel k = kernelFor(s);
    const double T = n0 * R * (std::atan(glm::length(P) / R) + std::atan(glm::length(image) / R));
    const int steps = 400;
    const double h = 2.0 / res;
    double worst = 0.0;
    int checked = 0;
    // Directions within 60° of the way to the centre, in and out of the plane through the axis.
    for (double polar : {0.0, 0.35, 0.7, 1.05})
        for (double azimuth : {0.0, 1.3, 2.6, 3.9, 5.2}) {
            const glm::dvec3 d(-std::cos(polar), std::sin(polar) * std::cos(azimuth),
                               std::sin(polar) * std::sin(azimuth));
            glm::vec3 x(P);
            glm::vec3 v = k.wavefrontIndexAt(x).w * glm::vec3(d);
            for (int i = 0; i < steps; ++i)
                REQUIRE(k.wavefrontAdvance(EK_WAVEFRONT_RK4, x, v, float(T / steps)));
            worst = std::max(worst, glm::length(glm::dvec3(x) - image) / h);
            ++checked;
            if (polar == 0.0) break;
        }
    INFO(checked << " particles; worst distance from the image " << worst << " voxels");
    // The bound: within 1 voxel at 64³ (0.069 measured).
    CHECK(worst < 1.0);
}

TEST_CASE("a parabolic GRIN rod: particles cross its axis every half period pi cos(theta0) / alpha",
          "[wavefront]") {
    // n² = n0² (1 − α²ρ²), ρ the distance from the z axis: in the optical parameter τ the
    // transverse motion is harmonic with angular frequency n0 α while z advances at the invariant
    // β = n0 cos θ0, so a ray from the axis crosses it again every π β / (n0 α) = π cos θ0 / α
    // along z. Rays at θ0 ≤ 20° stay within ρ ≤ sin θ0 / α = 0.11, far from where the profile
    // is clamped at n = 1 (ρ = 0.29).
    const int res = 64;
    const double n0 = 2.0, alpha = 3.0;
    auto n = [&](glm::vec3 x) {
        const double rho2 = double(x.x) * x.x + double(x.y) * x.y;
        return std::sqrt(std::max(n0 * n0 * (1.0 - alpha * alpha * rho2), 1.0));
    };
    const PhotonScene s(res, 2.0f, glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f),
                        [&](glm::vec3 x) { return float(n(x) - 1.0); });
    shared::WavefrontTestKernel k = kernelFor(s);
    const double h = 2.0 / res;
    double worst = 0.0;
    for (double degrees : {5.0, 10.0, 20.0}) {
        const double theta = glm::radians(degrees);
        // Start half a voxel off the box's end, on the axis.
        glm::vec3 x(0.0f, 0.0f, -0.95f);
        glm::vec3 v = k.wavefrontIndexAt(x).w *
                      glm::vec3(float(std::sin(theta)), 0.0f, float(std::cos(theta)));
        const double halfPeriod = glm::pi<double>() * std::cos(theta) / alpha;
        std::vector<double> crossings;
        const float dt = float(0.25 * h);
        for (int i = 0; i < 4000 && x.z < 0.95f; ++i) {
            const glm::vec3 before = x;
            REQUIRE(k.wavefrontAdvance(EK_WAVEFRONT_RK4, x, v, dt));
            if (i > 0 && before.x != 0.0f && (before.x < 0.0f) != (x.x < 0.0f))
                crossings.push_back(double(before.z) + double(x.z - before.z) * double(before.x) /
                                                           double(before.x - x.x));
        }
        INFO(degrees << "°: " << crossings.size() << " crossings, half period " << halfPeriod);
        REQUIRE(crossings.size() >= 1);
        for (size_t c = 0; c < crossings.size(); ++c) {
            const double want = -0.95 + double(c + 1) * halfPeriod;
            worst = std::max(worst, std::abs(crossings[c] - want) / h);
        }
    }
    INFO("worst crossing error " << worst << " voxels");
    CHECK(worst < 0.5);  // 0.18 measured
}
