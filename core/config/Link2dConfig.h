#pragma once
// Link2dConfig: the "link2d" element of a configuration (docs/configuration.md, "link2d"): a
// two-node 2D link / beam-column with 3 basic DOFs, numerical (a law or a held force per basic
// DOF) or experimental (an OpenFresco expSetup line and one actuator per setup actuator, each
// displacement- or force-controlled with its limits). Errors are ConfigErrors naming the field,
// and for the setup its type and parameter (SetupScript.h), at configuration time.

#include "core/config/JsonCursor.h"
#include "core/config/TestConfig.h"
#include "core/experimental/SpecimenBehindSetup.h"
#include "core/experimental/setup/ExperimentalSetup.h"

#include <memory>
#include <vector>

namespace hsmu {

ElementSpec parseLink2dElement(const JsonCursor& c, const std::vector<DofSpec>& dofs);

/// The setup of a link2d specimen from its script: exactly one top-level setup. nullptr with
/// `error` set otherwise.
std::unique_ptr<ExperimentalSetup> buildLink2dSetup(const Link2dSpec& s, std::string& error);

/// The specimen as a whole behind its setup (s.wholeSpecimen set; CantileverColumn of the
/// element's length), for the virtual lab. Throws ConfigError naming the element.
std::unique_ptr<SpecimenBehindSetup> buildWholeSpecimen(const std::string& element,
                                                        const Link2dSpec& s);

} // namespace hsmu
