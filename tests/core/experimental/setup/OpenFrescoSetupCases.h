#pragma once
// The cases of test_experimental_setups_openfresco (TestSetupsOpenFresco.cpp): each OpenFresco
// `expSetup` line with the HSMU setup built from the same numbers, the actuator materials, and
// where OpenFresco departs from exact geometry the departure as the issue describes it
// (docs/setups.md, "Differences from OpenFresco"), predicted from HSMU's exact basic forces.

#include "SetupCatalog.h"

#include <QString>
#include <QStringList>
#include <QtTest>

#include <array>
#include <cmath>
#include <functional>
#include <numbers>

namespace ofcases {

using namespace hsmu;

struct Case {
    QString label;
    QString tcl; ///< expSetup line(s); setup 1 on control 1
    std::function<std::unique_ptr<ExperimentalSetup>(std::string&)> make;
    std::vector<double> k; ///< elastic actuator stiffnesses [N/m]; empty: Steel01 actuators
    bool withV = true;     ///< the history moves v (TwoActuators2d: no, OpenFresco ignores v)
    /// OpenFresco's basic force predicted from HSMU's exact one (departures); null: equal.
    std::function<Eigen::Vector3d(const Eigen::Vector3d& q, const Eigen::VectorXd& s,
                                  const Eigen::VectorXd& f, const Eigen::Vector3d& d)>
        departure;
    /// basic DOFs no actuator drives: OpenFresco reports 0 for their measured displacement,
    /// HSMU the given (trial) one
    std::vector<int> undriven = {};
};

// OpenFresco's twoNodeLink adds its own correction kInit (trial - measured) to the setup's
// basic forces (element, not setup; kInit as OpenFrescoSetupRun.h's -initStif).
constexpr double kInit = 1e6;

inline std::vector<std::array<double, 3>> history(bool withV) {
    std::vector<std::array<double, 3>> h;
    const int n = 24;
    for (int k = 1; k <= n; ++k) {
        const double t = double(k) / n;
        h.push_back({0.08 * std::sin(2 * std::numbers::pi * 1.3 * t),
                     withV ? 0.03 * std::sin(2 * std::numbers::pi * 0.7 * t + 0.4) : 0.0,
                     0.3 * std::sin(2 * std::numbers::pi * t + 0.2)});
    }
    return h;
}

// TwoActuators2d -nlGeom with the actuators left: OpenFresco's moment takes the vertical force
// component of actuator 2 with the wrong sign (a term f2 n_y L sin(theta), third order), and
// both sides report no v force where actuator 2's vertical component f2 n_y acts.
inline Eigen::Vector3d twoLeftDeparture(const Eigen::Vector3d& q, const Eigen::VectorXd& s,
                                        const Eigen::VectorXd& f, const Eigen::Vector3d& d,
                                        double La2, double L, bool left) {
    const double th = d(2);
    const double rx = d(0) - L * std::sin(th) + (left ? La2 : -La2);
    const double ry = L * std::cos(th) - L;
    (void)s;
    const double ny = ry / std::hypot(rx, ry);
    Eigen::Vector3d of = q;
    of(1) = 0.0;
    if (left)
        of(2) = q(2) + 2.0 * f(1) * ny * L * std::sin(th);
    return of;
}

// ThreeActuators2d -nlGeom -posAct1 right: OpenFresco takes La2 where La3 belongs in the
// horizontal actuator's vertical force component: fy1 off by f1 (La3 - La2) / length1, which
// enters q_v and, with arm L2 cos(theta), q_theta.
inline Eigen::Vector3d threeRightDeparture(const Eigen::Vector3d& q, const Eigen::VectorXd& s,
                                           const Eigen::VectorXd& f, const Eigen::Vector3d& d) {
    const auto p = setupcatalog::three(SetupGeometry::Exact, true);
    const double dfy = f(0) * (p.La3 - p.La2) / (p.La1 + s(0));
    return {q(0), q(1) + dfy, q(2) + dfy * p.L2 * std::cos(d(2))};
}

// Exact statics from positions: q = sum f_i (n_i, (R a_i) x n_i), n_i the unit vector from
// base to the deformed attachment (docs/setups.md, eq. S3 written as forces and moments).
inline Eigen::Vector3d statics(const PlanarActuatorSetup& setup, const Eigen::Vector3d& d,
                               const Eigen::VectorXd& f) {
    Eigen::Vector3d q = Eigen::Vector3d::Zero();
    const double c = std::cos(d(2)), sn = std::sin(d(2));
    for (int i = 0; i < setup.actuatorCount(); ++i) {
        const PlanarActuator& a = setup.actuators()[i];
        const Eigen::Vector2d ra(c * a.attach.x() - sn * a.attach.y(),
                                 sn * a.attach.x() + c * a.attach.y());
        const Eigen::Vector2d n = (Eigen::Vector2d(d(0), d(1)) + ra - a.base).normalized();
        q += f(i) * Eigen::Vector3d(n.x(), n.y(), ra.x() * n.y() - ra.y() * n.x());
    }
    return q;
}

inline std::vector<Case> cases() {
    using G = SetupGeometry;
    std::vector<Case> out;
    const QStringList side = {"left", "right"};
    for (G g : {G::Linear, G::Exact}) {
        const QString nl = g == G::Exact ? " -nlGeom" : "";
        for (bool right : {false, true}) {
            const auto two = setupcatalog::two(g, right);
            Case c2{QString("TwoActuators2d%1 %2").arg(nl, side[right]),
                    QString("expSetup TwoActuators2d 1 -control 1 %1 %2 %3%4 -posAct %5")
                        .arg(two.La1)
                        .arg(two.La2)
                        .arg(two.L)
                        .arg(nl, side[right]),
                    [=](std::string& e) {
                        return std::unique_ptr<ExperimentalSetup>(makeTwoActuators2d(two, e));
                    },
                    {2.0e7, 3.0e7},
                    false,
                    nullptr,
                    {1}};
            if (g == G::Exact)
                c2.departure = [=](const Eigen::Vector3d& q, const Eigen::VectorXd& s,
                                   const Eigen::VectorXd& f, const Eigen::Vector3d& d) {
                    return twoLeftDeparture(q, s, f, d, two.La2, two.L, !right);
                };
            out.push_back(c2);
            const auto three = setupcatalog::three(g, right);
            Case c3{QString("ThreeActuators2d%1 %2").arg(nl, side[right]),
                    QString("expSetup ThreeActuators2d 1 -control 1 %1 %2 %3 %4 %5%6 -posAct1 %7")
                        .arg(three.La1)
                        .arg(three.La2)
                        .arg(three.La3)
                        .arg(three.L1)
                        .arg(three.L2)
                        .arg(nl, side[right]),
                    [=](std::string& e) {
                        return std::unique_ptr<ExperimentalSetup>(makeThreeActuators2d(three, e));
                    },
                    {2.0e7, 3.0e7, 2.5e7},
                    true,
                    nullptr};
            if (g == G::Exact && right)
                c3.departure = threeRightDeparture;
            out.push_back(c3);
            const auto jo = setupcatalog::jntOff(g, right);
            out.push_back(
                {QString("ThreeActuatorsJntOff2d%1 %2").arg(nl, side[right]),
                 QString("expSetup ThreeActuatorsJntOff2d 1 -control 1 %1 %2 %3 %4 %5 %6 %7 %8 "
                         "%9%10 -posAct1 %11")
                     .arg(jo.La1)
                     .arg(jo.La2)
                     .arg(jo.La3)
                     .arg(jo.L1)
                     .arg(jo.L2)
                     .arg(jo.L3)
                     .arg(jo.L4)
                     .arg(jo.L5)
                     .arg(jo.L6)
                     .arg(nl, side[right]),
                 [=](std::string& e) {
                     return std::unique_ptr<ExperimentalSetup>(makeThreeActuatorsJntOff2d(jo, e));
                 },
                 {2.0e7, 3.0e7, 2.5e7},
                 true,
                 nullptr});
        }
        const auto rot = setupcatalog::three(g, false, -20.0);
        out.push_back({QString("ThreeActuators2d%1 -phiLocX -20").arg(nl),
                       QString("expSetup ThreeActuators2d 1 -control 1 %1 %2 %3 %4 %5%6 "
                               "-phiLocX -20")
                           .arg(rot.La1)
                           .arg(rot.La2)
                           .arg(rot.La3)
                           .arg(rot.L1)
                           .arg(rot.L2)
                           .arg(nl),
                       [=](std::string& e) {
                           return std::unique_ptr<ExperimentalSetup>(makeThreeActuators2d(rot, e));
                       },
                       {},
                       true,
                       nullptr}); // Steel01 actuators
    }
    out.push_back({"OneActuator dir 2 of 3",
                   "expSetup OneActuator 1 -control 1 2 -sizeTrialOut 3 3",
                   [](std::string& e) {
                       return std::unique_ptr<ExperimentalSetup>(OneActuator::create(2, 3, e));
                   },
                   {4.0e7},
                   true,
                   nullptr,
                   {0, 2}});
    out.push_back(
        {"NoTransformation dirs 3 1 of 3",
         "expSetup NoTransformation 1 -control 1 -dir 3 1 -sizeTrialOut 3 3",
         [](std::string& e) {
             return std::unique_ptr<ExperimentalSetup>(NoTransformation::create({3, 1}, 3, e));
         },
         {4.0e7, 5.0e6},
         true,
         nullptr,
         {1}});
    out.push_back({"Aggregator (OneActuator 1 of 1, NoTransformation 2 1 of 2)",
                   "expSetup OneActuator 11 1 -sizeTrialOut 1 1\n"
                   "expSetup NoTransformation 12 -dir 2 1 -sizeTrialOut 2 2\n"
                   "expSetup Aggregator 1 -control 1 -setup 11 12 -sizeTrialOut 3 3",
                   [](std::string& e) -> std::unique_ptr<ExperimentalSetup> {
                       std::vector<std::unique_ptr<ExperimentalSetup>> parts;
                       parts.push_back(OneActuator::create(1, 1, e));
                       parts.push_back(NoTransformation::create({2, 1}, 2, e));
                       return Aggregator::create(std::move(parts), e);
                   },
                   {4.0e7, 5.0e6, 3.0e6},
                   true,
                   nullptr});
    return out;
}

} // namespace ofcases
