#pragma once
// A geometric multigrid V-cycle as the preconditioner of the pressure solve (as Mantaflow's
// MG-PCG): parallel where MIC(0)'s triangular solves are serial, and its iteration count barely
// grows with the resolution.
//
// - Levels: each coarse cell is a 2×2×2 block of the finer level (odd sizes round up), down to
//   4 cells or fewer along every axis.
// - Transfers: piecewise-constant prolongation P (a coarse value to all its children) and
//   restriction Pᵀ (the sum over the children); the coarse matrix is Galerkin's PᵀAP, which
//   carries solids, closed walls and open walls down without special cases (a coupling is the
//   sum of the fine couplings across the block face). Constant P makes that coarse correction
//   too small by about half for smooth errors (the well-known factor of aggregation multigrid),
//   so it is scaled by kCoarseWeight.
// - Smoothing: red-black Gauss–Seidel, red then black before the coarse correction and black then
//   red after it, and symmetric sweeps on the coarsest level, so that the cycle is a symmetric
//   operator, as conjugate gradients needs.
// Every sweep updates one colour from the other only, so the result does not depend on the
// thread count or the order of the slabs. Floats inside: the matrix entries are small integers
// (exact), and a preconditioner needs no more than float precision.
#include <vector>

#include "sim/poisson_matrix.h"

namespace eikon::sim {

class MultigridPreconditioner : public Preconditioner {
public:
    explicit MultigridPreconditioner(const PoissonMatrix& A);
    void apply(const std::vector<double>& r, std::vector<double>& z) override;
    int levelCount() const { return int(levels_.size()); }

    struct Level {
        glm::ivec3 n{0};
        // A in PoissonMatrix's layout; invDiag is 0 where there is nothing to solve.
        std::vector<float> diag, plusX, plusY, plusZ, invDiag;
        std::vector<float> x, b, r;
        std::size_t index(int i, int j, int k) const {
            return (std::size_t(k) * std::size_t(n.y) + std::size_t(j)) * std::size_t(n.x) +
                   std::size_t(i);
        }
    };

private:
    void cycle(std::size_t level);
    std::vector<Level> levels_;
};

}  // namespace eikon::sim
