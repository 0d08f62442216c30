#include "core/experimental/setup/FourActuators3d.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace hsmu {

namespace {

Eigen::Matrix3d skew(const Eigen::Vector3d& w) {
    Eigen::Matrix3d K;
    K << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
    return K;
}

// sin(t)/t, (1 - cos t)/t^2, (t - sin t)/t^3 with their series near 0
void rotationCoefficients(double t, double& a, double& b, double& c) {
    if (t < 1e-4) {
        const double t2 = t * t;
        a = 1.0 - t2 / 6.0;
        b = 0.5 - t2 / 24.0;
        c = 1.0 / 6.0 - t2 / 120.0;
        return;
    }
    a = std::sin(t) / t;
    b = (1.0 - std::cos(t)) / (t * t);
    c = (t - std::sin(t)) / (t * t * t);
}

Eigen::Matrix3d rotation(const Eigen::Vector3d& w) {
    double a, b, c;
    rotationCoefficients(w.norm(), a, b, c);
    const Eigen::Matrix3d K = skew(w);
    return Eigen::Matrix3d::Identity() + a * K + b * K * K;
}

Eigen::Matrix3d rightJacobian(const Eigen::Vector3d& w) {
    double a, b, c;
    rotationCoefficients(w.norm(), a, b, c);
    const Eigen::Matrix3d K = skew(w);
    return Eigen::Matrix3d::Identity() - b * K + c * K * K;
}

constexpr double kRankTolerance = 1e-9;

SetupResult sixBasic(const Eigen::VectorXd& d) {
    if (d.size() != 6)
        return SetupResult::fault("FourActuators3d: 6 basic displacements wanted, got " +
                                  std::to_string(d.size()));
    return SetupResult::success();
}

} // namespace

FourActuators3d::FourActuators3d(const FourActuators3dParams& p) : m_p(p) {
    m_attach = {Eigen::Vector3d(-p.a1, 0, 0), Eigen::Vector3d(0, -p.a2, 0),
                Eigen::Vector3d(-p.a3, 0, p.h), Eigen::Vector3d(0, -p.a4, p.h)};
    m_base = {Eigen::Vector3d(-p.a1 - p.L1, 0, 0), Eigen::Vector3d(0, -p.a2 - p.L2, 0),
              Eigen::Vector3d(-p.a3 - p.L3, 0, p.h), Eigen::Vector3d(0, -p.a4 - p.L4, p.h)};
    m_La = {p.L1, p.L2, p.L3, p.L4};
    const double phi = p.phiLocX * std::numbers::pi / 180.0;
    const double c = std::cos(phi), s = std::sin(phi);
    // D = (-d1, -d3, -d4, -d2), then each pair turned by [[c, s], [-s, c]]
    Mat4x6 select = Mat4x6::Zero();
    select(0, 1) = -1.0;
    select(1, 3) = -1.0;
    select(2, 4) = -1.0;
    select(3, 2) = -1.0;
    Eigen::Matrix4d turn = Eigen::Matrix4d::Zero();
    turn.block<2, 2>(0, 0) << c, s, -s, c;
    turn.block<2, 2>(2, 2) << c, s, -s, c;
    m_T = turn * select;
    // rods: (ux, uy) and (phix, phiy) as the actuators', uz = d(0) (the axial DOF)
    m_T5.setZero();
    m_T5.row(0) = m_T.row(0);
    m_T5.row(1) = m_T.row(1);
    m_T5(2, 0) = 1.0;
    m_T5.row(3) = m_T.row(2);
    m_T5.row(4) = m_T.row(3);
}

std::unique_ptr<FourActuators3d> FourActuators3d::create(const FourActuators3dParams& p,
                                                         std::string& error) {
    const std::string type = "FourActuators3d";
    const std::pair<const char*, double> lengths[] = {{"L1", p.L1},       {"L2", p.L2},
                                                      {"L3", p.L3},       {"L4", p.L4},
                                                      {"LrodN", p.LrodN}, {"LrodS", p.LrodS}};
    for (const auto& [name, v] : lengths)
        if (!(std::isfinite(v) && v > 0.0)) {
            std::ostringstream os;
            os << type << ": " << name << " = " << v << " must be a positive finite length ("
               << (name[1] == 'r' ? "an axial-load rod's pin-to-pin length"
                                  : "an actuator's length at rest")
               << ")";
            error = os.str();
            return nullptr;
        }
    const std::pair<const char*, double> others[] = {
        {"a1", p.a1},     {"a2", p.a2},       {"a3", p.a3},          {"a4", p.a4},
        {"h", p.h},       {"h1", p.h1},       {"h2", p.h2},          {"arlN", p.arlN},
        {"arlS", p.arlS}, {"Hbeam", p.Hbeam}, {"phiLocX", p.phiLocX}};
    for (const auto& [name, v] : others)
        if (!std::isfinite(v)) {
            error = type + ": " + name + " must be finite";
            return nullptr;
        }
    if (p.h == 0.0) {
        error = type + ": h = 0 puts both actuator levels at one height (the x actuators and the "
                       "y actuators each parallel and coincident): the rotations cannot be "
                       "controlled";
        return nullptr;
    }
    std::unique_ptr<FourActuators3d> setup(new FourActuators3d(p));
    Eigen::Matrix4d J0;
    setup->jacobianInternal(Eigen::Vector4d::Zero(), J0);
    if (std::abs(J0.colwise().normalized().determinant()) <= kRankTolerance) {
        error = type + ": a1..a4, h: the actuators cannot fix ux, uy, phix, phiy (singular)";
        return nullptr;
    }
    error.clear();
    return setup;
}

