// Photon tracing (Sun et al. 2008 steps 4-5, shaders/shared/photons.h): straight photons in a
// uniform medium, energy bookkeeping, curved photons against the closed-form parabola of a linear
// n² gradient, the deposited flux·length against Beer–Lambert, bit-identical results for any
// thread count, and hard inputs (a sharp n = 2.4 ball, grazing light).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <functional>

#include <tbb/task_arena.h>

#include "core/camera.h"
#include "render/gl_context.h"
#include "render/photon_tracing.h"
#include "render/refraction_volume.h"
#include "render/shader_program.h"
#include "render/volume_kernels_cpu.h"
#include "support/linear_n2_medium.h"
#include "support/photon_scene.h"

EK_NAMESPACE_BEGIN
// The shared photon functions with nothing to deposit into: for the photons' starting states.
struct PhotonTestKernel : VolumeAccessCpu {
    vec4 fetchOctree(ivec3) const { return vec4(0.0f); }
    void depositVoxel(ivec3, vec3, vec3) const {}
#include "shaders/shared/photons.h"
};
EK_NAMESPACE_END

using namespace eikon;

namespace {

using eikon::test::PhotonScene;

// Photon `index`'s starting state in scene `p`, from the shared generator.
shared::GpuPhoton photonStart(const PhotonScene& p, const PhotonSettings& s, int index) {
    shared::PhotonTestKernel k{{p.setup.params}};
    k.fields[0] = p.field.values.data();
    k.gradient = p.gradient.data();
    return k.generateDirectionalPhoton(0, s.photonsPerSide, index, s.seed, glm::uint(s.frame),
                                       s.fluxThreshold);
}

float voxelSize(const PhotonScene& s) {
    return s.field.volume.voxelSize().x;
}

double maxRelativeImbalance(const PhotonTotals& t) {
    double worst = 0.0;
    for (int c = 0; c < 3; ++c) {
        const double sum = t.escaped[c] + t.extinguished[c] + t.dropped[c];
        worst = std::max(worst, std::abs(sum - t.emitted[c]) / t.emitted[c]);
    }
    return worst;
}

float gradientField(glm::vec3 x) {
    return eikon::test::linearN2Field(x);
}

glm::dvec3 exactExit(glm::dvec3 x0, glm::dvec3 dir) {
    return eikon::test::linearN2Exit(x0, dir);
}

bool allFinite(const std::vector<glm::vec4>& v) {
    for (const glm::vec4& x : v)
        if (!std::isfinite(x.x) || !std::isfinite(x.y) || !std::isfinite(x.z) ||
            !std::isfinite(x.w))
            return false;
    return true;
}

bool sameBits(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0;
}

float ball(glm::vec3 x) {
    // A smooth ball of radius 0.5, its rim ~0.2 wide.
    return 0.5f - 0.5f * std::tanh((glm::length(x) - 0.5f) / 0.1f);
}

}  // namespace

TEST_CASE("photons in a uniform n = 1 clear medium leave where straight lines do", "[photons]") {
    const glm::vec3 d = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
    PhotonScene s(32, 1.0f, glm::vec3(0.0f), d, [](glm::vec3) { return 0.0f; });
    PhotonSettings settings;
    settings.photonsPerSide = 48;
    const PhotonResultCpu r = s.trace(settings);
    REQUIRE(r.photonsTraced > 0);
    double worst = 0.0;
    int checked = 0;
    for (int i = 0; i < int(r.photons.size()); ++i) {
        const shared::GpuPhoton start = photonStart(s, settings, i);
        if (int(start.position.w) != EK_PHOTON_ACTIVE) continue;
        const shared::GpuPhoton& end = r.photons[size_t(i)];
        REQUIRE(int(end.position.w) == EK_PHOTON_ESCAPED);
        // The straight line from the entry to the box's far side, in double precision.
        const glm::dvec3 x0(glm::vec3(start.position));
        const glm::dvec3 dd(d);
        double tExit = 1e30;
        for (int a = 0; a < 3; ++a)
            if (dd[a] != 0.0) tExit = std::min(tExit, ((dd[a] > 0 ? 1.0 : -1.0) - x0[a]) / dd[a]);
        const glm::dvec3 want = x0 + dd * tExit;
        worst = std::max(worst, glm::length(glm::dvec3(glm::vec3(end.position)) - want));
        ++checked;
    }
    worst /= voxelSize(s);
    INFO(checked << " photons; worst exit error " << worst << " voxels; steps " << r.steps);
    CHECK(checked == r.photonsTraced);
    CHECK(worst < 1e-4);
    CHECK(r.totals.extinguished == glm::dvec3(0.0));
    CHECK(r.totals.dropped == glm::dvec3(0.0));
}

