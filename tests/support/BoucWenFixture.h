#pragma once
// The Bouc-Wen specimen that the identification tests and benchmarks identify (docs/method.md,
// normalized units: uRef 0.02 rad, fRef 20 kN m) and a deliberately wrong start inside the
// paper's Table III bounds that every identifier must leave.

#include "core/hysteresis/BoucWen.h"

namespace hsmu::test {

/// The specimen's true parameters.
inline BoucWenParameters truth() {
    BoucWenParameters p;
    p.k0 = 1.0;
    p.alpha = 0.03;
    p.n = 2.0;
    p.beta = 2.5;
    p.gamma = 0.5;
    p.deltaNu = 0.03;
    p.deltaEta = 0.03;
    p.uRef = 0.02;
    p.fRef = 20.0;
    return p;
}

/// The wrong start: every identified parameter off, inside Table III (the scales kept).
inline BoucWenParameters wrongStart() {
    BoucWenParameters p = truth();
    p.k0 = 1.3;
    p.alpha = 0.01;
    p.n = 1.3;
    p.beta = 4.0;
    p.gamma = 2.0;
    p.deltaNu = 0.08;
    p.deltaEta = 0.08;
    return p;
}

} // namespace hsmu::test
