#include "core/experiment/HybridTest.h"

#include "core/experiment/ElementChannels.h"
#include "core/util/ReasonText.h"
#include "core/util/InputLimits.h"

#include "core/experimental/ExperimentalElement.h"
#include "core/integration/Integrator.h"
#include "core/structure/Structure.h"
#include "core/updating/ModelUpdater.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace hsmu {

const char* testStateName(HybridTest::State s)
{
    switch (s) {
    case HybridTest::State::Created: return "created";
    case HybridTest::State::Ready: return "ready";
    case HybridTest::State::Running: return "running";
    case HybridTest::State::Holding: return "holding";
    case HybridTest::State::Finished: return "finished";
    case HybridTest::State::Failed: return "failed";
    }
    return "?";
}

HybridTest::HybridTest(std::unique_ptr<Structure> structure,
                       std::unique_ptr<Integrator> integrator, const GroundMotion& groundMotion,
                       const HybridTestOptions& options)
    : m_structure(std::move(structure)), m_integrator(std::move(integrator)),
      m_groundMotion(groundMotion), m_options(options)
{
}

HybridTest::~HybridTest() = default;

void HybridTest::setUpdater(std::unique_ptr<ModelUpdater> updater)
{
    m_updater = std::move(updater);
}

bool HybridTest::approveUpdate(int proposalId)
{
    if (!m_updater || !m_updater->approve(proposalId, *m_structure, m_step, time(), m_alarms))
        return false;
    revisitUpdatedModel();
    return true;
}

namespace {

// Each element's initial generalized stiffness and, for a multi-DOF one, each basic DOF law's
// initial tangent: what an update may change of K0 (any basic DOF's law may be a target).
std::vector<double> initialStiffnesses(const Structure& structure)
{
    std::vector<double> out;
    for (const auto& e : structure.elements()) {
        out.push_back(e->initialGeneralizedStiffness());
        for (int k = 0; e->basicDofCount() > 1 && k < e->basicDofCount(); ++k)
            if (const HysteresisLaw* law = e->basicLaw(k))
                out.push_back(law->initialTangent());
    }
    return out;
}

} // namespace

void HybridTest::revisitUpdatedModel()
{
    // Only an update that changed an element's initial stiffness changes omega_max.
    const std::vector<double> before = std::move(m_initialStiffness);
    m_initialStiffness = initialStiffnesses(*m_structure);
    if (m_initialStiffness == before)
        return;
    const bool wasStable = m_updatedStability.stable;
    StabilityReport r = m_stability;
    try {
        r.omegaMax = m_structure->updatedMaxFrequency();
    } catch (const std::exception&) {
        return; // no frequency for this model (e.g. a zero stiffness): nothing to compare
    }
    r.omegaDt = r.omegaMax * m_options.dt;
    r.maxStableDt = r.omegaMax > 0.0 ? r.limit / r.omegaMax : r.maxStableDt;
    r.stable = !m_integrator->isExplicit() || r.omegaDt <= r.limit;
    char buf[400];
    std::snprintf(buf, sizeof buf,
                  "updated model: omega_max dt = %.4g (omega_max = %.4g rad/s, %.4g at the "
                  "start), limit %.4g; K0 and damping kept from the start",
                  r.omegaDt, r.omegaMax, m_stability.omegaMax, r.limit);
    r.message = buf;
    m_updatedStability = r;
    if (wasStable && !r.stable)
        raise(AlarmSeverity::Warning, AlarmKind::Stability,
              r.message + ": the explicit integration of the updated model may diverge");
    else if (!wasStable && r.stable)
        raise(AlarmSeverity::Info, AlarmKind::Stability, r.message);
}

bool HybridTest::rejectUpdate(int proposalId) { return m_updater && m_updater->reject(proposalId); }

bool HybridTest::approveOffsets(int id, std::string* error)
{
    if (!m_updater) {
        if (error)
            *error = "no online model updating in this test";
        return false;
    }
    if (!m_updater->approveOffsets(id, *m_structure, error))
        return false;
    revisitUpdatedModel();
    return true;
}

bool HybridTest::rejectOffsets(int id)
{
    return m_updater && m_updater->rejectOffsets(id).has_value();
}

void HybridTest::addObserver(StepObserver* observer) { m_observers.push_back(observer); }

