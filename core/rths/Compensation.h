#pragma once
// Delay compensation on the command path of one experimental element (docs/rths.md,
// "Compensation"). The desired state of the target DOF (x [m], v [m/s], a [m/s^2], from the
// numerical substructure) becomes the command sent to the servo-controller:
//
//   none         x* = x
//   polynomial   x* = the polynomial of the given order through the last order+1 targets,
//                evaluated tau ahead (Horiuchi et al. 1999); tau configured or estimated (C3)
//   feedforward  x* = c0 x + c1 v + c2 a  (the inverse of the loop, fitted over a band:
//                fitFeedforward)                                                          (C4)
//   ats          x* = a0 x + a1 v + a2 a with a0..a2 re-fitted by least squares over a moving
//                window so that u ~ a0 xm + a1 xm' + a2 xm'' (Chae, Kazemibidokhti & Ricles 2013;
//                both sides through one low-pass filter before the fit; bounded, rate-limited) (C5)
//
// followed, optionally, by the phase lead K (s + z) / (s + p) (the benchmark's Gt, C1).

#include "core/rths/DiscreteFilters.h"

#include <Eigen/Core>

#include <complex>
#include <deque>
#include <functional>
#include <string>

namespace hsmu::rths {

struct TargetState {
    double x = 0.0; ///< [m]
    double v = 0.0; ///< [m/s]
    double a = 0.0; ///< [m/s^2]
};

struct LeadSettings {
    bool enabled = false;
    double gain = 50.8316; ///< K [-]
    double zero = 168.604; ///< z [rad/s]
    double pole = 8570.40; ///< p [rad/s]
};

struct CompensationSettings {
    enum class Type { None, Polynomial, Feedforward, Ats };
    Type type = Type::None;
    // polynomial
    int order = 3;
    double delay = 0.0;          ///< tau [s]
    bool estimateDelay = false;  ///< tau from the online estimate (DelayEstimator) instead
    // feedforward (and the ATS's start)
    double c0 = 1.0, c1 = 0.0, c2 = 0.0; ///< [-], [s], [s^2]
    bool fitToLoop = false; ///< c0..c2 fitted to the nominal loop before the run (fitFeedforward)
    // ats
    double window = 2.0;          ///< least-squares window [s]
    double updateInterval = 0.25; ///< [s] between re-fits
    double filterFrequency = 20.0; ///< low-pass on both sides of the fit [Hz]
    double maxC1 = 0.05, maxC2 = 0.002; ///< bounds of a1 [s] and |a2| [s^2]; a0 in [0.5, 2]
    double maxChange = 0.1;       ///< largest relative change of a coefficient per re-fit
    LeadSettings lead;
};

const char* compensationTypeName(CompensationSettings::Type t);
/// "none", "polynomial", "feedforward", "ats"; false when unknown.
bool parseCompensationType(const std::string& s, CompensationSettings::Type& out);

class Compensator {
public:
    Compensator(const CompensationSettings& s, double h);

    /// The command for this tick from the target state.
    double command(const TargetState& target);
    /// Feed the fit (ATS) with the measured displacement of this tick.
    void observe(double measured);
    /// The delay estimate [s] for a polynomial compensator with estimateDelay.
    void setDelayEstimate(double tau) { m_tauEstimate = tau; }
    void reset(double x);
    double c0() const { return m_c[0]; }
    double c1() const { return m_c[1]; }
    double c2() const { return m_c[2]; }
    const CompensationSettings& settings() const { return m_s; }

private:
    double primary(const TargetState& t);
    void refit();
    CompensationSettings m_s;
    double m_h;
    double m_c[3];
    std::deque<double> m_past; // last order+1 targets, newest first
    double m_tauEstimate = 0.0;
    FirstOrderSection m_lead;
    // ATS state: the low-passed command and measurement, their recent history.
    struct Filtered {
        double a = 0.0, b = 0.0; // two cascaded first-order low-passes
        double step(double x, double alpha)
        {
            a += alpha * (x - a);
            b += alpha * (a - b);
            return b;
        }
    } m_fu, m_fx;
    double m_alpha = 1.0;
    std::deque<double> m_u, m_xm; // filtered, newest last
    long m_ticks = 0;
    Eigen::Matrix3d m_r = Eigen::Matrix3d::Zero(); // forgetting sums of phi phi^T
    Eigen::Vector3d m_q = Eigen::Vector3d::Zero(); // and of phi u
    double m_lastPrimary = 0.0; // the last output before the lead (what the ATS fit maps)
};

/// The loop's closed-loop response T(j omega) from command to measured displacement.
using LoopResponse = std::function<std::complex<double>(double omega)>;
/// c0, c1, c2 minimizing sum |(c0 + c1 j w - c2 w^2) T(j w) - 1|^2 over fLow..fHigh [Hz] (C4).
void fitFeedforward(const LoopResponse& t, double fLow, double fHigh, CompensationSettings& s);

} // namespace hsmu::rths