bool FourActuators3d::strokesInternal(const Eigen::Vector4d& x, Eigen::Vector4d& s) const {
    const Eigen::Vector3d u(x(0), x(1), 0.0);
    const Eigen::Vector3d w(x(2), x(3), 0.0);
    if (m_p.geometry == SetupGeometry::Linear) {
        for (int i = 0; i < 4; ++i) {
            const Eigen::Vector3d e = (m_attach[i] - m_base[i]) / m_La[i];
            s(i) = e.dot(u + w.cross(m_attach[i]));
        }
        return true;
    }
    const Eigen::Matrix3d R = rotation(w);
    bool ok = true;
    for (int i = 0; i < 4; ++i) {
        const double len = (u + R * m_attach[i] - m_base[i]).norm();
        s(i) = len - m_La[i];
        ok = ok && len > 1e-9 * m_La[i];
    }
    return ok;
}

bool FourActuators3d::jacobianInternal(const Eigen::Vector4d& x, Eigen::Matrix4d& J) const {
    const bool exact = m_p.geometry == SetupGeometry::Exact;
    const Eigen::Vector3d u(x(0), x(1), 0.0);
    const Eigen::Vector3d w = exact ? Eigen::Vector3d(x(2), x(3), 0.0) : Eigen::Vector3d::Zero();
    const Eigen::Matrix3d R = rotation(w);
    const Eigen::Matrix3d Jr = rightJacobian(w);
    for (int i = 0; i < 4; ++i) {
        Eigen::Vector3d r = m_attach[i] - m_base[i];
        if (exact)
            r = u + R * m_attach[i] - m_base[i];
        const double len = r.norm();
        if (!(len > 1e-9 * m_La[i]))
            return false;
        const Eigen::Vector3d n = r / len;
        const Eigen::Matrix3d dRa = -R * skew(m_attach[i]) * Jr; // d(R a)/dw
        J(i, 0) = n.x();
        J(i, 1) = n.y();
        J(i, 2) = n.dot(dRa.col(0));
        J(i, 3) = n.dot(dRa.col(1));
    }
    return true;
}

SetupResult FourActuators3d::strokes(const Eigen::VectorXd& d, Eigen::VectorXd& s) const {
    if (SetupResult r = sixBasic(d); !r.ok)
        return r;
    Eigen::Vector4d s4;
    if (!strokesInternal(internal(d), s4))
        return SetupResult::fault(
            "FourActuators3d: an actuator would shrink to zero length at the commanded motion");
    s = s4;
    return SetupResult::success();
}

SetupResult FourActuators3d::jacobian(const Eigen::VectorXd& d, Eigen::MatrixXd& J) const {
    if (SetupResult r = sixBasic(d); !r.ok)
        return r;
    Eigen::Matrix4d Ji;
    if (!jacobianInternal(internal(d), Ji))
        return SetupResult::fault("FourActuators3d: an actuator has zero length at the motion");
    J = Ji * m_T;
    return SetupResult::success();
}

SetupResult FourActuators3d::basicDisplacements(const Eigen::VectorXd& s,
                                                const Eigen::VectorXd& given,
                                                Eigen::VectorXd& d) const {
    if (s.size() != 4 || given.size() != 6)
        return SetupResult::fault("FourActuators3d: 4 strokes and 6 given basic displacements "
                                  "wanted");
    // Newton on the internal coordinates from the given (trial) ones (docs/setups.md, S4);
    // the linear formulation converges in one step.
    Eigen::Vector4d x = internal(given), si, r;
    Eigen::Matrix4d J;
    const double maxLa = std::max(std::max(m_La[0], m_La[1]), std::max(m_La[2], m_La[3]));
    bool converged = false;
    for (int it = 0; it < 30 && !converged; ++it) {
        if (!strokesInternal(x, si))
            return SetupResult::fault(
                "FourActuators3d: an actuator reaches zero length solving the measured strokes");
        r = s - si;
        if (r.cwiseAbs().maxCoeff() <= 1e-13 * maxLa) {
            converged = true;
            break;
        }
        if (!jacobianInternal(x, J) ||
            std::abs(J.colwise().normalized().determinant()) <= kRankTolerance)
            return SetupResult::fault("FourActuators3d: measured strokes at a singular geometry");
        x += J.partialPivLu().solve(r);
    }
    if (!converged)
        return SetupResult::fault("FourActuators3d: the measured strokes have no geometric "
                                  "solution (Newton did not converge in 30 iterations)");
    // back to the basic DOFs: T's rows are orthonormal on d(1..4), d(0) and d(5) given
    d = given;
    const Eigen::Vector4d dx = x - internal(given);
    d += m_T.transpose() * dx;
    return SetupResult::success();
}

