#include "sim/advection_problems.h"

#include <array>
#include <chrono>
#include <cmath>
#include <vector>

namespace eikon::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;

using Clock = std::chrono::steady_clock;

MacGrid unitBox(glm::ivec3 n, float h) {
    Domain d;
    d.resolution = n;
    d.voxelSize = h;
    return MacGrid(d);
}

// advectField() itself.
class EikonAdvector : public DensityAdvector {
public:
    explicit EikonAdvector(const AdvectionSettings& s) : settings_(s) {}
    void advect(MacGrid& g, float dt) override {
        Array3 next;
        advectField(g, g.density, next, dt, settings_);
        g.density = std::move(next);
    }

private:
    AdvectionSettings settings_;
};

// One step, adding the wall time of the advect call to `ms`.
void advectTimed(DensityAdvector& advector, MacGrid& g, float dt, double& ms) {
    advector.setVelocity(g);
    const Clock::time_point t0 = Clock::now();
    advector.advect(g, dt);
    ms += std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

void compare(const std::vector<float>& initial, const Array3& final, AdvectionProblemResult& r) {
    double sum0 = 0.0, sum = 0.0, diff = 0.0;
    long vol0 = 0, vol = 0;
    for (std::size_t c = 0; c < initial.size(); ++c) {
        sum0 += initial[c];
        sum += final[c];
        diff += std::fabs(final[c] - initial[c]);
        vol0 += initial[c] >= 0.5f;
        vol += final[c] >= 0.5f;
    }
    r.l1 = diff / sum0;
    r.volumeLoss = 1.0 - double(vol) / double(vol0);
    r.massChange = sum / sum0 - 1.0;
}

}  // namespace

AdvectionProblemResult zalesakRotation(int n, ZalesakShape shape,
                                       const AdvectionSettings& settings) {
    EikonAdvector advector(settings);
    return zalesakRotation(n, shape, advector);
}

AdvectionProblemResult zalesakRotation(int n, ZalesakShape shape, DensityAdvector& advector) {
    const float h = 1.0f / float(n);
    const int nz = shape == ZalesakShape::Disk ? 2 : n;
    MacGrid g = unitBox({n, n, nz}, h);
    const glm::vec3 centre(0.5f, 0.75f, 0.5f);
    const float radius = 0.15f, slotHalfWidth = 0.025f, slotTop = 0.85f;
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const glm::vec3 p((i + 0.5f) * h, (j + 0.5f) * h, (k + 0.5f) * h);
                glm::vec3 d = p - centre;
                if (shape == ZalesakShape::Disk) d.z = 0.0f;
                const bool inShape = d.x * d.x + d.y * d.y + d.z * d.z <= radius * radius;
                const bool inSlot = std::fabs(d.x) <= slotHalfWidth && p.y <= slotTop;
                g.density(i, j, k) = inShape && !inSlot ? 1.0f : 0.0f;
            }
    const std::vector<float> initial = g.density.values();
    const float omega = 2.0f * float(kPi);  // one turn per second
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i <= n; ++i) g.velocity[0](i, j, k) = -omega * ((j + 0.5f) * h - 0.5f);
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i < n; ++i) g.velocity[1](i, j, k) = omega * ((i + 0.5f) * h - 0.5f);
    g.velocity[2].fill(0.0f);

    AdvectionProblemResult r;
    r.resolution = n;
    r.steps = int(std::ceil(0.4f * float(n) * 2.0f * float(kPi)));
    const float dt = 1.0f / float(r.steps);
    advector.load(g);
    for (int s = 0; s < r.steps; ++s) advectTimed(advector, g, dt, r.advectionMs);
    advector.store(g);
    compare(initial, g.density, r);
    return r;
}

AdvectionProblemResult enrightDeformation(int n, const AdvectionSettings& settings, double period) {
    EikonAdvector advector(settings);
    return enrightDeformation(n, advector, period);
}

AdvectionProblemResult enrightDeformation(int n, DensityAdvector& advector, double period) {
    const float h = 1.0f / float(n);
    MacGrid g = unitBox({n, n, n}, h);
    const glm::vec3 centre(0.35f);
    const float radius = 0.15f;
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const glm::vec3 d = glm::vec3(i + 0.5f, j + 0.5f, k + 0.5f) * h - centre;
                g.density(i, j, k) =
                    d.x * d.x + d.y * d.y + d.z * d.z <= radius * radius ? 1.0f : 0.0f;
            }
    const std::vector<float> initial = g.density.values();

    // The spatial part of each face component, once; each step scales it by c(t).
    auto sin2 = [](double x) { return std::sin(kPi * x) * std::sin(kPi * x); };
    auto sinTwo = [](double x) { return std::sin(2.0 * kPi * x); };
    std::array<Array3, 3> shape;
    for (int a = 0; a < 3; ++a) {
        shape[std::size_t(a)] = g.velocity[std::size_t(a)];
        Array3& f = shape[std::size_t(a)];
        const glm::ivec3 s = f.size();
        for (int k = 0; k < s.z; ++k)
            for (int j = 0; j < s.y; ++j)
                for (int i = 0; i < s.x; ++i) {
                    const glm::dvec3 p = glm::dvec3(f.position(i, j, k)) * double(h);
                    double v = 0.0;
                    if (a == 0) v = 2.0 * sin2(p.x) * sinTwo(p.y) * sinTwo(p.z);
                    if (a == 1) v = -sinTwo(p.x) * sin2(p.y) * sinTwo(p.z);
                    if (a == 2) v = -sinTwo(p.x) * sinTwo(p.y) * sin2(p.z);
                    f(i, j, k) = float(v);
                }
    }

    AdvectionProblemResult r;
    r.resolution = n;
    r.steps = int(std::ceil(2.0 * n * period - 1e-9));
    const double dt = period / r.steps;
    advector.load(g);
    for (int s = 0; s < r.steps; ++s) {
        const float c = float(std::cos(kPi * (s + 0.5) * dt / period));
        for (std::size_t a = 0; a < 3; ++a)
            for (std::size_t m = 0; m < shape[a].count(); ++m) g.velocity[a][m] = c * shape[a][m];
        advectTimed(advector, g, float(dt), r.advectionMs);
    }
    advector.store(g);
    compare(initial, g.density, r);
    return r;
}

}  // namespace eikon::sim
