#pragma once
// ServoHydraulicPlant: a servo-valve, a hydraulic actuator and the specimen it pushes, with the
// control-structure interaction between them (docs/rths.md, "The plant"). SI units throughout:
// u, x [m], Q [m/s-equivalent valve flow state], F [N], time [s].
//
//   servo-valve:  Q'' + b1 Q' + b2 Q = a1b0 (g u - x)                         (rths.md eq. P1)
//   actuator:     F'  = -a3 F + Q - a2 x'                                      (P2)
//   specimen:     me x'' + ce x' + ke x = F                                    (P3)
//
// whose transfer function from u to x is G(s) = g a1b0 / (A5 s^5 + ... + A0) (P4). State
// s = [Q, Q', F, x, x']; advance() integrates it over one loop period h with u held (zero-order
// hold, classical fourth-order Runge-Kutta, as the RTHS benchmark's reference package does).
// The defaults are the benchmark's nominal plant (Silva et al. 2020).

#include <array>
#include <complex>
#include <string>

namespace hsmu::rths {

struct PlantParameters {
    double a1b0 = 2.1283e13; ///< servo-valve gain [1/s^3 per m]
    double a2 = 4.2297e6;    ///< actuator velocity feedback (CSI) [N s/m per ...]
    double a3 = 3.3;         ///< actuator force decay [1/s]
    double b1 = 425.0;       ///< servo-valve damping [1/s]
    double b2 = 9.9976e4;    ///< servo-valve stiffness [1/s^2]
    double me = 29.13;       ///< specimen mass [kg]
    double ce = 114.2;       ///< specimen damping [N s/m]
    double ke = 1.19e6;      ///< specimen stiffness [N/m]
    double g = 1.0261;       ///< command gain [-]

    /// ce for a damping ratio zeta of the specimen alone: 2 zeta sqrt(ke me).
    static double specimenDamping(double zeta, double ke, double me);
    /// Denominator coefficients A0..A5 of G(s) (eq. P4).
    std::array<double, 6> denominator() const;
    /// G(j omega), omega [rad/s], from the closed form (P4).
    std::complex<double> frequencyResponse(double omega) const;
    /// A sentence naming the first non-physical value, "" when all are usable.
    std::string validate() const;
};

class ServoHydraulicPlant {
public:
    using State = std::array<double, 5>; ///< Q, Q', F, x, x'

    explicit ServoHydraulicPlant(const PlantParameters& p = {});

    /// At rest at displacement x0 (the valve holding it: Q = a2*0 + a3 F, F = ke x0).
    void reset(double x0 = 0.0);
    /// Integrate over h [s] with the valve command u [m] held; fd [N]: a force of the specimen
    /// held over h (a damper's: P3 with -fd on its right; docs/rths.md, "A damper and its twin").
    void advance(double u, double h, double fd = 0.0);
    /// ds/dt at state s, command u and specimen force fd (eqs. P1-P3).
    State derivative(const State& s, double u, double fd = 0.0) const;
    /// G(j omega) of the state-space form, C (j omega I - A)^-1 B (equal to P4; tested).
    std::complex<double> stateSpaceResponse(double omega) const;

    double displacement() const { return m_s[3]; } ///< x [m]
    double velocity() const { return m_s[4]; }     ///< x' [m/s]
    double force() const { return m_s[2]; }        ///< F, the actuator's load-cell force [N]
    const State& state() const { return m_s; }
    const PlantParameters& parameters() const { return m_p; }

private:
    PlantParameters m_p;
    State m_s{};
};

} // namespace hsmu::rths
