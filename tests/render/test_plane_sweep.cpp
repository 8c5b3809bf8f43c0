// Plane-by-plane semi-Lagrangian light propagation (Magnus's thesis ch. 4.2;
// shaders/shared/plane_sweep.h), CPU twin, against closed forms: light unbent in n = 1 and
// Beer–Lambert in a homogeneous slab, the straight light volumes' sweep where both are exact, a
// linear n² medium's parabola, a ball lens's paraxial focus, the intensity law with the
// correction on and off, byte-identical results for any thread count, and buffers that scale
// with a plane, not the volume.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

#include <tbb/global_control.h>

#include "render/transport/light_volumes/light_volume.h"
#include "render/transport/plane_sweep/plane_sweep_cpu.h"
#include "support/grin_lens.h"
#include "support/light_transport_setup.h"
#include "support/linear_n2_medium.h"
#include "support/photon_scene.h"

using namespace eikon;
using eikon::test::PhotonScene;

namespace {

// The scene's lights all through the fluence, as configure() sets them for the method.
PlaneSweepResultCpu sweep(PhotonScene& s, const PlaneSweepSettings& settings = {},
                          const PlaneSweepObserver& observer = {}) {
    for (int l = 0; l < shared::lightCount(s.setup.params); ++l)
        shared::setLightInFluence(s.setup.params, l);
    return sweepLightsCpu(s.setup, {&s.field}, s.gradient, settings, observer);
}

double voxelVolume(const PhotonScene& s) {
    const glm::vec3 h = s.field.volume.voxelSize();
    return double(h.x) * h.y * h.z;
}

// Where the ray from world point x toward the light (along −d) leaves the box [-1, 1]³.
double distanceToLight(glm::vec3 x, glm::vec3 d) {
    double t = 1e30;
    for (int a = 0; a < 3; ++a)
        if (d[a] != 0.0f) t = std::min(t, (double(d[a] < 0.0f ? 1.0f : -1.0f) - x[a]) / -d[a]);
    return t;
}

// Whether the path from world point x toward the light (along −d) left the box through its top
// face at least `margin` from the side faces. Light that entered through a side meets none of
// the medium above, so the light field jumps across the shadow line of the box's top edge;
// bilinear lookups smear that jump over a few voxels (their numerical diffusion: about
// √(Σ f(1 − f)) voxels after planes shifted by fractions f), which the margin keeps out.
bool enteredThroughTop(glm::vec3 x, glm::vec3 d, double margin) {
    const glm::vec3 entry = x - float(distanceToLight(x, d)) * d;
    return entry.z > 0.999f && std::abs(entry.x) < 1.0 - margin && std::abs(entry.y) < 1.0 - margin;
}

}  // namespace

TEST_CASE("in n = 1 an axis-aligned light arrives unbent, exactly, and attenuated as Beer-Lambert",
          "[plane_sweep]") {
    const int res = 32;
    const glm::vec3 kappa(0.5f, 1.0f, 2.0f), color(1.0f, 0.5f, 0.25f);
    PhotonScene s(
        res, 1.0f, kappa, glm::vec3(0.0f, 0.0f, -1.0f), [](glm::vec3) { return 1.0f; }, color);
    int planes = 0;
    bool unbent = true;
    const PlaneSweepResultCpu r =
        sweep(s, {},
              [&](int, const PlaneSweepPlan& plan, int, const std::vector<glm::vec4>&,
                  const std::vector<glm::vec4>& direction) {
                  CHECK(plan.axis == 2);
                  CHECK(plan.order == -1);
                  ++planes;
                  for (const glm::vec4& v : direction)
                      unbent = unbent && v == glm::vec4(0, 0, -1, 1);
              });
    CHECK(planes == res);
    CHECK(unbent);
    CHECK(r.texelsLost == 0);
    double worst = 0.0;
    for (int k = 0; k < res; ++k) {
        const double depth = 1.0 - (-1.0 + (k + 0.5) * 2.0 / res);  // from the top face
        for (int j = 0; j < res; ++j)
            for (int i = 0; i < res; ++i) {
                const glm::vec4 got = r.fluence[s.field.index(i, j, k)];
                for (int c = 0; c < 3; ++c) {
                    const double want = color[c] * std::exp(-kappa[c] * depth) * voxelVolume(s);
                    worst = std::max(worst, std::abs(got[c] / want - 1.0));
                }
            }
    }
    INFO("worst relative error " << worst);
    CHECK(worst < 1e-5);  // the bound is 1e-3; the trapezoid is exact here
}

