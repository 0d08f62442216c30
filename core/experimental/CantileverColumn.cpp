#include "core/experimental/CantileverColumn.h"

#include <cmath>
#include <stdexcept>

namespace hsmu {

CantileverColumn::CantileverColumn(std::unique_ptr<HysteresisLaw> axial,
                                   std::unique_ptr<HysteresisLaw> hinge, double length, double ei)
    : m_axial(std::move(axial)), m_hinge(std::move(hinge)), m_l(length), m_ei(ei) {
    if (!m_axial || !m_hinge)
        throw std::invalid_argument("cantileverColumn: needs an axial and a hinge material");
    if (!(m_l > 0.0) || !std::isfinite(m_l))
        throw std::invalid_argument("cantileverColumn: length must be a finite length > 0 m");
    if (!(m_ei > 0.0) || !std::isfinite(m_ei))
        throw std::invalid_argument("cantileverColumn: ei must be a finite EI > 0 kN m^2 (a "
                                    "rigid column fixes the top rotation to the hinge's)");
    m_k = initialTangent();
}

std::string CantileverColumn::description() const {
    return "cantilever column (hinge " + m_hinge->lawName() + ", axial " + m_axial->lawName() +
           ", P-Delta)";
}

void CantileverColumn::setTimeIncrement(double dt) {
    m_axial->setTimeIncrement(dt);
    m_hinge->setTimeIncrement(dt);
}

Eigen::Matrix3d CantileverColumn::tangent(double ka, double kh, double n, double lateral) const {
    const double l = m_l, c = m_ei / (l * l * l);
    Eigen::Matrix2d ke;
    ke << 12.0 * c, -6.0 * l * c, -6.0 * l * c, 4.0 * l * l * c; // eq. W1
    const Eigen::RowVector2d dth = Eigen::RowVector2d(6.0, -2.0 * l) * (m_ei / (l * l)) /
                                   (kh + 4.0 * m_ei / l); // d theta_h / d(D, phi)
    const Eigen::Matrix2d b = Eigen::Matrix2d::Identity() - Eigen::Vector2d(l, 1.0) * dth;
    Eigen::Matrix3d k = Eigen::Matrix3d::Zero();
    k(0, 0) = ka;
    k.bottomRightCorner<2, 2>() = ke * b;
    k(1, 1) += n / l; // eq. W3
    k(1, 0) += ka * lateral / l;
    return k;
}

Eigen::Matrix3d CantileverColumn::initialTangent() const {
    return tangent(m_axial->initialTangent(), m_hinge->initialTangent(), 0.0, 0.0);
}

std::string CantileverColumn::setTrial(const Eigen::Vector3d& d) {
    if (m_axial->setTrialDeformation(d[0]) != LawStatus::Ok)
        return "cantileverColumn: the axial material refused d_a = " + std::to_string(d[0]);
    const double l = m_l, ei = m_ei;
    const double drive = ei / (l * l) * (6.0 * d[1] - 2.0 * l * d[2]); // R = M_h + 4EI/L th - drive
    double th = m_hinge->committedDeformation();
    bool ok = false;
    for (int it = 0; it < 50; ++it) {
        if (m_hinge->setTrialDeformation(th) != LawStatus::Ok)
            break;
        const double r = m_hinge->trialForce() + 4.0 * ei / l * th - drive; // eq. W2
        if (std::abs(r) <= 1e-12 * std::max(1.0, std::abs(m_hinge->trialForce()))) {
            ok = true;
            break;
        }
        const double k = m_hinge->trialTangent() + 4.0 * ei / l;
        if (!(k > 0.0) || !std::isfinite(k))
            break;
        th -= r / k;
    }
    if (!ok)
        return "cantileverColumn: no hinge rotation balances the column at D = " +
               std::to_string(d[1]) + " m, phi = " + std::to_string(d[2]) + " rad";
    const double c = ei / (l * l * l), de = d[1] - l * th, pe = d[2] - th;
    const double n = m_axial->trialForce();
    m_q << n, c * (12.0 * de - 6.0 * l * pe) + n * d[1] / l, c * (-6.0 * l * de + 4.0 * l * l * pe);
    m_k = tangent(m_axial->trialTangent(), m_hinge->trialTangent(), n, d[1]);
    return {};
}

void CantileverColumn::commit() {
    m_axial->commit();
    m_hinge->commit();
}

void CantileverColumn::revert() {
    m_axial->revert();
    m_hinge->revert();
}

} // namespace hsmu
