#pragma once
// Shared by the N-channel controller tests of this folder: the two-actuator column's specimen
// (preset two-actuator-column-frame, its left column: channel 1 'vertical' force-controlled,
// channel 2 'lateral' displacement-controlled) with chosen actuator models and controller
// settings, and the discrete first-order lag's closed form over a linear command ramp.
#include "../MultiActuatorFixture.h"

#include "comms/link/ControlFactory.h"
#include "core/config/ConfigLoader.h"

#include <cmath>

namespace channelloops {

/// Link options generous enough for a loaded 2-core CI machine, reconnecting after a drop.
inline hsmu::comms::TcpControlOptions patient() {
    hsmu::comms::TcpControlOptions o;
    o.connectTimeout = 20.0;
    o.stepDeadline = 30.0;
    o.silenceTimeout = 30.0;
    o.reconnectAttempts = 3;
    o.reconnectDelay = 0.2;
    return o;
}

/// The native protocol's controls for a controller on 127.0.0.1:port.
inline hsmu::ControlFactory nativeAt(quint16 port) {
    return hsmu::comms::makeControlFactory(
        hsmu::comms::LinkAddress{hsmu::comms::LinkAddress::Kind::Tcp, "127.0.0.1", port},
        patient());
}

/// The preset with both actuators elastic (vertical 2e5 kN/m, lateral 1000 kN/m), lateral
/// lag tauLateral, vertical (force loop) lag tauVertical ([s]; 0: ideal), the controller's
/// loop at `rate` [Hz] with predictFraction `predict`.
inline nlohmann::json lagColumn(double tauLateral, double tauVertical, double rate, double predict,
                                double duration = 1.0) {
    nlohmann::json j = multiactuator::preset(duration);
    nlohmann::json& col = j["structure"]["elements"][0];
    col["actuators"][1]["material"] = {{"law", "elastic"}, {"k", 1000.0}};
    if (tauLateral > 0.0)
        col["actuators"][1]["actuator"] = {{"type", "lag"}, {"timeConstant", tauLateral}};
    if (tauVertical > 0.0)
        col["actuators"][0]["actuator"] = {{"type", "lag"}, {"timeConstant", tauVertical}};
    j["controller"]["rate"] = rate;
    j["controller"]["predictFraction"] = predict;
    return j;
}

/// The first-order lag a_k = a_{k-1} + (c_k - a_{k-1})(1 - q), q = exp(-h / tau), driven over
/// K ticks by the ramp c_k = c0 + (T - c0) k / K from a_0: with e_k = c_k - a_k and the ramp's
/// per-tick rise r = (T - c0) / K, e_k = q (e_{k-1} + r), so e_k = e* + (e_0 - e*) q^k with
/// e* = q r / (1 - q); returns a_K = T - e_K.
inline double lagAfterRamp(double a0, double c0, double target, int ticks, double h, double tau) {
    const double q = std::exp(-h / tau);
    const double r = (target - c0) / ticks;
    const double eStar = q * r / (1.0 - q);
    return target - eStar - ((c0 - a0) - eStar) * std::pow(q, ticks);
}

} // namespace channelloops
