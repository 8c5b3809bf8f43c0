#include "apps/bench_method_cases.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "core/error.h"
#include "core/procedural.h"
#include "core/sphere_refraction.h"

namespace eikon::app {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Every case lives in the box [-1, 1]³.
const Bounds3 kBox{glm::vec3(-1.0f), glm::vec3(1.0f)};
// A faint fog everywhere, so that something scatters light toward a camera and every method
// computes its light (photons are traced only where something shows them), without dimming the
// beam measurably (1e-3 per unit: 0.2 % across the box).
constexpr float kFaintScattering = 1e-3f;

using FieldFunction = std::function<float(glm::vec3)>;

DenseGrid gridOf(const std::string& name, const RenderVolume& volume, const FieldFunction& f) {
    DenseGrid g;
    g.field = name;
    g.volume = volume;
    g.version = 1;
    g.values.resize(volume.voxelCount());
    for (int k = 0; k < volume.resolution.z; ++k)
        for (int j = 0; j < volume.resolution.y; ++j)
            for (int i = 0; i < volume.resolution.x; ++i)
                g.values[g.index(i, j, k)] = f(volume.voxelCenter(i, j, k));
    return g;
}

MaterialSpec material(const std::string& name, const std::string& field, float ior,
                      glm::vec3 absorption, glm::vec3 scattering) {
    MaterialSpec m;
    m.name = name;
    m.field = field;
    m.ior = ior;
    m.absorption = absorption;
    m.scattering = scattering;
    return m;
}

LightSpec directionalDown() {
    LightSpec l;
    l.type = LightType::Directional;
    l.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    return l;
}

// A narrow beam down the y axis: a spot light `distance` above `target` whose cone is
// `beamRadius` wide at the target, with a soft edge of 5 % of the cone.
LightSpec beamDown(glm::vec3 target, float distance, float beamRadius) {
    LightSpec l;
    l.type = LightType::Spot;
    l.position = target + glm::vec3(0.0f, distance, 0.0f);
    l.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    l.coneAngleDeg = glm::degrees(std::atan(beamRadius / distance));
    l.coneSoftnessDeg = 0.05f * l.coneAngleDeg;
    return l;
}

// A case over the box at `n` voxels per edge with a faint fog ("density" = 1) added.
MethodCase boxCase(const std::string& name, int n) {
    MethodCase c;
    c.name = name;
    c.volume = RenderVolume{kBox, glm::ivec3(n)};
    c.scene.render.width = c.scene.render.height = 4;
    return c;
}

void addFog(MethodCase& c, glm::vec3 absorption, glm::vec3 scattering) {
    c.scene.materials.push_back(material("fog", "density", 1.0f, absorption, scattering));
    c.fields["density"] = gridOf("density", c.volume, [](glm::vec3) { return 1.0f; });
}

// The closed forms follow rays by Snell's law and the ray equation, without Fresnel reflection:
// the suite measures where light goes, so its index fields reflect nothing (the Fresnel factor has
// its own closed-form tests, tests/render/test_wavefront_fresnel.cpp).
void addIndexField(MethodCase& c, float ior, const FieldFunction& f) {
    c.scene.materials.push_back(material("glass", "n", ior, glm::vec3(0.0f), glm::vec3(0.0f)));
    c.scene.materials.back().fresnel = false;
    c.fields["n"] = gridOf("n", c.volume, f);
}

size_t voxelIndex(const RenderVolume& v, int i, int j, int k) {
    return (size_t(k) * size_t(v.resolution.y) + size_t(j)) * size_t(v.resolution.x) + size_t(i);
}

// The green fluence rate along the column x = z = 0 (the resolution is odd: a voxel column).
std::function<double(int)> axisProfile(const CaseOutput& out) {
    const int c = out.volume.resolution.x / 2;
    return [&out, c](int j) { return double(out.fluenceRate[voxelIndex(out.volume, c, j, c)].g); };
}

// The centre, in samples, of the run of samples within `fraction` of the maximum of at(i) over
// [lo, hi] (a focus is a plateau several voxels long whose single highest sample is noise), its
// ends interpolated; NaN when the run touches the range's ends (no focus inside it).
double plateauCentre(const std::function<double(int)>& at, int lo, int hi, double fraction) {
    int best = lo;
    for (int i = lo; i <= hi; ++i)
        if (at(i) > at(best)) best = i;
    if (!(at(best) > 0.0)) return kNaN;
    const double level = (1.0 - fraction) * at(best);
    int left = best, right = best;
    while (left > lo && at(left - 1) >= level) --left;
    while (right < hi && at(right + 1) >= level) ++right;
    if (left == lo || right == hi) return kNaN;
    const double l = double(left) - (at(left) - level) / (at(left) - at(left - 1));
    const double r = double(right) + (at(right) - level) / (at(right) - at(right + 1));
    return 0.5 * (l + r);
}

// Beer–Lambert: a homogeneous slab of extinction 4 per unit filling the box, a directional light
// straight down; the fluence rate at depth d is E e^(−κ d). Error: the largest relative error
// down the centre column where the optical depth is between 0.1 and 8.
MethodCase slabCase(int n) {
    MethodCase c = boxCase("slab", n);
    constexpr float kKappa = 4.0f;
    c.closedForm = "fluence E exp(-kappa d), optical depth 0.1 to 8";
    c.errorUnit = "relative";
    addFog(c, glm::vec3(kKappa - 0.04f), glm::vec3(0.04f));
    c.scene.lights.push_back(directionalDown());
    c.error = [](const CaseOutput& out) {
        const auto at = axisProfile(out);
        const double h = double(out.volume.voxelSize().y);
        double worst = 0.0;
        for (int j = 0; j < out.volume.resolution.y; ++j) {
            const double depth = 1.0 - (-1.0 + (j + 0.5) * h);
            const double tau = double(kKappa) * depth;
            if (tau < 0.1 || tau > 8.0) continue;
            worst = std::max(worst, std::abs(at(j) / std::exp(-tau) - 1.0));
        }
        return worst;
    };
    return c;
}

// A glass ball (n = 1.5, R = 0.6, its rim smoothed over two voxels) under a narrow paraxial
// beam from a source 40 units above: the focus lies 1 / (1/f − 1/D) below its centre, with
// f = nR / (2(n − 1)) the ball lens's focal length. Error in voxels; NaN: no focus.
MethodCase ballLensCase(int n) {
    MethodCase c = boxCase("ball_lens", n);
    constexpr float kIor = 1.5f, kRadius = 0.6f, kDistance = 40.0f;
    const glm::vec3 centre(0.0f, 0.3f, 0.0f);
    const float rim = 2.0f * 2.0f / float(n);
    c.closedForm = "paraxial focus 1/(1/f - 1/D) below the centre, f = nR/(2(n-1))";
    c.errorUnit = "voxels";
    addFog(c, glm::vec3(0.0f), glm::vec3(kFaintScattering));
    addIndexField(c, kIor, [=](glm::vec3 x) {
        return std::clamp(0.5f - (glm::length(x - centre) - kRadius) / rim, 0.0f, 1.0f);
    });
    c.index = [=](const glm::dvec3& x) {
        const glm::dvec3 d = x - glm::dvec3(centre);
        const double r = glm::length(d);
        const double ramp = 0.5 - (r - double(kRadius)) / double(rim);
        const double n = 1.0 + (double(kIor) - 1.0) * std::clamp(ramp, 0.0, 1.0);
        if (ramp <= 0.0 || ramp >= 1.0 || !(r > 0.0)) return glm::dvec4(0.0, 0.0, 0.0, n);
        return glm::dvec4(-(double(kIor) - 1.0) / double(rim) * d / r, n);
    };
    c.scene.lights.push_back(beamDown(centre, kDistance, kRadius / 5.0f));
    c.error = [=](const CaseOutput& out) {
        const double h = double(out.volume.voxelSize().y);
        const double f = double(kIor) * kRadius / (2.0 * (double(kIor) - 1.0));
        const double expected = 1.0 / (1.0 / f - 1.0 / double(kDistance));
        // From the first voxel below the rim down to the box.
        const int top = int(std::floor((centre.y - kRadius - rim + 1.0f) / h)) - 1;
        const double peak = plateauCentre(axisProfile(out), 1, top, 0.005);
        const double distance = double(centre.y) - (-1.0 + (peak + 0.5) * h);
        return std::abs(distance - expected) / h;
    };
    return c;
}

// A Luneburg lens, n = sqrt(2 − (r/R)²): a parallel beam focuses on its far surface, R below
// the centre. Error in voxels; NaN: no focus.
MethodCase luneburgCase(int n) {
    MethodCase c = boxCase("luneburg", n);
    constexpr float kRadius = 0.6f;
    const glm::vec3 centre(0.0f, 0.3f, 0.0f);
    c.closedForm = "a parallel beam focuses on the far surface, R below the centre";
    c.errorUnit = "voxels";
    addFog(c, glm::vec3(0.0f), glm::vec3(kFaintScattering));
    addIndexField(c, 2.0f, [=](glm::vec3 x) {
        const float r = glm::length(x - centre) / kRadius;
        return r < 1.0f ? std::sqrt(2.0f - r * r) - 1.0f : 0.0f;
    });
    c.index = [=](const glm::dvec3& x) {
        const glm::dvec3 d = (x - glm::dvec3(centre)) / double(kRadius);
        const double r2 = glm::dot(d, d);
        if (r2 >= 1.0) return glm::dvec4(0.0, 0.0, 0.0, 1.0);
        const double n = std::sqrt(2.0 - r2);
        return glm::dvec4(-d / (double(kRadius) * n), n);
    };
    c.scene.lights.push_back(directionalDown());
    c.error = [=](const CaseOutput& out) {
        const double h = double(out.volume.voxelSize().y);
        const int middle = int(std::floor((centre.y + 1.0f) / h));
        const double peak = plateauCentre(axisProfile(out), 1, middle, 0.005);
        const double distance = double(centre.y) - (-1.0 + (peak + 0.5) * h);
        return std::abs(distance - double(kRadius)) / h;
    };
    return c;
}

// A narrow beam sent straight down from `kDistance` above the top face at x = beamX through a
// medium whose n depends on x alone: p_y = n dy/ds is constant along every ray, so the exit
// height fixes τ, and exitX(x0, p0x, τ) is the closed form of x(τ) (dτ = ds/n). Error: the
// fluence centroid on the bottom layer against the power-weighted mean of the closed-form exit
// points of the beam's rays, in voxels.
struct BentBeam {
    std::function<double(double)> index;                  // n(x)
    std::function<double(double)> slope;                  // dn/dx
    std::function<double(double, double, double)> exitX;  // x(τ) from x0, p0x
    double beamX = 0.0;
};

MethodCase bentBeamCase(const std::string& name, int n, const std::string& closedForm,
                        const BentBeam& beam) {
    MethodCase c = boxCase(name, n);
    constexpr float kDistance = 40.0f, kBeam = 0.1f;
    c.closedForm = closedForm;
    c.errorUnit = "voxels";
    addFog(c, glm::vec3(0.0f), glm::vec3(kFaintScattering));
    addIndexField(c, 2.0f, [=](glm::vec3 x) { return float(beam.index(double(x.x))) - 1.0f; });
    c.index = [=](const glm::dvec3& x) {
        return glm::dvec4(beam.slope(x.x), 0.0, 0.0, beam.index(x.x));
    };
    const glm::vec3 top(float(beam.beamX), 1.0f, 0.0f);
    c.scene.lights.push_back(beamDown(top, kDistance, kBeam));
    c.error = [=](const CaseOutput& out) {
        const RenderVolume& v = out.volume;
        const double h = double(v.voxelSize().y);
        const double yBottom = -1.0 + 0.5 * h;  // the bottom layer's centres
        // The rays through a grid over the beam's disk at the top face, from the source.
        const glm::dvec3 source(beam.beamX, 1.0 + double(kDistance), 0.0);
        double sum = 0.0;
        int rays = 0;
        for (int a = -20; a <= 20; ++a)
            for (int b = -20; b <= 20; ++b) {
                const glm::dvec3 x0(beam.beamX + kBeam * a / 20.0, 1.0, kBeam * b / 20.0);
                if ((a * a + b * b) > 400) continue;
                const glm::dvec3 p0 = beam.index(x0.x) * glm::normalize(x0 - source);
                const double tau = (yBottom - 1.0) / p0.y;  // p_y is constant: ∇n ⟂ y
                sum += beam.exitX(x0.x, p0.x, tau);
                ++rays;
            }
        const double expected = sum / rays;
        double weight = 0.0, moment = 0.0;
        for (int k = 0; k < v.resolution.z; ++k)
            for (int i = 0; i < v.resolution.x; ++i) {
                const double phi = double(out.fluenceRate[voxelIndex(v, i, 0, k)].g);
                weight += phi;
                moment += phi * double(v.voxelCenter(i, 0, k).x);
            }
        if (!(weight > 0.0)) return kNaN;
        return std::abs(moment / weight - expected) / h;
    };
    return c;
}

// n² linear across the beam, n² = 1.44 + 0.3 (x + 1): the beam bends toward +x along the
// parabola x = x0 + p0 τ + (∇n²/4) τ².
MethodCase linearN2Case(int n) {
    constexpr double kN0 = 1.2, kAlpha = 0.3;
    BentBeam beam;
    beam.index = [=](double x) { return std::sqrt(kN0 * kN0 + kAlpha * (x + 1.0)); };
    beam.slope = [=](double x) {
        return kAlpha / (2.0 * std::sqrt(kN0 * kN0 + kAlpha * (x + 1.0)));
    };
    beam.exitX = [=](double x0, double p0, double tau) {
        return x0 + p0 * tau + kAlpha / 4.0 * tau * tau;
    };
    return bentBeamCase("linear_n2", n, "exit point on the parabola x0 + p0 t + (grad n^2/4) t^2",
                        beam);
}

// A graded-index (GRIN) slab, n² = n0² (1 − α² x²), n0 = 1.5, α = 0.6 (n from 1.2 at the faces
// to 1.5 on the axis): rays oscillate about x = 0 as x'' = −ω² x in τ, ω = n0 α, so a beam sent
// down at x = 0.5 exits on x0 cos ωτ + (p0/ω) sin ωτ, having swung 0.35 units toward the axis.
MethodCase grinCase(int n) {
    constexpr double kN0 = 1.5, kAlpha = 0.6, kOmega = kN0 * kAlpha;
    BentBeam beam;
    beam.index = [=](double x) { return kN0 * std::sqrt(1.0 - kAlpha * kAlpha * x * x); };
    beam.slope = [=](double x) {
        return -kN0 * kAlpha * kAlpha * x / std::sqrt(1.0 - kAlpha * kAlpha * x * x);
    };
    beam.exitX = [=](double x0, double p0, double tau) {
        return x0 * std::cos(kOmega * tau) + p0 / kOmega * std::sin(kOmega * tau);
    };
    beam.beamX = 0.5;
    return bentBeamCase(
        "grin", n, "exit point on x0 cos(wt) + (p0/w) sin(wt), n^2 = n0^2 (1 - a^2 x^2)", beam);
}

// The fluence rate that parallel light straight down (fluence 1 where unshadowed), refracted in
// and out of a sharp sphere by Snell's law, leaves in the horizontal voxel layer at height y:
// `rays`² rays over the sphere's disk, each spread bilinearly over the layer's voxel columns with
// its power over its cosine (a tube crossing the layer at θ lies 1/cos θ longer in it), then the
// binomial [1 2 1]/4 across x and z (the photons' smoothing, whose third axis changes little
// along a beam this straight). Columns x fastest.
std::vector<double> exactSphereCaustic(const RenderVolume& v, glm::dvec3 centre, double radius,
                                       double ior, double y, int rays) {
    const int n = v.resolution.x;
    const double h = double(v.voxelSize().x);
    const double x0 = double(v.bounds.min.x);
    const double z0 = double(v.bounds.min.z);
    std::vector<double> map(size_t(n) * size_t(n), 0.0);
    const double step = 2.0 * radius / rays;
    const double power = step * step / (h * h);  // fluence 1 over a tube of step² into a column
    for (int a = 0; a < rays; ++a)
        for (int b = 0; b < rays; ++b) {
            const double x = -radius + (a + 0.5) * step;
            const double z = -radius + (b + 0.5) * step;
            glm::dvec3 p2, t2;
            if (!refractDownThroughSphere(centre, radius, ior, x, z, p2, t2)) continue;
            if (!(t2.y < -1e-6)) continue;
            const glm::dvec3 hit = p2 + ((y - p2.y) / t2.y) * t2;
            const double fx = (hit.x - x0) / h - 0.5, fz = (hit.z - z0) / h - 0.5;
            const int i0 = int(std::floor(fx)), k0 = int(std::floor(fz));
            const double ax = fx - i0, az = fz - k0;
            const double w = power / -t2.y;
            for (int di = 0; di < 2; ++di)
                for (int dk = 0; dk < 2; ++dk) {
                    const int i = i0 + di, k = k0 + dk;
                    if (i < 0 || i >= n || k < 0 || k >= n) continue;
                    map[size_t(k) * size_t(n) + size_t(i)] +=
                        w * (di ? ax : 1.0 - ax) * (dk ? az : 1.0 - az);
                }
        }
    for (int axis = 0; axis < 2; ++axis) {
        std::vector<double> smoothed(map.size());
        for (int k = 0; k < n; ++k)
            for (int i = 0; i < n; ++i) {
                auto at = [&](int o) {
                    const int ii = axis == 0 ? std::clamp(i + o, 0, n - 1) : i;
                    const int kk = axis == 1 ? std::clamp(k + o, 0, n - 1) : k;
                    return map[size_t(kk) * size_t(n) + size_t(ii)];
                };
                smoothed[size_t(k) * size_t(n) + size_t(i)] = 0.25 * (at(-1) + 2.0 * at(0) + at(1));
            }
        map.swap(smoothed);
    }
    return map;
}

// A sharp glass ball's caustic past its focus (issue 15's rings and cross): a procedural sphere
// (n 1.5, R 0.4, falloff 0) with its edge averaged into the voxels by `filter`, under parallel
// light straight down; the horizontal layer 3 R below its centre, twice the focal length
// f = nR / (2(n − 1)) = 1.5 R (as the floor 3 radii below in `eikon bench caustic`). The rings
// of a box-averaged edge show from about 127 voxels per edge (R 25 voxels); at 63 the photons'
// smoothing and noise hide them and both filters measure alike. Error: Σ |F − F_exact| / Σ F_exact
// over the columns within 0.9 R of the axis (the light in the wrong place), F the method's fluence
// rate divided by its mean over the unshadowed ring 1.3-1.9 R from the axis.
MethodCase causticCase(const std::string& name, int n, EdgeFilter filter) {
    MethodCase c = boxCase(name, n);
    constexpr double kIor = 1.5, kRadius = 0.4;
    const glm::dvec3 centre(0.0, 0.5, 0.0);
    c.closedForm =
        "Snell trace of the sharp sphere, fluence 3R below its centre (L1 in the shadow)";
    c.errorUnit = "relative";
    addFog(c, glm::vec3(0.0f), glm::vec3(kFaintScattering));
    SourceSpec ball;
    ball.type = SourceType::Sphere;
    ball.field = "n";
    ball.center = glm::vec3(centre);
    ball.radius = float(kRadius);
    ball.voxelSize = c.volume.voxelSize().x;
    ball.edgeFilter = filter;
    addIndexField(c, float(kIor),
                  [ball](glm::vec3 x) { return float(proceduralValue(ball, glm::dvec3(x))); });
    c.scene.lights.push_back(directionalDown());
    const double h = double(c.volume.voxelSize().y);
    const int layer = int(std::floor((centre.y - 3.0 * kRadius + 1.0) / h));
    const double y = -1.0 + (layer + 0.5) * h;
    const auto exact = std::make_shared<std::vector<double>>(
        exactSphereCaustic(c.volume, centre, kRadius, kIor, y, 1200));
    c.error = [=](const CaseOutput& out) {
        const int res = out.volume.resolution.x;
        double lit = 0.0, litCount = 0.0, diff = 0.0, sum = 0.0;
        std::vector<double> got(exact->size());
        for (int k = 0; k < res; ++k)
            for (int i = 0; i < res; ++i) {
                const glm::vec3 p = out.volume.voxelCenter(i, layer, k);
                const double r = std::hypot(double(p.x), double(p.z)) / kRadius;
                const double f = double(out.fluenceRate[voxelIndex(out.volume, i, layer, k)].g);
                got[size_t(k) * size_t(res) + size_t(i)] = f;
                if (r > 1.3 && r < 1.9) lit += f, litCount += 1.0;
            }
        if (!(lit > 0.0)) return kNaN;
        const double unshadowed = lit / litCount;
        for (int k = 0; k < res; ++k)
            for (int i = 0; i < res; ++i) {
                const glm::vec3 p = out.volume.voxelCenter(i, layer, k);
                if (std::hypot(double(p.x), double(p.z)) >= 0.9 * kRadius) continue;
                const size_t at = size_t(k) * size_t(res) + size_t(i);
                diff += std::abs(got[at] / unshadowed - (*exact)[at]);
                sum += (*exact)[at];
            }
        return diff / sum;
    };
    return c;
}

MethodCase causticBSplineCase(int n) {
    return causticCase("caustic", n, EdgeFilter::BSpline);
}
MethodCase causticBoxCase(int n) {
    return causticCase("caustic_box", n, EdgeFilter::Box);
}

// A glass ball in absorbing, scattering fog under a spot light: every bit of power that enters
// must be extinguished, escape, be dropped or land on a receiver. Error: the largest relative
// imbalance of the three channels; NaN for a method that keeps no energy account.
MethodCase energyCase(int n) {
    MethodCase c = boxCase("energy", n);
    c.closedForm = "emitted = extinguished + escaped + dropped + received + reflected, per channel";
    c.errorUnit = "relative";
    addFog(c, glm::vec3(0.2f, 0.25f, 0.3f), glm::vec3(1.6f, 1.5f, 1.4f));
    const float rim = 2.0f * 2.0f / float(n);
    addIndexField(c, 1.5f, [=](glm::vec3 x) {
        return std::clamp(0.5f - (glm::length(x) - 0.45f) / rim, 0.0f, 1.0f);
    });
    c.scene.materials.back().fresnel = true;  // the account must hold with reflection too
    LightSpec spot;
    spot.type = LightType::Spot;
    spot.position = glm::vec3(0.8f, 3.0f, 0.5f);
    spot.direction = glm::normalize(-spot.position);
    spot.intensity = 20.0f;
    spot.coneAngleDeg = 20.0f;
    c.scene.lights.push_back(spot);
    c.error = [](const CaseOutput& out) {
        if (!out.energy) return kNaN;
        const EnergyBalance& e = *out.energy;
        const glm::dvec3 rest = e.accounted();
        double worst = 0.0;
        for (int ch = 0; ch < 3; ++ch)
            worst = std::max(worst, std::abs(e.emitted[ch] - rest[ch]) / e.emitted[ch]);
        return worst;
    };
    return c;
}

using CaseMaker = MethodCase (*)(int);
struct NamedCase {
    const char* name;
    CaseMaker make;
};
const NamedCase kCases[] = {{"slab", slabCase},
                            {"ball_lens", ballLensCase},
                            {"luneburg", luneburgCase},
                            {"linear_n2", linearN2Case},
                            {"grin", grinCase},
                            {"caustic", causticBSplineCase},
                            {"caustic_box", causticBoxCase},
                            {"energy", energyCase}};

}  // namespace

std::vector<std::string> methodCaseNames() {
    std::vector<std::string> names;
    for (const NamedCase& c : kCases) names.push_back(c.name);
    return names;
}

std::vector<std::string> refractingCaseNames() {
    return {"ball_lens", "luneburg", "linear_n2", "grin"};
}

std::vector<MethodCase> methodCases(int resolution, const std::vector<std::string>& only) {
    for (const std::string& name : only) {
        const std::vector<std::string> all = methodCaseNames();
        if (std::find(all.begin(), all.end(), name) == all.end())
            throw Error("--cases", "no case '" + name + "' (slab, ball_lens, luneburg, " +
                                       "linear_n2, grin, caustic, caustic_box, energy)");
    }
    const int odd = resolution | 1;
    std::vector<MethodCase> cases;
    for (const NamedCase& c : kCases)
        if (only.empty() || std::find(only.begin(), only.end(), c.name) != only.end())
            cases.push_back(c.make(odd));
    return cases;
}

}  // namespace eikon::app
