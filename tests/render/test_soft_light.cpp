// Soft distant lights (a directional light's angular_diameter_deg, docs/methods.md#soft-distant-
// lights), CPU twins against closed forms: the photons' directions fill the disc's cap uniformly
// in solid angle; behind an opaque edge the photons' penumbra has the disc's width at every
// depth; the plane sweep's incremental convolution has it at its reference depth and spreads as
// the square root of the depth elsewhere, as documented. Penumbrae are compared by variance: the
// spread of the profile's slope across the edge, with the same scene's sharp light (no disc)
// subtracted, since variances of convolved spreads add.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "render/transport/light_volumes/light_volume.h"
#include "render/transport/photons/photon_tracing.h"
#include "render/transport/plane_sweep/plane_sweep_cpu.h"
#include "support/photon_scene.h"

using namespace eikon;
using eikon::test::PhotonScene;

namespace {

constexpr int kRes = 64;               // the box [-1, 1]³ at 64³: h = 1/32
constexpr double kOccluderZ = 0.9375;  // the occluding slab's mid-plane
constexpr float kOccluderKappa = 150.0f;

// An opaque half-plane: a slab two voxels thick near the top, over x < 0 only.
float halfPlaneOccluder(glm::vec3 x) {
    return x.x < 0.0f && x.z > 0.9f && x.z < 0.97f ? 1.0f : 0.0f;
}

LightSpec discLight(float diameterDeg) {
    LightSpec light = PhotonScene::directionalLight(glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(1.0f));
    light.angularDiameterDeg = diameterDeg;
    return light;
}

// The light through the fluence (as photons and the sweep carry it), or not (as light volumes
// shadow it).
PhotonScene occluderScene(float diameterDeg, bool inFluence = true) {
    // The octree limits steps by κ, so that photons in n = 1 do not step over the thin slab.
    OctreeSettings octree;
    octree.kappaTolerance = 0.1f;
    PhotonScene s(kRes, 1.0f, glm::vec3(kOccluderKappa), discLight(diameterDeg), halfPlaneOccluder,
                  octree);
    if (inFluence) shared::setLightInFluence(s.setup.params, 0);
    return s;
}

double voxelCentre(int i) {
    return -1.0 + (i + 0.5) * 2.0 / kRes;
}

// Slice k's fluence across x (channel 0), averaged over the middle half of the rows.
std::vector<double> profileAcrossEdge(const std::vector<glm::vec4>& fluence, int k) {
    std::vector<double> profile(kRes, 0.0);
    const int first = kRes / 4, last = 3 * kRes / 4;
    for (int i = 0; i < kRes; ++i) {
        for (int j = first; j < last; ++j)
            profile[size_t(i)] += fluence[size_t(i + kRes * (j + kRes * k))].x;
        profile[size_t(i)] /= double(last - first);
    }
    return profile;
}

// The variance of the profile's rise across the edge at x = 0: its slope between neighbouring
// voxels as a distribution over x, within |x| < window.
double edgeVariance(const std::vector<double>& profile, double window) {
    double weight = 0.0, mean = 0.0, square = 0.0;
    for (int i = 0; i + 1 < kRes; ++i) {
        const double x = 0.5 * (voxelCentre(i) + voxelCentre(i + 1));
        if (std::abs(x) > window) continue;
        const double rise = profile[size_t(i + 1)] - profile[size_t(i)];
        weight += rise;
        mean += rise * x;
        square += rise * x * x;
    }
    mean /= weight;
    return square / weight - mean * mean;
}

// The disc's penumbra variance a distance D behind the edge: its projection, radius D tan α,
// seen across the edge (a uniform disc's marginal has variance R²/4).
double discPenumbraVariance(double diameterDeg, double depth) {
    const double radius = depth * std::tan(0.5 * diameterDeg * M_PI / 180.0);
    return radius * radius / 4.0;
}

// The share of a uniform disc of radius R (its projection's marginal) with coordinate below x.
double discMarginalCdf(double x, double radius) {
    const double t = std::clamp(x / radius, -1.0, 1.0);
    return 0.5 + (t * std::sqrt(1.0 - t * t) + std::asin(t)) / M_PI;
}

// `profile` (voxels of edge h) convolved with the disc's marginal of radius R, each voxel's
// weight the marginal's share of it; beyond the box the profile is taken as at its ends.
std::vector<double> blurredByDisc(const std::vector<double>& profile, double radius, double h) {
    const int reach = int(std::ceil(radius / h)) + 1;
    std::vector<double> out(profile.size(), 0.0);
    for (int i = 0; i < int(profile.size()); ++i)
        for (int m = -reach; m <= reach; ++m) {
            const double share =
                discMarginalCdf((m + 0.5) * h, radius) - discMarginalCdf((m - 0.5) * h, radius);
            const int from = std::clamp(i - m, 0, int(profile.size()) - 1);
            out[size_t(i)] += share * profile[size_t(from)];
        }
    return out;
}

int sliceAtDepth(double depth) {
    return int(std::lround((1.0 + kOccluderZ - depth) * kRes / 2.0 - 0.5));
}

double sliceDepth(int k) {
    return kOccluderZ - voxelCentre(k);
}

std::vector<glm::vec4> sweepFluence(float diameterDeg) {
    PhotonScene s = occluderScene(diameterDeg);
    return sweepLightsCpu(s.setup, {&s.field}, s.gradient, {}).fluence;
}

}  // namespace

