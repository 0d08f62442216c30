#pragma once
// Reporter (docs/method.md, The four modules): decides *when* identified parameters reach the
// target numerical elements and *which* ones go, with an optional conversion for category-2 twins.
//
// Policies:
//   EveryStep     apply every offer at once;
//   ZeroCrossing  apply at the first step where the target element's force changed sign
//                 since the last committed step (no jump in force: the paper's choice);
//   EveryNSteps   apply every N-th step;
//   OnApproval    at most one proposal per target, renewed every proposalInterval() [s] of
//                 test time: the first offer at least one interval after the target's last
//                 proposal becomes a new proposal with the estimator's values of that step,
//                 and it supersedes the one still pending for that target (which comes back
//                 as an UpdateEvent with decision Superseded, for the record). The operator
//                 approves or rejects the pending one; approve() refuses a proposal that is
//                 no longer pending (superseded: supersededBy() names its successor) or stale
//                 (made one interval or more before the approval: no offer renewed it), so
//                 an approval always applies the estimate of less than one interval before.
//                 The queue holds at most maxPending() proposals: an offer made while it is
//                 full is not queued and comes back with decision NotQueued, never dropped.
// Which: each target names its parameters (the paper sends all but A0 and deltaA); a value is
// multiplied by the target's scale factor for that parameter (default 1) before it is set.
// Applying keeps the target law's state (z, e for Bouc-Wen): only the parameters change.
// Nothing non-finite is ever applied; a value the law refuses is reported, not applied.
// Thread rules: none (called from the test's thread; the GUI calls approve/reject through it).

#include "core/identification/ParameterLayout.h"
#include "core/identification/ParameterUpdate.h"

#include <deque>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace hsmu {

class Element;
class HysteresisLaw;
class Structure;

enum class ReporterPolicy { EveryStep, ZeroCrossing, EveryNSteps, OnApproval };
const char* reporterPolicyName(ReporterPolicy p);
std::optional<ReporterPolicy> parseReporterPolicy(const std::string& text);

struct ReporterTarget {
    std::string element;                 ///< a numerical element with a law
    std::vector<std::string> parameters; ///< names sent to it (as configured)
    /// Per-parameter factor by name, as configured (category-2 conversion; default 1).
    std::map<std::string, double> scale;
    /// The twin's basic DOF whose law is updated (Element::basicLaw; docs/configuration.md,
    /// updating.basicDof): -1 (default) its law() (a one-DOF element's, a link2d's primary).
    int basicDof = -1;
};

/// The law target `basicDof` names in `e` (ReporterTarget::basicDof): e->law() for -1, else
/// e->basicLaw(basicDof); nullptr when there is none (or e is null, or the DOF out of range).
HysteresisLaw* reporterTargetLaw(Element* e, int basicDof);
const HysteresisLaw* reporterTargetLaw(const Element* e, int basicDof);
/// swapLaw() / swapBasicLaw() on the same law reporterTargetLaw() names.
bool swapReporterTargetLaw(Element& e, int basicDof, std::unique_ptr<HysteresisLaw>& law);

struct UpdateProposal {
    int id = 0;
    int step = 0;
    double time = 0.0; ///< [s]
    std::string element;
    ParameterLayout parameters;   ///< the target's parameters (name order)
    std::vector<double> proposed; ///< after scaling, in `parameters` order
    std::vector<double> current;  ///< the target's values when proposed (same order)
    double fitError = std::numeric_limits<double>::quiet_NaN(); ///< [-] when proposed (NaN: unknown)
    int basicDof = -1; ///< the target's basic DOF (ReporterTarget::basicDof)
};

class Reporter {
public:
    Reporter(std::vector<ReporterTarget> targets, ReporterPolicy policy, int everyN = 10);

    void setPolicy(ReporterPolicy p, int everyN);
    ReporterPolicy policy() const { return m_policy; }
    int everyN() const { return m_everyN; }
    const std::vector<ReporterTarget>& targets() const { return m_targets; }

