#include "core/experimental/setup/ExperimentalSetup.h"

namespace hsmu {

SetupResult ExperimentalSetup::basicForces(const Eigen::VectorXd& d, const Eigen::VectorXd& f,
                                           Eigen::VectorXd& q) const {
    if (d.size() != basicSize() || f.size() != actuatorCount())
        return SetupResult::fault(typeName() + ": basicForces wants " +
                                  std::to_string(basicSize()) + " basic displacements and " +
                                  std::to_string(actuatorCount()) + " actuator forces, got " +
                                  std::to_string(d.size()) + " and " + std::to_string(f.size()));
    Eigen::MatrixXd J;
    if (SetupResult r = jacobian(d, J); !r.ok)
        return r;
    q.noalias() = J.transpose() * f;
    return SetupResult::success();
}

SetupResult ExperimentalSetup::actuatorRates(const Eigen::VectorXd& d, const Eigen::VectorXd& v,
                                             const Eigen::VectorXd& a, Eigen::VectorXd& sv,
                                             Eigen::VectorXd& sa) const {
    const int n = basicSize();
    if (d.size() != n || v.size() != n || a.size() != n)
        return SetupResult::fault(typeName() + ": actuatorRates wants " + std::to_string(n) +
                                  " basic displacements, velocities and accelerations, got " +
                                  std::to_string(d.size()) + ", " + std::to_string(v.size()) +
                                  " and " + std::to_string(a.size()));
    Eigen::MatrixXd J;
    if (SetupResult r = jacobian(d, J); !r.ok)
        return r;
    sv.noalias() = J * v;
    sa.noalias() = J * a;
    const double vmax = v.cwiseAbs().maxCoeff();
    if (vmax == 0.0)
        return SetupResult::success();
    // Jdot v by a central difference of J along v (eq. S5)
    const double h = 1e-5 / vmax;
    Eigen::MatrixXd Jp, Jm;
    if (SetupResult r = jacobian(d + h * v, Jp); !r.ok)
        return r;
    if (SetupResult r = jacobian(d - h * v, Jm); !r.ok)
        return r;
    sa.noalias() += (Jp - Jm) * v / (2.0 * h);
    return SetupResult::success();
}

} // namespace hsmu