TEST_CASE("an oblique light in n = 1: unbent, Beer-Lambert where it entered through the top",
          "[plane_sweep]") {
    const int res = 32;
    const glm::vec3 d = glm::normalize(glm::vec3(0.3f, -0.2f, -1.0f));
    const glm::vec3 kappa(0.8f);
    PhotonScene s(res, 1.0f, kappa, d, [](glm::vec3) { return 1.0f; });
    double worstBend = 0.0;
    const PlaneSweepResultCpu r =
        sweep(s, {},
              [&](int, const PlaneSweepPlan&, int, const std::vector<glm::vec4>&,
                  const std::vector<glm::vec4>& direction) {
                  for (const glm::vec4& v : direction)
                      worstBend = std::max(worstBend, double(glm::length(glm::vec3(v) - d)));
              });
    INFO("largest change of direction " << worstBend);
    CHECK(worstBend < 1e-6);  // bilinear weights of equal vectors, float rounding
    const double h = 2.0 / res;
    double worst = 0.0;
    int checked = 0;
    for (int k = 0; k < res; ++k)
        for (int j = 0; j < res; ++j)
            for (int i = 0; i < res; ++i) {
                const glm::vec3 x = s.field.volume.voxelCenter(i, j, k);
                const double t = distanceToLight(x, d);
                if (!enteredThroughTop(x, d, 8 * h)) continue;
                ++checked;
                const double want = std::exp(-kappa.x * t) * voxelVolume(s);
                worst = std::max(worst, std::abs(r.fluence[s.field.index(i, j, k)].x / want - 1.0));
            }
    INFO(checked << " voxels, worst relative error " << worst);
    CHECK(checked > res * res * res / 8);
    CHECK(worst < 1e-3);
}

TEST_CASE("in n = 1 the sweep equals the straight light volumes' sweep", "[plane_sweep]") {
    // Both carry light slice to slice with bilinear lookups and the trapezoid rule; where both
    // are exact (straight light, single scattering) they must agree. A lumpy absorbing medium
    // under an oblique light.
    const int res = 32;
    const glm::vec3 d = glm::normalize(glm::vec3(-0.4f, 0.25f, -1.0f));
    auto lumps = [](glm::vec3 x) {
        return 0.5f + 0.5f * std::sin(3.0f * x.x) * std::cos(2.0f * x.y + x.z);
    };
    PhotonScene s(res, 1.0f, glm::vec3(1.5f), d, lumps);
    Scene lightVolumes = s.scene;
    test::setTransportMethod(lightVolumes, "light_volumes");
    test::setShadows(lightVolumes, "swept");
    const ViewSetup straight = makeConfiguredViewSetup(
        lightVolumes, s.field.volume, makeCameraFrame(s.scene.camera, s.field.volume.bounds, 4, 4));
    REQUIRE(shared::shadowMode(straight.params) == EK_SHADOWS_SWEPT);
    const std::vector<LightVolumeCpu> volumes = computeLightVolumesCpu(straight, {&s.field});
    const PlaneSweepResultCpu r = sweep(s);
    // Compared away from the shadow line of the box's top edge, where light entering through the
    // sides meets light from the top: there the two smear the jump differently (LightKernelCpu
    // marches next to a side face; the sweep reads the light arriving there).
    const double h = 2.0 / res;
    double worst = 0.0;
    for (int k = 0; k < res; ++k)
        for (int j = 0; j < res; ++j)
            for (int i = 0; i < res; ++i) {
                const glm::vec3 x = s.field.volume.voxelCenter(i, j, k);
                if (!enteredThroughTop(x, d, 8 * h)) continue;
                const size_t v = s.field.index(i, j, k);
                const double want = volumes[0][v].x * voxelVolume(s);
                worst = std::max(worst, std::abs(r.fluence[v].x - want) / voxelVolume(s));
            }
    INFO("largest difference of the fluence rate (light 1) " << worst);
    CHECK(worst < 1e-5);
}

