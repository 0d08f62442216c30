#pragma once
// UkfKernels: the small dense kernels of UnscentedKalmanFilter, written as plain loops over
// column-major storage. For the L <= ~20 of an estimator they are several times faster than
// Eigen's dynamic-size LLT and products, whose blocking and dispatch dominate at that size
// (the filter's step budget is a few microseconds, docs/method.md, The paper's UKF / issue 3).

#include <Eigen/Core>

namespace hsmu::ukfkernels {

/// Whether all `count` values from `data` are finite (branch-free: vectorized).
bool allFinite(const double* data, Eigen::Index count);
inline bool allFinite(const Eigen::MatrixXd& m) {
    return allFinite(m.data(), m.size());
}

/// Columns out_j = x + scale s_j for the n columns s_j of `root` (n x n, column-major), into
/// n x n column-major storage at `out`: the sigma points x +- c S_j.
void offsetColumns(const Eigen::VectorXd& x, const Eigen::MatrixXd& root, double scale,
                   double* out);

/// offsetColumns(), returning whether std::clamp into [lower, upper] (of x's size) would move
/// any of the values written: one below `lower` or above `upper` (never a NaN).
bool offsetColumnsOutside(const Eigen::VectorXd& x, const Eigen::MatrixXd& root, double scale,
                          double* out, const Eigen::VectorXd& lower, const Eigen::VectorXd& upper);

/// minus_j = x - (plus_j - x) for the n columns at `plus` (n x n, column-major), into `minus`.
void mirrorColumns(const Eigen::VectorXd& x, const double* plus, double* minus);

/// dev = points(:, 1..k) - points(:, 0) for points with k + 1 columns.
void deviations(const Eigen::MatrixXd& points, Eigen::MatrixXd& dev);

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

/// For 2p + 1 points (the columns of `points`, m x (2p + 1)): their deviations from the first,
/// dev = points(:, 1..2p) - points(:, 0), and the mean offset mu = sum_j w_j (dev_j + dev_p+j)
/// over the pairs j < p, leaving out each second difference dev_j + dev_p+j (per component)
/// not above `noise` times |plus| + |minus| + 2 |centre|: rounding noise there, which the
/// weights (~1e7 with the paper's settings) would turn into a mean offset.
void pairMoments(const Eigen::MatrixXd& points, const Eigen::VectorXd& w, double noise,
                 Eigen::MatrixXd& dev, Eigen::VectorXd& mu);

/// m(i, j) += (c mu(i)) mu(j) (as Eigen's m.noalias() += c * mu * mu.transpose(), without its
/// temporary).
void addScaledOuter(Eigen::MatrixXd& m, double c, const Eigen::VectorXd& mu);

/// Solves K A = B for K (B is r x m, A = L L^T is m x m with L from choleskyInPlace), in place
/// in b.
void solveRightInPlace(const Eigen::MatrixXd& lower, Eigen::MatrixXd& b);

} // namespace hsmu::ukfkernels
