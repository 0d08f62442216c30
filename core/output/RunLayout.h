#pragma once
// RunLayout: what the outputs of a run need to know about its structure (names, types, units),
// copied out of the Structure so that writers, statistics and the GUI's plots can label
// StepRecords without touching the live Structure (which belongs to the test's thread).
// Index i of dofs / elements matches index i of StepRecord::u / StepRecord::elements.
// With online model updating, `updating` names the identified parameters in the order of
// StepRecord::updating.parameters / .stddev (values in the law's own units: normalized by
// uRef / fRef for a Bouc-Wen law) and the specimen whose units the auxiliary force carries.
// Thread rules: plain data, copy freely.

#include "core/experiment/ElementChannels.h"
#include "core/output/ElementUnits.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace hsmu {

class HybridTest;
class Structure;

struct ElementInfo {
    std::string name;
    std::string type;          ///< configuration type, e.g. "rotationalBaseSpring"
    bool experimental = false; ///< a specimen (commanded and measured deformation)
    /// Hysteretic: a specimen, or a numerical element whose law is not "elastic".
    bool nonlinear = false;
    ElementUnits units;
};

struct UpdatingInfo {
    std::string specimen;                ///< the identified experimental element
    std::string method;                  ///< the identifier's name, e.g. "UKF"
    std::vector<std::string> parameters; ///< identified parameters, record order
    ElementUnits units;                  ///< the identified DOF's units (auxiliary force)
    /// The specimen's identified basic DOF (updating.basicDof) by its channel name ("axial",
    /// "shear", "rotation": its measured history is the specimen's channels "<name>
    /// deformation" and "<name> force"); "" for the specimen's own (reported) column.
    std::string basicDof;
};

struct RunLayout {
    std::vector<std::string> dofNames; ///< full DOFs, displacement in m
    std::vector<ElementInfo> elements;
    std::optional<UpdatingInfo> updating; ///< set when the test runs online model updating
    /// Sites of the experimental elements (docs/configuration.md), order of
    /// StepRecord::siteRoundTrips; empty without experimental elements.
    std::vector<std::string> sites;
    /// The multi-DOF elements' channels (core/experiment/ElementChannels.h: every basic DOF
    /// and actuator), order of StepRecord::channels; empty without multi-DOF elements.
    std::vector<ElementChannel> channels;

    /// Valid before or after Structure::finalize(); no updating information.
    static RunLayout of(const Structure& structure);
    /// The test's structure plus its updater's parameters (if it has an updater).
    static RunLayout of(const HybridTest& test);
};

/// How the console reached each site (site name -> "tls", "plaintext-loopback",
/// "insecure-plaintext" or "builtin": comms::LinkAddress::security(), docs/security.md).
using SiteSecurity = std::vector<std::pair<std::string, std::string>>;

/// The security of each site (e.g. RunLayout::sites), in that order: the last entry of `given`
/// naming the site, "" for a site `given` does not name. The record's /sites `security`,
/// summary.json's and compare.json's `link_security` (docs/recording.md, docs/cli.md).
std::vector<std::string> securityOfSites(const std::vector<std::string>& sites,
                                         const SiteSecurity& given);

/// Every site of layout.sites reached in-process ("builtin"): the runs of `hsmu compare`.
SiteSecurity builtinSiteSecurity(const RunLayout& layout);

} // namespace hsmu
