#pragma once
// ElementChannels: the per-step columns of a multi-DOF element beyond its one primary column
// (docs/recording.md, "Element channels"), so that nothing a lab measured is lost: every basic
// DOF and every actuator of a multi-DOF experimental element (ExperimentalLink2d), every basic
// DOF of its numerical twin (Link2dElement). One-DOF elements have none.
//
//   ExperimentalLink2d, per basic DOF k in (axial, shear, rotation):
//       "<k> commanded"   the trial basic deformation sent through the setup [m | rad]
//       "<k> deformation" the measured one, recovered through the setup (eq. S4) [m | rad]
//       "<k> force"       the basic force q = J(d_m)^T f_m (eq. S3) [kN | kN m]
//     then per actuator channel a (the setup's actuator order, its configured name):
//       "<a> command"     its command: the stroke (displacement control) [m] or the held force
//                         (force control) [kN]
//       "<a> stroke"      the measured stroke [m]
//       "<a> force"       the measured force [kN]
//   Link2dElement, per basic DOF k: "<k> deformation", "<k> force".
// Values are the element's last trial / measurement as the step committed it (step 0: the
// element's initial state, all zero). Units: the presets' (kN, m, rad); any consistent set
// reads the same with its own units.
// Thread rules: functions of the element; call on the thread that owns it.

#include <string>
#include <vector>

namespace hsmu {

class Element;

struct ElementChannel {
    std::string element; ///< the element's name
    std::string name;    ///< e.g. "shear force", "vertical stroke"
    std::string unit;    ///< "m", "rad", "kN", "kN m"
};

/// Element e's channels in the order above (empty for a one-DOF element).
std::vector<ElementChannel> elementChannels(const Element& e);

/// Append element e's current channel values, in elementChannels(e)'s order, to out.
void appendChannelValues(const Element& e, std::vector<double>& out);

} // namespace hsmu
