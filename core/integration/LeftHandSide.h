#pragma once
// LeftHandSide: the constant matrix A = M + c1 C (+ c2 K0) an integrator solves with every
// step, factored once in compute() (and again only when the model changes, i.e. when the
// integrator is initialized again).
//
// - A diagonal (lumped mass with mass-proportional damping, or a diagonal K0): no factor, the
//   solve is x_i = b_i / A_ii (bit-identical to a dense LDL^T of the same diagonal matrix).
// - Up to StepMatrix::kDenseSize free DOFs a dense LDL^T (the factor used before issue 17:
//   bit-identical results on small models, and as fast at that size).
// - Otherwise a sparse LDL^T (Eigen::SimplicialLDLT, AMD ordering); for a shear building
//   (tridiagonal A) the factor has O(n) non-zeros and a solve costs O(n).
// Preconditions: A symmetric positive definite (M > 0 and C, K0 positive semi-definite).

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <memory>

namespace hsmu {

class LeftHandSide {
public:
    using SparseMatrix = Eigen::SparseMatrix<double>;
    /// Factor A; returns false if A is not positive definite (the solve then gives NaN).
    bool compute(const SparseMatrix& a);
    bool isDiagonal() const { return m_diagonal; }
    /// x = A^-1 b.
    void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;
    Eigen::VectorXd solve(const Eigen::VectorXd& b) const
    {
        Eigen::VectorXd x;
        solve(b, x);
        return x;
    }

private:
    bool m_diagonal = true;
    Eigen::VectorXd m_diag;
    std::shared_ptr<Eigen::LDLT<Eigen::MatrixXd>> m_dense;
    std::shared_ptr<Eigen::SimplicialLDLT<SparseMatrix>> m_ldlt; // shared: snapshots copy cheaply
};

} // namespace hsmu
