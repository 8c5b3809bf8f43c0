#include "sim/poisson_matrix.h"

#include <atomic>

#include "sim/sim_parallel.h"

namespace eikon::sim {

PoissonMatrix buildPoissonMatrix(const MacGrid& g) {
    PoissonMatrix A;
    A.n = g.resolution();
    const std::size_t count = g.domain.cellCount();
    A.diag.assign(count, 0.0);
    A.plusX.assign(count, 0.0);
    A.plusY.assign(count, 0.0);
    A.plusZ.assign(count, 0.0);
    A.fluid.assign(count, 0);
    for (std::size_t c = 0; c < count; ++c) A.fluid[c] = g.solid[c] ? 0 : 1;
    // Each cell writes only its own entries: slab-parallel. The flag is an or.
    std::atomic<bool> dirichlet{false};
    forEachSlab(A.n.z, [&](int k) {
        bool touches = false;
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
                                touches = true;
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
        if (touches) dirichlet = true;
    });
    A.hasDirichlet = dirichlet;
    return A;
}

void multiply(const PoissonMatrix& A, const std::vector<double>& x, std::vector<double>& y) {
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

}  // namespace eikon::sim
