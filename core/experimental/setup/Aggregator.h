#pragma once
// Aggregator: several setups side by side as one (docs/setups.md, "Aggregator").
//   `expSetup Aggregator $tag -setup $tag1 $tag2 ... -sizeTrialOut $t $o`
// The basic displacements are the sub-setups' in order (the first basicSize() of setup 1, then
// setup 2's, ...), the actuators likewise; the Jacobian is block diagonal, so each part keeps
// its own units and conventions.

#include "core/experimental/setup/ExperimentalSetup.h"

#include <memory>
#include <vector>

namespace hsmu {

class Aggregator : public ExperimentalSetup {
public:
    /// nullptr with error when parts is empty or holds a null setup.
    static std::unique_ptr<Aggregator> create(std::vector<std::unique_ptr<ExperimentalSetup>> parts,
                                              std::string& error);

    std::string typeName() const override { return "Aggregator"; }
    int basicSize() const override { return m_basic; }
    int actuatorCount() const override { return m_actuators; }
    const ExperimentalSetup& part(int k) const { return *m_parts[k]; }
    int partCount() const { return static_cast<int>(m_parts.size()); }

    SetupResult strokes(const Eigen::VectorXd& d, Eigen::VectorXd& s) const override;
    SetupResult jacobian(const Eigen::VectorXd& d, Eigen::MatrixXd& J) const override;
    SetupResult basicDisplacements(const Eigen::VectorXd& s, const Eigen::VectorXd& given,
                                   Eigen::VectorXd& d) const override;

private:
    explicit Aggregator(std::vector<std::unique_ptr<ExperimentalSetup>> parts);
    SetupResult sizes(Eigen::Index basic, Eigen::Index actuators) const;

    std::vector<std::unique_ptr<ExperimentalSetup>> m_parts;
    int m_basic = 0, m_actuators = 0;
};

} // namespace hsmu
