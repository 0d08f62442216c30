#include "core/experimental/SetupSketch.h"

#include "core/experimental/setup/NoTransformation.h"
#include "core/experimental/setup/PlanarActuatorSetup.h"

#include <cmath>

namespace hsmu {

namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;
constexpr double kDirectArm = 0.4;   // [L] a direct setup's actuator length in the drawing
constexpr double kTick = 0.15;       // [L] the rotation tick at node j
constexpr double kTargetShare = 0.1; // the peak displacement drawn at this share of L

Eigen::Matrix2d rotation(double angle) {
    Eigen::Matrix2d r;
    r << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
    return r;
}

} // namespace

SetupSketch setupSketch(const ExperimentalSetup& setup, const Link2dGeometry& g,
                        const Eigen::Vector3d& d, double scale) {
    SetupSketch out;
    out.scale = scale;
    const double phi = g.angleDeg * kDegree;
    const Eigen::Vector2d e(std::cos(phi), std::sin(phi));
    const Eigen::Vector2d n(-std::sin(phi), std::cos(phi));
    const Eigen::Vector2d jRest = g.length * e;
    out.nodeJ = jRest + scale * (d(0) * e + d(1) * n); // eq. K1
    const double turn = scale * d(2);
    out.segments.push_back({out.nodeI, out.nodeJ, SketchPart::Element, -1});
    out.segments.push_back(
        {out.nodeJ, out.nodeJ + kTick * g.length * (rotation(turn) * e), SketchPart::Rotation, -1});

    if (const auto* planar = dynamic_cast<const PlanarActuatorSetup*>(&setup)) {
        Eigen::Matrix2d en;
        en.col(0) = e;
        en.col(1) = n;
        const Eigen::Matrix2d G = en * planar->elementToSetup().transpose(); // eq. K2
        const Eigen::Matrix2d turned = rotation(turn);
        const auto& acts = planar->actuators();
        for (int i = 0; i < int(acts.size()); ++i) {
            const Eigen::Vector2d base = jRest + G * acts[std::size_t(i)].base;
            const Eigen::Vector2d attach = out.nodeJ + G * (turned * acts[std::size_t(i)].attach);
            if (acts[std::size_t(i)].attach.norm() > 0.0)
                out.segments.push_back({out.nodeJ, attach, SketchPart::Platform, i});
            out.segments.push_back({base, attach, SketchPart::Actuator, i}); // eq. K3
        }
        out.drawable = true;
        return out;
    }
    if (const auto* direct = dynamic_cast<const NoTransformation*>(&setup)) {
        for (int i = 0; i < int(direct->dofs().size()); ++i) {
            const int dof = direct->dofs()[std::size_t(i)];
            if (dof > 1)
                continue; // a rotation (or a DOF beyond the link's): no line
            const Eigen::Vector2d along = dof == 0 ? e : n;
            out.segments.push_back(
                {jRest + kDirectArm * g.length * along, out.nodeJ, SketchPart::Actuator, i});
        }
        out.drawable = true;
        return out;
    }
    out.reason = setup.typeName() + ": no 2-D drawing of this setup";
    return out;
}

double sketchScale(double peak, double length) {
    if (!(peak > 0.0) || !std::isfinite(peak) || !(length > 0.0))
        return 1.0;
    const double wanted = kTargetShare * length / peak;
    if (wanted <= 1.0)
        return 1.0;
    const double decade = std::pow(10.0, std::floor(std::log10(wanted)));
    for (const double step : {5.0, 2.0, 1.0})
        if (step * decade <= wanted)
            return step * decade;
    return decade;
}

} // namespace hsmu
