#pragma once
// Reporter (docs/method.md, The four modules): decides *when* identified parameters reach the
// target numerical elements and *which* ones go, with an optional conversion for category-2 twins.
//
// Policies:
//   EveryStep     apply every offer at once;
//   ZeroCrossing  apply at the first step where the target element's force changed sign
//                 since the last committed step (no jump in force: the paper's choice);
//   EveryNSteps   apply every N-th step;
//   OnApproval    queue a proposal per target and offer, oldest first (a FIFO: nothing is
//                 replaced); the operator approves or rejects each one. The queue holds at
//                 most maxPending() proposals: an offer made while it is full is not queued and
//                 comes back as an UpdateEvent with decision NotQueued (for the record), never
//                 dropped silently.
// Which: each target names its parameters (the paper sends all but A0 and deltaA); a value is
// multiplied by the target's scale factor for that parameter (default 1) before it is set.
// Applying keeps the target law's state (z, e for Bouc-Wen): only the parameters change.
// Nothing non-finite is ever applied; a value the law refuses is reported, not applied.
// Thread rules: none (called from the test's thread; the GUI calls approve/reject through it).

#include "core/identification/ParameterSet.h"

#include <deque>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace hsmu {

class HysteresisLaw;
class Structure;

enum class ReporterPolicy { EveryStep, ZeroCrossing, EveryNSteps, OnApproval };
const char* reporterPolicyName(ReporterPolicy p);
std::optional<ReporterPolicy> parseReporterPolicy(const std::string& text);

struct ReporterTarget {
    std::string element;                 ///< a numerical element with a law
    std::vector<std::string> parameters; ///< names sent to it
    ParameterValues scale;               ///< per-parameter factor (category-2 conversion)
};

struct UpdateProposal {
    int id = 0;
    int step = 0;
    double time = 0.0; ///< [s]
    std::string element;
    ParameterValues proposed; ///< after scaling
    ParameterValues current;  ///< the target's values when proposed
    double fitError = std::numeric_limits<double>::quiet_NaN(); ///< [-] when proposed (NaN: unknown)
};

/// What became of an offer: applied to the target, refused by its law (or not finite), rejected
/// by the operator, or not queued (the approval queue was full). The record keeps the code
/// (updateDecisionName(), language-neutral).
enum class UpdateDecision { Applied, Refused, Rejected, NotQueued };
const char* updateDecisionName(UpdateDecision d);

struct UpdateEvent {
    int step = 0;
    double time = 0.0;
    std::string element;
    ParameterValues applied; ///< the values applied (Applied) or offered (otherwise)
    bool ok = true;          ///< decision == Applied
    std::string message; ///< why, when !ok
    UpdateDecision decision = UpdateDecision::Applied;
    int proposal = 0; ///< the proposal's id under OnApproval (0: none)
};

class Reporter {
public:
    Reporter(std::vector<ReporterTarget> targets, ReporterPolicy policy, int everyN = 10);

    void setPolicy(ReporterPolicy p, int everyN);
    ReporterPolicy policy() const { return m_policy; }
    int everyN() const { return m_everyN; }
    const std::vector<ReporterTarget>& targets() const { return m_targets; }

    /// Offer the identified values after step `step` was committed. Applies or queues
    /// according to the policy; returns the updates applied now.
    std::vector<UpdateEvent> offer(int step, double time, const ParameterValues& identified,
                                   Structure& structure);

    const std::deque<UpdateProposal>& pending() const { return m_pending; }
    /// Apply a pending proposal (by id) now; nullopt if there is no such proposal.
    std::optional<UpdateEvent> approve(int id, Structure& structure, int step, double time);
    bool reject(int id);
    /// Reject a pending proposal: its event (decision Rejected, the values it proposed) at
    /// `step`, `time`; nullopt if there is no such proposal.
    std::optional<UpdateEvent> rejectProposal(int id, int step, double time);
    /// Apply (true) or reject (false) every pending proposal: the headless approval flag.
    /// Returns every decision (rejections too, decision Rejected).
    std::vector<UpdateEvent> resolveAll(bool approve, Structure& structure, int step, double time);

    /// The approval queue's capacity (>= 1; default kDefaultMaxPending).
    void setMaxPending(int n) { m_maxPending = n < 1 ? 1 : n; }
    int maxPending() const { return m_maxPending; }
    static constexpr int kDefaultMaxPending = 100;
    /// The fit error [-] stamped on proposals queued from now on (ModelUpdater: the
    /// inspector's, before each offer).
    void setProposalFitError(double fitError) { m_fitError = fitError; }
    /// Offers not queued because the queue was full, since construction.
    int notQueuedCount() const { return m_notQueued; }

    int appliedCount() const { return m_applied; }

    /// Resolve once (ModelUpdater::attach) what offerValues() needs every step: each target's
    /// law in `structure` and, for each of its parameters, its position in `identifiedNames`
    /// (the identifier's estimateNames()) and in the law. False with a reason if a target is
    /// not a numerical element with a law.
    bool bind(Structure& structure, const std::vector<std::string>& identifiedNames,
              std::string* error);
    /// offer() for values in the bound layout, on the structure bound (else as offer()):
    /// the same decisions and updates without lookups by name or allocation (apart from
    /// OnApproval proposals, refusals and the event of an update applied). Returns how many
    /// updates were applied now; every update decided now, applied or refused, is appended to
    /// `events` as offer() returns it.
    int offerValues(int step, double time, std::span<const double> identified,
                    Structure& structure, std::vector<UpdateEvent>& events);

private:
    // A target resolved by bind(): its parameters in name order (the order offer() applies
    // them in), their positions in the identified layout and in the law, their scale.
    struct BoundTarget {
        HysteresisLaw* law = nullptr;
        std::vector<std::string> names; // sorted: proposalFor()'s map order
        std::vector<int> identifiedIndex, lawIndex;
        std::vector<double> scale, values; // values: this step's, scaled (kept: no allocation)
    };
    /// Whether target i takes an offer now (ZeroCrossing: its force changed sign since the
    /// last offer); remembers the force.
    bool dueNow(std::size_t i, int step, double force);
    /// Queue a proposal, or (queue full) append its NotQueued event to `events`.
    void queueProposal(const ReporterTarget& t, int step, double time,
                       const ParameterValues& identified, const HysteresisLaw* law,
                       std::vector<UpdateEvent>& events);
    ParameterValues identifiedMap(std::span<const double> identified) const;
    ParameterValues proposalFor(const ReporterTarget& t, const ParameterValues& identified) const;
    UpdateEvent apply(const std::string& element, const ParameterValues& values,
                      Structure& structure, int step, double time);

    std::vector<ReporterTarget> m_targets;
    ReporterPolicy m_policy;
    int m_everyN;
    std::vector<double> m_lastForce; // per target, committed force at the previous offer
    const Structure* m_boundStructure = nullptr;
    std::vector<std::string> m_boundNames;
    std::vector<BoundTarget> m_bound; // per target, after bind()
    std::deque<UpdateProposal> m_pending;
    int m_nextId = 1;
    int m_applied = 0;
    int m_maxPending = kDefaultMaxPending;
    int m_notQueued = 0;
    double m_fitError = std::numeric_limits<double>::quiet_NaN();
};

} // namespace hsmu
