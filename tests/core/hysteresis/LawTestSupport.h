#pragma once
// Small helpers shared by the hysteresis law tests: histories, driving a law point by point
// (trial + commit) and comparing force histories.

#include "core/hysteresis/HysteresisLaw.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

namespace hsmu::testsupport {

/// u(t) = amplitude sin(2 pi t) at t = i / pointsPerCycle, i = 1 .. cycles * pointsPerCycle.
inline std::vector<double> sineHistory(double amplitude, int cycles, int pointsPerCycle) {
    std::vector<double> u;
    for (int i = 1; i <= cycles * pointsPerCycle; ++i) {
        u.push_back(amplitude * std::sin(2.0 * std::numbers::pi * i / pointsPerCycle));
    }
    return u;
}

struct Run {
    std::vector<double> force, tangent;
    bool ok = true; ///< false if a trial did not return LawStatus::Ok (the run stops there)
};

/// Trial + commit at each point of u, recording the trial force and tangent.
inline Run drive(HysteresisLaw& law, const std::vector<double>& u) {
    Run run;
    for (const double ui : u) {
        if (law.setTrialDeformation(ui) != LawStatus::Ok) {
            run.ok = false;
            return run;
        }
        run.force.push_back(law.trialForce());
        run.tangent.push_back(law.trialTangent());
        law.commit();
    }
    return run;
}

inline double peakAbs(const std::vector<double>& v) {
    double m = 0.0;
    for (const double x : v) {
        m = std::max(m, std::abs(x));
    }
    return m;
}

/// Max |a[k strideA - 1] - b[k strideB - 1]|, k = 1, 2, ...: compares histories sampled at
/// t = k / N_a and t = k / N_b (sineHistory starts at i = 1) on their common points.
inline double maxDifference(const std::vector<double>& a, std::size_t strideA,
                            const std::vector<double>& b, std::size_t strideB) {
    double m = 0.0;
    for (std::size_t k = 1; k * strideA <= a.size() && k * strideB <= b.size(); ++k) {
        m = std::max(m, std::abs(a[k * strideA - 1] - b[k * strideB - 1]));
    }
    return m;
}

/// Trapezoidal integral of F du over points first .. last (indices into u and f).
inline double work(const std::vector<double>& u, const std::vector<double>& f, std::size_t first,
                   std::size_t last) {
    double w = 0.0;
    for (std::size_t i = first; i < last; ++i) {
        w += 0.5 * (f[i] + f[i + 1]) * (u[i + 1] - u[i]);
    }
    return w;
}

} // namespace hsmu::testsupport