TEST_CASE("a linear n^2 medium bends a beam onto the closed-form parabola", "[plane_sweep]") {
    // n² = n0² + α (y + 1) (support/linear_n2_medium.h): a ray entering the top face at (0, 0)
    // straight down follows y(τ) = (α/4) τ², z = 1 − n τ (dτ = ds/n, n its entry index). A narrow,
    // nearly parallel spot beam on that ray: its irradiance-weighted centre on the last plane
    // against y there.
    const int res = 64;
    const double h = 2.0 / res;
    // Far away, so that the beam hardly diverges: 5 voxels in radius.
    const float distance = 40.0f;
    const float coneDeg = glm::degrees(std::atan(5.0f * float(h) / distance));
    PhotonScene s(
        res, 2.0f, glm::vec3(0.0f),
        PhotonScene::spotLight(glm::vec3(0.0f, 0.0f, 1.0f + distance), glm::vec3(0.0f, 0.0f, -1.0f),
                               glm::vec3(1.0f), coneDeg, 0.4f * coneDeg),
        test::linearN2Field);
    double centre = 0.0, lastZ = 0.0;
    PlaneSweepSettings settings;
    settings.planesPerVoxel = GENERATE(1, 4);
    sweep(s, settings,
          [&](int, const PlaneSweepPlan& plan, int slice, const std::vector<glm::vec4>& light,
              const std::vector<glm::vec4>&) {
              if (slice != 0) return;
              double sum = 0.0, moment = 0.0;
              for (int b = 0; b < plan.size.y; ++b)
                  for (int a = 0; a < plan.size.x; ++a) {
                      const double e = light[size_t(b) * plan.size.x + size_t(a)].x;
                      sum += e;
                      moment += e * (-1.0 + (b + 0.5) * h);  // the plane's w axis is y
                  }
              centre = moment / sum;
              lastZ = -1.0 + 0.5 * h;
          });
    const double n0 = std::sqrt(double(test::kN0) * test::kN0 + test::kAlpha);
    const double tau = (1.0 - lastZ) / n0;
    const double want = 0.25 * test::kAlpha * tau * tau;
    INFO("beam centre y = " << centre << ", the parabola " << want << " (bent " << want / h
                            << " voxels), error " << (centre - want) / h << " voxels");
    CHECK(want / h > 5.0);
    // Measured 0.02 voxel, one plane a voxel or four. (From a spot light 3 above the box instead,
    // the beam ran 0.4 voxel ahead, the same at four planes a voxel: semi-Lagrangian bilinear
    // lookups in a diverging beam shift it by a fraction of its spread; docs/methods.md.)
    CHECK(std::abs(centre - want) < 0.1 * h);
}

namespace {

// A ball lens like test_ball_lens.cpp's (a rim two voxels wide), weaker (n = 1.25, R = 0.4) so
// that its focus lies 0.6 below it, 19 planes: light travels −y.
constexpr int kBallRes = 63;  // odd: the axis x = z = 0 runs through a column of texel centres
constexpr float kBallVoxel = 2.0f / float(kBallRes);
constexpr float kIor = 1.25f;
constexpr float kRadius = 0.4f;
const glm::vec3 kCentre(0.0f, 0.5f, 0.0f);

float ballField(glm::vec3 x) {
    const float r = glm::length(x - kCentre);
    return std::clamp(0.5f - (r - kRadius) / (2.0f * kBallVoxel), 0.0f, 1.0f);
}

// The on-axis irradiance of every plane below the ball (index: the slice along y), and the power
// crossing each plane, Σ irradiance × texel area.
struct AxisProfile {
    std::vector<double> onAxis = std::vector<double>(kBallRes, 0.0);
    std::vector<double> power = std::vector<double>(kBallRes, 0.0);
};

AxisProfile ballProfile(const LightSpec& light, const PlaneSweepSettings& settings) {
    PhotonScene s(kBallRes, kIor, glm::vec3(0.0f), light, ballField);
    AxisProfile p;
    const int axis = kBallRes / 2;
    sweep(s, settings,
          [&](int, const PlaneSweepPlan& plan, int slice, const std::vector<glm::vec4>& l,
              const std::vector<glm::vec4>&) {
              REQUIRE(plan.axis == 1);
              p.onAxis[size_t(slice)] = l[size_t(axis) * plan.size.x + size_t(axis)].x;
              double sum = 0.0;
              for (const glm::vec4& e : l) sum += e.x;
              p.power[size_t(slice)] = sum * kBallVoxel * kBallVoxel;
          });
    return p;
}

// Distance below the ball's centre of slice j's plane.
double depthBelowCentre(double slice) {
    return double(kCentre.y) - (-1.0 + (slice + 0.5) * kBallVoxel);
}

// The paraxial beam of test_ball_lens.cpp: radius R/5 from a spot light far above (distance D).
// Its image lies at s' = 1 / (1/f − 1/D) below the centre, where both principal planes of a ball
// lens lie, so below the ball the on-axis irradiance is E(z) = (1/D²) (s' / (s' − z))², z from
// the centre (the spot's intensity is 1; the sweep models no Fresnel loss).
constexpr float kSpotDistance = 40.0f;

LightSpec paraxialSpot() {
    const float coneDeg = glm::degrees(std::atan(kRadius / 5.0f / kSpotDistance));
    return PhotonScene::spotLight(kCentre + glm::vec3(0.0f, kSpotDistance, 0.0f),
                                  glm::vec3(0.0f, -1.0f, 0.0f), glm::vec3(1.0f), coneDeg,
                                  0.05f * coneDeg);
}

double imageDistance() {
    const double f = double(kIor) * kRadius / (2.0 * (double(kIor) - 1.0));
    return 1.0 / (1.0 / f - 1.0 / double(kSpotDistance));
}

// The first slice wholly below the ball's rim (its field reaches R + one voxel).
int belowRim() {
    return int(std::floor((kCentre.y - kRadius - kBallVoxel + 1.0f) / kBallVoxel - 0.5f));
}

}  // namespace

