#pragma once
// SyntheticGroundMotion: the built-in default record for machines without data files. A
// filtered, enveloped white noise, reproducible bit for bit on any IEEE-754 platform:
//
//   1. w_n ~ N(0, 1): std::mt19937_64 (fully specified by the C++ standard) raw 64-bit output
//      -> 53-bit uniforms -> Box-Muller in Marsaglia's polar form. std::normal_distribution is
//      not used: its algorithm differs between standard libraries.
//   2. Kanai-Tajimi filter (ground "soil" oscillator), omega_g = 5 pi rad/s, zeta_g = 0.6:
//        x'' + 2 zeta_g omega_g x' + omega_g^2 x = w(t),
//        a_KT = -(2 zeta_g omega_g x' + omega_g^2 x)        (H(s) ~ (2 zeta w s + w^2)/(...)).
//   3. Jennings-type envelope e(t): (t / 2 s)^2 for t < 2 s, 1 for 2 <= t <= 12 s,
//      exp(-0.3 (t - 12 s)) after 12 s.
//   4. Clough-Penzien high-pass on e(t) a_KT(t), omega_f = 0.5 pi rad/s, zeta_f = 0.6:
//        y'' + 2 zeta_f omega_f y' + omega_f^2 y = e a_KT,   a = y''  (H(s) = s^2/(...)).
//      With the trapezoidal rule the trapezoid integral of a is exactly y' (velocity) and
//      decays once the envelope has, so the record ends near zero velocity.
//   5. Scaled so that max |a| = pgaG * 9.80665 m/s^2 exactly.
//
// Both filters are integrated with the trapezoidal rule (bilinear transform: A-stable, only
// +, -, *, / and sqrt), and exp/log are evaluated by series in the .cpp rather than by the
// platform's libm, whose last bits differ between systems. The .cpp is compiled with
// -ffp-contract=off so no fused multiply-add changes the rounding on ARM.

#include "core/groundmotion/GroundMotion.h"

namespace hsmu {

inline constexpr unsigned kSyntheticDefaultSeed = 1940;
inline constexpr double kSyntheticOmegaG = 15.707963267948966; ///< 5 pi rad/s (2.5 Hz)
inline constexpr double kSyntheticZetaG = 0.6;
inline constexpr double kSyntheticOmegaF = 1.5707963267948966; ///< 0.5 pi rad/s (0.25 Hz)
inline constexpr double kSyntheticZetaF = 0.6;
inline constexpr double kSyntheticRiseTime = 2.0;   ///< end of the quadratic ramp [s]
inline constexpr double kSyntheticStrongEnd = 12.0; ///< end of the strong phase [s]
inline constexpr double kSyntheticDecayRate = 0.3;  ///< envelope decay after it [1/s]

/// The synthetic record: floor(duration / dt + 1e-9) + 1 samples at dt [s], peak |a| =
/// pgaG [g]. name "synthetic Kanai-Tajimi (seed N)", source "builtin".
/// Throws std::invalid_argument unless duration > 0, dt > 0 and pgaG > 0 (all finite).
GroundMotion makeSyntheticGroundMotion(unsigned seed = kSyntheticDefaultSeed,
                                       double duration = 30.0, double dt = 0.01,
                                       double pgaG = 0.32);

} // namespace hsmu
