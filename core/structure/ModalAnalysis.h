#pragma once
// ModalAnalysis: undamped circular frequencies of K phi = omega^2 M phi for a sparse stiffness
// K (symmetric positive semi-definite) and a diagonal lumped mass M = diag(m), m > 0, without
// a dense eigen-solve (docs/benchmarks.md, "Modal analysis at scale").
//
// Both work on the standard form A = M^-1/2 K M^-1/2 (same sparsity as K; eigenvalues
// lambda = omega^2):
// - lowestFrequencies: shift-invert Lanczos on (A - sigma I)^-1 with a sparse LDL^T factor,
//   sigma = -1e-10 ||A||_inf (so a stiffness-free DOF gives omega = 0, not a failed factor);
//   the wanted Ritz values converge to 1e-12 relative (the Krylov space grows until they do).
//   A singular K (a DOF without stiffness) gives omega_1 = 0, and the other modes then only
//   to about 1e-7 relative (the zero mode's Ritz value 1/|sigma| dwarfs theirs).
// - largestFrequency: Lanczos on A (at most 120 steps), omega_max^2 taken as
//   min(theta_max + r_max, Gershgorin bound max_i sum_j |A_ij|), an estimate from above
//   within the Ritz residual r_max of the true value (r_max ~ 1e-12 theta when converged;
//   for clustered top spectra the Gershgorin bound, exact for a uniform chain's supremum,
//   caps it).
// - denseFrequencies: Eigen's generalized self-adjoint solver, every mode, O(n^3) (the path
//   of small models, and the reference of the tests).
//
// Units: K [kN/m], m [t] -> omega [rad/s]. Throws std::invalid_argument on bad input.

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace hsmu {

/// The `count` lowest omega, ascending (count is clamped to 1..n).
Eigen::VectorXd lowestFrequencies(const Eigen::SparseMatrix<double>& k, const Eigen::VectorXd& m,
                                  int count);
/// The largest omega (an estimate from above, see the header comment).
double largestFrequency(const Eigen::SparseMatrix<double>& k, const Eigen::VectorXd& m);
/// Every omega, ascending (dense generalized solve).
Eigen::VectorXd denseFrequencies(const Eigen::SparseMatrix<double>& k, const Eigen::VectorXd& m);

} // namespace hsmu
