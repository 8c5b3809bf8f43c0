#include "sim/mic_preconditioner.h"

#include <cmath>

namespace eikon::sim {
namespace {

// MIC(0) parameters from Bridson: τ blends in the dropped fill-in (modified incomplete
// Cholesky); σ guards against tiny pivots (isolated cells, the singular all-closed system).
constexpr double kTau = 0.97;
constexpr double kSigma = 0.25;

}  // namespace

MicPreconditioner::MicPreconditioner(const PoissonMatrix& A)
    : A_(A), precon_(A.count(), 0.0), q_(A.count(), 0.0) {
    const glm::ivec3 n = A.n;
    const std::size_t sx = 1, sy = std::size_t(n.x), sz = std::size_t(n.x) * std::size_t(n.y);
    std::vector<double>& precon = precon_;
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
}

// z = M⁻¹ r with M = (L)(Lᵀ) from MIC(0): a forward then a backward substitution, in cell order.
void MicPreconditioner::apply(const std::vector<double>& r, std::vector<double>& z) {
    const PoissonMatrix& A = A_;
    const std::vector<double>& precon = precon_;
    std::vector<double>& q = q_;
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

}  // namespace eikon::sim
