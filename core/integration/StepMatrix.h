#pragma once
// StepMatrix: a constant matrix an integrator multiplies with every step (C, K_I), stored
// sparse (a product costs O(non-zeros)) or, for models of at most kDenseSize free DOFs,
// dense: at that size a dense product is as fast, and it sums in the order the dense code
// before issue 17 did, so small models (every shipped preset) give bit-identical results
// (a UKF on the record amplifies last-bit differences to 1e-7 over a few thousand steps).

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace hsmu {

class StepMatrix {
public:
    using SparseMatrix = Eigen::SparseMatrix<double>;
    /// Free DOF counts up to this use dense storage and kernels (also in LeftHandSide).
    static constexpr int kDenseSize = 32;

    void set(const SparseMatrix& a)
    {
        m_dense = a.rows() <= kDenseSize;
        if (m_dense) {
            m_d = Eigen::MatrixXd(a);
            m_s.resize(0, 0);
        } else {
            m_s = a;
            m_d.resize(0, 0);
        }
    }
    /// y = A x.
    Eigen::VectorXd operator*(const Eigen::VectorXd& x) const
    {
        Eigen::VectorXd y;
        multiply(x, y);
        return y;
    }
    /// y = A x into y, reusing its storage (no allocation once sized); y must not be x.
    void multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const
    {
        if (m_dense)
            y.noalias() = m_d * x;
        else
            y.noalias() = m_s * x;
    }

private:
    bool m_dense = true;
    Eigen::MatrixXd m_d;
    SparseMatrix m_s;
};

} // namespace hsmu
