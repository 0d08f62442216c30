#include "comms/openfresco/AdapterControl.h"

namespace hsmu::comms::of {

AdapterControl::AdapterControl(std::string host, std::uint16_t port, std::string element,
                               OfControlOptions options)
    : OpenFrescoControl(OfProtocol::Adapter, std::move(host), port, std::move(element), options),
      m_comp(options.adapter) {}

ControlResult AdapterControl::setTarget(double d) {
    // A refused target (holding, link down, a repeated step) leaves the compensation as it was.
    const AdapterCompensation before = m_comp;
    const ControlResult r = OpenFrescoControl::setTarget(m_comp.command(d));
    if (!r.ok)
        m_comp = before;
    return r;
}

ControlResult AdapterControl::measure(ControlMeasurement& out) {
    ControlMeasurement raw;
    if (ControlResult r = OpenFrescoControl::measure(raw); !r.ok)
        return r;
    const AdapterCompensation::Corrected c = m_comp.correct(raw.deformation, raw.force);
    out = raw;
    out.deformation = c.deformation;
    out.force = c.force;
    return ControlResult::success();
}

ControlResult AdapterControl::commit() {
    ControlResult r = OpenFrescoControl::commit();
    if (r.ok)
        m_comp.commit();
    return r;
}

} // namespace hsmu::comms::of
