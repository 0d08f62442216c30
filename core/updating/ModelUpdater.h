#pragma once
// ModelUpdater: the paper's four modules (its Figure 4; docs/method.md, The four modules) around
// one specimen, run by HybridTest after every committed step:
//
//   auxiliary model  <- measured deformation d_m        (its force F_aux vs measured F_m)
//   identifier       <- (d_m, F_m)                      (UKF every step / Nelder-Mead on request)
//   inspector        <- F_aux, F_m, d_m, d_cmd, estimate -> alarms, update request
//   reporter         <- estimate -> target numerical elements, by policy
//
// The auxiliary model starts as a copy of the specimen's numerical model and takes every new
// estimate (its z, e stay continuous); after a Nelder-Mead fit it is replayed over the stored
// history so its state matches the fitted parameters.
// Bounds, thresholds and policies may change between steps (effective next step).
// Offsets (docs/method.md, "Offsets", Online): with an OffsetCheck (setOffsetCheck) the
// specimen's history is calibrated with offsets now and then; offsets the data ask for are a
// separate pending item (pendingOffsets()) that only the operator's approveOffsets() applies
// to the twins (never the policy, never the headless approval flag).

#include "core/hysteresis/HysteresisLaw.h"
#include "core/util/Alarm.h"
#include "core/updating/Identifier.h"
#include "core/updating/Inspector.h"
#include "core/updating/OffsetCheck.h"
#include "core/updating/Reporter.h"

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace hsmu {

class ExperimentalElement;
class HysteresisLaw;
class Structure;

/// What one step of updating produced (for StepRecord and observers).
struct UpdatingSample {
    double auxiliaryForce = 0.0;     ///< F_aux at the step [force units]
    double fitError = 0.0;           ///< inspector's normalized RMS error [-]
    std::vector<double> parameters;  ///< estimate, in the identifier's layout() order
    std::vector<double> stddev;      ///< standard deviations, same order
    int appliedUpdates = 0;          ///< cumulative updates applied to targets
    int updatesThisStep = 0;
    int pendingProposals = 0;
    TrackingIndices tracking;        ///< inspector's last J1 [s], J2, J3 [-]
    bool updateRequested = false;    ///< inspector: fit error above its threshold
    std::vector<UpdateEvent> applied; ///< updates applied to targets at this step (ok ones)
    /// Offers decided at this step without being applied: rejected (headless flag), not
    /// queued (approval queue full) or superseded by a newer proposal. Written to
    /// /updating/events with their decision.
    std::vector<UpdateEvent> decided;
};

class ModelUpdater {
public:
    ModelUpdater(std::string specimenElement, std::unique_ptr<HysteresisLaw> auxiliaryLaw,
                 std::unique_ptr<Identifier> identifier, const InspectorSettings& inspector,
                 std::unique_ptr<Reporter> reporter);
    ~ModelUpdater();

    /// Resolve the specimen in a finalized structure; false with a reason if it is missing.
    bool attach(Structure& structure, double dt, std::string* error);
    /// After step `step` was committed. Returns a reason when the test must hold: the
    /// identifier rejected maxConsecutiveRejections steps in a row (a diverging estimator).
    std::optional<std::string> afterCommit(int step, double time, Structure& structure, std::vector<Alarm>& alarms,
                     UpdatingSample& out);

    const std::string& specimenElement() const { return m_specimen; }
    /// The specimen's basic DOF identified (docs/configuration.md, updating.basicDof): its
    /// measured deformation and force (ExperimentalElement::basicMeasurement) feed the
    /// auxiliary model, the identifier and the inspector. -1 (the default): the element's
    /// reported one (measurement(): a one-DOF specimen's, a link2d's primary). Before attach().
    void setBasicDof(int k) { m_basicDof = k < 0 ? -1 : k; }
    int basicDof() const { return m_basicDof; }
    /// The identifier's layout: the order of UpdatingSample's parameters and stddev.
    const ParameterLayout& layout() const { return m_identifier->layout(); }
    const std::vector<std::string>& parameterNames() const { return layout().names(); }
    Identifier& identifier() { return *m_identifier; }
    const Identifier& identifier() const { return *m_identifier; }
    Inspector& inspector() { return m_inspector; }
    const Inspector& inspector() const { return m_inspector; }
    Reporter& reporter() { return *m_reporter; }
    const Reporter& reporter() const { return *m_reporter; }
    const HysteresisLaw& auxiliaryModel() const { return *m_aux; }
    /// The current estimate and standard deviations, in layout() order.
    void fillEstimate(UpdatingSample& out) const;

    /// Operator decisions (between steps).
    bool approve(int proposalId, Structure& structure, int step, double time,
                 std::vector<Alarm>& alarms);
    bool reject(int proposalId) { return m_reporter->reject(proposalId); }
    void setMaxConsecutiveRejections(int n) { m_maxRejections = n < 1 ? 1 : n; }
    /// Headless flag for the OnApproval policy: approve (true) or reject every proposal.
    /// It never decides the offsets.
    void setAutoResolve(std::optional<bool> approveAll) { m_autoResolve = approveAll; }

    /// The online offset check (nullptr: none, the default).
    void setOffsetCheck(std::unique_ptr<OffsetCheck> check) { m_offsets = std::move(check); }
    const OffsetCheck* offsetCheck() const { return m_offsets.get(); }
    /// The offsets waiting for the operator's decision (nullptr: none).
    const OffsetProposal* pendingOffsets() const;
    /// The operator approves the pending offsets `id` (between steps): every reporter
    /// target's law becomes F = F_law(u - u0) + F0 (OffsetLaw.h: an OffsetLaw around it, or
    /// its offsets set if it has them), all targets or none. Returns the proposal applied;
    /// nullopt with `error` set if `id` is not pending or a target has no law to change
    /// (the proposal then stays pending).
    std::optional<OffsetProposal> approveOffsets(int id, Structure& structure,
                                                 std::string* error);
    /// The operator rejects the pending offsets `id`; nullopt if it is not pending.
    std::optional<OffsetProposal> rejectOffsets(int id);

private:
    /// The identified values (layout order) to the auxiliary model: as one set, else value by
    /// value (non-finite and refused values skipped).
    void applyToAuxiliary(std::span<const double> values);
    /// Trial + commit of the auxiliary model at a measured deformation (`first`: the first
    /// sample, reached quasi-statically by a rate-dependent model).
    LawStatus stepAuxiliary(double deformation, bool first);
    /// Moves the applied events into out.applied, rejected and not-queued ones into
    /// out.decided; refusals become alarms (a full approval queue one alarm until it drains).
    void report(std::vector<UpdateEvent>& events, std::vector<Alarm>& alarms, int step,
                double time, UpdatingSample& out);

    std::string m_specimen;
    std::unique_ptr<HysteresisLaw> m_aux;
    std::unique_ptr<HysteresisLaw> m_auxInitial; // virgin copy for replays
    std::unique_ptr<Identifier> m_identifier;
    Inspector m_inspector;
    std::unique_ptr<Reporter> m_reporter;
    std::unique_ptr<OffsetCheck> m_offsets;
    ExperimentalElement* m_element = nullptr;
    int m_basicDof = -1;
    std::vector<double> m_history; // measured deformations, for replays of the auxiliary model
    double m_dt = 0.0;             // the step (a rate-dependent auxiliary law's time increment)
    std::optional<bool> m_autoResolve;
    // Resolved by attach(): the position in the auxiliary law of each layout entry (-1: none).
    std::vector<int> m_auxIndex;
    // Per-step buffers (kept: no allocation per step).
    std::vector<double> m_auxValues;
    std::vector<int> m_auxApply;
    std::vector<UpdateEvent> m_events; ///< this step's update decisions (reused)
    int m_rejections = 0;
    int m_maxRejections = 20;
    bool m_queueFullReported = false;
};

} // namespace hsmu
