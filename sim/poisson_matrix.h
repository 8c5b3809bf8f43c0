#pragma once
// The pressure projection's matrix: the 7-point Laplacian over the fluid cells of a MAC grid, in
// the unknown p' = p·dt/(ρ·h) (pressure_solver.h), stored as Bridson does ("Fluid Simulation for
// Computer Graphics", ch. 5): the diagonal and the coupling to the +x, +y, +z neighbours (−1
// when both are fluid, else 0). Closed walls and solid cells drop their coupling (no flow
// through them); an open wall adds 1 to the diagonal (a ghost pressure of 0 beyond it).
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "sim/mac_grid.h"

namespace eikon::sim {

struct PoissonMatrix {
    glm::ivec3 n{0};
    std::vector<double> diag, plusX, plusY, plusZ;
    std::vector<std::uint8_t> fluid;
    bool hasDirichlet = false;  // an open wall touches the fluid: the system is not singular

    std::size_t index(int i, int j, int k) const {
        return (std::size_t(k) * std::size_t(n.y) + std::size_t(j)) * std::size_t(n.x) +
               std::size_t(i);
    }
    std::size_t count() const { return diag.size(); }
    // A fluid cell with something to solve for (walled in on every side it has diag 0).
    bool active(std::size_t c) const { return fluid[c] && diag[c] > 0.0; }
};

PoissonMatrix buildPoissonMatrix(const MacGrid& grid);

// y = A x (slab-parallel; each y[c] is summed in a fixed order).
void multiply(const PoissonMatrix& A, const std::vector<double>& x, std::vector<double>& y);

// z ≈ A⁻¹ r for conjugate gradients: symmetric positive definite, and the same whatever the
// thread count.
class Preconditioner {
public:
    virtual ~Preconditioner() = default;
    virtual void apply(const std::vector<double>& r, std::vector<double>& z) = 0;
};

}  // namespace eikon::sim