TEST_CASE("ball lens: on the axis below it the intensity law converges light on nR / (2(n - 1))",
          "[plane_sweep][lens]") {
    // Below the ball, paraxially, E ∝ 1/(s' − z)²: 1/√E falls linearly to zero at the focus s'.
    // The line through the sweep's on-axis 1/√E on the planes from the ball's rim a quarter of the
    // way to the focus, extrapolated to zero, is where its light converges; and E itself there
    // against the paraxial law. Both under parallel light (s' = f) and under the narrow spot beam
    // (s' = 1/(1/f − 1/D)). Further down the sweep is not paraxial any more: under parallel light
    // the marginal rays cross the axis before the paraxial focus (spherical aberration), and a
    // beam narrower than two texels is not resolved; one direction per texel cannot hold rays
    // that cross, so no light is carried through a focus (docs/methods.md).
    const bool directional = GENERATE(false, true);
    const AxisProfile p = ballProfile(
        directional ? PhotonScene::directionalLight(glm::vec3(0.0f, -1.0f, 0.0f), glm::vec3(1.0f))
                    : paraxialSpot(),
        {});
    const double f = double(kIor) * kRadius / (2.0 * (double(kIor) - 1.0));
    const double expected = directional ? f : imageDistance();
    const double entering = directional ? 1.0 : 1.0 / (double(kSpotDistance) * kSpotDistance);
    const int first = belowRim();
    const int last = int(
        std::ceil((kCentre.y - (kRadius + 0.25 * (expected - kRadius)) + 1.0) / kBallVoxel - 0.5));
    REQUIRE(first - last >= 2);
    double sz = 0, sy = 0, szz = 0, szy = 0, worst = 0.0;
    int n = 0;
    for (int j = last; j <= first; ++j) {
        const double z = depthBelowCentre(j), e = p.onAxis[size_t(j)];
        const double y = 1.0 / std::sqrt(e);
        sz += z, sy += y, szz += z * z, szy += z * y, ++n;
        worst = std::max(worst,
                         std::abs(e / (entering * std::pow(expected / (expected - z), 2)) - 1.0));
    }
    const double slope = (n * szy - sz * sy) / (n * szz - sz * sz);
    const double focus = (slope * sz - sy) / (n * slope);  // where the line reaches zero
    INFO((directional ? "parallel light" : "spot beam")
         << ", planes " << last << "-" << first << ": E against the paraxial law, worst relative "
         << "error " << worst << "; 1/sqrt(E) reaches zero " << focus << " below the centre, "
         << "expected " << expected << ", error " << (focus - expected) / kBallVoxel << " voxels");
    CHECK(worst < 0.05);
    CHECK(std::abs(focus - expected) < 1.0 * kBallVoxel);  // the bound
}

