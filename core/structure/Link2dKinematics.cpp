#include "core/structure/Link2dKinematics.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace hsmu {

namespace {
constexpr const char* kBasicDofNames[3] = {"axial", "shear", "rotation"};
constexpr const char* kBasicDeformationUnits[3] = {"m", "m", "rad"};
constexpr const char* kBasicForceUnits[3] = {"kN", "kN", "kN m"};
constexpr double kCollapsedChord = 1e-9; // a chord shorter than this times L cannot turn
} // namespace

const char* link2dTransformationName(Link2dTransformation t)
{
    return t == Link2dTransformation::Corotational ? "corotational" : "linear";
}

bool link2dTransformationFromName(const std::string& name, Link2dTransformation& t)
{
    for (auto k : {Link2dTransformation::Linear, Link2dTransformation::Corotational})
        if (name == link2dTransformationName(k)) {
            t = k;
            return true;
        }
    return false;
}

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

Link2dVector6 Link2dKinematics::local(const Eigen::VectorXd& uFull) const
{
    Link2dVector6 ue = Link2dVector6::Zero();
    for (int k = 0; k < 6; ++k)
        if (m_g.dofs[k] >= 0)
            ue[k] = uFull[m_g.dofs[k]];
    return ue;
}

Link2dKinematics::Chord Link2dKinematics::chord(const Link2dVector6& ue) const
{
    const Eigen::Vector2d e0(m_a(0, 3), m_a(0, 4));
    const Eigen::Vector2d dl = m_g.length * e0 + ue.segment<2>(3) - ue.segment<2>(0);
    const double ln = dl.norm();
    // node i's turned axis e_i = R(theta_i) e0; beta_i = the chord's angle from it (eq. L3)
    const double ci = std::cos(ue[2]), si = std::sin(ue[2]);
    const Eigen::Vector2d ei(ci * e0.x() - si * e0.y(), si * e0.x() + ci * e0.y());
    const double beta = std::atan2(ei.x() * dl.y() - ei.y() * dl.x(), ei.dot(dl));
    return {dl / ln, ln, beta};
}

std::string Link2dKinematics::chordFault(const Link2dVector6& ue) const
{
    if (!corotational())
        return {};
    const Chord ch = chord(ue);
    if (!(ch.length > kCollapsedChord * m_g.length))
        return "the chord from node i to node j collapses (length " +
               std::to_string(ch.length) + " m of " + std::to_string(m_g.length) +
               " m): no corotational frame";
    return {};
}

Eigen::Vector3d Link2dKinematics::basicAt(const Link2dVector6& ue) const
{
    if (!corotational())
        return m_a * ue;
    const Chord ch = chord(ue);
    if (!(ch.length > kCollapsedChord * m_g.length))
        return Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
    return {ch.length - m_g.length, m_g.length * ch.beta, ue[5] - ue[2]}; // eq. L3
}

Link2dMatrix36 Link2dKinematics::transformationAt(const Link2dVector6& ue) const
{
    if (!corotational())
        return m_a;
    const Chord ch = chord(ue);
    const Eigen::Vector2d n(-ch.e.y(), ch.e.x());
    const double l = m_g.length;
    Link2dMatrix36 b;
    b.row(0) << -ch.e.x(), -ch.e.y(), 0.0, ch.e.x(), ch.e.y(), 0.0;
    b.row(1) << -l * n.x() / ch.length, -l * n.y() / ch.length, -l, l * n.x() / ch.length,
        l * n.y() / ch.length, 0.0;
    b.row(2) << 0.0, 0.0, -1.0, 0.0, 0.0, 1.0;
    return b;
}

Link2dMatrix66 Link2dKinematics::geometricStiffness(const Link2dVector6& ue,
                                                    const Eigen::Vector3d& q) const
{
    Link2dMatrix66 kg = Link2dMatrix66::Zero();
    if (!corotational())
        return kg;
    const Chord ch = chord(ue);
    const Eigen::Vector2d n(-ch.e.y(), ch.e.x());
    const Eigen::Matrix2d h = q[0] * (n * n.transpose()) / ch.length -
                              q[1] * m_g.length * (ch.e * n.transpose() + n * ch.e.transpose()) /
                                  (ch.length * ch.length); // eq. L5
    kg.block<2, 2>(0, 0) = h;
    kg.block<2, 2>(3, 3) = h;
    kg.block<2, 2>(0, 3) = -h;
    kg.block<2, 2>(3, 0) = -h;
    return kg;
}

Link2dMatrix66 Link2dKinematics::tangent(const Link2dVector6& ue, const Eigen::Matrix3d& kb,
                                         const Eigen::Vector3d& q) const
{
    const Link2dMatrix36 b = transformationAt(ue);
    Link2dMatrix66 k = b.transpose() * kb * b;
    if (corotational())
        k += geometricStiffness(ue, q);
    return k;
}

void Link2dKinematics::addNodalForces(const Link2dVector6& ue, const Eigen::Vector3d& q,
                                      Eigen::VectorXd& rFull) const
{
    if (!corotational()) {
        addNodalForces(q, rFull);
        return;
    }
    const Link2dMatrix36 b = transformationAt(ue);
    for (int k = 0; k < 6; ++k)
        if (m_g.dofs[k] >= 0)
            rFull[m_g.dofs[k]] += b.col(k).dot(q); // eq. L4
}

void Link2dKinematics::addMatrix(const Link2dMatrix66& ke, std::vector<Eigen::Triplet<double>>& k,
                                 const std::vector<int>& freeOf) const
{
    for (int a = 0; a < 6; ++a)
        for (int b = 0; b < 6; ++b)
            if (m_g.dofs[a] >= 0 && m_g.dofs[b] >= 0 && ke(a, b) != 0.0)
                k.emplace_back(freeOf[m_g.dofs[a]], freeOf[m_g.dofs[b]], ke(a, b));
}

Eigen::Vector3d Link2dKinematics::basic(const Eigen::VectorXd& uFull) const
{
    if (corotational())
        return basicAt(local(uFull));
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
    addMatrix(m_a.transpose() * kb * m_a, k, freeOf);
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
