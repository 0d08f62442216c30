#include "core/experimental/setup/PlanarActuatorSetup.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace hsmu {

namespace {
constexpr int kMaxNewton = 30;
constexpr double kRankTolerance = 1e-9;   // smallest / largest singular value, columns normalized
constexpr double kLengthTolerance = 1e-9; // current actuator length / rest length
} // namespace

bool parseActuatorSide(const std::string& word, bool& right) {
    if (word == "left" || word == "l") {
        right = false;
        return true;
    }
    if (word == "right" || word == "r") {
        right = true;
        return true;
    }
    return false;
}

PlanarActuatorSetup::PlanarActuatorSetup(std::string typeName,
                                         std::vector<PlanarActuator> actuators,
                                         SetupGeometry geometry, double phiLocXDeg,
                                         std::vector<int> controlledDofs)
    : m_typeName(std::move(typeName)), m_actuators(std::move(actuators)), m_geometry(geometry),
      m_controlled(std::move(controlledDofs)) {
    for (const PlanarActuator& a : m_actuators)
        m_La.push_back((a.attach - a.base).norm());
    const double phi = phiLocXDeg * std::numbers::pi / 180.0;
    m_cphi = std::cos(phi);
    m_sphi = std::sin(phi);
    for (int k = 0; k < 3; ++k)
        if (std::find(m_controlled.begin(), m_controlled.end(), k) == m_controlled.end())
            m_given.push_back(k);
    m_J0.setZero(static_cast<int>(m_actuators.size()), 3);
    for (int i = 0; i < m_J0.rows(); ++i) {
        if (!(m_La[i] > 0.0))
            continue; // refused by restSingularity()
        const PlanarActuator& a = m_actuators[i];
        const Eigen::Vector2d e = (a.attach - a.base) / m_La[i];
        m_J0.row(i) << e.x(), e.y(), -e.x() * a.attach.y() + e.y() * a.attach.x();
    }
}

Eigen::Vector3d PlanarActuatorSetup::toSetupFrame(const Eigen::VectorXd& d) const {
    return {m_cphi * d(0) - m_sphi * d(1), m_sphi * d(0) + m_cphi * d(1), d(2)};
}

Eigen::Vector3d PlanarActuatorSetup::toElementFrame(const Eigen::Vector3d& dl) const {
    return {m_cphi * dl(0) + m_sphi * dl(1), -m_sphi * dl(0) + m_cphi * dl(1), dl(2)};
}

PlanarActuatorSetup::Pose PlanarActuatorSetup::pose(const Eigen::Vector3d& dl) const {
    if (m_geometry == SetupGeometry::Linear)
        return {dl(0), dl(1), dl(2), 1.0, 0.0};
    return {dl(0), dl(1), dl(2), std::cos(dl(2)), std::sin(dl(2))};
}

bool PlanarActuatorSetup::stroke(int i, const Pose& p, double& s) const {
    const PlanarActuator& a = m_actuators[i];
    if (m_geometry == SetupGeometry::Linear) {
        s = m_J0(i, 0) * p.u + m_J0(i, 1) * p.v + m_J0(i, 2) * p.theta; // S1L
        return true;
    }
    const double rx = p.u + p.c * a.attach.x() - p.s * a.attach.y() - a.base.x();
    const double ry = p.v + p.s * a.attach.x() + p.c * a.attach.y() - a.base.y();
    const double len = std::sqrt(rx * rx + ry * ry);
    s = len - m_La[i];
    return len > kLengthTolerance * m_La[i];
}

bool PlanarActuatorSetup::rowAt(int i, const Pose& p, double* row) const {
    const PlanarActuator& a = m_actuators[i];
    const double rx = p.u + p.c * a.attach.x() - p.s * a.attach.y() - a.base.x();
    const double ry = p.v + p.s * a.attach.x() + p.c * a.attach.y() - a.base.y();
    const double len = std::sqrt(rx * rx + ry * ry);
    if (!(len > kLengthTolerance * m_La[i]))
        return false;
    const double nx = rx / len, ny = ry / len;
    // d/dtheta of R(theta) a
    const double dpx = -p.s * a.attach.x() - p.c * a.attach.y();
    const double dpy = p.c * a.attach.x() - p.s * a.attach.y();
    row[0] = nx;
    row[1] = ny;
    row[2] = nx * dpx + ny * dpy;
    return true;
}

SetupResult PlanarActuatorSetup::strokes(const Eigen::VectorXd& d, Eigen::VectorXd& s) const {
    if (d.size() != 3)
        return SetupResult::fault(m_typeName +
                                  ": 3 basic displacements (u, v, theta) wanted, got " +
                                  std::to_string(d.size()));
    const Pose p = pose(toSetupFrame(d));
    s.resize(actuatorCount());
    for (int i = 0; i < actuatorCount(); ++i)
        if (!stroke(i, p, s(i)))
            return SetupResult::fault(m_typeName + ": actuator " + std::to_string(i + 1) +
                                      " would shrink to zero length at the commanded motion");
    return SetupResult::success();
}

