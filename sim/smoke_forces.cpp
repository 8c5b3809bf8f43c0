#include "sim/smoke_forces.h"

#include <cmath>
#include <type_traits>
#include <vector>

#include <glm/geometric.hpp>

#include "sim/sim_parallel.h"

namespace eikon::sim {
namespace {

// Adds dt·(average of a cell-centred force's `axis` component over the two cells beside each
// interior face). Boundary faces are left to the boundary conditions.
template <typename CellForce>
void addCentredForceToFaces(MacGrid& grid, int axis, float dt, const CellForce& force) {
    Array3& face = grid.velocity[std::size_t(axis)];
    const glm::ivec3 s = face.size();
    forEachSlab(s.z, [&](int k) {
        for (int j = 0; j < s.y; ++j)
            for (int i = 0; i < s.x; ++i) {
                glm::ivec3 hi(i, j, k), lo(i, j, k);
                lo[axis] -= 1;
                if (lo[axis] < 0 || hi[axis] >= grid.resolution()[axis]) continue;
                face(i, j, k) += dt * 0.5f * (force(lo) + force(hi));
            }
    });
}

}  // namespace

void applyBuoyancy(MacGrid& grid, const ForceSettings& settings, float dt) {
    addCentredForceToFaces(grid, 1, dt, [&](glm::ivec3 c) {
        return -settings.buoyancyAlpha * grid.density(c.x, c.y, c.z) +
               settings.buoyancyBeta *
                   (grid.temperature(c.x, c.y, c.z) - settings.ambientTemperature);
    });
}

void applyVorticityConfinement(MacGrid& grid, float epsilon, float dt) {
    const glm::ivec3 n = grid.resolution();
    const float h = grid.domain.voxelSize;
    // Cell-centred velocity, then its curl ω and |ω|, by central differences (one-sided at the
    // domain's edges, where the neighbour is clamped).
    std::vector<glm::vec3> centre(grid.domain.cellCount()), omega(centre.size());
    std::vector<float> magnitude(centre.size());
    forEachSlab(n.z, [&](int k) {
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i < n.x; ++i)
                centre[grid.cellIndex(i, j, k)] = grid.sampleVelocity(glm::vec3(i, j, k) + 0.5f);
    });
    // d/d(axis) of a cell quantity at c, by the clamped central difference.
    auto derivative = [&](const auto& q, glm::ivec3 c, int axis) {
        glm::ivec3 lo = c, hi = c;
        lo[axis] = std::max(c[axis] - 1, 0);
        hi[axis] = std::min(c[axis] + 1, n[axis] - 1);
        const float span = float(hi[axis] - lo[axis]) * h;
        using T = std::decay_t<decltype(q[0])>;
        if (span == 0.0f) return T(0.0f);
        return (q[grid.cellIndex(hi.x, hi.y, hi.z)] - q[grid.cellIndex(lo.x, lo.y, lo.z)]) / span;
    };
    forEachSlab(n.z, [&](int k) {
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i < n.x; ++i) {
                const glm::ivec3 c(i, j, k);
                const glm::vec3 dx = derivative(centre, c, 0), dy = derivative(centre, c, 1),
                                dz = derivative(centre, c, 2);
                const glm::vec3 w(dy.z - dz.y, dz.x - dx.z, dx.y - dy.x);
                omega[grid.cellIndex(i, j, k)] = w;
                magnitude[grid.cellIndex(i, j, k)] = glm::length(w);
            }
    });
    std::vector<glm::vec3> force(centre.size());
    forEachSlab(n.z, [&](int k) {
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i < n.x; ++i) {
                const glm::ivec3 c(i, j, k);
                const glm::vec3 g(derivative(magnitude, c, 0), derivative(magnitude, c, 1),
                                  derivative(magnitude, c, 2));
                const float len = glm::length(g);
                // Where |ω| is flat there is no vortex centre to push toward.
                const glm::vec3 N = len > 1e-12f ? g / len : glm::vec3(0.0f);
                force[grid.cellIndex(i, j, k)] =
                    epsilon * h * glm::cross(N, omega[grid.cellIndex(i, j, k)]);
            }
    });
    for (int a = 0; a < 3; ++a)
        addCentredForceToFaces(
            grid, a, dt, [&](glm::ivec3 c) { return force[grid.cellIndex(c.x, c.y, c.z)][a]; });
}

void applyWind(MacGrid& grid, glm::vec3 acceleration, float dt) {
    for (int a = 0; a < 3; ++a) {
        if (acceleration[a] == 0.0f) continue;
        for (float& u : grid.velocity[std::size_t(a)].values()) u += dt * acceleration[a];
    }
}

void applyForces(MacGrid& grid, const ForceSettings& settings, float dt) {
    if (settings.buoyancyAlpha != 0.0f || settings.buoyancyBeta != 0.0f)
        applyBuoyancy(grid, settings, dt);
    if (settings.vorticity != 0.0f) applyVorticityConfinement(grid, settings.vorticity, dt);
    if (settings.wind != glm::vec3(0.0f)) applyWind(grid, settings.wind, dt);
}

}  // namespace eikon::sim
