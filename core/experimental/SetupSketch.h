#pragma once
// SetupSketch: the geometry of the console's drawing of a link2d specimen and its experimental
// setup, at rest or deformed (docs/console.md, "Actuators and setup"). Computed here, drawn by
// gui/plots/SetupSketchView; no Qt.
//
// Global frame, x to the right, y up [m], node i at the origin. With e = (cos phi, sin phi)
// along the element and n = (-sin phi, cos phi) across it (core/structure/Link2dKinematics.h),
// basic displacements d = (axial, shear, rotation) magnified by the scale m:
//   node j          x_j = L e + m (d_axial e + d_shear n)                              (eq. K1)
//   setup frame     a vector p of the setup's frame is G p in the global one,
//                   G = [e n] R(phiLocX)^T (the setup's (u, v) = R(phiLocX) (axial, shear),
//                   docs/setups.md)                                                    (eq. K2)
//   planar setups   actuator i's base      L e + G b_i                  (fixed)
//                   its attachment         x_j + G R(m theta) a_i       (the platform turned
//                                                                         by the magnified
//                                                                         rotation)     (eq. K3)
//   direct setups   (NoTransformation, OneActuator) the actuator on the axial DOF along e, on
//                   the shear DOF along n, each from a base at 0.4 L from node j at rest
//                   (L e + 0.4 L e, L e + 0.4 L n) to x_j; an actuator on the rotation has
//                   no line (its stroke is a rotation).
// The element is drawn as its chord i -> j plus a tick of 0.15 L at j along R(m d_rot) e (the
// end's rotation). m = 0 gives the rest shape. The drawing uses the exact rigid-body positions
// at the magnified motion whatever the setup's formulation (linear or -nlGeom): a picture, not
// the strokes. Setups without a 2-D drawing (FourActuators3d, an Aggregator) return
// drawable = false and the reason.
// Thread rules: plain functions.

#include "core/structure/Link2dKinematics.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace hsmu {

class ExperimentalSetup;

enum class SketchPart {
    Element,  ///< the specimen's chord i -> j
    Rotation, ///< the tick at node j showing its rotation
    Platform, ///< a rigid arm from node j to an actuator's attachment
    Actuator  ///< base -> attachment
};

struct SketchSegment {
    Eigen::Vector2d from = Eigen::Vector2d::Zero(); ///< [m] global frame
    Eigen::Vector2d to = Eigen::Vector2d::Zero();   ///< [m]
    SketchPart part = SketchPart::Element;
    int actuator = -1; ///< the setup's actuator index (Actuator, Platform), else -1
};

struct SetupSketch {
    bool drawable = false;
    std::string reason; ///< why not drawable (names the setup)
    double scale = 1.0; ///< m of eq. K1 [-]
    Eigen::Vector2d nodeI = Eigen::Vector2d::Zero();
    Eigen::Vector2d nodeJ = Eigen::Vector2d::Zero(); ///< x_j of eq. K1 [m]
    std::vector<SketchSegment> segments;
};

/// The drawing of a link2d element of geometry g behind `setup` at basic displacements d
/// (axial [m], shear [m], rotation [rad]) magnified by scale (eqs. K1-K3).
SetupSketch setupSketch(const ExperimentalSetup& setup, const Link2dGeometry& g,
                        const Eigen::Vector3d& d, double scale);

/// A round magnification (1, 2 or 5 x 10^k, at least 1) that draws a peak displacement
/// `peak` [m] (the largest |d_axial|, |d_shear|, L |d_rot| so far) at about 10 % of the
/// element's length L [m]; 1 when peak is 0 or not finite.
double sketchScale(double peak, double length);

} // namespace hsmu
