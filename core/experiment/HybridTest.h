#pragma once
// HybridTest: the step loop of ARCHITECTURE.md ("Data flow of one integration step").
//
//   integrator predicts u[n+1]
//   every specimen target is checked against its limits before any is sent (else: hold)
//   experimental elements: setTarget / measure; numerical elements: trial forces
//   integrator solves a[n+1], v[n+1]; commit all elements
//   StepRecord -> observers
//
// Single-threaded, no sleeps: the caller (CLI loop or the GUI's worker thread) calls step().
// A fault never throws out of step(): the test goes to State::Holding with an Alarm saying
// why, every committed step has already reached the observers, and resume() retries the
// same step (after the operator changed what caused the hold).
// Thread rules: one thread (the caller of step()), except emergencyHold(), which any thread
// may call at any time, also while step() is blocked on a silent link.
//
// The updated model (docs/method.md, "The updated model"): when online updating changes a
// numerical element's parameters, K0, the Rayleigh damping matrix C (and its coefficients)
// and the integrator's matrices are KEPT as computed at prepare(): the damping of the test
// is a property of the structure chosen before it starts, and the explicit schemes' matrices
// are factored once. The stability check is REVISITED: omega_max of the updated initial
// stiffness (Structure::updatedMaxFrequency) is computed after every applied update
// (updatedStability()); a Warning alarm (kind Stability) is raised when an explicit scheme
// crosses its limit omega_max dt (once per crossing, and an Info alarm when it is back within).
// The test is not held for it: the step's own checks hold it if the response diverges.

#include "core/groundmotion/GroundMotion.h"
#include "core/integration/Integrator.h"
#include "core/integration/StabilityCheck.h"
#include "core/experimental/SiteStatus.h"
#include "core/util/Alarm.h"
#include "core/experiment/StepRecord.h"

#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace hsmu {

class Element;
class ExperimentalElement;
class ModelUpdater;
class Integrator;
class Structure;

struct HybridTestOptions {
    double dt = 0.01;           ///< integration step [s]
    double duration = 0.0;      ///< test duration [s]; <= 0: the whole record
    bool allowUnstable = false; ///< run an explicit scheme past omega_max dt anyway
};

class HybridTest {
public:
    enum class State { Created, Ready, Running, Holding, Finished, Failed };
    enum class StepResult { Advanced, Finished, Held, NotReady };

    /// groundMotion is resampled to options.dt if its interval differs.
    HybridTest(std::unique_ptr<Structure> structure, std::unique_ptr<Integrator> integrator,
               const GroundMotion& groundMotion, const HybridTestOptions& options);
    ~HybridTest();
    HybridTest(const HybridTest&) = delete;
    HybridTest& operator=(const HybridTest&) = delete;

    /// Finalize the structure, check stability, evaluate the initial state, emit step 0.
    /// False (state Failed) with lastError() set if the test cannot start.
    bool prepare();
    StepResult step();
    /// Operator's emergency hold between steps.
    void hold(const std::string& reason);
    /// Leave a hold; the held step is retried by the next step().
    /// Who leaves a hold, as the record tells it: the operator (Resume) or the session's
    /// reconnect policy after a link fault (TestSession, ReconnectPolicy).
    enum class ResumeCause { Operator, Reconnect };
    /// Leave a hold; the alarm says who: Operator: OperatorHold "test resumed"; Reconnect: an
    /// Info ControlFault "test resumed after an automatic reconnect".
    void resume(ResumeCause cause = ResumeCause::Operator);
    /// Out of band, thread-safe (any thread, any time; returns after at most a short bounded
    /// send per control): every experimental element's control gets
    /// ExperimentalControl::emergencyHold(reason) now, a step blocked on a link returns
    /// promptly, and the test holds (AlarmKind::OperatorHold, "test held: emergency hold:
    /// reason") at the end of the current step() or at the start of the next one. Before
    /// prepare() has connected every control, only the next step() holds. Cleared by resume().
    void emergencyHold(const std::string& reason);