TEST_CASE("photon flux is conserved: emitted = escaped + extinguished + dropped", "[photons]") {
    const glm::vec3 d = glm::normalize(glm::vec3(0.4f, -1.0f, 0.3f));
    PhotonScene s(32, 1.5f, glm::vec3(4.0f, 6.0f, 10.0f), d, ball, glm::vec3(1.0f, 0.7f, 0.4f));
    PhotonSettings settings;
    settings.photonsPerSide = 64;
    settings.fluxThreshold = 0.05f;  // high, so that some photons are dropped
    const PhotonResultCpu r = s.trace(settings);
    const PhotonTotals& t = r.totals;
    const double imbalance = maxRelativeImbalance(t);
    INFO("emitted " << t.emitted.x << " escaped " << t.escaped.x << " extinguished "
                    << t.extinguished.x << " dropped " << t.dropped.x << " (red); worst imbalance "
                    << imbalance << "; steps " << r.steps << " cut " << r.photonsCut);
    for (int c = 0; c < 3; ++c) {
        CHECK(t.extinguished[c] > 0.0);
        CHECK(t.escaped[c] > 0.0);
    }
    CHECK(t.dropped.z > 0.0);
    CHECK(imbalance < 1e-3);
    // The emitted power is E × the box's projected area, up to the cells along its silhouette.
    const double area = 4.0 * (std::abs(d.x) + std::abs(d.y) + std::abs(d.z));
    CHECK(std::abs(t.emitted.x / area - 1.0) < 0.01);
}

TEST_CASE("photons in a linear n^2 gradient follow the closed-form parabola", "[photons]") {
    const glm::vec3 d = glm::normalize(glm::vec3(0.15f, -1.0f, -0.25f));
    // Worst exit-point error, in voxels, of 16 × 16 photons at minimum step `step` (voxels).
    auto worstError = [&](float step, const OctreeSettings& os, int64_t& steps) {
        PhotonScene s(32, 2.0f, glm::vec3(0.0f), d, gradientField, glm::vec3(1.0f), os);
        PhotonSettings settings;
        settings.photonsPerSide = 16;
        settings.minStepVoxels = step;
        const PhotonResultCpu r = s.trace(settings);
        steps = r.steps;
        double worst = 0.0;
        int checked = 0;
        for (int i = 0; i < int(r.photons.size()); ++i) {
            const shared::GpuPhoton start = photonStart(s, settings, i);
            if (int(start.position.w) != EK_PHOTON_ACTIVE) continue;
            const shared::GpuPhoton& end = r.photons[size_t(i)];
            REQUIRE(int(end.position.w) == EK_PHOTON_ESCAPED);
            const glm::dvec3 want = exactExit(glm::dvec3(glm::vec3(start.position)), glm::dvec3(d));
            worst = std::max(worst, glm::length(glm::dvec3(glm::vec3(end.position)) - want));
            ++checked;
        }
        REQUIRE(checked > 100);
        return worst / voxelSize(s);
    };

    // Default settings: the octree labels this medium level 1 (2-voxel nodes, ε ≤ range < ε'),
    // so steps run from the 1-voxel minimum to a node's width.
    int64_t steps = 0;
    const double atDefault = worstError(1.0f, OctreeSettings{}, steps);
    INFO("default settings: " << steps << " steps, worst exit error " << atDefault << " voxels");
    CHECK(atDefault < 0.25);

    // Convergence: with ε = ε' = 0 every voxel is a level-0 leaf capped at the minimum step, so
    // the march takes exactly the minimum step and the error must shrink with it.
    double previous = 1e9;
    for (float step : {1.0f, 0.5f, 0.25f}) {
        OctreeSettings os;
        os.epsilon = os.epsilonPrime = 0.0f;
        os.minStepVoxels = step;
        const double worst = worstError(step, os, steps);
        INFO("min step " << step << " voxels: " << steps << " steps, worst exit error " << worst
                         << " voxels");
        CHECK(worst < previous);
        previous = worst;
    }
}

