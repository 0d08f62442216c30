#include "core/structure/Lanczos.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace hsmu {

namespace {

/// Deterministic vector with entries in [-1, 1] (splitmix64), so runs are reproducible.
Eigen::VectorXd startVector(int n, std::uint64_t seed)
{
    Eigen::VectorXd v(n);
    std::uint64_t x = seed * 0x9E3779B97F4A7C15ull + 0x632BE59BD9B4E019ull;
    for (int i = 0; i < n; ++i) {
        x += 0x9E3779B97F4A7C15ull;
        std::uint64_t z = x;
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        z ^= z >> 31;
        v[i] = double(z >> 11) * (2.0 / 9007199254740992.0) - 1.0;
    }
    return v;
}

/// Remove from w its components along the first k columns of q (two passes).
void orthogonalize(const Eigen::MatrixXd& q, int k, Eigen::VectorXd& w)
{
    if (k == 0)
        return;
    for (int pass = 0; pass < 2; ++pass)
        w.noalias() -= q.leftCols(k) * (q.leftCols(k).transpose() * w);
}

} // namespace

LanczosResult lanczos(int n, const SymmetricOperator& a, int m, std::uint64_t seed)
{
    m = std::clamp(m, 1, n);
    Eigen::MatrixXd q(n, m);
    Eigen::VectorXd alpha = Eigen::VectorXd::Zero(m);
    Eigen::VectorXd beta = Eigen::VectorXd::Zero(m); // beta[j]: T(j, j+1); beta[m-1] the residual
    Eigen::VectorXd w(n);
    Eigen::VectorXd v = startVector(n, seed);
    v.normalize();
    double scale = 0.0; // running size of A, for the breakdown test
    for (int j = 0; j < m; ++j) {
        q.col(j) = v;
        a(v, w);
        alpha[j] = v.dot(w);
        orthogonalize(q, j + 1, w);
        double b = w.norm();
        scale = std::max(scale, std::abs(alpha[j]) + b);
        if (j + 1 < m && !(b > 1e-12 * scale)) {
            // Invariant subspace: continue from a fresh direction (T decouples there).
            for (std::uint64_t s = seed + 1 + std::uint64_t(j);; ++s) {
                w = startVector(n, s);
                orthogonalize(q, j + 1, w);
                if (w.norm() > 1e-8)
                    break;
            }
            beta[j] = 0.0;
            v = w.normalized();
            continue;
        }
        beta[j] = b;
        if (j + 1 < m)
            v = w / b;
    }
    Eigen::MatrixXd t = Eigen::MatrixXd::Zero(m, m);
    for (int j = 0; j < m; ++j) {
        t(j, j) = alpha[j];
        if (j + 1 < m)
            t(j, j + 1) = t(j + 1, j) = beta[j];
    }
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(t);
    LanczosResult r;
    r.ritz = eig.eigenvalues();
    r.residual = (beta[m - 1] * eig.eigenvectors().row(m - 1).transpose()).cwiseAbs();
    return r;
}

} // namespace hsmu
