#pragma once
// LinkConfig: the console's side of the "controller" section (docs/configuration.md): which
// wire protocol links the console to a controller given as tcp://HOST:PORT, and for the
// OpenFresco protocols the frame sizes (docs/openfresco.md). core only carries these values;
// comms builds the link. The section's other fields (rate, stepDuration, ...) belong to
// hsmu-controller (comms/controller/ControllerSettings.h) and are ignored here.

#include "core/config/TlsConfig.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace hsmu {

class JsonCursor;

/// The one set of link timeout defaults (seconds), used by every link (comms' TcpControlOptions
/// and OpenFresco options) and so by the console, `hsmu run` and `hsmu compare` alike
/// (docs/configuration.md, "Timeouts"). A configuration's controller section may override them.
struct LinkTimeouts {
    static constexpr double kConnect = 3.0;       ///< [s] per connection attempt
    static constexpr double kStepDeadline = 10.0; ///< [s] for each reply of a step
};

struct LinkSpec {
    std::string protocol = "native"; ///< "native", "simapp" or "generictcp"
    int dataSize = 256;              ///< OpenFresco: doubles per frame
    /// OpenFresco sizes header: disp, vel, accel, force, time (ctrl: sent, daq: received).
    std::array<int, 5> ctrlSizes{1, 0, 0, 0, 0};
    std::array<int, 5> daqSizes{1, 0, 0, 1, 0};
    std::string initFile;               ///< generictcp: path (resolved), "" = none
    std::vector<std::string> initLines; ///< its lines, read when the configuration is loaded
    /// controller.connectTimeout / controller.stepDeadline [s], when the configuration sets
    /// them (in (0, 600]); otherwise the link's own options (LinkTimeouts defaults) apply.
    std::optional<double> connectTimeout, stepDeadline;
    /// The configuration's "tls" block (TlsConfig.h), or a site's own: certificates for a
    /// tls://HOST:PORT link. Absent: such a link cannot connect (the error says why).
    std::optional<TlsSpec> tls;
};

/// The names of the protocol field's values, for messages.
inline constexpr const char* kLinkProtocols = "native, simapp or generictcp";

/// Read the link fields of root.controller (defaults when absent) and root.tls. baseDir resolves a relative
/// initFile. Throws ConfigError naming the field.
LinkSpec parseLinkSpec(const JsonCursor& root, const std::string& baseDir);
/// The link fields (protocol, dataSize, ctrlSizes, daqSizes, initFile) of the object at c,
/// starting from defaults (a site in "sites" starts from the controller section's).
LinkSpec parseLinkFields(const JsonCursor& c, const std::string& baseDir, LinkSpec defaults);

} // namespace hsmu
