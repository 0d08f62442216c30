#pragma once
// The planar setups of OpenFresco with their Tcl parameters, each built as a
// PlanarActuatorSetup (docs/setups.md has a figure and the equations of each). Lengths [m].
// Every create() checks its parameters and the rest geometry and returns nullptr with `error`
// = "<type>: <parameter> ..." when they cannot make a working setup (configuration time).
//
// Coordinates: setup frame, origin at the element's control point, x to the right, y up.
//
// TwoActuators2d  `expSetup TwoActuators2d $tag $La1 $La2 $L <-nlGeom> <-posAct left|right>
//                  <-phiLocX $deg>`
//   two horizontal actuators on the platform's vertical arm: actuator 1 at the control point,
//   actuator 2 at L above it; their bases La1, La2 to the left (default) or right. Basic DOFs
//   (u, v, theta); the actuators fix u and theta, v is given (the specimen's axial response).
// ThreeActuators2d  `expSetup ThreeActuators2d $tag $La1 $La2 $La3 $L1 $L2 <-nlGeom>
//                    <-posAct1 left|right> <-phiLocX $deg>`
//   a horizontal platform: actuator 1 horizontal at its left end (x = -L1; -posAct1 right:
//   at its right end x = L2, base to the right), actuators 2 and 3 vertical at x = -L1 and
//   x = L2, bases below (La2, La3).
// ThreeActuatorsJntOff2d  `... $La1 $La2 $La3 $L1 $L2 $L3 $L4 $L5 $L6 ...`
//   as ThreeActuators2d with joint offsets: actuator 1 at x = -(L1 + L2) (right: L3 + L4),
//   y = 0; actuator 2 at (-L2, -L5); actuator 3 at (L3, -L6); bases as above.
// InvertedVBrace2d, ChevronBrace2d: the geometry of ThreeActuators2d (OpenFresco gives them
// the same actuator kinematics); InvertedVBraceJntOff2d: that of ThreeActuatorsJntOff2d.

#include "core/experimental/setup/PlanarActuatorSetup.h"

#include <memory>

namespace hsmu {

struct TwoActuators2dParams {
    double La1 = 0, La2 = 0, L = 0;
    SetupGeometry geometry = SetupGeometry::Linear;
    bool actuatorsRight = false; ///< -posAct right
    double phiLocX = 0.0;        ///< [deg]
};

struct ThreeActuators2dParams {
    double La1 = 0, La2 = 0, La3 = 0;
    double L1 = 0, L2 = 0;
    SetupGeometry geometry = SetupGeometry::Linear;
    bool horizontalRight = false; ///< -posAct1 right
    double phiLocX = 0.0;         ///< [deg]
};

struct ThreeActuatorsJntOff2dParams {
    double La1 = 0, La2 = 0, La3 = 0;
    double L1 = 0, L2 = 0, L3 = 0, L4 = 0, L5 = 0, L6 = 0;
    SetupGeometry geometry = SetupGeometry::Linear;
    bool horizontalRight = false; ///< -posAct1 right
    double phiLocX = 0.0;         ///< [deg]
};

std::unique_ptr<PlanarActuatorSetup> makeTwoActuators2d(const TwoActuators2dParams& p,
                                                        std::string& error);
std::unique_ptr<PlanarActuatorSetup>
makeThreeActuators2d(const ThreeActuators2dParams& p, std::string& error,
                     const std::string& typeName = "ThreeActuators2d");
std::unique_ptr<PlanarActuatorSetup>
makeThreeActuatorsJntOff2d(const ThreeActuatorsJntOff2dParams& p, std::string& error,
                           const std::string& typeName = "ThreeActuatorsJntOff2d");
/// InvertedVBrace2d / ChevronBrace2d: ThreeActuators2d's geometry under their own name.
std::unique_ptr<PlanarActuatorSetup> makeInvertedVBrace2d(const ThreeActuators2dParams& p,
                                                          std::string& error);
std::unique_ptr<PlanarActuatorSetup> makeChevronBrace2d(const ThreeActuators2dParams& p,
                                                        std::string& error);
std::unique_ptr<PlanarActuatorSetup>
makeInvertedVBraceJntOff2d(const ThreeActuatorsJntOff2dParams& p, std::string& error);

} // namespace hsmu