TEST_CASE("intensity correction: a lens brightens light by the area ratio, or only moves it",
          "[plane_sweep][lens]") {
    // Parallel light down through the converging GRIN lens of support/grin_lens.h: on the axis,
    // E(z) against its paraxial ray's (r0/r(z))² from below the lens to z = 3f/4 (E ×16), and the
    // power through every plane down to there against the power that entered. Without the
    // correction light is only moved: the beam narrows without brightening.
    const test::GrinLens grin;
    constexpr int res = test::GrinLens::kRes;
    constexpr double h = test::GrinLens::kVoxel;
    auto run = [&](const PlaneSweepSettings& settings, std::vector<double>& onAxis,
                   std::vector<double>& power) {
        PhotonScene s(res, 2.0f, glm::vec3(0.0f), glm::vec3(0.0f, -1.0f, 0.0f),
                      &test::GrinLens::field);
        onAxis.assign(res, 0.0);
        power.assign(res, 0.0);
        sweep(s, settings,
              [&](int, const PlaneSweepPlan& plan, int slice, const std::vector<glm::vec4>& l,
                  const std::vector<glm::vec4>&) {
                  onAxis[size_t(slice)] = l[size_t(res / 2) * plan.size.x + size_t(res / 2)].x;
                  double sum = 0.0;
                  for (const glm::vec4& e : l) sum += e.x;
                  power[size_t(slice)] = sum * h * h;
              });
    };
    std::vector<double> onAxis, power, movedAxis, movedPower;
    run({}, onAxis, power);
    PlaneSweepSettings off;
    off.intensityCorrection = 0;
    run(off, movedAxis, movedPower);
    auto zOf = [&](int j) { return double(test::GrinLens::kLensY) - (-1.0 + (j + 0.5) * h); };
    double worst = 0.0, worstAt = 0.0, brightest = 0.0, drift = 0.0, movedPeak = 0.0,
           movedDrift = 0.0;
    int checked = 0;
    for (int j = res - 1; j >= 0; --j) {
        const double z = zOf(j);
        if (z > 0.75 * test::GrinLens::kFocal) break;
        drift = std::max(drift, std::abs(power[size_t(j)] / power[res - 1] - 1.0));
        movedPeak = std::max(movedPeak, movedAxis[size_t(j)]);
        movedDrift =
            std::max(movedDrift, std::abs(movedPower[size_t(j)] / movedPower[res - 1] - 1.0));
        if (z < test::GrinLens::kHalfWidth) continue;  // in the lens
        const double error = std::abs(onAxis[size_t(j)] / grin.paraxialE(z) - 1.0);
        if (error > worst) worst = error, worstAt = z;
        brightest = std::max(brightest, onAxis[size_t(j)]);
        ++checked;
    }
    INFO(checked << " planes below the lens: on-axis E against the paraxial ray, worst relative "
                 << "error " << worst << " at z = " << worstAt
                 << " (E/E0 = " << grin.paraxialE(worstAt) << "); brightest " << brightest);
    INFO("power through the planes down to 3f/4: worst relative change " << drift);
    INFO("uncorrected: on-axis peak " << movedPeak << ", power's worst relative change "
                                      << movedDrift);
    CHECK(checked > 10);
    CHECK(brightest > 10.0);
    CHECK(worst < 0.05);
    CHECK(drift < 0.01);
    CHECK(movedPeak < 1.01);
    // Uncorrected, uniform light stays uniform whatever the lens does to its directions: moved,
    // never concentrated, so the power through a plane stays what entered.
    CHECK(movedDrift < 0.01);
}

