#pragma once
// Initial conditions and measures shared by the smoke solver tests.
#include <cmath>
#include <cstdint>
#include <cstring>

#include "sim/mac_grid.h"

namespace eikon::test {

inline sim::Domain closedBox(glm::ivec3 n, float h) {
    sim::Domain d;
    d.resolution = n;
    d.voxelSize = h;
    return d;
}

// A swirl in the xy plane that is discretely divergence-free and has no flow through the walls:
// the face velocities are differences of a stream function ψ = A·sin(πx/Lx)·sin(πy/Ly) taken at
// the cell corners, so the net outflow of every cell cancels exactly (up to rounding).
// `peak` is the largest speed in scene units/s.
inline void setSwirl(sim::MacGrid& g, float peak) {
    const glm::ivec3 n = g.resolution();
    const double pi = 3.14159265358979323846;
    const double amp = double(peak) * std::max(n.x, n.y) / pi;  // ψ in velocity·cells
    auto psi = [&](int i, int j) { return amp * std::sin(pi * i / n.x) * std::sin(pi * j / n.y); };
    for (int k = 0; k < n.z; ++k)
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i <= n.x; ++i)
                g.velocity[0](i, j, k) = float(psi(i, j + 1) - psi(i, j));
    for (int k = 0; k < n.z; ++k)
        for (int j = 0; j <= n.y; ++j)
            for (int i = 0; i < n.x; ++i) g.velocity[1](i, j, k) = float(psi(i, j) - psi(i + 1, j));
    g.velocity[2].fill(0.0f);
}

// A smooth bump of density (cos² falloff, peak 1) of `radius` cells around cell-space `centre`.
inline void setDensityBump(sim::MacGrid& g, glm::vec3 centre, float radius) {
    const glm::ivec3 n = g.resolution();
    for (int k = 0; k < n.z; ++k)
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i < n.x; ++i) {
                glm::vec3 d = glm::vec3(i, j, k) + 0.5f - centre;
                if (n.z <= 2) d.z = 0.0f;  // a slab: a cylinder through it
                const float r = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z) / radius;
                const float c = r < 1.0f ? std::cos(1.5707963f * r) : 0.0f;
                g.density(i, j, k) = c * c;
            }
}

inline double totalDensity(const sim::MacGrid& g) {
    double s = 0.0;
    for (float v : g.density.values()) s += v;
    return s;
}

// FNV-1a over the bits of every float of the state.
// Where a plume's smoke is around a solid of radius `radius` centred at `centre`: inside the
// solid cells, in a ring 0.15 wide just outside it level with its upper half (smoke that got
// round it), and in all.
struct SmokeAroundSolid {
    double insideSolid = 0.0, besideAbove = 0.0, total = 0.0;
};

inline SmokeAroundSolid smokeAroundSolid(const sim::MacGrid& g, glm::vec3 centre, float radius) {
    SmokeAroundSolid s;
    const glm::ivec3 n = g.resolution();
    for (int k = 0; k < n.z; ++k)
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i < n.x; ++i) {
                const glm::vec3 p = g.domain.cellCenter(i, j, k);
                s.total += g.density(i, j, k);
                if (g.isSolid(i, j, k)) {
                    s.insideSolid += g.density(i, j, k);
                    continue;
                }
                const float ring = std::hypot(p.x - centre.x, p.z - centre.z);
                if (p.y > centre.y && ring > radius && ring < radius + 0.15f)
                    s.besideAbove += g.density(i, j, k);
            }
    return s;
}

inline std::uint64_t hashState(const sim::MacGrid& g) {
    std::uint64_t h = 1469598103934665603ull;
    auto mix = [&](const sim::Array3& a) {
        for (float v : a.values()) {
            std::uint32_t bits;
            std::memcpy(&bits, &v, sizeof bits);
            for (int b = 0; b < 4; ++b) {
                h ^= (bits >> (8 * b)) & 0xffu;
                h *= 1099511628211ull;
            }
        }
    };
    for (const auto& v : g.velocity) mix(v);
    mix(g.density);
    mix(g.temperature);
    return h;
}

}  // namespace eikon::test