void HybridTest::removeObserver(StepObserver* observer)
{
    m_observers.erase(std::remove(m_observers.begin(), m_observers.end(), observer),
                      m_observers.end());
}

void HybridTest::raise(AlarmSeverity severity, AlarmKind kind, const std::string& message)
{
    m_alarms.push_back({time(), m_step, severity, kind, message});
}

void HybridTest::raise(AlarmSeverity severity, AlarmKind kind, const std::string& message,
                       const char* code, std::vector<std::string> args)
{
    m_alarms.push_back({time(), m_step, severity, kind, message, code, std::move(args)});
}

bool HybridTest::prepare()
{
    auto fail = [this](const std::string& why) {
        m_lastError = why;
        m_state = State::Failed;
        return false;
    };
    if (m_state != State::Created)
        return fail("prepare() was already called");
    if (!(m_options.dt > 0.0) || !std::isfinite(m_options.dt))
        return fail("the integration step dt must be a positive number of seconds");
    if (m_groundMotion.acceleration.size() < 2 || !(m_groundMotion.dt > 0.0))
        return fail("the ground motion has fewer than two samples");
    {
        // Counted before anything is allocated from them (resampling, records): a run of
        // 0 steps or of more than limits::kMaxSteps is refused with the figures.
        const double gmDuration = m_groundMotion.duration();
        const double span = m_options.duration > 0.0 ? std::min(m_options.duration, gmDuration)
                                                      : gmDuration;
        const double steps = std::floor(span / m_options.dt + 1e-9);
        char buf[300];
        if (!(steps >= 1.0)) {
            std::snprintf(buf, sizeof buf,
                          "the run would make 0 steps: duration %.6g s (ground motion %.6g s) "
                          "is shorter than dt = %.6g s",
                          span, gmDuration, m_options.dt);
            return fail(buf);
        }
        if (steps > double(limits::kMaxSteps)) {
            std::snprintf(buf, sizeof buf,
                          "the run would make %.6g steps (duration %.6g s / dt %.6g s), more "
                          "than the %lld allowed",
                          steps, span, m_options.dt, static_cast<long long>(limits::kMaxSteps));
            return fail(buf);
        }
    }
    try {
        if (std::abs(m_groundMotion.dt - m_options.dt) > 1e-12 * m_options.dt)
            m_groundMotion = m_groundMotion.resampled(m_options.dt);
        m_structure->finalize();
    } catch (const std::exception& e) {
        return fail(e.what());
    }
    const double duration = m_options.duration > 0.0
                                ? std::min(m_options.duration, m_groundMotion.duration())
                                : m_groundMotion.duration();
    m_totalSteps = static_cast<int>(std::floor(duration / m_options.dt + 1e-9));
    m_totalSteps = std::min<int>(m_totalSteps, int(m_groundMotion.acceleration.size()) - 1);

    for (const auto& e : m_structure->elements()) // rate-dependent laws step with the test
        for (int k = 0; k < e->basicDofCount(); ++k)
            if (HysteresisLaw* law = e->basicLaw(k))
                law->setTimeIncrement(m_options.dt);
    m_stability = checkStability(*m_structure, *m_integrator, m_options.dt);
    m_updatedStability = m_stability;
    m_initialStiffness = initialStiffnesses(*m_structure);
    if (!m_stability.stable) {
        if (!m_options.allowUnstable)
            return fail(m_stability.message);
        raise(AlarmSeverity::Warning, AlarmKind::Stability,
              m_stability.message + " (forced by the operator)");
    }
    m_specimens.clear();
    m_timed.clear();
    m_channelElements.clear();
    for (const auto& e : m_structure->elements()) {
        if (auto* x = dynamic_cast<ExperimentalElement*>(e.get()))
            m_specimens.push_back(x);
        else if (e->timeDependent())
            m_timed.push_back(e.get()); // e.g. a twin's scheduled axial load
        if (!elementChannels(*e).empty())
            m_channelElements.push_back(e.get());
    }
    for (ExperimentalElement* x : m_specimens)
        if (ControlResult r = x->control().prepare(m_options.dt); !r.ok)
            return fail(x->name() + ": " + r.reason);
    for (ExperimentalElement* x : m_specimens) // e.g. a pairing that may be wrong, at connect
        if (std::string notice = x->control().takeNotice(); !notice.empty())
            raise(AlarmSeverity::Warning, AlarmKind::ControlFault, x->name() + ": " + notice);
    // From here on emergencyHold() reaches the controls (connected); one raised while they
    // connected only holds the first step, which sends the hold in band.
    m_prepared.store(true, std::memory_order_release);
    if (m_updater) {
        std::string why;
        if (!m_updater->attach(*m_structure, m_options.dt, &why))
            return fail(why);
    }
    // Initial state at rest: elements at zero deformation, no measurement taken yet.
    const int nf = m_structure->freeDofCount();
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(nf);
    m_integrator->initialize(*m_structure, m_options.dt, zero, zero,
                             m_groundMotion.acceleration[0], zero);
    m_step = 0;
    m_state = State::Ready;
    publish();
    return true;
}

