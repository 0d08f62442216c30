#pragma once
// AdapterControl: the console as the client of OpenSees' `adapter` element (OpenSees listens:
// `element adapter TAG -node ... -dof ... -stif KB PORT`), so that a numerical substructure
// living in an OpenSees model is driven like any site and its restoring force enters the
// console's equation of motion. The adapter imposes the client's ctrl disp on its DOFs through
// the penalty stiffness KB and, one analysis step later, reports [daq disp, daq force] of the
// converged state. Its exact action sequence, which this client keeps:
//   connect, sizes header (ctrl disp 1, daq disp 1, daq force 1; no probe: the adapter
//   accepts nothing else before the first trial)
//   per step  setTarget(d): [3, s] [10]   measure(): -> [daq disp, daq force]   commit(): nothing
//   end       [99] (the adapter then ends OpenSees: "The Simulation has successfully completed")
// Any other action makes the adapter exit OpenSees ("wrong action received: expecting 3"). A
// step is final once the next trial is sent (no commit, no revert): a measured step cannot be
// repeated after a hold. OpenSees' `analyze N` must have at least as many steps as the
// console's test. See OpenFrescoControl.
// The penalty: sent d, the substructure would sit F / KB short of it. The control sends
// s = d + F^ / KB instead and corrects the force read to the target (AdapterCompensation,
// options.adapter; KB is estimated from the data): measure() reports deformation = the target
// and the corrected force; the actuator channels keep s (commanded) and db (measured) as sent
// and read.

#include "comms/openfresco/AdapterCompensation.h"
#include "comms/openfresco/OpenFrescoControl.h"

namespace hsmu::comms::of {

class AdapterControl : public OpenFrescoControl {
public:
    AdapterControl(std::string host, std::uint16_t port, std::string element,
                   OfControlOptions options);

    ControlResult setTarget(double d) override;
    ControlResult measure(ControlMeasurement& out) override;
    ControlResult commit() override;

    const AdapterCompensation& compensation() const { return m_comp; }

private:
    AdapterCompensation m_comp;
};

} // namespace hsmu::comms::of
