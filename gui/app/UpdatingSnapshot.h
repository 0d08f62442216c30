#pragma once
// UpdatingSnapshot: the state of a test's online model updating that the operator's panels
// show (parameters with sigma, bounds and locks; pending proposals; the reporter's policy and
// the inspector's threshold), copied out of the live ModelUpdater on the worker thread so the
// GUI never touches the test. Values are in the law's own units (normalized by uRef / fRef for
// a Bouc-Wen law, docs/method.md, Normalized units); times in s.
// Thread rules: plain data; snapshotOf() on the thread that runs the test.

#include "core/identification/ParameterSet.h"
#include "core/updating/OffsetCheck.h"
#include "core/updating/Reporter.h"

#include <QMetaType>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace hsmu {
class HybridTest;
}

namespace hsmu::gui {

struct ParameterState {
    std::string name;
    double value = 0.0; ///< current estimate
    double sigma = 0.0; ///< standard deviation (0 where the method has none)
    ParameterBounds bounds;
    bool locked = false;
};

struct UpdatingSnapshot {
    bool enabled = false; ///< false: the test has no updater, everything else is empty
    int step = 0;         ///< the committed step the snapshot was taken after
    double time = 0.0;    ///< its test time [s]
    std::string specimen; ///< the identified experimental element
    std::string method;   ///< e.g. "UKF", "Nelder-Mead"
    bool canLock = false; ///< the method can lock parameters
    std::vector<ParameterState> parameters;         ///< identifier order
    std::vector<UpdateProposal> pending;            ///< the approval queue, oldest first
    /// Target element -> the estimator's latest values as that target would take them (in
    /// its proposals' parameter order): what a proposal is compared with (onApproval).
    std::map<std::string, std::vector<double>> latest;
    /// onApproval: test time [s] between two proposals for a target; a proposal this old is
    /// stale (Reporter::stale) and refused.
    double proposalInterval = 0.0;
    std::map<std::string, ParameterValues> targets; ///< target element -> its current values
    ReporterPolicy policy = ReporterPolicy::EveryStep;
    int everyN = 10;
    double fitError = 0.0;     ///< inspector's normalized RMS error [-]
    double fitThreshold = 0.0; ///< inspector's threshold [-]
    int appliedUpdates = 0;
    int notQueued = 0;   ///< offers not queued (approval queue full), all in the record
    int maxPending = 0;  ///< the approval queue's capacity
    /// The offsets waiting for the operator (ModelUpdater::pendingOffsets), in the
    /// specimen's units below; never applied without the operator's approval.
    std::optional<OffsetProposal> offsets;
    std::string deformationUnit, forceUnit; ///< the specimen's (ElementUnits.h)

    const ParameterState* parameter(const std::string& name) const;
    /// Whether proposal p is stale at this snapshot's time (Reporter::stale).
    bool stale(const UpdateProposal& p) const;
};

/// Copy the updating state of `test` (enabled = false if it has no updater).
UpdatingSnapshot snapshotOf(const HybridTest& test);

} // namespace hsmu::gui

Q_DECLARE_METATYPE(hsmu::gui::UpdatingSnapshot)
