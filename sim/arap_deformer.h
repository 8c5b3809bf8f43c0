#pragma once
// As-rigid-as-possible surface editing (Sorkine & Alexa 2007, "As-Rigid-As-Possible Surface
// Modeling"): drag handle vertices and the rest of the mesh follows, each vertex's one-ring
// moving as close to a rotation of its rest shape as the handles allow.
//
// Energy: E = Σ_i Σ_{j∈N(i)} w_ij ‖(p'_i − p'_j) − R_i (p_i − p_j)‖², p rest, p' deformed, with
// cotangent weights w_ij = ½ (cot α_ij + cot β_ij). An iteration is a local step (each R_i by SVD
// of its one-ring's covariance, reflections turned into rotations) and a global step (the free
// vertices from the sparse linear system L p' = b, handles held fixed). Each step minimises E
// over its own variables, so E never increases; that needs positive weights, so cotangent
// weights below a floor (obtuse opposite angles make them negative) are clamped up to it:
// kArapWeightFloor times the mean of the positive weights. The system matrix depends only on the
// mesh and on which vertices are handles, so it is factorized (sparse LDLᵀ) once per handle set
// and reused by every iteration and frame.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "core/triangle_mesh.h"

namespace eikon {

constexpr double kArapWeightFloor = 0.01;

class ArapDeformer {
public:
    // Throws eikon::Error("arap", ...) for a mesh without triangles or with non-finite vertices.
    explicit ArapDeformer(const TriangleMesh& rest);
    ~ArapDeformer();
    ArapDeformer(const ArapDeformer&) = delete;
    ArapDeformer& operator=(const ArapDeformer&) = delete;

    // Which vertices are handles (indices into the rest mesh, distinct); factorizes the system.
    // Throws where an index is out of range or repeated, or where a connected piece of the
    // mesh has no handle (its position would be undetermined).
    void setHandles(const std::vector<std::uint32_t>& handles);

    // Puts the handles at `targets` (in setHandles' order) and runs `iterations` local/global
    // iterations from the current shape (the rest shape at first, then the last result). Returns
    // E after each iteration, with the rotations that best fit that iteration's positions.
    std::vector<double> solve(const std::vector<glm::vec3>& targets, int iterations);

    // Back to the rest shape (the factorization stays): the next solve starts from rest.
    void reset() { positions_ = rest_.positions; }

    // E of the current shape with its best-fitting rotations.
    double energy() const;

    const std::vector<glm::vec3>& positions() const { return positions_; }
    const TriangleMesh& rest() const { return rest_; }
    // The deformed mesh (the rest mesh's triangles). Vertex normals, areas and the like are not
    // kept here: whoever needs them recomputes them from this after each solve.
    TriangleMesh deformedMesh() const;

    std::size_t factorizations() const { return factorizations_; }

private:
    struct Solver;
    std::unique_ptr<Solver> solver_;
    TriangleMesh rest_;
    std::vector<glm::vec3> positions_;
    std::size_t factorizations_ = 0;
};

}  // namespace eikon
