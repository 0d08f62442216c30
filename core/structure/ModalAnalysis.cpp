#include "core/structure/ModalAnalysis.h"

#include "core/structure/Lanczos.h"

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hsmu {

namespace {

using SpMat = Eigen::SparseMatrix<double>;

/// A = M^-1/2 K M^-1/2.
SpMat standardForm(const SpMat& k, const Eigen::VectorXd& m)
{
    if (k.rows() != k.cols() || k.rows() != m.size() || m.size() == 0)
        throw std::invalid_argument("modal analysis: K and M sizes differ or are empty");
    if (!(m.minCoeff() > 0.0))
        throw std::invalid_argument("modal analysis: every mass must be > 0");
    const Eigen::VectorXd d = m.cwiseSqrt().cwiseInverse();
    SpMat a = d.asDiagonal() * k * d.asDiagonal();
    a.makeCompressed();
    return a;
}

double rowSumBound(const SpMat& a)
{
    Eigen::VectorXd rows = Eigen::VectorXd::Zero(a.rows());
    for (int j = 0; j < a.outerSize(); ++j)
        for (SpMat::InnerIterator it(a, j); it; ++it)
            rows[it.row()] += std::abs(it.value());
    return rows.maxCoeff();
}

} // namespace

Eigen::VectorXd lowestFrequencies(const SpMat& k, const Eigen::VectorXd& m, int count)
{
    const SpMat a = standardForm(k, m);
    const int n = int(a.rows());
    count = std::clamp(count, 1, n);
    const double norm = rowSumBound(a);
    const double sigma = -1e-10 * (norm > 0.0 ? norm : 1.0);
    SpMat shifted = a;
    for (int i = 0; i < n; ++i)
        shifted.coeffRef(i, i) -= sigma;
    Eigen::SimplicialLDLT<SpMat> ldlt(shifted);
    if (ldlt.info() != Eigen::Success)
        throw std::invalid_argument("modal analysis: the stiffness could not be factored");
    const SymmetricOperator inverse = [&](const Eigen::VectorXd& x, Eigen::VectorXd& y) {
        y = ldlt.solve(x);
    };
    // The Ritz values of (A - sigma I)^-1 are mu = 1 / (lambda - sigma): lowest lambda first.
    for (int steps = std::min(n, std::max(2 * count + 20, 40));; steps = std::min(n, 2 * steps)) {
        const LanczosResult r = lanczos(n, inverse, steps);
        bool converged = steps == n;
        for (int i = 0; i < count && !converged; ++i) {
            const int idx = steps - 1 - i;
            converged = true;
            if (r.residual[idx] > 1e-12 * std::abs(r.ritz[idx]))
                converged = false;
        }
        if (converged || steps == n) {
            Eigen::VectorXd omega(count);
            for (int i = 0; i < count; ++i) {
                const double mu = r.ritz[steps - 1 - i];
                omega[i] = std::sqrt(std::max(0.0, 1.0 / mu + sigma));
            }
            return omega;
        }
    }
}

double largestFrequency(const SpMat& k, const Eigen::VectorXd& m)
{
    const SpMat a = standardForm(k, m);
    const int n = int(a.rows());
    const double gershgorin = rowSumBound(a);
    const SymmetricOperator apply = [&](const Eigen::VectorXd& x, Eigen::VectorXd& y) {
        y.noalias() = a * x;
    };
    const LanczosResult r = lanczos(n, apply, std::min(n, 120));
    const int top = int(r.ritz.size()) - 1;
    const double lambda = std::min(gershgorin, r.ritz[top] + r.residual[top]);
    return std::sqrt(std::max(0.0, lambda));
}

Eigen::VectorXd denseFrequencies(const SpMat& k, const Eigen::VectorXd& m)
{
    if (k.rows() != m.size())
        throw std::invalid_argument("modal analysis: K and M sizes differ");
    const Eigen::MatrixXd kd(k);
    const Eigen::MatrixXd md(m.asDiagonal());
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(kd, md);
    if (eig.info() != Eigen::Success)
        throw std::invalid_argument("eigenvalue analysis of the initial stiffness failed");
    return eig.eigenvalues().cwiseMax(0.0).cwiseSqrt();
}

} // namespace hsmu
