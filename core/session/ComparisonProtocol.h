#pragma once
// ComparisonProtocol: the paper's test protocol (docs/method.md, The test protocol; paper sec. 7)
// for one configuration, three runs under the same record:
//   reference  the compared element, and every other element the updating reaches, is a
//              specimen too: a copy of the true specimen (the updating specimen's
//              `specimen` section, noise-free, each with its own state);
//   initial    the compared element is numerical with its configured (deliberately wrong)
//              parameters, never updated;
//   updated    the same initial parameters, updated online as the configuration says.
// Metrics against the reference, for the compared element's force and the compared DOF's
// displacement:  NRMSE = RMS(x - x_ref) / RMS(x_ref),  peak error = max |x - x_ref|.
// With multi-DOF (link2d) elements also per basic DOF and per actuator (ChannelComparison.h);
// a link2d compared element becomes, in the reference run, a copy of the link2d specimen
// (its setup, actuators and lab) on the compared element's own nodes and geometry.

#include "core/config/TestConfig.h"
#include "core/output/RunLayout.h"
#include "core/session/ChannelComparison.h"
#include "core/rths/TrackingMetrics.h"

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace hsmu {

struct ComparisonOptions {
    std::string element; ///< compared element; "" = the first updating target
    std::string dof;     ///< compared DOF; "" = that element's DOF
    /// One HDF5 record per run (docs/recording.md): DIR/reference/record.h5,
    /// DIR/initial/record.h5, DIR/updated/record.h5, root attribute "run" naming the run;
    /// "" records nothing. Each run is a TestSession (core/session/TestSession.h).
    std::string recordDir;
};

/// One run's histories (physical units: s, rad or m, kN m or kN, m).
struct ComparisonRun {
    std::string name; ///< "reference", "initial", "updated"
    std::vector<double> time, deformation, force, displacement;
    std::vector<std::string> parameterNames;          ///< updated run only
    std::vector<std::vector<double>> parameters;      ///< [step][parameter]
    std::vector<std::vector<double>> stddev;          ///< [step][parameter]
    int appliedUpdates = 0;
    int steps = 0;
    std::string finalState;
    std::vector<std::string> alarms; ///< "t = ... s: message"
    /// Each specimen's tracking, commanded against measured (core/rths/TrackingMetrics.h), and
    /// its deformation unit; specimens in the structure's order.
    std::vector<std::pair<std::string, rths::TrackingReport>> tracking;
    std::vector<std::string> trackingUnits;
    std::string recordError;         ///< why its record could not be written ("" = fine)
    /// How each site of its experimental elements was reached: always "builtin" (the three
    /// runs are in-process); its record's /sites `security` and compare.json's link_security.
    SiteSecurity linkSecurity;
    std::vector<std::string> sites; ///< RunLayout::sites of the run
    /// The multi-DOF elements' channels (empty without them), and from them: every basic DOF
    /// against the reference run's (initial and updated runs) and every actuator's tracking
    /// and force against the reference's (ChannelComparison.h).
    ChannelHistory channels;
    std::vector<BasicDofComparison> basicDofs;
    std::vector<ActuatorComparison> actuators;
};

struct ComparisonMetric {
    double forceNrmse = 0.0, forcePeakError = 0.0;             ///< [-], [force units]
    double displacementNrmse = 0.0, displacementPeakError = 0.0; ///< [-], [m]
};

struct ComparisonResult {
    std::string element, dof;
    std::string forceUnit, deformationUnit;
    ComparisonRun reference, initial, updated;
    ComparisonMetric initialMetric, updatedMetric;
};

/// The three configurations (exposed for tests). Throws ConfigError if cfg has no updating
/// section, the compared element is not numerical, or the specimen has no `specimen` spec.
TestConfig referenceConfig(const TestConfig& cfg, const ComparisonOptions& o = {});
TestConfig initialConfig(const TestConfig& cfg);

/// Run all three to the end (compute only). progress(run index 0..2, fraction) may be empty.
ComparisonResult runComparison(const TestConfig& cfg, const ComparisonOptions& o = {},
                               const std::function<void(int, double)>& progress = {});

/// NRMSE and peak error of x against ref over their common length.
void compareSeries(const std::vector<double>& x, const std::vector<double>& ref, double& nrmse,
                   double& peak);

} // namespace hsmu
