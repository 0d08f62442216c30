#include "core/experimental/setup/NoTransformation.h"

#include <algorithm>

namespace hsmu {

NoTransformation::NoTransformation(std::string typeName, std::vector<int> dofs, int sizeTrial)
    : m_typeName(std::move(typeName)), m_dofs(std::move(dofs)), m_sizeTrial(sizeTrial) {}

std::unique_ptr<NoTransformation> NoTransformation::create(std::vector<int> dirs, int sizeTrial,
                                                           std::string& error) {
    return build("NoTransformation", std::move(dirs), sizeTrial, error);
}

std::unique_ptr<NoTransformation> NoTransformation::build(const std::string& type,
                                                          std::vector<int> dirs, int sizeTrial,
                                                          std::string& error) {
    if (sizeTrial < 1) {
        error = type + ": sizeTrial = " + std::to_string(sizeTrial) + " must be at least 1";
        return nullptr;
    }
    if (dirs.empty()) {
        error = type + ": dir: at least one direction wanted";
        return nullptr;
    }
    std::vector<int> dofs;
    for (int dir : dirs) {
        if (dir < 1 || dir > sizeTrial) {
            error = type + ": dir " + std::to_string(dir) + " outside 1.." +
                    std::to_string(sizeTrial) + " (sizeTrial)";
            return nullptr;
        }
        if (std::find(dofs.begin(), dofs.end(), dir - 1) != dofs.end()) {
            error = type + ": dir " + std::to_string(dir) +
                    " given twice (two actuators on one basic DOF: singular)";
            return nullptr;
        }
        dofs.push_back(dir - 1);
    }
    error.clear();
    return std::unique_ptr<NoTransformation>(
        new NoTransformation(type, std::move(dofs), sizeTrial));
}

SetupResult NoTransformation::strokes(const Eigen::VectorXd& d, Eigen::VectorXd& s) const {
    if (d.size() != m_sizeTrial)
        return SetupResult::fault(m_typeName + ": " + std::to_string(m_sizeTrial) +
                                  " basic displacements wanted, got " + std::to_string(d.size()));
    s.resize(actuatorCount());
    for (int k = 0; k < actuatorCount(); ++k)
        s(k) = d(m_dofs[k]);
    return SetupResult::success();
}

SetupResult NoTransformation::jacobian(const Eigen::VectorXd& d, Eigen::MatrixXd& J) const {
    if (d.size() != m_sizeTrial)
        return SetupResult::fault(m_typeName + ": " + std::to_string(m_sizeTrial) +
                                  " basic displacements wanted, got " + std::to_string(d.size()));
    J.setZero(actuatorCount(), m_sizeTrial);
    for (int k = 0; k < actuatorCount(); ++k)
        J(k, m_dofs[k]) = 1.0;
    return SetupResult::success();
}

SetupResult NoTransformation::basicDisplacements(const Eigen::VectorXd& s,
                                                 const Eigen::VectorXd& given,
                                                 Eigen::VectorXd& d) const {
    if (s.size() != actuatorCount() || given.size() != m_sizeTrial)
        return SetupResult::fault(m_typeName + ": " + std::to_string(actuatorCount()) +
                                  " strokes and " + std::to_string(m_sizeTrial) +
                                  " given basic displacements wanted");
    d = given;
    for (int k = 0; k < actuatorCount(); ++k)
        d(m_dofs[k]) = s(k);
    return SetupResult::success();
}

} // namespace hsmu
