#pragma once
// Lanczos: the extreme eigenvalues of a symmetric linear operator A (n x n) from a Krylov
// basis of m vectors, with full re-orthogonalization (two Gram-Schmidt passes), so no spurious
// copies of converged Ritz values appear (docs/benchmarks.md, "Modal analysis at scale").
//
//   A Q_m = Q_m T_m + beta_m q_{m+1} e_m^T,   T_m tridiagonal (alpha on, beta off the diagonal)
//
// A Ritz value theta_i of T_m (eigenvector s_i) has the residual ||A y_i - theta_i y_i|| =
// |beta_m s_i(m)|: some eigenvalue of A lies within that distance of theta_i.
// A breakdown (beta ~ 0: an invariant subspace) restarts with a fresh vector orthogonal to
// the basis, so m = n always gives every eigenvalue.
//
// Cost: m applications of A plus O(n m^2) for the re-orthogonalization; memory n m doubles.
// Preconditions: A symmetric; 1 <= m <= n.

#include <Eigen/Core>

#include <cstdint>
#include <functional>

namespace hsmu {

struct LanczosResult {
    Eigen::VectorXd ritz;     ///< Ritz values, ascending (size m)
    Eigen::VectorXd residual; ///< |beta_m s_i(m)| for each Ritz value
};

/// y = A x for vectors of size n (y is sized by the caller).
using SymmetricOperator = std::function<void(const Eigen::VectorXd& x, Eigen::VectorXd& y)>;

/// m Lanczos steps on A from a deterministic pseudo-random start vector (seed).
LanczosResult lanczos(int n, const SymmetricOperator& a, int m, std::uint64_t seed = 1);

} // namespace hsmu