void FourActuators3d::rodInternal(const Vec5& x, Eigen::Vector2d& len,
                                  Eigen::Matrix<double, 2, 5>& G) const {
    const double h1 = m_p.h1;
    const double Lrod[2] = {m_p.LrodN, m_p.LrodS};
    if (m_p.geometry == SetupGeometry::Linear) {
        // eq. S8: l = Lrod + uz - h1 |phi|^2 / 2 + ((ux + h1 phiy)^2 + (uy - h1 phix)^2) / (2 Lrod)
        const double ex = x(0) + h1 * x(4), ey = x(1) - h1 * x(3);
        for (int k = 0; k < 2; ++k) {
            len(k) = Lrod[k] + x(2) - 0.5 * h1 * (x(3) * x(3) + x(4) * x(4)) +
                     (ex * ex + ey * ey) / (2.0 * Lrod[k]);
            G.row(k) << ex / Lrod[k], ey / Lrod[k], 1.0, -h1 * ey / Lrod[k] - h1 * x(3),
                h1 * ex / Lrod[k] - h1 * x(4);
        }
        return;
    }
    // eq. S6: l = |(ux, uy, uz) + R(phi) p - b|, p = (0, 0, h1), b = (0, 0, h1 - Lrod)
    const Eigen::Vector3d w(x(3), x(4), 0.0);
    const Eigen::Vector3d pin(0.0, 0.0, h1);
    const Eigen::Matrix3d R = rotation(w);
    const Eigen::Matrix3d dRp = -R * skew(pin) * rightJacobian(w); // d(R p)/dw
    const Eigen::Vector3d top = Eigen::Vector3d(x(0), x(1), x(2)) + R * pin;
    for (int k = 0; k < 2; ++k) {
        const Eigen::Vector3d r = top - Eigen::Vector3d(0.0, 0.0, h1 - Lrod[k]);
        len(k) = r.norm();
        const Eigen::Vector3d n = r / len(k);
        G.row(k) << n.x(), n.y(), n.z(), n.dot(dRp.col(0)), n.dot(dRp.col(1));
    }
}

SetupResult FourActuators3d::rodLengths(const Eigen::VectorXd& d, Eigen::Vector2d& lengths) const {
    if (SetupResult r = sixBasic(d); !r.ok)
        return r;
    Eigen::Matrix<double, 2, 5> G;
    rodInternal(m_T5 * d, lengths, G);
    return SetupResult::success();
}

SetupResult FourActuators3d::rodJacobian(const Eigen::VectorXd& d, Eigen::MatrixXd& Jrod) const {
    if (SetupResult r = sixBasic(d); !r.ok)
        return r;
    Eigen::Vector2d len;
    Eigen::Matrix<double, 2, 5> G;
    rodInternal(m_T5 * d, len, G);
    if (!(len.minCoeff() > 1e-9 * std::min(m_p.LrodN, m_p.LrodS)))
        return SetupResult::fault("FourActuators3d: an axial-load rod has zero length at the "
                                  "motion");
    Jrod = G * m_T5;
    return SetupResult::success();
}

SetupResult FourActuators3d::basicForces(const Eigen::VectorXd& d, const Eigen::VectorXd& f,
                                         Eigen::VectorXd& q) const {
    if (d.size() != 6 || (f.size() != 4 && f.size() != 6))
        return SetupResult::fault(
            "FourActuators3d: basicForces wants 6 basic displacements and 4 actuator forces or "
            "OpenFresco's 6 daq forces (rod N, rod S, actuators 1-4), got " +
            std::to_string(d.size()) + " and " + std::to_string(f.size()));
    Eigen::MatrixXd J;
    if (SetupResult r = jacobian(d, J); !r.ok)
        return r;
    if (f.size() == 4) {
        q.noalias() = J.transpose() * f;
        return SetupResult::success();
    }
    q.noalias() = J.transpose() * f.tail<4>();
    Eigen::MatrixXd Jrod;
    if (SetupResult r = rodJacobian(d, Jrod); !r.ok)
        return r;
    q.noalias() += Jrod.transpose() * f.head<2>(); // eq. S7
    return SetupResult::success();
}

} // namespace hsmu
