#include "sim/arap_deformer.h"

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "sim/mesh_edges.h"
#include "sim/sim_parallel.h"

namespace eikon {

namespace {

Eigen::Vector3d toEigen(const glm::vec3& p) {
    return Eigen::Vector3d(p.x, p.y, p.z);
}

// cot of the angle at `apex` in the triangle (apex, a, b).
double cotangent(const Eigen::Vector3d& apex, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    const Eigen::Vector3d u = a - apex, v = b - apex;
    // A zero-area triangle has no angle to speak of; its floor keeps the weight finite.
    const double sine = std::max(u.cross(v).norm(), 1e-12 * u.norm() * v.norm());
    return u.dot(v) / sine;
}

}  // namespace

struct ArapDeformer::Solver {
    std::size_t n = 0;
    Eigen::MatrixX3d rest;
    // One-rings: neighbours[offsets[i] .. offsets[i+1]) with their weights.
    std::vector<std::size_t> offsets;
    std::vector<std::uint32_t> neighbours;
    std::vector<double> weights;

    std::vector<std::int64_t> freeIndex;  // row in the system, −1 for handles and lone vertices
    std::vector<std::uint32_t> handles;
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
    std::vector<Eigen::Matrix3d> rotations;

    void buildOneRings(const TriangleMesh& mesh);
    void checkEveryPieceHasAHandle(const std::vector<bool>& isHandle) const;
    void fitRotations(const Eigen::MatrixX3d& x, std::vector<Eigen::Matrix3d>& out) const;
    double energy(const Eigen::MatrixX3d& x, const std::vector<Eigen::Matrix3d>& r) const;
    void solvePositions(Eigen::MatrixX3d& x) const;
};

void ArapDeformer::Solver::buildOneRings(const TriangleMesh& mesh) {
    const MeshEdges edges = meshEdges(mesh);
    std::vector<double> edgeWeight(edges.edges.size(), 0.0);
    double positiveSum = 0.0;
    std::size_t positiveCount = 0;
    for (std::size_t e = 0; e < edges.edges.size(); ++e) {
        const MeshEdge& edge = edges.edges[e];
        for (std::uint32_t u = 0; u < edge.uses; ++u) {
            const glm::uvec3& t = mesh.triangles[edges.uses[edge.firstUse + u].triangle];
            // The corner of the triangle opposite the edge.
            const std::uint32_t apex = t.x != edge.a && t.x != edge.b   ? t.x
                                       : t.y != edge.a && t.y != edge.b ? t.y
                                                                        : t.z;
            if (apex == edge.a || apex == edge.b) continue;  // a repeated index: no angle
            edgeWeight[e] += 0.5 * cotangent(rest.row(apex), rest.row(edge.a), rest.row(edge.b));
        }
        if (edgeWeight[e] > 0.0) {
            positiveSum += edgeWeight[e];
            ++positiveCount;
        }
    }
    const double floor = kArapWeightFloor * (positiveCount > 0 ? positiveSum / positiveCount : 1.0);
    std::vector<std::size_t> degree(n, 0);
    for (const MeshEdge& edge : edges.edges) ++degree[edge.a], ++degree[edge.b];
    offsets.assign(n + 1, 0);
    for (std::size_t i = 0; i < n; ++i) offsets[i + 1] = offsets[i] + degree[i];
    neighbours.resize(offsets[n]);
    weights.resize(offsets[n]);
    std::vector<std::size_t> fill(offsets.begin(), offsets.end() - 1);
    for (std::size_t e = 0; e < edges.edges.size(); ++e) {
        const MeshEdge& edge = edges.edges[e];
        const double w = std::max(edgeWeight[e], floor);
        neighbours[fill[edge.a]] = edge.b;
        weights[fill[edge.a]++] = w;
        neighbours[fill[edge.b]] = edge.a;
        weights[fill[edge.b]++] = w;
    }
}

void ArapDeformer::Solver::checkEveryPieceHasAHandle(const std::vector<bool>& isHandle) const {
    std::vector<bool> seen(n, false);
    std::vector<std::uint32_t> stack;
    for (std::uint32_t start = 0; start < n; ++start) {
        if (seen[start] || offsets[start] == offsets[start + 1]) continue;
        bool anchored = false;
        std::size_t size = 0;
        stack.assign(1, start);
        seen[start] = true;
        while (!stack.empty()) {
            const std::uint32_t v = stack.back();
            stack.pop_back();
            ++size;
            anchored = anchored || isHandle[v];
            for (std::size_t k = offsets[v]; k < offsets[v + 1]; ++k) {
                if (!seen[neighbours[k]]) {
                    seen[neighbours[k]] = true;
                    stack.push_back(neighbours[k]);
                }
            }
        }
        if (!anchored)
            throw Error("arap", "a connected piece of " + std::to_string(size) +
                                    " vertices (with vertex " + std::to_string(start) +
                                    ") has no handle, so its position is undetermined");
    }
}

// Local step: for each vertex, the rotation closest to mapping its rest one-ring onto the
// deformed one: R = V Uᵀ from the SVD U Σ Vᵀ of S = Σ w e eᵀ' (rest edges e, deformed e').
void ArapDeformer::Solver::fitRotations(const Eigen::MatrixX3d& x,
                                        std::vector<Eigen::Matrix3d>& out) const {
    sim::forEachIndex(n, [&](std::size_t i) {
        Eigen::Matrix3d s = Eigen::Matrix3d::Zero();
        for (std::size_t k = offsets[i]; k < offsets[i + 1]; ++k) {
            const std::uint32_t j = neighbours[k];
            s += weights[k] * (rest.row(i) - rest.row(j)).transpose() * (x.row(i) - x.row(j));
        }
        const Eigen::JacobiSVD<Eigen::Matrix3d> svd(s, Eigen::ComputeFullU | Eigen::ComputeFullV);
        Eigen::Matrix3d u = svd.matrixU();
        Eigen::Matrix3d r = svd.matrixV() * u.transpose();
        if (r.determinant() < 0.0) {  // a reflection: flip the axis of least singular value
            u.col(2) = -u.col(2);
            r = svd.matrixV() * u.transpose();
        }
        out[i] = r;
    });
}

double ArapDeformer::Solver::energy(const Eigen::MatrixX3d& x,
                                    const std::vector<Eigen::Matrix3d>& r) const {
    return sim::deterministicSum(n, [&](std::size_t i) {
        double e = 0.0;
        for (std::size_t k = offsets[i]; k < offsets[i + 1]; ++k) {
            const std::uint32_t j = neighbours[k];
            const Eigen::Vector3d restEdge = (rest.row(i) - rest.row(j)).transpose();
            const Eigen::Vector3d edge = (x.row(i) - x.row(j)).transpose();
            e += weights[k] * (edge - r[i] * restEdge).squaredNorm();
        }
        return e;
    });
}

// Global step: the free vertices from L p' = b with b_i = Σ_j ½ w_ij (R_i + R_j)(p_i − p_j),
// the handles' columns of L moved to the right-hand side.
void ArapDeformer::Solver::solvePositions(Eigen::MatrixX3d& x) const {
    Eigen::MatrixX3d rhs(ldlt.rows(), 3);
    sim::forEachIndex(n, [&](std::size_t i) {
        if (freeIndex[i] < 0) return;
        Eigen::Vector3d b = Eigen::Vector3d::Zero();
        for (std::size_t k = offsets[i]; k < offsets[i + 1]; ++k) {
            const std::uint32_t j = neighbours[k];
            b += 0.5 * weights[k] * (rotations[i] + rotations[j]) *
                 (rest.row(i) - rest.row(j)).transpose();
            if (freeIndex[j] < 0) b += weights[k] * x.row(j).transpose();
        }
        rhs.row(freeIndex[i]) = b.transpose();
    });
    const Eigen::MatrixX3d solved = ldlt.solve(rhs);
    for (std::size_t i = 0; i < n; ++i)
        if (freeIndex[i] >= 0) x.row(i) = solved.row(freeIndex[i]);
}

ArapDeformer::ArapDeformer(const TriangleMesh& rest) : solver_(new Solver), rest_(rest) {
    if (rest.triangles.empty()) throw Error("arap", "the mesh has no triangles");
    Solver& s = *solver_;
    s.n = rest.positions.size();
    s.rest.resize(Eigen::Index(s.n), 3);
    for (std::size_t i = 0; i < s.n; ++i) {
        const glm::vec3& p = rest.positions[i];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw Error("arap", "vertex " + std::to_string(i) + " is not finite");
        s.rest.row(Eigen::Index(i)) = toEigen(p).transpose();
    }
    s.buildOneRings(rest);
    s.rotations.assign(s.n, Eigen::Matrix3d::Identity());
    positions_ = rest.positions;
}

ArapDeformer::~ArapDeformer() = default;

void ArapDeformer::setHandles(const std::vector<std::uint32_t>& handles) {
    Solver& s = *solver_;
    if (handles.empty()) throw Error("arap", "at least one handle vertex is needed");
    std::vector<bool> isHandle(s.n, false);
    for (std::uint32_t h : handles) {
        if (h >= s.n)
            throw Error("arap", "handle " + std::to_string(h) + " is not a vertex (the mesh has " +
                                    std::to_string(s.n) + ")");
        if (isHandle[h]) throw Error("arap", "handle " + std::to_string(h) + " is listed twice");
        isHandle[h] = true;
    }
    s.checkEveryPieceHasAHandle(isHandle);

    s.freeIndex.assign(s.n, -1);
    std::int64_t rows = 0;
    for (std::size_t i = 0; i < s.n; ++i)
        if (!isHandle[i] && s.offsets[i] != s.offsets[i + 1]) s.freeIndex[i] = rows++;
    std::vector<Eigen::Triplet<double>> entries;
    for (std::size_t i = 0; i < s.n; ++i) {
        if (s.freeIndex[i] < 0) continue;
        double diagonal = 0.0;
        for (std::size_t k = s.offsets[i]; k < s.offsets[i + 1]; ++k) {
            diagonal += s.weights[k];
            const std::int64_t j = s.freeIndex[s.neighbours[k]];
            if (j >= 0) entries.emplace_back(s.freeIndex[i], j, -s.weights[k]);
        }
        entries.emplace_back(s.freeIndex[i], s.freeIndex[i], diagonal);
    }
    Eigen::SparseMatrix<double> laplacian(rows, rows);
    laplacian.setFromTriplets(entries.begin(), entries.end());
    s.ldlt.compute(laplacian);
    if (s.ldlt.info() != Eigen::Success)
        throw Error("arap", "the sparse Cholesky factorization failed");
    s.handles = handles;
    ++factorizations_;
}

std::vector<double> ArapDeformer::solve(const std::vector<glm::vec3>& targets, int iterations) {
    Solver& s = *solver_;
    if (s.handles.empty()) throw Error("arap", "solve before setHandles");
    if (targets.size() != s.handles.size())
        throw Error("arap", std::to_string(targets.size()) + " targets for " +
                                std::to_string(s.handles.size()) + " handles");
    Eigen::MatrixX3d x(Eigen::Index(s.n), 3);
    for (std::size_t i = 0; i < s.n; ++i) x.row(Eigen::Index(i)) = toEigen(positions_[i]);
    for (std::size_t h = 0; h < targets.size(); ++h) x.row(s.handles[h]) = toEigen(targets[h]);

    std::vector<double> energies;
    s.fitRotations(x, s.rotations);
    for (int it = 0; it < iterations; ++it) {
        s.solvePositions(x);
        s.fitRotations(x, s.rotations);
        energies.push_back(s.energy(x, s.rotations));
    }
    for (std::size_t i = 0; i < s.n; ++i)
        positions_[i] = glm::vec3(float(x(Eigen::Index(i), 0)), float(x(Eigen::Index(i), 1)),
                                  float(x(Eigen::Index(i), 2)));
    return energies;
}

double ArapDeformer::energy() const {
    Eigen::MatrixX3d x(Eigen::Index(solver_->n), 3);
    for (std::size_t i = 0; i < solver_->n; ++i) x.row(Eigen::Index(i)) = toEigen(positions_[i]);
    std::vector<Eigen::Matrix3d> rotations(solver_->n);
    solver_->fitRotations(x, rotations);
    return solver_->energy(x, rotations);
}

TriangleMesh ArapDeformer::deformedMesh() const {
    return {positions_, rest_.triangles};
}

}  // namespace eikon