TEST_CASE("a floor receiver stops the swept light and gathers E cos(theta) exp(-kappa d)",
          "[plane_sweep][receivers]") {
    // Parallel light tilted 30° from the vertical through a homogeneous absorbing box onto a
    // floor at y = -0.5: every map texel away from the box's sides gathers E cos θ exp(−κ d), d
    // the slanted path from the top face, and no light goes on through the floor.
    const int res = 32;
    const float kappa = 0.6f, tilt = glm::radians(30.0f);
    const glm::vec3 d(std::sin(tilt), -std::cos(tilt), 0.0f);
    PhotonScene s(res, 1.0f, glm::vec3(kappa), d, [](glm::vec3) { return 1.0f; });
    ReceiverSpec floor;
    floor.axis = 1;
    floor.position = -0.5f;
    floor.facing = 1;
    floor.jsonPath = "/receivers/0";
    s.scene.receivers.push_back(floor);
    s.setup = makeViewSetup(s.scene, s.field.volume,
                            makeCameraFrame(s.scene.camera, s.field.volume.bounds, 4, 4));
    // The plane just under the floor is dark but for the light entering through the side x = -1
    // (a voxel of it: the tilt moves light 0.58 voxel a plane).
    double below = 0.0;
    const PlaneSweepResultCpu r =
        sweep(s, {},
              [&](int, const PlaneSweepPlan& plan, int slice, const std::vector<glm::vec4>& light,
                  const std::vector<glm::vec4>&) {
                  REQUIRE(plan.axis == 1);
                  if (slice != res / 4 - 1) return;
                  for (int b = 2; b < plan.size.y; ++b)  // w is x
                      for (int a = 0; a < plan.size.x; ++a)
                          below += light[size_t(b) * plan.size.x + a].x;
              });
    CHECK(below == 0.0);
    const shared::GpuReceiver& map = s.setup.params.receivers[0];
    const int width = shared::receiverMapWidth(map), height = shared::receiverMapHeight(map);
    REQUIRE(r.receiverMap.size() == size_t(width) * size_t(height));
    const double want = std::cos(tilt) * std::exp(-kappa * 1.5 / std::cos(tilt));
    double worst = 0.0;
    int checked = 0;
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) {
            // Map u is z, w is x (receivers.h); the path back to the top face must not leave
            // through the side x = -1 (8 voxels of margin, as above).
            const double x = -1.0 + (j + 0.5) * 2.0 / height;
            if (x - 1.5 * std::tan(tilt) < -1.0 + 8 * 2.0 / res) continue;
            const double z = -1.0 + (i + 0.5) * 2.0 / width;
            // The map's outer texels: the footprints of the last texels of the sweep, shifted
            // back toward where their light came from, do not reach the box's faces.
            if (std::abs(z) > 1.0 - 2.0 / res || x > 1.0 - 2.0 / res) continue;
            ++checked;
            worst = std::max(worst,
                             std::abs(r.receiverMap[size_t(j) * width + size_t(i)].x / want - 1.0));
        }
    INFO(checked << " map texels, worst relative error " << worst);
    CHECK(checked > 200);
    CHECK(worst < 1e-5);  // measured 5e-7: the trapezoid is exact in a homogeneous box
}

TEST_CASE("plane sweep results are bit-identical for any thread count", "[plane_sweep]") {
    const int res = 32;
    auto run = [&](int threads) {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
        PhotonScene s(
            res, kIor, glm::vec3(0.3f), glm::normalize(glm::vec3(0.2f, -1.0f, 0.1f)),
            [](glm::vec3 x) { return std::clamp(2.0f - 4.0f * glm::length(x), 0.0f, 1.0f); });
        return sweep(s);
    };
    const PlaneSweepResultCpu one = run(1), many = run(4);
    REQUIRE(one.fluence.size() == many.fluence.size());
    CHECK(std::memcmp(one.fluence.data(), many.fluence.data(),
                      one.fluence.size() * sizeof(glm::vec4)) == 0);
    CHECK(std::memcmp(one.direction.data(), many.direction.data(),
                      one.direction.size() * sizeof(glm::vec4)) == 0);
}

TEST_CASE("the light buffers scale with a plane, not with the volume's depth", "[plane_sweep]") {
    auto memory = [](glm::ivec3 res) {
        PhotonScene s(4, 1.0f, glm::vec3(0.5f), glm::vec3(0.0f, 0.0f, -1.0f),
                      [](glm::vec3) { return 1.0f; });
        s.field.volume.resolution = res;
        s.field.values.assign(s.field.volume.voxelCount(), 1.0f);
        s.setup = makeViewSetup(s.scene, s.field.volume,
                                makeCameraFrame(s.scene.camera, s.field.volume.bounds, 4, 4));
        s.gradient = computeIndexGradientCpu(s.setup, {&s.field});
        return sweep(s).memory;
    };
    const PlaneSweepMemory shallow = memory({32, 32, 8}), deep = memory({32, 32, 64}),
                           wide = memory({64, 64, 8});
    CHECK(shallow.bufferBytes == deep.bufferBytes);
    CHECK(wide.bufferBytes == 4 * shallow.bufferBytes);
    CHECK(shallow.bufferBytes ==
          5 * 32 * 32 * sizeof(glm::vec4));              // 2 × (light, direction) + traces
    CHECK(deep.outputBytes == 8 * shallow.outputBytes);  // the output volumes are the volume's
}
