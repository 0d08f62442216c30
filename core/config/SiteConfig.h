#pragma once
// SiteConfig: the "sites" section of a test configuration (docs/configuration.md, Sites).
// A site is one place that answers for experimental elements: the built-in virtual lab, an
// hsmu-controller, an OpenFresco site server or an OpenSees adapter element. Each site names
// its address, the elements it serves, and optionally its protocol, frame sizes, token file
// and timeouts:
//
//   "sites": [
//     {"name": "Lab D", "address": "tcp://10.0.0.5:5101", "elements": ["Bearing D"],
//      "tokenFile": "lab-d.token", "connectTimeout": 3, "stepDeadline": 10},
//     {"name": "Lab C", "address": "tcp://10.0.0.6:5101", "elements": ["Bearing C"]}
//   ]
//
// Experimental elements not listed in any site belong to the site "controller": the front
// end's --controller address (the built-in virtual lab by default), i.e. a configuration
// without "sites" is one site, as before. core only carries these values; comms builds the
// links (comms/link/ControlFactory.h). Timeouts are seconds whatever the "units" block says.

#include "core/config/LinkConfig.h"

#include <optional>
#include <string>
#include <vector>

namespace hsmu {

class JsonCursor;
struct ElementSpec;

/// The name of the site of the experimental elements no site lists.
inline constexpr const char* kDefaultSiteName = "controller";

struct SiteSpec {
    std::string name;
    /// "builtin", tcp://HOST:PORT, simapp://, generictcp:// or adapter://HOST:PORT (checked
    /// when the links are built: comms::LinkAddress)
    std::string address;
    std::vector<std::string> elements; ///< experimental elements it serves (>= 1)
    LinkSpec link;         ///< protocol and sizes (defaults: the "controller" section's)
    std::string tokenFile; ///< resolved path, "" = none
    std::string token;     ///< read from tokenFile at load (never in the configuration)
    std::optional<double> connectTimeout; ///< [s]; absent: the front end's
    std::optional<double> stepDeadline;   ///< [s]; absent: the front end's
};

/// Read root.sites (none when absent), checking names, addresses and the element mapping, and
/// set ElementSpec::site of every element a site lists. Throws ConfigError naming the field.
std::vector<SiteSpec> parseSites(const JsonCursor& root, const std::string& baseDir,
                                 const LinkSpec& defaults, std::vector<ElementSpec>& elements);

} // namespace hsmu
