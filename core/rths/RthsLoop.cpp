#include "core/rths/RthsLoop.h"

#include "core/rths/DamperReference.h"
#include "core/rths/Rk4.h"

#include <Eigen/Dense>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace hsmu::rths {


RthsLoop::RthsLoop(const Partition& partition, const GroundMotion& groundMotion,
                   const RthsSettings& settings)
    : m_p(partition), m_ag(groundMotion), m_s(settings), m_h(1.0 / settings.rate),
      m_plant(settings.plant), m_pid(settings.pid, 1.0 / settings.rate),
      m_comp(settings.compensation, 1.0 / settings.rate), m_random(settings.sensors.seed)
{
    if (!(settings.rate > 0.0 && std::isfinite(settings.rate)))
        throw std::invalid_argument("RTHS: the loop rate must be a positive number of Hz");
    if (settings.forceDelay < 0)
        throw std::invalid_argument("RTHS: the force delay cannot be negative");
    if (const std::string why = settings.plant.validate(); !why.empty())
        throw std::invalid_argument("RTHS: " + why);
    m_mnInv = m_p.numerical.m.inverse();
    const auto n = m_p.numerical.m.rows();
    m_x = Eigen::VectorXd::Zero(n);
    m_v = Eigen::VectorXd::Zero(n);
    if (settings.damper.enabled) {
        const int d = settings.damper.twinDof;
        if (d < 0 || d >= int(n))
            throw std::invalid_argument("RTHS: the damper twin's DOF must be one of the structure's (0 to " +
                                        std::to_string(n - 1) + ")");
        if (!MrDamper::admissible(settings.damper.specimen) || !MrDamper::admissible(settings.damper.twin))
            throw std::invalid_argument("RTHS: the damper's or its twin's mrDamper parameters are not admissible");
        m_damper.emplace(settings.damper.specimen);
        m_damper->setTimeIncrement(m_h);
        m_twin.emplace(settings.damper, m_h);
    }
    m_plant.reset(0.0);
    m_pid.reset(0.0);
    m_comp.reset(0.0);
}

double RthsLoop::quantize(double v) const
{
    const double q = m_s.sensors.quantum;
    return q > 0.0 ? q * std::round(v / q) : v;
}

double RthsLoop::sense(double value, double rms)
{
    return m_s.sensors.noise && rms > 0.0 ? value + rms * m_random.normal() : value;
}

Eigen::VectorXd RthsLoop::accelerationOf(const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                                         double ag, double fe) const
{
    const auto& n = m_p.numerical;
    Eigen::VectorXd load = -(m_p.reference.m * m_p.reference.iota) * ag - n.c * v - n.k * x;
    load(m_p.specimen.dof) -= fe;
    if (m_twin) { // the twin's storey force, held over the tick
        const int d = m_s.damper.twinDof;
        load(d) -= m_twinForce;
        if (d > 0)
            load(d - 1) += m_twinForce;
    }
    return m_mnInv * load;
}

std::string plantLimitBreach(const ServoHydraulicPlant& plant, const ActuatorLimits& l)
{
    std::ostringstream o;
    o.precision(4);
    if (std::abs(plant.displacement()) > l.stroke)
        o << "actuator displacement " << plant.displacement() * 1000.0
          << " mm beyond the stroke limit +-" << l.stroke * 1000.0 << " mm";
    else if (std::abs(plant.force()) > l.force)
        o << "actuator force " << plant.force() << " N beyond the limit +-" << l.force << " N";
    else if (std::abs(plant.velocity()) > l.velocity)
        o << "actuator velocity " << plant.velocity() * 1000.0 << " mm/s beyond the limit +-"
          << l.velocity * 1000.0 << " mm/s";
    return o.str();
}

void RthsLoop::holdAt(const std::string& why)
{
    std::ostringstream o;
    o.precision(4);
    o << why << " at tick " << m_k << " (t = " << double(m_k) * m_h << " s): test held";
    m_hold = o.str();
}

