#pragma once
// Modified incomplete Cholesky, MIC(0) (Bridson, "Fluid Simulation for Computer Graphics",
// ch. 5): A ≈ L·Lᵀ with L's sparsity that of A's lower half. Its two triangular solves run
// serially in cell order (each cell needs the one before it), which is what makes it slow on
// large grids; see multigrid_preconditioner.h for the parallel alternative.
#include "sim/poisson_matrix.h"

namespace eikon::sim {

class MicPreconditioner : public Preconditioner {
public:
    explicit MicPreconditioner(const PoissonMatrix& A);
    void apply(const std::vector<double>& r, std::vector<double>& z) override;

private:
    const PoissonMatrix& A_;
    std::vector<double> precon_;
    std::vector<double> q_;  // the forward substitution's result
};

}  // namespace eikon::sim
