#pragma once
// UkfKernels: the small dense kernels of UnscentedKalmanFilter, written as plain loops over
// column-major storage. For the L <= ~20 of an estimator they are several times faster than
// Eigen's dynamic-size LLT and products, whose blocking and dispatch dominate at that size
// (the filter's step budget is a few microseconds, METHOD.md section 5 / issue 3).

#include <Eigen/Core>

namespace hsmu::ukfkernels {

/// In-place Cholesky factor A = L L^T of a symmetric matrix (only its lower triangle is
/// read); on return A holds L with a zero strictly-upper part. False, with A partly
/// overwritten, if a pivot is not finite and > 0 (A not positive definite).
bool choleskyInPlace(Eigen::MatrixXd& a);

/// m = (m + m^T) / 2 for a square m, in place.
void symmetrize(Eigen::MatrixXd& m);

/// out = sum_c w_c a_c b_c^T over the columns c of a (m x k) and b (n x k); out is m x n.
void weightedOuter(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, const Eigen::VectorXd& w,
                   Eigen::MatrixXd& out);

/// out = sum_c w_c a_c a_c^T (m x m), computed on the lower triangle and mirrored (exactly
/// symmetric).
void weightedGram(const Eigen::MatrixXd& a, const Eigen::VectorXd& w, Eigen::MatrixXd& out);

/// Solves K A = B for K (B is r x m, A = L L^T is m x m with L from choleskyInPlace), in place
/// in b.
void solveRightInPlace(const Eigen::MatrixXd& lower, Eigen::MatrixXd& b);

} // namespace hsmu::ukfkernels