SetupResult PlanarActuatorSetup::jacobianLocal(const Eigen::Vector3d& dl, Rows& J) const {
    if (m_geometry == SetupGeometry::Linear) {
        J = m_J0;
        return SetupResult::success();
    }
    const Pose p = pose(dl);
    J.resize(actuatorCount(), 3);
    for (int i = 0; i < actuatorCount(); ++i) {
        double row[3];
        if (!rowAt(i, p, row))
            return SetupResult::fault(m_typeName + ": actuator " + std::to_string(i + 1) +
                                      " has zero length at the commanded motion");
        J(i, 0) = row[0];
        J(i, 1) = row[1];
        J(i, 2) = row[2];
    }
    return SetupResult::success();
}

PlanarActuatorSetup::Square PlanarActuatorSetup::controlledColumns(const Rows& J) const {
    Square Jc(J.rows(), static_cast<int>(m_controlled.size()));
    for (int k = 0; k < Jc.cols(); ++k)
        Jc.col(k) = J.col(m_controlled[k]);
    return Jc;
}

double PlanarActuatorSetup::normalizedVolume(const Square& Jc) {
    Square n = Jc;
    for (int k = 0; k < n.cols(); ++k) {
        const double norm = n.col(k).norm();
        if (norm == 0.0)
            return 0.0;
        n.col(k) /= norm;
    }
    return std::abs(n.determinant());
}

SetupResult PlanarActuatorSetup::jacobian(const Eigen::VectorXd& d, Eigen::MatrixXd& J) const {
    if (d.size() != 3)
        return SetupResult::fault(m_typeName +
                                  ": 3 basic displacements (u, v, theta) wanted, got " +
                                  std::to_string(d.size()));
    Rows Jl;
    if (SetupResult r = jacobianLocal(toSetupFrame(d), Jl); !r.ok)
        return r;
    J = Jl;
    // chain rule through (u, v)_setup = R(phi) (u, v)_element
    for (int i = 0; i < J.rows(); ++i) {
        const double jx = J(i, 0), jy = J(i, 1);
        J(i, 0) = jx * m_cphi + jy * m_sphi;
        J(i, 1) = -jx * m_sphi + jy * m_cphi;
    }
    return SetupResult::success();
}

std::string PlanarActuatorSetup::singularity(const Eigen::MatrixXd& Jc) {
    Eigen::MatrixXd n = Jc;
    for (int k = 0; k < n.cols(); ++k) {
        const double norm = n.col(k).norm();
        if (norm == 0.0)
            return "no actuator acts on basic DOF column " + std::to_string(k + 1);
        n.col(k) /= norm;
    }
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(n);
    const auto& sv = svd.singularValues();
    if (sv(sv.size() - 1) <= kRankTolerance * sv(0)) {
        std::ostringstream os;
        os << "the actuators cannot fix the controlled DOFs (parallel or coincident; singular "
              "value "
              "ratio "
           << sv(sv.size() - 1) / sv(0) << ")";
        return os.str();
    }
    return {};
}

std::string PlanarActuatorSetup::restSingularity() const {
    if (actuatorCount() > 3 || actuatorCount() != static_cast<int>(m_controlled.size()))
        return "one actuator per controlled basic DOF wanted (at most 3)";
    for (int i = 0; i < actuatorCount(); ++i)
        if (!(m_La[i] > 0.0))
            return "actuator " + std::to_string(i + 1) +
                   " has zero length (attachment on its base)";
    return singularity(controlledColumns(m_J0));
}

SetupResult PlanarActuatorSetup::basicDisplacements(const Eigen::VectorXd& s,
                                                    const Eigen::VectorXd& given,
                                                    Eigen::VectorXd& d) const {
    const int m = actuatorCount();
    if (s.size() != m || given.size() != 3)
        return SetupResult::fault(m_typeName + ": " + std::to_string(m) +
                                  " strokes and 3 given basic displacements wanted, got " +
                                  std::to_string(s.size()) + " and " +
                                  std::to_string(given.size()));
    Eigen::Vector3d dl = toSetupFrame(given);
    const Eigen::Vector3d start = dl;
    // Linear solution: J0_c d_c = s - J0_g d_g (S4).
    auto linear = [&](Eigen::Vector3d& at) -> SetupResult {
        Small rhs = s, x(m);
        for (int g : m_given)
            rhs -= m_J0.col(g) * at(g);
        if (SetupResult q = solveControlled(m_J0, rhs, x); !q.ok)
            return q;
        for (int k = 0; k < m; ++k)
            at(m_controlled[k]) = x(k);
        return SetupResult::success();
    };
    if (m_geometry == SetupGeometry::Linear) {
        if (SetupResult q = linear(dl); !q.ok)
            return q;
    } else {
        // Newton from the given (trial) displacements, where the measurement nearly always is;
        // from the linear solution when that fails.
        SetupResult q = newton(s, dl);
        if (!q.ok) {
            dl = start;
            if (SetupResult l = linear(dl); !l.ok)
                return l;
            q = newton(s, dl);
        }
        if (!q.ok)
            return q;
    }
    d = toElementFrame(dl);
    return SetupResult::success();
}

