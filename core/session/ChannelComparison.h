#pragma once
// ChannelComparison: `hsmu compare` per basic DOF and per actuator (docs/cli.md, "Per basic DOF
// and per actuator"), from the multi-DOF elements' channels of each run (StepRecord::channels,
// RunLayout::channels; core/experiment/ElementChannels.h):
//   basic DOF k of an element present in both runs: its "<k> deformation" and "<k> force"
//     against the reference run's same element, NRMSE = RMS(x - x_ref) / RMS(x_ref) and
//     peak error = max |x - x_ref| over the common steps from step 1 (step 0 holds a specimen's
//     initial state, all zero, not a measurement), in the DOF's units (m | rad, kN | kN m);
//     NRMSE NaN (not a measure) where RMS(x_ref) <= 1e-9 RMS(x): a reference zero to round-off;
//   actuator a of a specimen: its tracking (rths::trackingReport, docs/rths.md M1-M6) of the
//     measured stroke against the command (displacement control) or of the measured force
//     against the commanded force (force control) from step 1, and its measured force against the
//     reference run's same actuator (NRMSE, peak error [kN]) when the reference has it.
// Units: the channels' own (the presets' kN, m, rad).

#include "core/experiment/ElementChannels.h"
#include "core/rths/TrackingMetrics.h"

#include <string>
#include <vector>

namespace hsmu {

/// A run's channels: their layout and one row of values per committed step.
struct ChannelHistory {
    std::vector<ElementChannel> layout;
    std::vector<std::vector<double>> steps; ///< [step][channel], layout's order
};

struct BasicDofComparison {
    std::string element, dof;               ///< e.g. "Column R", "shear"
    std::string deformationUnit, forceUnit; ///< "m" | "rad", "kN" | "kN m"
    double deformationNrmse = 0.0, deformationPeakError = 0.0; ///< [-], [deformation unit]
    double forceNrmse = 0.0, forcePeakError = 0.0;             ///< [-], [force unit]
};

struct ActuatorComparison {
    std::string element, actuator;
    std::string control;     ///< "displacement" or "force"
    std::string commandUnit; ///< "m" (a stroke) or "kN" (a force)
    std::string forceUnit;   ///< "kN"
    rths::TrackingReport tracking; ///< measured against commanded, in commandUnit
    bool compared = false;   ///< the reference run has this actuator
    double forceNrmse = 0.0, forcePeakError = 0.0; ///< [-], [kN]; when compared
};

/// One channel's history ("" when the run has no such channel).
std::vector<double> channelSeries(const ChannelHistory& h, const std::string& element,
                                  const std::string& name);

/// Every basic DOF (a "<k> deformation" and "<k> force" pair) of `run` that `reference` has
/// too, in `run`'s channel order.
std::vector<BasicDofComparison> compareBasicDofs(const ChannelHistory& run,
                                                 const ChannelHistory& reference);

/// Every actuator (a "<a> command", "<a> stroke", "<a> force" triple) of `run`, its tracking
/// sampled at dt [s]; against `reference`'s same actuator when reference is given and has it.
std::vector<ActuatorComparison> compareActuators(const ChannelHistory& run,
                                                 const ChannelHistory* reference, double dt);

} // namespace hsmu
