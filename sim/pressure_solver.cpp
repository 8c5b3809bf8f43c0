#include "sim/pressure_solver.h"

#include <cmath>
#include <memory>
#include <vector>

#include "sim/mic_preconditioner.h"
#include "sim/multigrid_preconditioner.h"
#include "sim/poisson_matrix.h"
#include "sim/sim_parallel.h"

namespace eikon::sim {
namespace {

// h·∇·u in one cell: the net outflow through its six faces.
double netOutflow(const MacGrid& g, int i, int j, int k) {
    return double(g.velocity[0](i + 1, j, k)) - double(g.velocity[0](i, j, k)) +
           double(g.velocity[1](i, j + 1, k)) - double(g.velocity[1](i, j, k)) +
           double(g.velocity[2](i, j, k + 1)) - double(g.velocity[2](i, j, k));
}

double dot(const std::vector<double>& a, const std::vector<double>& b) {
    return deterministicSum(a.size(), [&](std::size_t i) { return a[i] * b[i]; });
}

// max |v| and where (the lowest index among ties; a max is exact in any order).
double maxAbs(const std::vector<double>& v, std::size_t* where = nullptr) {
    double m = 0.0;
    std::size_t at = 0;
    for (std::size_t i = 0; i < v.size(); ++i)
        if (std::fabs(v[i]) > m) {
            m = std::fabs(v[i]);
            at = i;
        }
    if (where) *where = at;
    return m;
}

glm::ivec3 cellOf(const glm::ivec3& n, std::size_t c) {
    return {int(c % std::size_t(n.x)), int((c / std::size_t(n.x)) % std::size_t(n.y)),
            int(c / (std::size_t(n.x) * std::size_t(n.y)))};
}

// u -= p_b − p_a across every face that is not solid; beyond an open wall p = 0.
void subtractPressureGradient(MacGrid& g, const std::vector<double>& p) {
    const glm::ivec3 n = g.resolution();
    for (int axis = 0; axis < 3; ++axis) {
        Array3& face = g.velocity[std::size_t(axis)];
        const glm::ivec3 s = face.size();
        forEachSlab(s.z, [&](int k) {
            for (int j = 0; j < s.y; ++j)
                for (int i = 0; i < s.x; ++i) {
                    if (g.faceIsSolid(axis, i, j, k)) continue;
                    glm::ivec3 hi(i, j, k), lo(i, j, k);
                    lo[axis] -= 1;
                    const double ph = hi[axis] < n[axis] ? p[g.cellIndex(hi.x, hi.y, hi.z)] : 0.0;
                    const double pl = lo[axis] >= 0 ? p[g.cellIndex(lo.x, lo.y, lo.z)] : 0.0;
                    face(i, j, k) = float(double(face(i, j, k)) - (ph - pl));
                }
        });
    }
}

}  // namespace

double maxDivergence(const MacGrid& g, glm::ivec3* where) {
    const glm::ivec3 n = g.resolution();
    double m = 0.0;
    for (int k = 0; k < n.z; ++k)
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i < n.x; ++i) {
                if (g.isSolid(i, j, k)) continue;
                const double d = std::fabs(netOutflow(g, i, j, k));
                if (d > m) {
                    m = d;
                    if (where) *where = glm::ivec3(i, j, k);
                }
            }
    return m;
}

PressureResult project(MacGrid& g, const PressureSettings& settings) {
    const PoissonMatrix A = buildPoissonMatrix(g);
    const std::size_t count = A.diag.size();
    std::vector<double> b(count, 0.0);
    forEachSlab(A.n.z, [&](int k) {
        for (int j = 0; j < A.n.y; ++j)
            for (int i = 0; i < A.n.x; ++i) {
                const std::size_t c = A.index(i, j, k);
                // A fluid cell walled in on all sides has nothing to solve for.
                if (A.fluid[c] && A.diag[c] > 0.0) b[c] = -netOutflow(g, i, j, k);
            }
    });
    PressureResult result;
    result.initialDivergence = maxAbs(b);
    if (!A.hasDirichlet) {
        // All walls closed: A is singular and only b with zero mean is solvable. Rounding leaves
        // a small mean that CG could never remove, so take it out (one connected fluid region
        // assumed; pockets sealed off by obstacles keep their own small mean).
        double fluidCells = 0.0;
        for (std::size_t c = 0; c < count; ++c) fluidCells += (A.fluid[c] && A.diag[c] > 0.0);
        const double mean =
            fluidCells > 0.0
                ? deterministicSum(count, [&](std::size_t c) { return b[c]; }) / fluidCells
                : 0.0;
        for (std::size_t c = 0; c < count; ++c)
            if (A.fluid[c] && A.diag[c] > 0.0) b[c] -= mean;
    }
    if (result.initialDivergence == 0.0) return result;
    const double target = settings.tolerance * result.initialDivergence;

    std::unique_ptr<Preconditioner> precon;
    if (settings.preconditioner == PressurePreconditioner::Multigrid)
        precon = std::make_unique<MultigridPreconditioner>(A);
    else
        precon = std::make_unique<MicPreconditioner>(A);
    std::vector<double> p(count, 0.0), r = b, z(count), s(count);
    std::size_t worst = 0;
    double rmax = maxAbs(r, &worst);
    if (rmax > target) {
        precon->apply(r, z);
        s = z;
        double sigma = dot(z, r);
        for (int it = 1; it <= settings.maxIterations; ++it) {
            multiply(A, s, z);
            const double zs = dot(z, s);
            if (zs == 0.0) break;
            const double alpha = sigma / zs;
            forEachIndex(count, [&](std::size_t c) {
                p[c] += alpha * s[c];
                r[c] -= alpha * z[c];
            });
            result.iterations = it;
            rmax = maxAbs(r, &worst);
            if (rmax <= target) break;
            precon->apply(r, z);
            const double sigmaNew = dot(z, r);
            const double beta = sigmaNew / sigma;
            forEachIndex(count, [&](std::size_t c) { s[c] = z[c] + beta * s[c]; });
            sigma = sigmaNew;
        }
    }
    result.residual = rmax / result.initialDivergence;
    result.converged = rmax <= target;
    result.worstCell = cellOf(A.n, worst);
    subtractPressureGradient(g, p);
    return result;
}

}  // namespace eikon::sim
