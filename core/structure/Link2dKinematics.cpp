#include "core/structure/Link2dKinematics.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace hsmu {

namespace {
constexpr const char* kBasicDofNames[3] = {"axial", "shear", "rotation"};
constexpr const char* kBasicDeformationUnits[3] = {"m", "m", "rad"};
constexpr const char* kBasicForceUnits[3] = {"kN", "kN", "kN m"};
} // namespace

const char* link2dBasicDofName(int k)
{
    return k >= 0 && k < 3 ? kBasicDofNames[k] : "";
}

const char* link2dBasicDeformationUnit(int k)
{
    return k >= 0 && k < 3 ? kBasicDeformationUnits[k] : "";
}

const char* link2dBasicForceUnit(int k)
{
    return k >= 0 && k < 3 ? kBasicForceUnits[k] : "";
}

int link2dBasicDofIndex(const std::string& name)
{
    for (int k = 0; k < 3; ++k)
        if (name == kBasicDofNames[k])
            return k;
    return -1;
}

Link2dKinematics::Link2dKinematics(const std::string& element, const Link2dGeometry& g) : m_g(g)
{
    if (!std::isfinite(g.length) || g.length <= 0.0)
        throw std::invalid_argument("element '" + element + "': length must be finite and > 0");
    if (!std::isfinite(g.angleDeg))
        throw std::invalid_argument("element '" + element + "': angle must be finite");
    for (int a = 0; a < 6; ++a)
        for (int b = a + 1; b < 6; ++b)
            if (g.dofs[a] >= 0 && g.dofs[a] == g.dofs[b])
                throw std::invalid_argument("element '" + element + "': DOF " +
                                            std::to_string(g.dofs[a]) + " given twice");
    const double phi = g.angleDeg * std::numbers::pi / 180.0;
    const double c = std::cos(phi), s = std::sin(phi), L = g.length;
    m_a.setZero();
    m_a.row(0) << -c, -s, 0.0, c, s, 0.0;
    m_a.row(1) << s, -c, -L, -s, c, 0.0;
    m_a.row(2) << 0.0, 0.0, -1.0, 0.0, 0.0, 1.0;
}

Eigen::Vector3d Link2dKinematics::basic(const Eigen::VectorXd& uFull) const
{
    Eigen::Vector3d d = Eigen::Vector3d::Zero();
    for (int k = 0; k < 6; ++k)
        if (m_g.dofs[k] >= 0)
            d += m_a.col(k) * uFull[m_g.dofs[k]];
    return d;
}

void Link2dKinematics::addNodalForces(const Eigen::Vector3d& q, Eigen::VectorXd& rFull) const
{
    for (int k = 0; k < 6; ++k)
        if (m_g.dofs[k] >= 0)
            rFull[m_g.dofs[k]] += m_a.col(k).dot(q);
}

void Link2dKinematics::addStiffness(const Eigen::Matrix3d& kb,
                                    std::vector<Eigen::Triplet<double>>& k,
                                    const std::vector<int>& freeOf) const
{
    const Eigen::Matrix<double, 6, 6> ke = m_a.transpose() * kb * m_a;
    for (int a = 0; a < 6; ++a)
        for (int b = 0; b < 6; ++b)
            if (m_g.dofs[a] >= 0 && m_g.dofs[b] >= 0 && ke(a, b) != 0.0)
                k.emplace_back(freeOf[m_g.dofs[a]], freeOf[m_g.dofs[b]], ke(a, b));
}

std::vector<DofTerm> Link2dKinematics::terms(int row) const
{
    std::vector<DofTerm> t;
    for (int k = 0; k < 6; ++k)
        if (m_g.dofs[k] >= 0)
            t.push_back({m_g.dofs[k], m_a(row, k)});
    return t;
}

} // namespace hsmu