    State state() const { return m_state; }
    int currentStep() const { return m_step; }
    int totalSteps() const { return m_totalSteps; }
    double time() const { return m_step * m_options.dt; }
    double dt() const { return m_options.dt; }
    const std::string& lastError() const { return m_lastError; }
    const StabilityReport& stability() const { return m_stability; }
    /// The stability check of the updated model (equal to stability() until an update).
    const StabilityReport& updatedStability() const { return m_updatedStability; }
    const std::vector<Alarm>& alarms() const { return m_alarms; }
    const GroundMotion& groundMotion() const { return m_groundMotion; }
    Structure& structure() { return *m_structure; }
    const Structure& structure() const { return *m_structure; }
    const Integrator& integrator() const { return *m_integrator; }

    /// Online model updating (optional; set before prepare()).
    void setUpdater(std::unique_ptr<ModelUpdater> updater);
    ModelUpdater* updater() { return m_updater.get(); }
    const ModelUpdater* updater() const { return m_updater.get(); }
    /// Recheck the stability of the updated model (see above) after a numerical element's
    /// parameters changed; the updater's applied updates and approveUpdate() call it.
    void revisitUpdatedModel();
    /// Operator decision on a pending update proposal (between steps).
    bool approveUpdate(int proposalId);
    bool rejectUpdate(int proposalId);
    /// Operator decision on the pending offsets (ModelUpdater::approveOffsets; between
    /// steps): false with `error` set if they are not pending or cannot be applied.
    bool approveOffsets(int id, std::string* error);
    bool rejectOffsets(int id);

    /// Per-site health (sites: docs/configuration.md), updated after every step, hold and
    /// resume; readable from any thread.
    std::shared_ptr<const SiteMonitor> siteMonitor() const { return m_siteMonitor; }

    /// Observers are not owned; they must outlive the test or be removed.
    void addObserver(StepObserver* observer);
    void removeObserver(StepObserver* observer);

private:
    void enterHold(AlarmKind kind, const std::string& reason);
    /// The pending emergency hold's reason (and clears it), nullopt when none.
    std::optional<std::string> takeEmergency();
    void raise(AlarmSeverity severity, AlarmKind kind, const std::string& message);
    /// A message from a template: its code and arguments (Alarm).
    void raise(AlarmSeverity severity, AlarmKind kind, const std::string& message,
               const char* code, std::vector<std::string> args);
    void publish();

    std::unique_ptr<Structure> m_structure;
    std::unique_ptr<Integrator> m_integrator;
    GroundMotion m_groundMotion;
    HybridTestOptions m_options;
    State m_state = State::Created;
    int m_step = 0;
    int m_totalSteps = 0;
    std::string m_lastError;
    StabilityReport m_stability;
    StabilityReport m_updatedStability;
    std::vector<double> m_initialStiffness; ///< per element, at the last revisit
    std::vector<Alarm> m_alarms;
    std::vector<StepObserver*> m_observers;
    std::vector<ExperimentalElement*> m_specimens; // owned by the structure
    std::vector<Element*> m_timed; // numerical elements with a scheduled force (Element.h)
    std::unique_ptr<ModelUpdater> m_updater;
    StepRecord m_record;
    Eigen::VectorXd m_uFull; // step()'s trial at every DOF (storage reused)
    // step()'s trial, restoring force and undo state, kept so that a step allocates nothing.
    Eigen::VectorXd m_uTrial, m_r;
    Integrator::Snapshot m_before;
    // The elements with channels (ElementChannels.h), in structure order: found once at
    // prepare() rather than asked of every element every step.
    std::vector<const Element*> m_channelElements;
    std::shared_ptr<SiteMonitor> m_siteMonitor = std::make_shared<SiteMonitor>();
    std::vector<SiteStatus> m_sites; // rebuilt at prepare, hold and resume; refreshed per step
    void updateSites();
    // Emergency hold (written by any thread).
    std::atomic<bool> m_prepared{false}; // m_specimens is complete and never changes again
    std::atomic<bool> m_emergency{false};
    std::mutex m_emergencyMutex;
    std::string m_emergencyReason;
};

const char* testStateName(HybridTest::State s);

} // namespace hsmu