void RthsLoop::checkCommand(double command)
{
    const double stroke = m_s.limits.stroke;
    if (std::abs(command) <= stroke)
        return;
    std::ostringstream o;
    o.precision(4);
    o << "actuator command " << command * 1000.0 << " mm beyond the stroke limit +-"
      << stroke * 1000.0 << " mm";
    holdAt(o.str());
    m_commandHold = true;
}

std::string RthsLoop::resume()
{
    if (!holding())
        return {};
    if (m_commandHold)
        return m_hold + " (the state that gave this command has not moved: not resumed)";
    if (const std::string why = plantLimitBreach(m_plant, m_s.limits); !why.empty())
        return why + " (still; tick " + std::to_string(m_k) + "): not resumed";
    m_hold.clear();
    return {};
}

void RthsLoop::checkPlant()
{
    if (const std::string why = plantLimitBreach(m_plant, m_s.limits); !why.empty())
        holdAt(why);
}

bool RthsLoop::tick()
{
    if (holding())
        return false;
    const double t = double(m_k) * m_h;
    const int j = m_p.specimen.dof;
    // L1: sensors.
    const double xm = quantize(sense(m_plant.displacement(), m_s.sensors.displacementNoise));
    const double fm = sense(m_plant.force(), m_s.sensors.forceNoise);
    m_forces.push_back(fm);
    while (int(m_forces.size()) > m_s.forceDelay + 1)
        m_forces.pop_front();
    const double fe = int(m_forces.size()) > m_s.forceDelay ? m_forces.front() : 0.0;
    // The damper in the specimen and its twin: one tick of each law, their forces held over it.
    double damperForce = 0.0;
    if (m_damper) {
        if (m_damper->setTrialDeformation(m_plant.displacement()) == LawStatus::Ok)
            m_damper->commit();
        else
            m_damper->revert();
        damperForce = m_damper->committedForce();
        const int d = m_s.damper.twinDof;
        m_twinForce = m_twin->step(m_x(d) - (d > 0 ? m_x(d - 1) : 0.0));
    }
    // L2: the target, compensation, servo-controller.
    const double ag0 = m_ag.at(t);
    const Eigen::VectorXd a0 = accelerationOf(m_x, m_v, ag0, fe);
    const TargetState target{m_x(j), m_v(j), a0(j)};
    const double command = m_comp.command(target);
    m_comp.observe(xm);
    const double valve = quantize(m_pid.step(command - xm));
    m_last.time = t;
    m_last.desired = target.x;
    m_last.command = command;
    m_last.valve = valve;
    m_last.measured = xm;
    m_last.force = fm;
    m_last.floors = m_x;
    m_last.floors(j) = xm;
    m_last.damperForce = m_damper ? sense(damperForce, m_s.damper.forceNoise) : 0.0;
    m_last.twinForce = m_twinForce;
    checkCommand(command); // the plant's state was checked at the end of the last tick
    if (holding())
        return false;
    // L4: the plant over [t, t + h].
    m_plant.advance(valve, m_h, damperForce);
    // L5: the numerical substructure over [t, t + h] (RK4, fe held).
    const double agMid = m_ag.at(t + 0.5 * m_h), ag1 = m_ag.at(t + m_h);
    rk4Step(m_x, m_v, m_h, a0,
            [&](const Eigen::VectorXd& x, const Eigen::VectorXd& v, double s) {
                return accelerationOf(x, v, s < 1.0 ? agMid : ag1, fe);
            });
    ++m_k;
    checkPlant();
    return !holding();
}

UpdateEvent RthsLoop::updateTwin(const TwinUpdate& u)
{
    const double t = double(m_k) * m_h;
    if (!m_twin) {
        UpdateEvent ev{int(m_k), t, "damper twin", ParameterLayout(u.names), u.values, false,
                       u.source + ": this RTHS run has no damper twin; nothing applied"};
        ev.decision = UpdateDecision::Refused;
        return ev;
    }
    return m_twin->apply(u, m_k, t);
}

Eigen::MatrixXd referenceResponse(const LinearStructure& r, const GroundMotion& ag, double h,
                                  long n)
{
    return referenceResponse(r, ag, h, n, ReferenceDampers{});
}

} // namespace hsmu::rths
