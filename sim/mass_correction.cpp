#include "sim/mass_correction.h"

#include <algorithm>
#include <limits>
#include <vector>

#include "sim/sim_parallel.h"

namespace eikon::sim {
namespace {

// Water-filling passes: each freezes the cells the last factor pushed to the cap. Every pass
// can only raise the factor toward the exact one, so stopping early under-corrects safely; in
// practice a handful of passes settles it (the cap is reached by few cells when it is at all).
constexpr int kMaxFillPasses = 32;

bool fluid(const MacGrid& grid, std::size_t n) {
    return grid.solid[n] == 0;
}

}  // namespace

double MassCorrection::relativeDeficit() const {
    return target != 0.0 ? (target - advected) / target : 0.0;
}

double MassCorrection::relativeRemainder() const {
    return target != 0.0 ? remainder / target : 0.0;
}

FieldRange fluidRange(const MacGrid& grid, const Array3& field) {
    // Per-slab extremes, then a serial pass: min and max do not depend on the order anyway.
    const glm::ivec3 s = field.size();
    const std::size_t slab = std::size_t(s.x) * std::size_t(s.y);
    std::vector<float> lo(std::size_t(s.z), std::numeric_limits<float>::infinity());
    std::vector<float> hi(std::size_t(s.z), -std::numeric_limits<float>::infinity());
    forEachSlab(s.z, [&](int k) {
        float a = lo[std::size_t(k)], b = hi[std::size_t(k)];
        for (std::size_t n = std::size_t(k) * slab; n < std::size_t(k + 1) * slab; ++n)
            if (fluid(grid, n)) {
                a = std::min(a, field[n]);
                b = std::max(b, field[n]);
            }
        lo[std::size_t(k)] = a;
        hi[std::size_t(k)] = b;
    });
    FieldRange r{*std::min_element(lo.begin(), lo.end()), *std::max_element(hi.begin(), hi.end())};
    if (r.lo > r.hi) r = FieldRange{};  // no fluid cell at all
    return r;
}

double fluidMass(const MacGrid& grid, const Array3& field) {
    return deterministicSum(field.count(),
                            [&](std::size_t n) { return fluid(grid, n) ? double(field[n]) : 0.0; });
}

double openWallOutflow(const MacGrid& grid, const Array3& field, float dt) {
    const glm::ivec3 res = grid.resolution();
    const double cellsPerSecond = double(dt) / grid.domain.voxelSize;
    double out = 0.0;  // serial, in a fixed order: boundary faces are few
    for (int axis = 0; axis < 3; ++axis) {
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        const Array3& face = grid.velocity[std::size_t(axis)];
        for (int upper = 0; upper < 2; ++upper) {
            if (grid.domain.wall(axis, upper != 0) != Wall::Open) continue;
            // Outward is +axis on the upper wall, −axis on the lower one.
            const double outward = upper ? 1.0 : -1.0;
            for (int b = 0; b < res[v]; ++b)
                for (int a = 0; a < res[u]; ++a) {
                    glm::ivec3 cell(0), f(0);
                    cell[u] = f[u] = a;
                    cell[v] = f[v] = b;
                    cell[axis] = upper ? res[axis] - 1 : 0;
                    f[axis] = upper ? res[axis] : 0;
                    if (grid.isSolid(cell.x, cell.y, cell.z)) continue;
                    out += outward * double(face(f.x, f.y, f.z)) * cellsPerSecond *
                           double(field(cell.x, cell.y, cell.z));
                }
        }
    }
    return out;
}

MassCorrection correctMass(const MacGrid& grid, Array3& field, double target, FieldRange range) {
    MassCorrection c;
    c.target = target;
    c.advected = fluidMass(grid, field);
    const float lo = std::max(0.0f, range.lo);
    const float hi = std::max(lo, range.hi);
    const double cap = double(hi) - double(lo);
    // The excess over lo of the cells the correction may change: fluid, inside [lo, hi].
    auto excess = [&](std::size_t n) {
        const float r = field[n];
        return (fluid(grid, n) && r > lo && r <= hi) ? double(r) - double(lo) : 0.0;
    };
    const double total = deterministicSum(field.count(), excess);
    const double deficit = target - c.advected;
    if (deficit == 0.0 || total <= 0.0) {
        c.remainder = deficit;
        return c;
    }
    double s = 1.0;
    if (deficit < 0.0) {
        // Remove: scale every excess down by one factor, never below lo.
        s = std::max(0.0, 1.0 - (-deficit) / total);
    } else {
        // Add: scale up, freezing cells at the cap (water-filling from below).
        double frozenAt = 1.0;
        for (int pass = 0; pass < kMaxFillPasses; ++pass) {
            auto capped = [&](std::size_t n, double scale) {
                const double e = excess(n);
                return e > 0.0 && scale * e >= cap;
            };
            const double freeExcess = deterministicSum(field.count(), [&](std::size_t n) {
                return capped(n, frozenAt) ? 0.0 : excess(n);
            });
            const double cappedMass = deterministicSum(
                field.count(), [&](std::size_t n) { return capped(n, frozenAt) ? cap : 0.0; });
            if (freeExcess <= 0.0) break;  // everything is at the cap: nothing more fits
            const double next = std::max(frozenAt, (total + deficit - cappedMass) / freeExcess);
            s = next;
            const double newlyCapped = deterministicSum(field.count(), [&](std::size_t n) {
                return capped(n, next) && !capped(n, frozenAt) ? 1.0 : 0.0;
            });
            if (newlyCapped == 0.0) break;
            frozenAt = next;
        }
    }
    c.factor = s;
    forEachIndex(field.count(), [&](std::size_t n) {
        const double e = excess(n);
        if (e <= 0.0) return;
        const float scaled = lo + float(std::min(cap, s * e));
        field[n] = std::clamp(scaled, lo, hi);
    });
    const double after = fluidMass(grid, field);
    c.placed = after - c.advected;
    c.remainder = target - after;
    return c;
}

}  // namespace eikon::sim