std::optional<std::string> HybridTest::takeEmergency()
{
    if (!m_emergency.load(std::memory_order_acquire))
        return std::nullopt;
    std::lock_guard lock(m_emergencyMutex);
    m_emergency.store(false, std::memory_order_release);
    return m_emergencyReason;
}

void HybridTest::emergencyHold(const std::string& reason)
{
    const std::string why =
        "emergency hold: " + (reason.empty() ? std::string("operator") : reason);
    {
        std::lock_guard lock(m_emergencyMutex);
        m_emergencyReason = why;
        m_emergency.store(true, std::memory_order_release);
    }
    if (!m_prepared.load(std::memory_order_acquire))
        return;
    for (ExperimentalElement* x : m_specimens)
        x->control().emergencyHold(why);
}

void HybridTest::enterHold(AlarmKind kind, const std::string& reason)
{
    std::string why = reason;
    if (std::optional<std::string> e = takeEmergency()) {
        // The fault (if any) is what the emergency hold caused: say what held the test.
        why = kind == AlarmKind::OperatorHold ? *e : *e + " (" + reason + ")";
        kind = AlarmKind::OperatorHold;
    }
    m_structure->revert();
    for (ExperimentalElement* x : m_specimens)
        x->control().hold(why);
    raise(AlarmSeverity::Critical, kind, "test held: " + why, "test-held", {why});
    m_state = State::Holding;
    updateSites();
}

void HybridTest::updateSites()
{
    m_sites = siteStatuses(m_specimens); // descriptions change with (re)connections
    m_siteMonitor->update(m_sites, m_state == State::Holding);
}

void HybridTest::hold(const std::string& reason)
{
    if (m_state != State::Ready && m_state != State::Running)
        return;
    enterHold(AlarmKind::OperatorHold, reason.empty() ? "operator hold" : reason);
}

void HybridTest::resume(ResumeCause cause)
{
    if (m_state != State::Holding)
        return;
    takeEmergency(); // an emergency hold raised while held is answered by this resume
    for (ExperimentalElement* x : m_specimens)
        x->control().resume();
    if (cause == ResumeCause::Reconnect)
        raise(AlarmSeverity::Info, AlarmKind::ControlFault,
              reasonText("test-resumed-reconnect"), "test-resumed-reconnect", {});
    else
        raise(AlarmSeverity::Info, AlarmKind::OperatorHold, "test resumed", "test-resumed", {});
    m_state = State::Running;
    updateSites();
}

