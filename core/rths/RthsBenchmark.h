#pragma once
// The RTHS benchmark (Silva, Gomez, Maghareh, Dyke & Spencer 2020; docs/rths.md, "The
// benchmark"): a whole run of RthsLoop over a record, the histories it leaves, and the
// evaluation criteria J1..J9 against the reference structure's response; the nominal loop's
// closed-loop response (for the feedforward fit and pre-flight) and perturbed plants drawn from
// the benchmark's distributions.

#include "core/rths/RthsLoop.h"
#include "core/rths/TrackingMetrics.h"

#include <complex>
#include <optional>
#include <vector>

namespace hsmu::rths {

struct RthsRun {
    std::vector<double> time, desired, command, measured, force; ///< per tick [s], [m], [N]
    Eigen::MatrixXd hybrid;    ///< per tick x floor: the hybrid response [m]
    Eigen::MatrixXd reference; ///< per tick x floor: the reference structure's response [m]
    std::string hold;          ///< why the run stopped early, "" when it ran to the end
    BenchmarkCriteria criteria;
    FrequencyEvaluation frequency;
    double trackingIndicator = 0.0; ///< [m^2]
    double peakForce = 0.0, peakStroke = 0.0, peakVelocity = 0.0; ///< of the plant [N], [m], [m/s]
    /// The twin updates decided during the run (step = the tick they came before), in order.
    std::vector<UpdateEvent> updates;
    std::optional<MrDamperParameters> twin; ///< the twin's parameters at the end (with a damper)
};

/// The benchmark's sample controller: PI 2 + 95 / s with the phase lead Gt on the command.
RthsSettings benchmarkSampleController();
/// The product's default RTHS compensation (docs/rths.md): the sample controller with an
/// adaptive feedforward (ATS) ahead of its lead, starting from the feedforward fitted to the
/// nominal loop over 0.2-6 Hz and re-fitted online to the plant it meets.
RthsSettings defaultCompensation(const PlantParameters& nominal = {});

/// When s.compensation.fitToLoop: fit the feedforward to the nominal loop of s over 0.2-6 Hz
/// (a lab knows only its model of the plant); the one preparation every runner applies.
void fitToNominalLoop(RthsSettings& s);

/// The benchmark case's partition with the plant's specimen (me, ce, ke) at floor 1.
Partition benchmarkPartition(int benchmarkCase, const PlantParameters& plant);

/// Paces the ticks of runRths (the real-time runner in comms; nothing at the simulated pace).
class TickGate {
public:
    virtual ~TickGate() = default;
    /// Before tick k: wait for its release time; false (with why) holds the run before it.
    virtual bool admit(long k, std::string& why) = 0;
    /// Tick k's work is done (its lateness is judged here).
    virtual void done(long k) = 0;
    /// A held run goes on with tick k (RthsRunner::resume): forget the hold, restart the pace.
    virtual void resume(long /*k*/) {}
};

/// Receives every tick of runRths as it is sampled (the run's HDF5 record: RthsRecord.h), on
/// the loop's thread, after the gate's done(): its cost is outside the tick's deadline.
class TickObserver {
public:
    virtual ~TickObserver() = default;
    /// Tick k: what it produced, and the reference structure's floors at the same time [m].
    virtual void onTick(long k, const RthsTick& tick,
                        const Eigen::Ref<const Eigen::RowVectorXd, 0, Eigen::InnerStride<>>& reference) = 0;
    /// A twin update decided before tick k (applied or refused: the event says).
    virtual void onUpdate(long /*k*/, const UpdateEvent& /*event*/) {}
    /// A held run goes on with tick k at time t [s] (RthsRunner::resume); note: "resumed before
    /// tick K ...".
    virtual void onResume(long /*k*/, double /*t*/, const std::string& /*note*/) {}
};

/// Hands every tick to each of several observers, in the order added (e.g. the controller's
/// telemetry feed and its record); not owned.
class TickObservers final : public TickObserver {
public:
    void add(TickObserver* observer) { if (observer) m_observers.push_back(observer); }
    bool empty() const { return m_observers.empty(); }
    void onTick(long k, const RthsTick& tick,
                const Eigen::Ref<const Eigen::RowVectorXd, 0, Eigen::InnerStride<>>& reference) override
    {
        for (TickObserver* o : m_observers)
            o->onTick(k, tick, reference);
    }
    void onUpdate(long k, const UpdateEvent& event) override
    {
        for (TickObserver* o : m_observers)
            o->onUpdate(k, event);
    }
    void onResume(long k, double t, const std::string& note) override
    {
        for (TickObserver* o : m_observers)
            o->onResume(k, t, note);
    }

private:
    std::vector<TickObserver*> m_observers;
};

/// Run a whole record (its duration, at settings.rate) and evaluate it; with a gate, each tick
/// waits for admit() and reports done(); with an observer, each tick is handed to it as it is
/// sampled (so a record on disk holds every tick up to a crash). duration > 0 stops earlier [s].
/// With updates (a damper twin: DamperTwin.h), before each tick (after the gate admitted it)
/// every update it has due is applied to the twin (RthsLoop::updateTwin; the events in
/// RthsRun::updates, and to the observer), and after the tick it observes the damper's
/// measured deformation and force. A hold ends it (RthsRunner holds and resumes).
RthsRun runRths(const Partition& partition, const GroundMotion& groundMotion,
                const RthsSettings& settings, TickGate* gate = nullptr, double duration = 0.0,
                TickObserver* observer = nullptr, TwinUpdateSource* updates = nullptr);

/// Command (before the lead) to measured displacement of the discrete loop at omega [rad/s]:
/// Lead(z) C(z) Gd / (1 + C(z) Gd), z = e^{j omega h}, Gd ~ G(j omega) e^{-j omega h / 2} (ZOH).
std::complex<double> closedLoopResponse(const RthsSettings& s, double omega);
/// The loop's delay at f [Hz] from closedLoopResponse [s].
double loopDelay(const RthsSettings& s, double f);

/// A plant drawn from the benchmark's distributions around nominal (a3, b1, b2, ke normal with
/// the benchmark's standard deviations; ce follows ke at the nominal specimen damping ratio; a
/// draw with a3 <= 0 is drawn again).
PlantParameters perturbedPlant(const PlantParameters& nominal, PortableRandom& random);

} // namespace hsmu::rths
