#pragma once
// SimAppControl: the console as an OpenFresco SimApp client (the role of OpenFresco Express or
// OpenSees' `element genericClient`), connecting to `startSimAppSiteServer` /
// `startSimAppElemServer` or to `hsmu-controller --protocol simapp`. Per step [3, trial],
// [6] -> measured response, [5] commit; [99] at the end. See OpenFrescoControl.

#include "comms/openfresco/OpenFrescoControl.h"

namespace hsmu::comms::of {

class SimAppControl final : public OpenFrescoControl {
public:
    SimAppControl(std::string host, std::uint16_t port, std::string element,
                  OfControlOptions options)
        : OpenFrescoControl(OfProtocol::SimApp, std::move(host), port, std::move(element),
                            std::move(options)) {}
};

} // namespace hsmu::comms::of