HybridTest::StepResult HybridTest::step()
{
    switch (m_state) {
    case State::Created:
    case State::Failed: return StepResult::NotReady;
    case State::Holding: return StepResult::Held;
    case State::Finished: return StepResult::Finished;
    case State::Ready:
    case State::Running: break;
    }
    if (m_step >= m_totalSteps) {
        m_state = State::Finished;
        return StepResult::Finished;
    }
    if (m_emergency.load(std::memory_order_acquire)) {
        enterHold(AlarmKind::OperatorHold, "");
        return StepResult::Held;
    }
    m_state = State::Running;
    const double agNext = m_groundMotion.acceleration[m_step + 1];
    m_integrator->predictInto(m_uTrial);
    const Eigen::VectorXd& uTrial = m_uTrial;
    if (!uTrial.allFinite()) {
        enterHold(AlarmKind::IntegratorFault, "predicted displacement is not finite");
        return StepResult::Held;
    }
    // Every target is checked before any is sent: nothing leaves a limit, ever.
    m_structure->toFull(uTrial, m_uFull);
    const Eigen::VectorXd& uFull = m_uFull;
    const double targetTime = (m_step + 1) * m_options.dt; // the step being computed
    for (Element* e : m_timed)
        e->setTargetTime(targetTime);
    for (ExperimentalElement* x : m_specimens) {
        x->setTargetTime(targetTime);
        if (auto why = x->targetViolation(uFull)) {
            enterHold(AlarmKind::LimitExceeded, *why);
            return StepResult::Held;
        }
    }
    if (ElementStatus s = m_structure->setTrial(uTrial); !s.ok) {
        enterHold(s.limit ? AlarmKind::LimitExceeded : AlarmKind::ControlFault, s.message);
        return StepResult::Held;
    }
    m_structure->restoringForce(m_r);
    const Eigen::VectorXd& r = m_r;
    m_integrator->snapshot(m_before);
    const Integrator::Snapshot& before = m_before;
    if (!r.allFinite() || !m_integrator->correct(r, agNext)) {
        enterHold(AlarmKind::IntegratorFault, "restoring force or response is not finite");
        return StepResult::Held;
    }
    if (ElementStatus s = m_structure->commit(); !s.ok) {
        // The retried step must start where this one did: undo the integrator's advance.
        m_integrator->restore(before);
        enterHold(AlarmKind::ControlFault, s.message);
        return StepResult::Held;
    }
    ++m_step;
    for (ExperimentalElement* x : m_specimens)
        if (std::string notice = x->control().takeNotice(); !notice.empty())
            raise(AlarmSeverity::Warning, AlarmKind::ControlFault, x->name() + ": " + notice);
    std::optional<std::string> updaterHold;
    if (m_updater) {
        updaterHold = m_updater->afterCommit(m_step, time(), *m_structure, m_alarms,
                                             m_record.updating);
        if (!m_record.updating.applied.empty())
            revisitUpdatedModel();
    }
    publish();
    if (updaterHold) {
        enterHold(AlarmKind::EstimatorRejected, *updaterHold);
        return StepResult::Held;
    }
    if (m_emergency.load(std::memory_order_acquire)) { // raised during this step
        enterHold(AlarmKind::OperatorHold, "");
        return StepResult::Held;
    }
    if (m_step >= m_totalSteps) {
        m_state = State::Finished;
        return StepResult::Finished;
    }
    return StepResult::Advanced;
}

void HybridTest::publish()
{
    StepRecord& rec = m_record;
    rec.step = m_step;
    rec.time = time();
    rec.groundAcceleration = m_groundMotion.acceleration[m_step];
    m_structure->toFull(m_integrator->displacement(), rec.u);
    m_structure->toFull(m_integrator->velocity(), rec.v);
    m_structure->toFull(m_integrator->acceleration(), rec.a);
    const auto& elements = m_structure->elements();
    rec.elements.resize(elements.size());
    rec.channels.clear();
    for (const Element* e : m_channelElements)
        appendChannelValues(*e, rec.channels);
    for (std::size_t i = 0; i < elements.size(); ++i) {
        const Element& e = *elements[i];
        ElementSample& s = rec.elements[i];
        if (m_step == 0) {
            s = ElementSample{};
        } else {
            s.deformation = e.deformation();
            s.force = e.force();
        }
        if (e.isExperimental()) {
            const auto& x = static_cast<const ExperimentalElement&>(e);
            s.commanded = m_step == 0 ? 0.0 : x.commandedDeformation();
            s.actuator = ActuatorChannels{};
            if (m_step > 0)
                if (std::optional<ActuatorChannels> c = x.control().actuatorChannels())
                    s.actuator = *c;
        }
    }
    if (!m_specimens.empty()) {
        if (m_sites.empty() || m_step == 0)
            m_sites = siteStatuses(m_specimens);
        else
            refreshSiteHealth(m_sites, m_specimens);
        rec.siteRoundTrips.resize(m_sites.size());
        for (std::size_t i = 0; i < m_sites.size(); ++i)
            rec.siteRoundTrips[i] = m_step == 0 ? std::numeric_limits<double>::quiet_NaN()
                                                : m_sites[i].lastRoundTrip;
        m_siteMonitor->update(m_sites, m_state == State::Holding);
    }
    rec.hasUpdating = m_updater != nullptr;
    if (m_updater && m_step == 0) {
        rec.updating = UpdatingSample{};
        m_updater->fillEstimate(rec.updating);
    }
    for (StepObserver* o : m_observers)
        o->onStep(rec);
}

} // namespace hsmu
