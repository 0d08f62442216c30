#pragma once
// NumericalSite: numerical elements whose force another program computes (an element's
// "numericalSite", docs/configuration.md). core only parses the address and asks a factory
// for the element's law; comms provides the factory (comms/openfresco/OpenSeesTwinSite.h:
// "opensees://HOST:PORT", an OpenSees twin updated online, docs/opensees-twins.md), the same
// way experimental elements get their controls through a ControlFactory (TestFactory.h).
// Thread rules: set the factory before building tests (the front ends do it at start-up);
// reading it is safe from any thread.

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace hsmu {

class HysteresisLaw;
struct ElementSpec;

/// Host and port of "opensees://HOST:PORT".
struct NumericalSiteAddress {
    std::string scheme; ///< "opensees"
    std::string host;
    std::uint16_t port = 0;
};

/// Parse an address; nullopt-like: false with the reason in why.
bool parseNumericalSite(const std::string& text, NumericalSiteAddress& out, std::string& why);
/// "" when text is a valid numerical site address, else why not (for ConfigError).
std::string numericalSiteProblem(const std::string& text);

/// Makes the law of a numerical element on a site from the element's spec and its model law
/// (the configured material, built in process: the site's copy starts from it). Throws
/// ConfigError (or std::exception) with a message when it cannot.
using NumericalSiteFactory = std::function<std::unique_ptr<HysteresisLaw>(
    const ElementSpec& spec, std::unique_ptr<HysteresisLaw> model)>;

/// Install the factory for elements with a numericalSite (replaces any previous one).
void setNumericalSiteFactory(NumericalSiteFactory factory);
/// The installed factory; empty when none (building such an element is then a ConfigError).
NumericalSiteFactory numericalSiteFactory();

} // namespace hsmu
