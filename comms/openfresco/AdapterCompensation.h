#pragma once
// AdapterCompensation: removes the penalty error of OpenSees' `adapter` element from what the
// console sends and reads (docs/openfresco.md "The adapter's penalty and its compensation").
//
// The adapter imposes the sent ctrl displacement s on its DOF through a penalty stiffness KB:
// the substructure comes to rest at db where its own force balances the penalty, and the
// adapter reports [db, q] with q = KB (s - db) = F(db) (the substructure's force at db, up to
// the residual of OpenSees' Newton iteration, about KB ulp(db)). Sent the console's target d
// unchanged, the substructure sits F / KB short of it and follows a path F / KB off the
// console's (force error about kt F / KB; 3e-8 kN with KB = 1e10 in the test).
//
// Three steps, all from what the adapter reports (no model of the substructure):
//  1. Penalty from the data: KB = q / (s - db). The adapter computes q exactly so, and s - db
//     is exact in floating point, so the estimate is KB to a few ulps whenever s != db.
//  2. Target prediction: s = d + F^ / KB with F^ the force predicted at d from the committed
//     history (the state at rest counts as a step): the parabola through the last three
//     points while the motion keeps its direction, the secant of the last reversal step when
//     it reverses (a hysteretic substructure unloads stiffly). The substructure then sits at
//     db = d + (F^ - F(db)) / KB, within |F - F^| / KB of the target, and follows the
//     console's path.
//  3. Force correction to the target: F = q + k (d - db), k the slope at db of the parabola
//     through (db, q) and the last two committed points (the secant of this step when it
//     reverses the motion); the reported deformation is the target d.
// What is left: KB ulp(d) (the adapter's rounding) + (k - k^)(F - F^) / KB (second order):
// with KB about 1e6 k0, 1.7e-10 kN against the built-in run for the test's Bouc-Wen spring
// (k0 40 kN/m, KB 5e7; table in docs/openfresco.md). Units: those of the console's element
// (kN, m).
// Thread rules: one thread (the control's).

namespace hsmu::comms::of {

class AdapterCompensation {
public:
    struct Options {
        bool predictTarget = true; ///< correction 2
        bool correctForce = true;  ///< correction 3
    };

    struct Corrected {
        double deformation = 0.0; ///< [m] the target when corrected, else db
        double force = 0.0;       ///< [kN]
    };

    AdapterCompensation() = default;
    explicit AdapterCompensation(Options options) : m_opt(options) {}

    /// The ctrl displacement to send for the console's target d [m].
    double command(double d);
    /// The adapter's answer [db, q] to the last command(): estimate KB, correct to the target.
    Corrected correct(double daqDisp, double daqForce);
    /// The last corrected step is final (the adapter commits each step): it becomes history.
    void commit();

    /// [kN/m] the penalty estimated from the data (0 before the first step with s != db).
    double penalty() const { return m_kb; }
    /// [kN/m] the tangent estimate k^ used for the next step.
    double tangent() const { return m_k; }

private:
    /// The force [kN] and tangent [kN/m] predicted at d from the committed history.
    void predict(double d, double& force, double& tangent) const;
    /// The tangent [kN/m] at the measured point (db, q), for the correction to the target.
    double endTangent(double db, double q) const;

    Options m_opt;
    double m_kb = 0.0;        ///< estimated penalty
    double m_k = 0.0;         ///< secant of the last committed step
    double m_kReversal = 0.0; ///< secant of the last step that reversed the motion
    int m_steps = 0;          ///< committed steps
    double m_d[3] = {0.0, 0.0, 0.0}; ///< committed targets, the last at [2]
    double m_f[3] = {0.0, 0.0, 0.0}; ///< their corrected forces
    double m_target = 0.0, m_sent = 0.0; ///< this step
    Corrected m_now;
    double m_kStep = 0.0; ///< the tangent predicted for this step
};

} // namespace hsmu::comms::of
