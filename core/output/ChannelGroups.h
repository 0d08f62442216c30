#pragma once
// ChannelGroups: the multi-DOF elements' channels (RunLayout::channels, ElementChannels.h)
// grouped for the console's per-actuator and per-DOF views (docs/console.md, "Actuators and
// setup") and the plots of every basic DOF and actuator:
//   BasicDof   one basic DOF of one element: "<k> commanded" (specimens only),
//              "<k> deformation", "<k> force"
//   Actuator   one actuator: "<a> command", "<a> stroke", "<a> force"
//   then per element, every member of a kind in one group (one curve each):
//   Deformations  every basic DOF's measured deformation (units differ: m and rad)
//   Forces        every basic force (kN and kN m)
//   Strokes       every actuator's stroke [m]
//   ActuatorForces every actuator's force [kN]
// Indices are into RunLayout::channels (and StepRecord::channels). Within a group the
// channels keep the layout's order. Names are parsed from the channel suffixes above; the
// force channel belongs to the group whose name it carries.
// Thread rules: plain functions.

#include "core/experiment/ElementChannels.h"

#include <array>
#include <string>
#include <vector>

namespace hsmu {

enum class ChannelGroupKind { BasicDof, Actuator, Deformations, Forces, Strokes, ActuatorForces };

struct ChannelGroup {
    ChannelGroupKind kind = ChannelGroupKind::BasicDof;
    std::string element; ///< the element's name
    std::string subject; ///< the basic DOF or actuator name ("" for the per-element kinds)
    std::vector<int> channels;
};

/// The groups of `channels`: per element (layout order) its BasicDof groups, its Actuator
/// groups, then its Deformations, Forces, Strokes and ActuatorForces (those it has).
std::vector<ChannelGroup> channelGroups(const std::vector<ElementChannel>& channels);

/// "command" of "lateral command" (the text after the group's subject; the channel's own
/// name when it does not start with the subject).
std::string channelRole(const ElementChannel& c, const ChannelGroup& g);

/// The group's name in English for file names and logs: "<element> <DOF>" (BasicDof),
/// "<element> actuator <name>", "<element> deformations", "... forces", "... strokes",
/// "... actuator forces".
std::string channelGroupName(const ChannelGroup& g);

/// The indices of element's measured basic deformations ("axial deformation", "shear
/// deformation", "rotation deformation"; ElementChannels.h), -1 where it has none.
std::array<int, 3> basicDeformationChannels(const std::vector<ElementChannel>& channels,
                                            const std::string& element);

} // namespace hsmu
