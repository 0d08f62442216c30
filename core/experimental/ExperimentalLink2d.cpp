#include "core/experimental/ExperimentalLink2d.h"

#include <stdexcept>

namespace hsmu {

const char* actuatorModeName(ActuatorMode m)
{
    return m == ActuatorMode::Force ? "force control" : "displacement control";
}

namespace {
std::vector<DofTerm> primaryTerms(const std::string& name, const Link2dGeometry& g, int primary)
{
    if (primary < 0 || primary > 2)
        throw std::invalid_argument("element '" + name + "': primary basic DOF must be 0, 1 or 2");
    return Link2dKinematics(name, g).terms(primary);
}

// The control, once the setup, the channels and the control agree (argument of the base's
// constructor: it must not be moved from before it is checked).
std::unique_ptr<ExperimentalControl> checkedControl(const std::string& name,
                                                    const ExperimentalSetup* setup,
                                                    std::size_t channels,
                                                    std::unique_ptr<ExperimentalControl> control)
{
    const std::string who = "element '" + name + "': ";
    if (!setup || !control)
        throw std::invalid_argument(who + "needs a setup and a control");
    if (setup->basicSize() != 3)
        throw std::invalid_argument(who + "setup " + setup->typeName() + " serves " +
                                    std::to_string(setup->basicSize()) +
                                    " basic DOFs, the element has 3 (axial, shear, rotation)");
    if (int(channels) != setup->actuatorCount())
        throw std::invalid_argument(who + "setup " + setup->typeName() + " has " +
                                    std::to_string(setup->actuatorCount()) + " actuators, " +
                                    std::to_string(channels) + " channels configured");
    if (control->channelCount() != setup->actuatorCount())
        throw std::invalid_argument(who + "setup " + setup->typeName() + " has " +
                                    std::to_string(setup->actuatorCount()) +
                                    " actuators, the control " + control->description() + " " +
                                    std::to_string(control->channelCount()) + " channels");
    return control;
}
} // namespace

ExperimentalLink2d::ExperimentalLink2d(std::string name, const Link2dGeometry& geometry,
                                       std::unique_ptr<ExperimentalSetup> setup,
                                       std::vector<ActuatorChannelSpec> channels,
                                       std::unique_ptr<ExperimentalControl> control, int primary)
    : ExperimentalElement(name, "experimentalLink2d", primaryTerms(name, geometry, primary),
                          checkedControl(name, setup.get(), channels.size(), std::move(control)),
                          SafetyLimits{}, 0.0),
      m_kin(name, geometry), m_setup(std::move(setup)), m_channels(std::move(channels)),
      m_primary(primary)
{
    const int m = m_setup->actuatorCount();
    Eigen::MatrixXd j0;
    if (SetupResult r = m_setup->jacobian(Eigen::VectorXd::Zero(3), j0); !r.ok)
        throw std::invalid_argument("element '" + name + "': " + r.reason);
    Eigen::VectorXd k = Eigen::VectorXd::Zero(m);
    for (int i = 0; i < m; ++i)
        if (m_channels[i].mode == ActuatorMode::Displacement)
            k[i] = m_channels[i].initialStiffness;
    m_kb0 = j0.transpose() * k.asDiagonal() * j0;
    // the basic forces at rest: the force channels' loads at t = 0 (eq. S3 at d = 0)
    Eigen::VectorXd f0 = Eigen::VectorXd::Zero(m);
    for (int i = 0; i < m; ++i)
        if (m_channels[i].mode == ActuatorMode::Force)
            f0[i] = commandedForce(m_channels[i], 0.0);
    m_q0 = j0.transpose() * f0;
    m_cmd = m_sMeas = m_fMeas = m_lastStroke = m_cSMeas = m_cFMeas = Eigen::VectorXd::Zero(m);
    m_dMeas = m_q = m_cDMeas = m_cQ = Eigen::VectorXd::Zero(3);
}

std::optional<std::string> ExperimentalLink2d::commandsFor(const Eigen::Vector3d& d,
                                                           Eigen::VectorXd& cmd) const
{
    Eigen::VectorXd s;
    if (SetupResult r = m_setup->strokes(d, s); !r.ok)
        return name() + ": " + r.reason;
    cmd.resize(s.size());
    for (int i = 0; i < s.size(); ++i) {
        const ActuatorChannelSpec& c = m_channels[i];
        std::optional<std::string> why;
        if (c.mode == ActuatorMode::Displacement) {
            cmd[i] = s[i];
            why = c.limits.violationOfTarget(s[i], m_lastStroke[i]);
        } else {
            cmd[i] = commandedForce(c, m_targetTime); // constant or scheduled
            why = c.limits.violationOfForce(cmd[i]);
        }
        if (why)
            return name() + ": actuator '" + c.name + "': " + *why;
    }
    return std::nullopt;
}

std::optional<std::string> ExperimentalLink2d::chordFault(const Eigen::VectorXd& uFull) const
{
    if (const std::string why = m_kin.chordFault(m_kin.local(uFull)); !why.empty())
        return name() + ": " + why;
    return std::nullopt;
}

std::optional<std::string> ExperimentalLink2d::targetViolation(const Eigen::VectorXd& uFull) const
{
    if (auto why = chordFault(uFull))
        return why;
    Eigen::VectorXd cmd;
    return commandsFor(m_kin.basic(uFull), cmd);
}

ElementStatus ExperimentalLink2d::sendTrial(const Eigen::VectorXd& uFull)
{
    m_linkSent = false;
    if (auto why = chordFault(uFull))
        return ElementStatus::limitReached(*why);
    const Eigen::Vector3d d = m_kin.basic(uFull); // eq. L1 or L3
    Eigen::VectorXd cmd;
    if (auto why = commandsFor(d, cmd)) // defence in depth: the test checked already
        return ElementStatus::limitReached(*why);
    markSent();
    if (ControlResult r = control().setTargets(cmd); !r.ok)
        return fault(r);
    m_dTrial = d;
    m_ue = m_kin.local(uFull);
    m_cmd = cmd;
    m_linkSent = true;
    return ElementStatus::success();
}

ElementStatus ExperimentalLink2d::setTrial(const Eigen::VectorXd& uFull)
{
    if (!m_linkSent)
        if (ElementStatus s = sendTrial(uFull); !s.ok)
            return s;
    m_linkSent = false;
    if (ControlResult r = control().measureChannels(m_sMeas, m_fMeas); !r.ok)
        return fault(r);
    markMeasured();
    if (m_sMeas.size() != m_cmd.size() || m_fMeas.size() != m_cmd.size())
        return fault(ControlResult::fault("measured " + std::to_string(m_sMeas.size()) +
                                          " channels, commanded " +
                                          std::to_string(m_cmd.size())));
    for (int i = 0; i < m_cmd.size(); ++i) {
        const ActuatorChannelSpec& c = m_channels[i];
        auto why = c.limits.violationOfMeasuredDeformation(m_sMeas[i]);
        if (!why)
            why = c.limits.violationOfForce(m_fMeas[i]);
        if (why)
            return ElementStatus::limitReached(name() + ": actuator '" + c.name + "': " + *why);
    }
    const Eigen::VectorXd given = m_dTrial;
    if (SetupResult r = m_setup->basicDisplacements(m_sMeas, given, m_dMeas); !r.ok)
        return ElementStatus::failure(name() + ": " + r.reason);
    if (SetupResult r = m_setup->basicForces(m_dMeas, m_fMeas, m_q); !r.ok)
        return ElementStatus::failure(name() + ": " + r.reason);
    setReported(m_dTrial[m_primary], {m_dMeas[m_primary], m_q[m_primary]});
    return ElementStatus::success();
}

ElementStatus ExperimentalLink2d::commit()
{
    if (ElementStatus s = ExperimentalElement::commit(); !s.ok)
        return s;
    for (int i = 0; i < m_cmd.size(); ++i)
        if (m_channels[i].mode == ActuatorMode::Displacement)
            m_lastStroke[i] = m_cmd[i];
    m_cSMeas = m_sMeas;
    m_cFMeas = m_fMeas;
    m_cDMeas = m_dMeas;
    m_cQ = m_q;
    m_cUe = m_ue;
    return ElementStatus::success();
}

void ExperimentalLink2d::revert()
{
    ExperimentalElement::revert();
    m_linkSent = false;
    m_sMeas = m_cSMeas;
    m_fMeas = m_cFMeas;
    m_dMeas = m_cDMeas;
    m_q = m_cQ;
    m_ue = m_cUe;
}

void ExperimentalLink2d::addNodalForces(Eigen::VectorXd& rFull) const
{
    m_kin.addNodalForces(m_ue, Eigen::Vector3d(m_q[0], m_q[1], m_q[2]), rFull); // L2 or L4
}

void ExperimentalLink2d::addInitialStiffness(std::vector<Eigen::Triplet<double>>& k,
                                             const std::vector<int>& freeOf) const
{
    if (!m_kin.corotational()) {
        m_kin.addStiffness(m_kb0, k, freeOf);
        return;
    }
    m_kin.addMatrix(m_kin.tangent(Link2dVector6::Zero(), m_kb0, m_q0), k, freeOf); // eq. L5
}

} // namespace hsmu