TEST_CASE("a disc light's photons fill its cap uniformly in solid angle", "[soft_light]") {
    const float diameter = 12.0f;
    PhotonScene s(16, 1.0f, glm::vec3(0.0f), discLight(diameter), [](glm::vec3) { return 0.0f; });
    PhotonSettings settings;
    settings.photonsPerSide = 256;
    const std::vector<shared::GpuPhoton> photons =
        generatePhotonsCpu(s.setup, s.gradient, settings);
    const double versine = 1.0 - std::cos(0.5 * diameter * M_PI / 180.0);
    double sumVersine = 0.0, largest = 0.0, sumX = 0.0, sumY = 0.0, sumX2 = 0.0;
    int active = 0;
    for (const shared::GpuPhoton& p : photons) {
        if (int(p.position.w) != EK_PHOTON_ACTIVE) continue;
        const glm::dvec3 d = glm::normalize(glm::dvec3(glm::vec3(p.direction)));
        // Only photons through the middle of the plane z = 0 across the light: every one of them
        // enters the box whatever its tilt. (Near the rectangle's rim, which photons hit the box
        // depends on their tilt: counting those would bias the mean.)
        const glm::dvec3 entry(glm::vec3(p.position));
        const glm::dvec3 centre = entry + (-entry.z / d.z) * d;
        if (std::abs(centre.x) > 0.5 || std::abs(centre.y) > 0.5) continue;
        const double v = 1.0 + d.z;  // 1 − cos θ from the light's direction −z
        sumVersine += v;
        largest = std::max(largest, v);
        sumX += d.x;
        sumY += d.y;
        sumX2 += d.x * d.x;
        ++active;
    }
    REQUIRE(active > 5000);
    const double n = double(active);
    INFO(active << " photons; mean versine " << sumVersine / n << ", cap's " << versine);
    // Uniform in solid angle: 1 − cos θ is uniform on [0, versine], its mean versine/2 (a
    // uniform disc in the angle's plane would give versine/2 too, to first order: the second
    // moment of the tilt tells them apart only at large discs, so the bound is checked too).
    CHECK(sumVersine / n == Approx(versine / 2.0).epsilon(0.02));  // 4 standard errors
    CHECK(largest <= versine * (1.0 + 1e-4));
    CHECK(largest > 0.99 * versine);
    // No azimuth preferred: mean tilt 0, and sin²θ cos²φ averaging (sin²θ)/2.
    const double tilt = std::sqrt(versine * (2.0 - versine));
    CHECK(std::abs(sumX / n) < 0.02 * tilt);
    CHECK(std::abs(sumY / n) < 0.02 * tilt);
    CHECK(sumX2 / n == Approx(0.5 * (versine - versine * versine / 3.0)).epsilon(0.05));
}

TEST_CASE("without a disc a directional light's photons are the single direction's, bit for bit",
          "[soft_light]") {
    PhotonScene sharp(16, 1.0f, glm::vec3(0.0f), discLight(0.0f), [](glm::vec3) { return 0.0f; });
    PhotonSettings settings;
    settings.photonsPerSide = 32;
    for (const shared::GpuPhoton& p : generatePhotonsCpu(sharp.setup, sharp.gradient, settings)) {
        if (int(p.position.w) != EK_PHOTON_ACTIVE) continue;
        REQUIRE(glm::vec3(p.direction) == glm::vec3(0.0f, 0.0f, -1.0f));
    }
}