TEST_CASE("deposited flux-length in a homogeneous box equals Beer-Lambert", "[photons]") {
    const int res = 32;
    const glm::vec3 kappa(0.5f, 1.0f, 2.0f);
    const glm::vec3 color(1.0f, 0.5f, 0.25f);
    PhotonScene s(
        res, 1.0f, kappa, glm::vec3(0.0f, 0.0f, -1.0f), [](glm::vec3) { return 1.0f; }, color);
    PhotonSettings settings;
    settings.photonsPerSide = 64;  // 2 × 2 photons per voxel column
    const PhotonResultCpu r = s.trace(settings);
    const double h = voxelSize(s);
    double worst = 0.0, worstDirection = 0.0;
    for (int k = 0; k < res; ++k)
        for (int j = 0; j < res; ++j)
            for (int i = 0; i < res; ++i) {
                // Light enters at z = 1; voxel k spans depths [s0, s0 + h].
                const double s0 = 1.0 - (-1.0 + (k + 1) * h);
                const glm::vec4 got = r.radiance[s.field.index(i, j, k)];
                glm::dvec3 want;
                for (int c = 0; c < 3; ++c)
                    want[c] = color[c] * h * h * std::exp(-kappa[c] * s0) *
                              (1.0 - std::exp(-kappa[c] * h)) / kappa[c];
                for (int c = 0; c < 3; ++c)
                    worst = std::max(worst, std::abs(got[c] / want[c] - 1.0));
                // The weighted direction: luminance of the flux·length along −z.
                const glm::vec4 dir = r.direction[s.field.index(i, j, k)];
                const double lum = 0.2126 * got.x + 0.7152 * got.y + 0.0722 * got.z;
                worstDirection = std::max({worstDirection, std::abs(-dir.z / lum - 1.0),
                                           std::abs(dir.x / lum), std::abs(dir.y / lum)});
            }
    INFO("worst relative error " << worst << ", of the direction " << worstDirection);
    CHECK(worst < 1e-3);
    CHECK(worstDirection < 1e-3);
}

TEST_CASE("photon results are bit-identical for any thread count; seeds change only noise",
          "[photons]") {
    const glm::vec3 d = glm::normalize(glm::vec3(0.4f, -1.0f, 0.3f));
    PhotonScene s(24, 1.5f, glm::vec3(1.0f, 2.0f, 4.0f), d, ball, glm::vec3(1.0f, 0.7f, 0.4f));
    PhotonSettings settings;
    settings.photonsPerSide = 48;
    settings.seed = 7;
    PhotonResultCpu one, two;
    tbb::task_arena(1).execute([&] { one = s.trace(settings); });
    tbb::task_arena(2).execute([&] { two = s.trace(settings); });
    CHECK(sameBits(one.radiance, two.radiance));
    CHECK(sameBits(one.direction, two.direction));
    CHECK(one.totals.escaped == two.totals.escaped);
    CHECK(one.totals.extinguished == two.totals.extinguished);
    CHECK(one.steps == two.steps);

    settings.seed = 8;
    const PhotonResultCpu other = s.trace(settings);
    CHECK_FALSE(sameBits(one.radiance, other.radiance));
    bool moved = false;
    for (size_t i = 0; i < one.photons.size(); ++i)
        moved = moved || one.photons[i].position != other.photons[i].position;
    CHECK(moved);
    for (int c = 0; c < 3; ++c) {
        const double e = std::abs(other.totals.emitted[c] / one.totals.emitted[c] - 1.0);
        const double x = std::abs(other.totals.escaped[c] / one.totals.escaped[c] - 1.0);
        INFO("channel " << c << ": emitted differ by " << e << ", escaped by " << x);
        CHECK(e < 0.01);
        CHECK(x < 0.02);
    }
}

TEST_CASE("a sharp n = 2.4 ball under grazing light: no NaN, every photon ends", "[photons]") {
    for (glm::vec3 d : {glm::vec3(1.0f, -0.002f, 0.0f), glm::vec3(0.3f, -1.0f, 0.001f)}) {
        PhotonScene s(32, 2.4f, glm::vec3(0.3f, 0.6f, 1.0f), glm::normalize(d),
                      [](glm::vec3 x) { return glm::length(x) < 0.5f ? 1.0f : 0.0f; });
        PhotonSettings settings;
        settings.photonsPerSide = 64;
        settings.maxSteps = 4000;
        const PhotonResultCpu r = s.trace(settings);
        int ended = 0;
        bool finite = true;
        for (const shared::GpuPhoton& p : r.photons) {
            const int state = int(p.position.w);
            if (state == EK_PHOTON_ESCAPED || state == EK_PHOTON_DROPPED) ++ended;
            finite = finite && allFinite({p.position, p.direction, p.flux});
        }
        INFO("direction " << d.x << " " << d.y << " " << d.z << ": " << r.photonsTraced
                          << " photons, " << ended << " ended, " << r.photonsCut << " cut, "
                          << r.steps << " steps, imbalance " << maxRelativeImbalance(r.totals));
        CHECK(r.photonsTraced > 0);
        CHECK(ended == r.photonsTraced);
        CHECK(r.photonsCut == 0);
        CHECK(finite);
        CHECK(allFinite(r.radiance));
        CHECK(allFinite(r.direction));
        CHECK(maxRelativeImbalance(r.totals) < 1e-3);
    }
}

TEST_CASE("the shared photon code compiles as GLSL 4.30", "[photons][gpu]") {
    // The GPU port runs this same file; a construct valid only in C++ must fail here, not later.
    auto context = eikon::createHeadlessContext();
    CHECK_NOTHROW(eikon::ShaderProgram::compute("test/photons_compile.comp"));
}
