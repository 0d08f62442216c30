#pragma once
// installOpenSeesTwins: comms' factory for numerical elements on an OpenSees site
// ("numericalSite": "opensees://HOST:PORT", core/config/NumericalSite.h): each such element gets
// an OpenSeesTwinLaw (docs/opensees-twins.md). makeControlFactory() installs it, so every front
// end that builds a test through comms has it; calling it again replaces the options.

#include "comms/openfresco/OpenSeesTwinLaw.h"

namespace hsmu::comms::of {

void installOpenSeesTwins(OpenSeesTwinOptions options = {});

} // namespace hsmu::comms::of
