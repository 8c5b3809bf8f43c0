#include "sim/advection.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "sim/sim_parallel.h"

namespace eikon::sim {

const char* schemeName(AdvectionScheme scheme) {
    switch (scheme) {
        case AdvectionScheme::SemiLagrangian:
            return "semi-Lagrangian";
        case AdvectionScheme::MacCormack:
            return "MacCormack";
        case AdvectionScheme::Bfecc:
            return "BFECC";
    }
    return "?";
}

namespace {

// Where the point at p (cell index space) was dt seconds ago (dt < 0: where it will be), by the
// midpoint rule; v is the velocity at p, and s = dt / voxel size (scene units per second -> cells).
inline glm::vec3 backTrace(const MacGrid& flow, glm::vec3 p, glm::vec3 v, float s) {
    const glm::vec3 mid = p - 0.5f * s * v;
    return p - s * flow.sampleVelocity(mid);
}

// Visits every sample of a lattice, slab-parallel: fn(i, j, k, n) with n its linear index.
template <typename Fn>
void forEachSample(const Array3& a, const Fn& fn) {
    const glm::ivec3 s = a.size();
    forEachSlab(s.z, [&](int k) {
        for (int j = 0; j < s.y; ++j)
            for (int i = 0; i < s.x; ++i) fn(i, j, k, a.index(i, j, k));
    });
}

// Where every sample of a lattice comes from (back) and, for the error estimate of the
// second-order schemes, where it goes (ahead). Fields on the same lattice share them (density and
// temperature), which saves most of the velocity sampling.
struct LatticeTraces {
    std::vector<glm::vec3> back, ahead;
};

LatticeTraces traceLattice(const MacGrid& flow, const Array3& lattice, float dt, bool needAhead) {
    LatticeTraces t;
    t.back.resize(lattice.count());
    if (needAhead) t.ahead.resize(lattice.count());
    const float s = dt / flow.domain.voxelSize;
    forEachSample(lattice, [&](int i, int j, int k, std::size_t n) {
        const glm::vec3 p = lattice.position(i, j, k);
        // Both traces start from the velocity at p: sampled once, a quarter fewer samples.
        const glm::vec3 v = flow.sampleVelocity(p);
        t.back[n] = backTrace(flow, p, v, s);
        if (needAhead) t.ahead[n] = backTrace(flow, p, v, -s);
    });
    return t;
}

void resample(const Array3& src, const std::vector<glm::vec3>& points, Array3& dst) {
    forEachSample(src, [&](int, int, int, std::size_t n) { dst[n] = src.sample(points[n]); });
}

// The final pass of the second-order schemes: value(n) is the unlimited result at sample n; the
// limiter bounds it by src's neighbourhood of the back-traced point, reverting to `firstOrder`
// when asked.
template <typename Value>
void limitedPass(const Array3& src, const std::vector<glm::vec3>& back, const Array3& firstOrder,
                 Array3& dst, Limiter limiter, const Value& value) {
    forEachSample(src, [&](int, int, int, std::size_t n) {
        const float v = value(n);
        if (limiter == Limiter::None) {
            dst[n] = v;
            return;
        }
        float lo, hi;
        src.sample(back[n], lo, hi);
        if (limiter == Limiter::Clamp)
            dst[n] = std::clamp(v, lo, hi);
        else
            dst[n] = (v < lo || v > hi) ? firstOrder[n] : v;
    });
}

bool secondOrder(const AdvectionSettings& s) {
    return s.scheme != AdvectionScheme::SemiLagrangian;
}

void advectAlong(const LatticeTraces& traces, const Array3& src, Array3& dst,
                 const AdvectionSettings& settings) {
    dst = Array3(src.size(), src.offset());
    if (!secondOrder(settings)) {
        // A trilinear blend already stays in its neighbourhood; the limiter would change nothing.
        resample(src, traces.back, dst);
        return;
    }
    Array3 forward(src.size(), src.offset());
    Array3 backward(src.size(), src.offset());
    resample(src, traces.back, forward);
    resample(forward, traces.ahead, backward);  // ≈ src if the forward pass were exact
    if (settings.scheme == AdvectionScheme::MacCormack) {
        limitedPass(src, traces.back, forward, dst, settings.limiter,
                    [&](std::size_t n) { return forward[n] + 0.5f * (src[n] - backward[n]); });
        return;
    }
    // BFECC: correct the input by half the round-trip error, then advect the corrected field.
    Array3 corrected(src.size(), src.offset());
    forEachSample(src, [&](int, int, int, std::size_t n) {
        corrected[n] = src[n] + 0.5f * (src[n] - backward[n]);
    });
    limitedPass(src, traces.back, forward, dst, settings.limiter,
                [&](std::size_t n) { return corrected.sample(traces.back[n]); });
}

// Whether every sample holds the same value. Such a field comes out of every scheme unchanged,
// bit for bit (a lerp of equal values is that value; MacCormack's and BFECC's corrections are
// then 0), so advecting it is wasted work: the temperature of a scene without heat sources, or
// the density before any source has run.
bool uniform(const Array3& a) {
    if (a.count() == 0) return true;
    const float first = a[0];
    const glm::ivec3 s = a.size();
    const std::size_t slab = std::size_t(s.x) * std::size_t(s.y);
    std::vector<std::uint8_t> differs(std::size_t(s.z), 0);
    forEachSlab(s.z, [&](int k) {
        for (std::size_t n = std::size_t(k) * slab; n < std::size_t(k + 1) * slab; ++n)
            if (a[n] != first) {
                differs[std::size_t(k)] = 1;
                return;
            }
    });
    return std::find(differs.begin(), differs.end(), 1) == differs.end();
}

// advectAlong, or a copy of a uniform field.
void advectScalar(const LatticeTraces& traces, const Array3& src, Array3& dst,
                  const AdvectionSettings& settings) {
    if (uniform(src))
        dst = src;
    else
        advectAlong(traces, src, dst, settings);
}

}  // namespace

void advectField(const MacGrid& flow, const Array3& src, Array3& dst, float dt,
                 const AdvectionSettings& settings) {
    advectAlong(traceLattice(flow, src, dt, secondOrder(settings)), src, dst, settings);
}

void advectState(MacGrid& grid, float dt, const AdvectionSettings& settings) {
    // Every quantity moves with the velocity at the start of the step, so the new arrays are
    // written apart and swapped in at the end.
    const bool ahead = secondOrder(settings);
    Array3 density, temperature;
    std::array<Array3, 3> velocity;
    if (uniform(grid.density) && uniform(grid.temperature)) {
        density = grid.density;  // no traces needed at all
        temperature = grid.temperature;
    } else {
        const LatticeTraces centres = traceLattice(grid, grid.density, dt, ahead);
        advectScalar(centres, grid.density, density, settings);
        advectScalar(centres, grid.temperature, temperature, settings);
    }
    for (std::size_t a = 0; a < 3; ++a)
        advectAlong(traceLattice(grid, grid.velocity[a], dt, ahead), grid.velocity[a], velocity[a],
                    settings);
    grid.density = std::move(density);
    grid.temperature = std::move(temperature);
    grid.velocity = std::move(velocity);
}

}  // namespace eikon::sim