TEST_CASE("photons from a disc light: an edge's penumbra has the disc's width at every depth",
          "[soft_light]") {
    // The soft profile against the sharp one blurred by the disc's projection at that depth,
    // radius s · D tan α: the s of least squared difference, over three neighbouring slices
    // (the photons are noisy; the fit uses every voxel across the edge).
    const float diameter = 20.0f;
    const double tangent = std::tan(0.5 * diameter * M_PI / 180.0);
    const double h = 2.0 / kRes;
    PhotonSettings settings;
    settings.photonsPerSide = 768;
    const auto trace = [&](float d) { return occluderScene(d).trace(settings).radiance; };
    const std::vector<glm::vec4> sharp = trace(0.0f);
    const std::vector<glm::vec4> soft = trace(diameter);
    for (const double depth : {0.5, 1.0, 1.5}) {
        double bestScale = 0.0, bestError = 1e300;
        for (double scale = 0.5; scale <= 1.5; scale += 0.01) {
            double error = 0.0;
            for (int k = sliceAtDepth(depth) - 1; k <= sliceAtDepth(depth) + 1; ++k) {
                const std::vector<double> want =
                    blurredByDisc(profileAcrossEdge(sharp, k), scale * sliceDepth(k) * tangent, h);
                const std::vector<double> got = profileAcrossEdge(soft, k);
                for (int i = 0; i < kRes; ++i)
                    if (std::abs(voxelCentre(i)) < 0.6)
                        error +=
                            (got[size_t(i)] - want[size_t(i)]) * (got[size_t(i)] - want[size_t(i)]);
            }
            if (error < bestError) bestError = error, bestScale = scale;
        }
        INFO("depth " << depth << ": the penumbra fits the disc's projection at " << bestScale
                      << " x its radius");
        CHECK(bestScale == Approx(1.0).margin(0.08));
    }
}

TEST_CASE(
    "the plane sweep's soft light: the disc's penumbra at the reference depth, spreading "
    "as the square root of the depth",
    "[soft_light][plane_sweep]") {
    const float diameter = 20.0f;
    const std::vector<glm::vec4> sharp = sweepFluence(0.0f);
    const std::vector<glm::vec4> soft = sweepFluence(diameter);
    const double reference = 1.0;  // half the light's path across the box
    for (const double depth : {0.5, 1.0, 1.5}) {
        const int k = sliceAtDepth(depth);
        const double got = edgeVariance(profileAcrossEdge(soft, k), 0.6) -
                           edgeVariance(profileAcrossEdge(sharp, k), 0.6);
        const double disc = discPenumbraVariance(diameter, sliceDepth(k));
        // The convolution's variance grows as D · D_ref where the disc's grows as D².
        const double designed = disc * reference / sliceDepth(k);
        INFO("depth " << sliceDepth(k) << ": penumbra variance " << got << ", the disc's " << disc
                      << ", the convolution's design " << designed);
        CHECK(got / designed == Approx(1.0).epsilon(0.1));
    }
    // The kernel turns by plane index, not by chance: a rerun gives the same bits.
    const std::vector<glm::vec4> again = sweepFluence(diameter);
    CHECK(std::memcmp(again.data(), soft.data(), soft.size() * sizeof(glm::vec4)) == 0);
}

// [release_only]: 304 s under the sanitizers; the disc's 16 marches run there in
// test_light_volume.cpp's smaller GPU-against-twin case.
TEST_CASE("light volumes march a disc light's 16 directions: the disc's penumbra at every depth",
          "[soft_light][light_volume][release_only]") {
    const float diameter = 20.0f;
    const auto transmittance = [](float d, int mode) {
        PhotonScene s = occluderScene(d, false);
        shared::setShadowMode(s.setup.params, mode);
        shared::setShadowStep(s.setup.params, 2.0f / kRes);  // a voxel, as the method sets it
        return computeLightVolumesCpu(s.setup, {&s.field})[0];
    };
    const std::vector<glm::vec4> sharp = transmittance(0.0f, EK_SHADOWS_VOLUME);
    const std::vector<glm::vec4> soft = transmittance(diameter, EK_SHADOWS_VOLUME);
    for (const double depth : {0.5, 1.0, 1.5}) {
        const int k = sliceAtDepth(depth);
        const double got = edgeVariance(profileAcrossEdge(soft, k), 0.6) -
                           edgeVariance(profileAcrossEdge(sharp, k), 0.6);
        const double disc = discPenumbraVariance(diameter, sliceDepth(k));
        INFO("depth " << sliceDepth(k) << ": penumbra variance " << got << ", the disc's " << disc);
        CHECK(got / disc == Approx(1.0).epsilon(0.06));
    }
}
