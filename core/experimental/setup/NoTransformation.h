#pragma once
// NoTransformation and OneActuator: actuators that each follow one basic DOF as it is
// (docs/setups.md, "Direct setups").
//   `expSetup NoTransformation $tag -dir $dirs -sizeTrialOut $t $o`
//   `expSetup OneActuator $tag $dir -sizeTrialOut $t $o`
// dirs are OpenFresco's 1-based basic DOF numbers; actuator k's stroke is d(dirs[k] - 1), its
// force is basic force q(dirs[k] - 1); the other basic DOFs carry no actuator (zero force, and
// their displacements are the given ones when measured). Linear by nature: geometry does not
// enter. Units: whatever the basic DOFs are in ([m] or [rad]; [N] or [N m]).

#include "core/experimental/setup/ExperimentalSetup.h"

#include <memory>
#include <vector>

namespace hsmu {

class NoTransformation : public ExperimentalSetup {
public:
    /// nullptr with error naming the setup and parameter when sizeTrial < 1, a dir is outside
    /// 1..sizeTrial, or a dir repeats (two actuators on one DOF: singular).
    static std::unique_ptr<NoTransformation> create(std::vector<int> dirs, int sizeTrial,
                                                    std::string& error);

    std::string typeName() const override { return m_typeName; }
    int basicSize() const override { return m_sizeTrial; }
    int actuatorCount() const override { return static_cast<int>(m_dofs.size()); }
    /// The basic DOF each actuator follows (0-based).
    const std::vector<int>& dofs() const { return m_dofs; }
    SetupResult strokes(const Eigen::VectorXd& d, Eigen::VectorXd& s) const override;
    SetupResult jacobian(const Eigen::VectorXd& d, Eigen::MatrixXd& J) const override;
    SetupResult basicDisplacements(const Eigen::VectorXd& s, const Eigen::VectorXd& given,
                                   Eigen::VectorXd& d) const override;

protected:
    NoTransformation(std::string typeName, std::vector<int> dofs, int sizeTrial);
    static std::unique_ptr<NoTransformation>
    build(const std::string& typeName, std::vector<int> dirs, int sizeTrial, std::string& error);

private:
    std::string m_typeName;
    std::vector<int> m_dofs; // 0-based
    int m_sizeTrial;
};

class OneActuator : public NoTransformation {
public:
    static std::unique_ptr<NoTransformation> create(int dir, int sizeTrial, std::string& error) {
        return build("OneActuator", {dir}, sizeTrial, error);
    }
};

} // namespace hsmu