    /// Resolve once (ModelUpdater::attach) what offer() needs every step: each target's law
    /// in `structure` and, for each of its parameters that `identified` (the identifier's
    /// layout) has, its position there and in the law. A target's parameters are taken in
    /// name order (the order of its events and proposals). False with a reason if a target
    /// is not a numerical element with a law, or names (in its parameters or scale) a
    /// parameter its law does not have.
    bool bind(Structure& structure, const ParameterLayout& identified, std::string* error);
    /// Offer the identified values (the bound layout) after step `step` was committed.
    /// Applies or queues according to the policy, without lookups by name or allocation
    /// (apart from OnApproval proposals, refusals and the event of an update applied).
    /// Returns how many updates were applied now; every update decided now, applied or
    /// refused, is appended to `events`. On a structure other than the bound one the targets
    /// are bound to it first (a target that cannot be is refused with the reason).
    /// Precondition: bind() was called; identified.size() == the bound layout's size.
    int offer(int step, double time, std::span<const double> identified, Structure& structure,
              std::vector<UpdateEvent>& events);

    const std::deque<UpdateProposal>& pending() const { return m_pending; }
    /// Apply a pending proposal (by id) now; nullopt if there is no such proposal, or if it
    /// is stale at `time` (it stays pending until an offer supersedes it).
    std::optional<UpdateEvent> approve(int id, Structure& structure, int step, double time);
    /// OnApproval: test time [s] between two proposals for a target (> 0; default
    /// kDefaultProposalInterval). 0 or less: every offer supersedes the pending proposal.
    void setProposalInterval(double seconds) { m_proposalInterval = seconds > 0.0 ? seconds : 0.0; }
    double proposalInterval() const { return m_proposalInterval; }
    static constexpr double kDefaultProposalInterval = 2.0;
    /// Whether `p` is one interval or more older than `time` [s] (approve() refuses it).
    bool stale(const UpdateProposal& p, double time) const
    {
        return stale(p, time, m_proposalInterval);
    }
    /// The same for a proposal interval `interval` [s] (0: any step later is stale).
    static bool stale(const UpdateProposal& p, double time, double interval);
    /// The id of the proposal that superseded proposal `id` (the most recent ones are
    /// remembered), or nullopt.
    std::optional<int> supersededBy(int id) const;
    /// The values of the latest offer to target element `element` (after scaling, in the
    /// order of its proposals' parameters): what the estimator believes now, as the target
    /// would take it. Empty before the first offer or for an unknown element.
    std::span<const double> latestOffer(const std::string& element) const;
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

private:
    // A target resolved by bind(): its parameters in name order, their positions in the
    // identified layout and in the law (-1: the law has none), their scale.
    struct BoundTarget {
        HysteresisLaw* law = nullptr;
        ParameterLayout names;
        std::vector<int> identifiedIndex, lawIndex;
        std::vector<double> scale, values; // values: this step's, scaled (kept: no allocation)
        bool offered = false;              // values hold an offer
    };
    /// Whether target i takes an offer now (ZeroCrossing: its force changed sign since the
    /// last offer); remembers the force.
    bool dueNow(std::size_t i, int step, double force);
    /// Queue target i's proposal of b.values, or (queue full) append its NotQueued event.
    void queueProposal(std::size_t i, int step, double time, std::vector<UpdateEvent>& events);
    /// Set `values` (in `names` order) to `law` at the positions `lawIndex`, all or nothing:
    /// the event, refused with the reason when a value is not finite or the law refuses it.
    UpdateEvent apply(HysteresisLaw* law, const std::string& element, const ParameterLayout& names,
                      std::span<const int> lawIndex, std::span<const double> values, int step,
                      double time);

    std::vector<ReporterTarget> m_targets;
    ReporterPolicy m_policy;
    int m_everyN;
    std::vector<double> m_lastForce; // per target, committed force at the previous offer
    std::vector<double> m_lastProposal; // per target, test time [s] of its last proposal (NaN: none)
    const Structure* m_boundStructure = nullptr;
    ParameterLayout m_identified;
    std::vector<BoundTarget> m_bound; // per target, after bind()
    std::deque<UpdateProposal> m_pending;
    int m_nextId = 1;
    int m_applied = 0;
    int m_maxPending = kDefaultMaxPending;
    int m_notQueued = 0;
    double m_proposalInterval = kDefaultProposalInterval;
    std::deque<std::pair<int, int>> m_superseded; // (old id, new id), the most recent
    double m_fitError = std::numeric_limits<double>::quiet_NaN();
};

} // namespace hsmu
