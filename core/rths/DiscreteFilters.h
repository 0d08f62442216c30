#pragma once
// Discrete filters of the servo-controller's loop, all by the bilinear (Tustin) transform
// s = (2 / h) (z - 1) / (z + 1) at the loop period h [s] (docs/rths.md, "The servo-controller"):
//
//   FirstOrderSection  (n1 s + n0) / (d1 s + d0)                                     (rths.md C1)
//   Pid                u = Kp e + Ki / s e + Kd s / (tauD s + 1) e                    (C2)
//
// Each has direct feedthrough: step(x) returns the output at the same sample.

namespace hsmu::rths {

class FirstOrderSection {
public:
    FirstOrderSection() = default;
    /// (n1 s + n0) / (d1 s + d0) at period h; d1 and d0 not both zero.
    FirstOrderSection(double n1, double n0, double d1, double d0, double h);
    /// The phase lead K (s + z) / (s + p).
    static FirstOrderSection lead(double gain, double zero, double pole, double h);

    double step(double x);
    /// At rest with input and output x (the section's DC gain must be 1 for y = x).
    void reset(double x, double y);
    /// The discrete section's gain at z = 1.
    double dcGain() const;

private:
    double m_b0 = 1.0, m_b1 = 0.0, m_a1 = 0.0; // y = b0 x + b1 x[-1] - a1 y[-1]
    double m_x = 0.0, m_y = 0.0;
};

struct PidGains {
    double kp = 2.0;    ///< proportional [m/m]
    double ki = 95.0;   ///< integral [1/s]
    double kd = 0.0;    ///< derivative [s]
    double tauD = 0.0;  ///< derivative filter time constant [s] (0: none, kd must be 0 then)
};

class Pid {
public:
    Pid() = default;
    Pid(const PidGains& gains, double h);
    double step(double error);
    /// The integrator preloaded so that a zero error gives output u0.
    void reset(double u0);
    const PidGains& gains() const { return m_g; }

private:
    PidGains m_g;
    double m_h = 0.0;
    double m_integral = 0.0, m_ePrev = 0.0;
    double m_d = 0.0; // filtered derivative term
};

} // namespace hsmu::rths
