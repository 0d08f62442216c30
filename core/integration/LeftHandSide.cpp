#include "core/integration/LeftHandSide.h"

#include "core/integration/StepMatrix.h"

#include <limits>

namespace hsmu {

bool LeftHandSide::compute(const SparseMatrix& a)
{
    m_diagonal = true;
    for (int j = 0; j < a.outerSize() && m_diagonal; ++j)
        for (SparseMatrix::InnerIterator it(a, j); it; ++it)
            if (it.row() != j && it.value() != 0.0) {
                m_diagonal = false;
                break;
            }
    m_ldlt.reset();
    m_dense.reset();
    if (m_diagonal) {
        m_diag = a.diagonal();
        return (m_diag.array() > 0.0).all();
    }
    m_diag.resize(0);
    if (a.rows() <= StepMatrix::kDenseSize) {
        m_dense = std::make_shared<Eigen::LDLT<Eigen::MatrixXd>>(Eigen::MatrixXd(a));
        return m_dense->info() == Eigen::Success && m_dense->isPositive();
    }
    m_ldlt = std::make_shared<Eigen::SimplicialLDLT<SparseMatrix>>(a);
    return m_ldlt->info() == Eigen::Success && (m_ldlt->vectorD().array() > 0.0).all();
}

void LeftHandSide::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const
{
    if (m_diagonal) {
        x = b.cwiseQuotient(m_diag);
        return;
    }
    if (m_dense) {
        x = m_dense->solve(b);
        return;
    }
    if (!m_ldlt || m_ldlt->info() != Eigen::Success) {
        x = Eigen::VectorXd::Constant(b.size(), std::numeric_limits<double>::quiet_NaN());
        return;
    }
    x = m_ldlt->solve(b);
}

} // namespace hsmu