SetupResult PlanarActuatorSetup::solveControlled(const Rows& J, const Small& rhs, Small& x) const {
    const Square Jc = controlledColumns(J);
    if (normalizedVolume(Jc) <= kRankTolerance)
        return SetupResult::fault(m_typeName +
                                  ": measured strokes at a singular geometry: " + singularity(Jc));
    x = Jc.partialPivLu().solve(rhs);
    return SetupResult::success();
}

SetupResult PlanarActuatorSetup::newton(const Eigen::VectorXd& s, Eigen::Vector3d& dl) const {
    const int m = actuatorCount();
    double maxLa = 0;
    for (double La : m_La)
        maxLa = std::max(maxLa, La);
    Rows J;
    Small r(m), x(m);
    for (int it = 0; it < kMaxNewton; ++it) {
        const Pose p = pose(dl);
        for (int i = 0; i < m; ++i) {
            double si = 0;
            if (!stroke(i, p, si))
                return SetupResult::fault(m_typeName + ": actuator " + std::to_string(i + 1) +
                                          " reaches zero length solving the measured strokes");
            r(i) = s(i) - si;
        }
        if (r.cwiseAbs().maxCoeff() <= 1e-13 * maxLa)
            return SetupResult::success();
        if (SetupResult q = jacobianLocal(dl, J); !q.ok)
            return q;
        if (SetupResult q = solveControlled(J, r, x); !q.ok)
            return q;
        for (int k = 0; k < m; ++k)
            dl(m_controlled[k]) += x(k);
    }
    return SetupResult::fault(m_typeName + ": the measured strokes have no geometric solution "
                                           "(Newton did not converge in 30 iterations)");
}

SetupResult PlanarActuatorSetup::basicForces(const Eigen::VectorXd& d, const Eigen::VectorXd& f,
                                             Eigen::VectorXd& q) const {
    if (d.size() != 3 || f.size() != actuatorCount())
        return SetupResult::fault(m_typeName + ": 3 basic displacements and " +
                                  std::to_string(actuatorCount()) + " actuator forces wanted");
    Rows J;
    if (SetupResult r = jacobianLocal(toSetupFrame(d), J); !r.ok)
        return r;
    const Eigen::Vector3d ql = J.transpose() * f; // setup frame (S3)
    // back to the element frame: q_element = R(phi)^T q_setup
    q.resize(3);
    q << m_cphi * ql(0) + m_sphi * ql(1), -m_sphi * ql(0) + m_cphi * ql(1), ql(2);
    return SetupResult::success();
}

SetupResult PlanarActuatorSetup::actuatorRates(const Eigen::VectorXd& d, const Eigen::VectorXd& v,
                                               const Eigen::VectorXd& a, Eigen::VectorXd& sv,
                                               Eigen::VectorXd& sa) const {
    if (d.size() != 3 || v.size() != 3 || a.size() != 3)
        return SetupResult::fault(m_typeName + ": 3 basic displacements, velocities and "
                                               "accelerations (u, v, theta) wanted");
    const Eigen::Vector3d dl = toSetupFrame(d), vl = toSetupFrame(v), al = toSetupFrame(a);
    const int m = actuatorCount();
    sv.resize(m);
    sa.resize(m);
    if (m_geometry == SetupGeometry::Linear) {
        sv = m_J0 * vl;
        sa = m_J0 * al;
        return SetupResult::success();
    }
    const Pose p = pose(dl);
    for (int i = 0; i < m; ++i) {
        const Eigen::Vector2d at = m_actuators[i].attach;
        const Eigen::Vector2d Ra(p.c * at.x() - p.s * at.y(), p.s * at.x() + p.c * at.y());
        const Eigen::Vector2d dRa(-Ra.y(), Ra.x()); // R'(theta) a
        const Eigen::Vector2d r = Eigen::Vector2d(p.u, p.v) + Ra - m_actuators[i].base;
        const double len = r.norm();
        if (!(len > kLengthTolerance * m_La[i]))
            return SetupResult::fault(m_typeName + ": actuator " + std::to_string(i + 1) +
                                      " has zero length at the commanded motion");
        const Eigen::Vector2d n = r / len;
        const Eigen::Vector2d rd = vl.head<2>() + dRa * vl(2);
        const Eigen::Vector2d rdd = al.head<2>() + dRa * al(2) - Ra * (vl(2) * vl(2));
        const double nrd = n.dot(rd);
        sv(i) = nrd;
        sa(i) = n.dot(rdd) + (rd.squaredNorm() - nrd * nrd) / len;
    }
    return SetupResult::success();
}

} // namespace hsmu
