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

} // namespace hsmu
