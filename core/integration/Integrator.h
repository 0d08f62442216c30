#pragma once
// Integrator: a step-by-step scheme for  M a + C v + R(u) = -influence * ag(t)
// over the free DOFs of a Structure, split so that no iteration on a specimen is ever needed:
//
//   1. predict()  -> the displacement at which every element is evaluated (sent to specimens)
//   2. the caller evaluates the structure there and passes the restoring force R~
//   3. correct(R~, ag[n+1]) -> a, v, u at n+1
//
// Units: those of the Structure (presets: m, s, t, kN); ag in m/s^2.

#include <Eigen/Core>

#include <string>

namespace hsmu {

class Structure;

class Integrator {
public:
    virtual ~Integrator() = default;
    virtual std::string name() const = 0;
    /// True for conditionally stable schemes (refuse omega_max dt above stabilityLimit()).
    virtual bool isExplicit() const = 0;
    /// Largest stable omega dt for a linear undamped system (infinity if unconditional).
    virtual double stabilityLimit() const = 0;

    /// Start at rest-or-given state: u0, v0 (free DOFs), ground acceleration ag0 and the
    /// restoring force r0 = R(u0). Computes a0 from equilibrium.
    virtual void initialize(const Structure& s, double dt, const Eigen::VectorXd& u0,
                            const Eigen::VectorXd& v0, double ag0, const Eigen::VectorXd& r0);
    /// The displacement at which the elements are evaluated for step n+1.
    virtual Eigen::VectorXd predict() const = 0;
    /// predict() into out; a scheme that overrides it reuses out's storage (no allocation
    /// once sized: the stepping loop calls it every step, issue 27).
    virtual void predictInto(Eigen::VectorXd& out) const { out = predict(); }
    /// Complete step n+1 from the restoring force measured at predict() and ag[n+1].
    /// Returns false (state unchanged) if the result is not finite.
    virtual bool correct(const Eigen::VectorXd& rTrial, double agNext) = 0;

    /// The scheme's whole state, to undo a step whose commit failed (see HybridTest::step).
    struct Snapshot {
        Eigen::VectorXd u, v, a, extra;
    };
    /// Copies the state into `into`, reusing its storage (no allocation once sized: taken
    /// every step, issue 27).
    virtual void snapshot(Snapshot& into) const
    {
        into.u = m_u;
        into.v = m_v;
        into.a = m_a;
        into.extra.resize(0);
    }
    virtual void restore(const Snapshot& s)
    {
        m_u = s.u;
        m_v = s.v;
        m_a = s.a;
    }

    const Eigen::VectorXd& displacement() const { return m_u; }
    const Eigen::VectorXd& velocity() const { return m_v; }
    const Eigen::VectorXd& acceleration() const { return m_a; }
    double dt() const { return m_dt; }

protected:
    const Structure* m_s = nullptr;
    double m_dt = 0.0;
    Eigen::VectorXd m_u, m_v, m_a;
};

} // namespace hsmu
