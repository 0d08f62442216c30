#include "core/experimental/setup/PlanarSetups.h"

#include <cmath>
#include <sstream>

namespace hsmu {

namespace {

bool positive(const std::string& type, const char* name, double v, std::string& error) {
    if (std::isfinite(v) && v > 0.0)
        return true;
    std::ostringstream os;
    os << type << ": " << name << " = " << v
       << " must be a positive finite length (an actuator's length from its base to its "
          "attachment)";
    error = os.str();
    return false;
}

bool finite(const std::string& type, const char* name, double v, std::string& error) {
    if (std::isfinite(v))
        return true;
    error = type + ": " + name + " must be finite";
    return false;
}

std::unique_ptr<PlanarActuatorSetup> finish(std::unique_ptr<PlanarActuatorSetup> setup,
                                            const std::string& hint, std::string& error) {
    if (std::string why = setup->restSingularity(); !why.empty()) {
        error = setup->typeName() + ": " + hint + ": " + why;
        return nullptr;
    }
    error.clear();
    return setup;
}

} // namespace

std::unique_ptr<PlanarActuatorSetup> makeTwoActuators2d(const TwoActuators2dParams& p,
                                                        std::string& error) {
    const std::string type = "TwoActuators2d";
    if (!positive(type, "La1", p.La1, error) || !positive(type, "La2", p.La2, error) ||
        !finite(type, "L", p.L, error) || !finite(type, "phiLocX", p.phiLocX, error))
        return nullptr;
    if (p.L == 0.0) {
        error = type + ": L = 0 puts both horizontal actuators at the control point (parallel "
                       "and coincident): the rotation cannot be controlled";
        return nullptr;
    }
    const double side = p.actuatorsRight ? 1.0 : -1.0;
    std::vector<PlanarActuator> acts = {
        {{0.0, 0.0}, {side * p.La1, 0.0}},
        {{0.0, p.L}, {side * p.La2, p.L}},
    };
    return finish(std::make_unique<PlanarActuatorSetup>(type, std::move(acts), p.geometry,
                                                        p.phiLocX, std::vector<int>{0, 2}),
                  "L", error);
}

std::unique_ptr<PlanarActuatorSetup>
makeThreeActuatorsJntOff2d(const ThreeActuatorsJntOff2dParams& p, std::string& error,
                           const std::string& type) {
    if (!positive(type, "La1", p.La1, error) || !positive(type, "La2", p.La2, error) ||
        !positive(type, "La3", p.La3, error))
        return nullptr;
    const std::pair<const char*, double> lengths[] = {
        {"L1", p.L1}, {"L2", p.L2}, {"L3", p.L3},          {"L4", p.L4},
        {"L5", p.L5}, {"L6", p.L6}, {"phiLocX", p.phiLocX}};
    for (const auto& [name, v] : lengths)
        if (!finite(type, name, v, error))
            return nullptr;
    if (p.L2 + p.L3 == 0.0) {
        error = type + ": L2 + L3 = 0 puts both vertical actuators on one line (parallel and "
                       "coincident): the rotation cannot be controlled";
        return nullptr;
    }
    const Eigen::Vector2d h = p.horizontalRight ? Eigen::Vector2d(p.L3 + p.L4, 0.0)
                                                : Eigen::Vector2d(-(p.L1 + p.L2), 0.0);
    const double side = p.horizontalRight ? 1.0 : -1.0;
    std::vector<PlanarActuator> acts = {
        {h, h + Eigen::Vector2d(side * p.La1, 0.0)},
        {{-p.L2, -p.L5}, {-p.L2, -p.L5 - p.La2}},
        {{p.L3, -p.L6}, {p.L3, -p.L6 - p.La3}},
    };
    return finish(std::make_unique<PlanarActuatorSetup>(type, std::move(acts), p.geometry,
                                                        p.phiLocX, std::vector<int>{0, 1, 2}),
                  "L1..L6", error);
}

std::unique_ptr<PlanarActuatorSetup>
makeThreeActuators2d(const ThreeActuators2dParams& p, std::string& error, const std::string& type) {
    // ThreeActuators2d's L1, L2 are the joint-offset setup's L2, L3 with no offsets.
    if (!finite(type, "L1", p.L1, error) || !finite(type, "L2", p.L2, error))
        return nullptr;
    if (p.L1 + p.L2 == 0.0) {
        error = type + ": L1 + L2 = 0 puts both vertical actuators on one line (parallel and "
                       "coincident): the rotation cannot be controlled";
        return nullptr;
    }
    ThreeActuatorsJntOff2dParams q;
    q.La1 = p.La1;
    q.La2 = p.La2;
    q.La3 = p.La3;
    q.L2 = p.L1;
    q.L3 = p.L2;
    q.geometry = p.geometry;
    q.horizontalRight = p.horizontalRight;
    q.phiLocX = p.phiLocX;
    return makeThreeActuatorsJntOff2d(q, error, type);
}

std::unique_ptr<PlanarActuatorSetup> makeInvertedVBrace2d(const ThreeActuators2dParams& p,
                                                          std::string& error) {
    return makeThreeActuators2d(p, error, "InvertedVBrace2d");
}

std::unique_ptr<PlanarActuatorSetup> makeChevronBrace2d(const ThreeActuators2dParams& p,
                                                        std::string& error) {
    return makeThreeActuators2d(p, error, "ChevronBrace2d");
}

std::unique_ptr<PlanarActuatorSetup>
makeInvertedVBraceJntOff2d(const ThreeActuatorsJntOff2dParams& p, std::string& error) {
    return makeThreeActuatorsJntOff2d(p, error, "InvertedVBraceJntOff2d");
}

} // namespace hsmu
