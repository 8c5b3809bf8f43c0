#include "sim/pressure_solver.h"

#include <cmath>
#include <vector>

#include "sim/sim_parallel.h"

namespace eikon::sim {
namespace {

// MIC(0) parameters from Bridson: τ blends in the dropped fill-in (modified incomplete
// Cholesky); σ guards against tiny pivots (isolated cells, the singular all-closed system).
constexpr double kTau = 0.97;
constexpr double kSigma = 0.25;

// h·∇·u in one cell: the net outflow through its six faces.
double netOutflow(const MacGrid& g, int i, int j, int k) {
    return double(g.velocity[0](i + 1, j, k)) - double(g.velocity[0](i, j, k)) +
           double(g.velocity[1](i, j + 1, k)) - double(g.velocity[1](i, j, k)) +
           double(g.velocity[2](i, j, k + 1)) - double(g.velocity[2](i, j, k));
}

// The Laplacian over fluid cells, stored as Bridson does: the diagonal and the coupling to the
// +x, +y, +z neighbours (−1 when both are fluid, else 0).
struct Laplacian {
    glm::ivec3 n;
    std::vector<double> diag, plusX, plusY, plusZ;
    std::vector<std::uint8_t> fluid;
    bool hasDirichlet = false;  // an open wall touches the fluid: the system is not singular

    std::size_t index(int i, int j, int k) const {
        return (std::size_t(k) * std::size_t(n.y) + std::size_t(j)) * std::size_t(n.x) +
               std::size_t(i);
    }
};

Laplacian buildLaplacian(const MacGrid& g) {
    Laplacian A;
    A.n = g.resolution();
    const std::size_t count = g.domain.cellCount();
    A.diag.assign(count, 0.0);
    A.plusX.assign(count, 0.0);
    A.plusY.assign(count, 0.0);
    A.plusZ.assign(count, 0.0);
    A.fluid.assign(count, 0);
    for (std::size_t c = 0; c < count; ++c) A.fluid[c] = g.solid[c] ? 0 : 1;
    // Serial: cheap, and hasDirichlet is a plain flag.
    for (int k = 0; k < A.n.z; ++k)
        for (int j = 0; j < A.n.y; ++j)
            for (int i = 0; i < A.n.x; ++i) {
                const std::size_t c = A.index(i, j, k);
                if (!A.fluid[c]) continue;
                const glm::ivec3 cell(i, j, k);
                for (int axis = 0; axis < 3; ++axis)
                    for (int side = -1; side <= 1; side += 2) {
                        glm::ivec3 nb = cell;
                        nb[axis] += side;
                        if (!g.inside(nb.x, nb.y, nb.z)) {
                            if (g.domain.wall(axis, side > 0) == Wall::Open) {
                                A.diag[c] += 1.0;  // ghost pressure 0 beyond an open wall
                                A.hasDirichlet = true;
                            }
                            continue;
                        }
                        if (!A.fluid[A.index(nb.x, nb.y, nb.z)]) continue;
                        A.diag[c] += 1.0;
                        if (side > 0) {
                            std::vector<double>& plus = axis == 0   ? A.plusX
                                                        : axis == 1 ? A.plusY
                                                                    : A.plusZ;
                            plus[c] = -1.0;
                        }
                    }
            }
    return A;
}

void multiply(const Laplacian& A, const std::vector<double>& x, std::vector<double>& y) {
    const glm::ivec3 n = A.n;
    const std::size_t sx = 1, sy = std::size_t(n.x), sz = std::size_t(n.x) * std::size_t(n.y);
    forEachSlab(n.z, [&](int k) {
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i < n.x; ++i) {
                const std::size_t c = A.index(i, j, k);
                if (!A.fluid[c]) {
                    y[c] = 0.0;
                    continue;
                }
                double v = A.diag[c] * x[c];
                if (i + 1 < n.x) v += A.plusX[c] * x[c + sx];
                if (i > 0) v += A.plusX[c - sx] * x[c - sx];
                if (j + 1 < n.y) v += A.plusY[c] * x[c + sy];
                if (j > 0) v += A.plusY[c - sy] * x[c - sy];
                if (k + 1 < n.z) v += A.plusZ[c] * x[c + sz];
                if (k > 0) v += A.plusZ[c - sz] * x[c - sz];
                y[c] = v;
            }
    });
}

std::vector<double> micPreconditioner(const Laplacian& A) {
    const glm::ivec3 n = A.n;
    const std::size_t sx = 1, sy = std::size_t(n.x), sz = std::size_t(n.x) * std::size_t(n.y);
    std::vector<double> precon(A.diag.size(), 0.0);
    for (int k = 0; k < n.z; ++k)
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i < n.x; ++i) {
                const std::size_t c = A.index(i, j, k);
                if (!A.fluid[c] || A.diag[c] == 0.0) continue;
                double e = A.diag[c];
                if (i > 0) {
                    const std::size_t m = c - sx;
                    const double a = A.plusX[m] * precon[m];
                    e -= a * a +
                         kTau * A.plusX[m] * (A.plusY[m] + A.plusZ[m]) * precon[m] * precon[m];
                }
                if (j > 0) {
                    const std::size_t m = c - sy;
                    const double a = A.plusY[m] * precon[m];
                    e -= a * a +
                         kTau * A.plusY[m] * (A.plusX[m] + A.plusZ[m]) * precon[m] * precon[m];
                }
                if (k > 0) {
                    const std::size_t m = c - sz;
                    const double a = A.plusZ[m] * precon[m];
                    e -= a * a +
                         kTau * A.plusZ[m] * (A.plusX[m] + A.plusY[m]) * precon[m] * precon[m];
                }
                if (e < kSigma * A.diag[c]) e = A.diag[c];
                precon[c] = 1.0 / std::sqrt(e);
            }
    return precon;
}

// z = M⁻¹ r with M = (L)(Lᵀ) from MIC(0): a forward then a backward substitution, in cell order.
void applyPreconditioner(const Laplacian& A, const std::vector<double>& precon,
                         const std::vector<double>& r, std::vector<double>& q,
                         std::vector<double>& z) {
    const glm::ivec3 n = A.n;
    const std::size_t sx = 1, sy = std::size_t(n.x), sz = std::size_t(n.x) * std::size_t(n.y);
    for (int k = 0; k < n.z; ++k)
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i < n.x; ++i) {
                const std::size_t c = A.index(i, j, k);
                if (!A.fluid[c]) {
                    q[c] = 0.0;
                    continue;
                }
                double t = r[c];
                if (i > 0) t -= A.plusX[c - sx] * precon[c - sx] * q[c - sx];
                if (j > 0) t -= A.plusY[c - sy] * precon[c - sy] * q[c - sy];
                if (k > 0) t -= A.plusZ[c - sz] * precon[c - sz] * q[c - sz];
                q[c] = t * precon[c];
            }
    for (int k = n.z - 1; k >= 0; --k)
        for (int j = n.y - 1; j >= 0; --j)
            for (int i = n.x - 1; i >= 0; --i) {
                const std::size_t c = A.index(i, j, k);
                if (!A.fluid[c]) {
                    z[c] = 0.0;
                    continue;
                }
                double t = q[c];
                if (i + 1 < n.x) t -= A.plusX[c] * precon[c] * z[c + sx];
                if (j + 1 < n.y) t -= A.plusY[c] * precon[c] * z[c + sy];
                if (k + 1 < n.z) t -= A.plusZ[c] * precon[c] * z[c + sz];
                z[c] = t * precon[c];
            }
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
    const Laplacian A = buildLaplacian(g);
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

    const std::vector<double> precon = micPreconditioner(A);
    std::vector<double> p(count, 0.0), r = b, z(count), s(count), q(count);
    std::size_t worst = 0;
    double rmax = maxAbs(r, &worst);
    if (rmax > target) {
        applyPreconditioner(A, precon, r, q, z);
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
            applyPreconditioner(A, precon, r, q, z);
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
