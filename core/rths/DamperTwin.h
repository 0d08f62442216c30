#pragma once
// An RTHS of a rate-dependent device with a numerical twin of it (docs/rths.md, "A damper and
// its twin"): the physical specimen holds an MR damper (the mrDamper law, MrDamper.h, acting on
// the actuator's displacement beside the plant's me, ce, ke: eq. P3 with -Fd on its right), and
// the numerical substructure holds a twin of that damper in one storey (between DOF twinDof and
// the DOF below it, or the ground for DOF 0). Both are stepped once per tick at the loop period
// (their force held over the tick, as the measured force fe is: operator splitting).
//
// The twin's parameters change only between two ticks, by a TwinUpdate (from the online
// identification, TwinIdentification.h, or from the operator over the link: docs/protocol.md,
// rths-update), through the one parameter path of the updating (applyParameterUpdate, the
// Reporter's): all or nothing, the law's state kept. Before it, checkTwinUpdate() refuses an
// update naming a parameter the law does not have, a value that is not finite, or one outside
// the parameter box (`box`, by name, in the twin's own scales uRef / fRef). Units: m, N, s (the
// laws' uRef / fRef scale them: MrDamper.h).

#include "core/hysteresis/MrDamper.h"
#include "core/identification/ParameterSet.h"
#include "core/identification/ParameterUpdate.h"

#include <cstdint>
#include <deque>
#include <mutex>
#include <string>
#include <vector>

namespace hsmu::rths {

struct DamperSettings {
    bool enabled = false;
    MrDamperParameters specimen; ///< the physical damper (deformation [m] -> force [N])
    MrDamperParameters twin;     ///< the twin's initial law (the same units)
    int twinDof = 1;             ///< the numerical DOF whose storey holds the twin (0-based)
    double forceNoise = 2.2;     ///< RMS of the damper's load cell [N] (with the sensors' noise)
    ParameterBoundsMap box;      ///< every update's bounds by name (the twin's scales)
};

/// New values for some of the twin's parameters, by name (MrDamper::parameterNames()).
struct TwinUpdate {
    std::vector<std::string> names;
    std::vector<double> values;
    std::string source; ///< "identification", "operator", "replay": in the event's message
    long due = 0;       ///< the tick before which it is applied (sources that schedule)
    int proposal = 0;   ///< the approved proposal it carries (TwinProposals; 0: none)
};

/// "" when `u` may be applied to a twin with `settings`, else the reason naming the parameter
/// (unknown name, not finite, outside the box, a law refusing the set, counts differing).
std::string checkTwinUpdate(const DamperSettings& settings, const TwinUpdate& u);

/// The physical unit of an mrDamper parameter's value times twinParameterFactor() (the
/// console's view shows both); Dimensionless for A, beta, gamma, n and an unknown name.
enum class TwinParameterUnit { Dimensionless, NewtonSecondPerMetre, NewtonPerMetre, Newton, Metre };
TwinParameterUnit twinParameterUnit(const std::string& name);
/// The factor from a value in the twin's scales (uRef [m], fRef [N]: MrDamper.h) to the
/// physical one: fRef / uRef for c0, c1 [N s/m] and k0, k1, alpha [N/m] (z scales as the
/// deformation); fRef for f0 [N]; 1 for uRef [m], fRef [N] and the dimensionless ones.
double twinParameterFactor(const std::string& name, double uRef, double fRef);

/// The twin's law, updated between ticks.
class DamperTwin {
public:
    explicit DamperTwin(const DamperSettings& s, double h);
    /// The storey drift [m] -> the twin's force [N], committed (one tick of the law).
    double step(double drift);
    /// Apply `u` before tick `tick` (time t): checked (checkTwinUpdate), then
    /// applyParameterUpdate; the event's step is the tick.
    UpdateEvent apply(const TwinUpdate& u, long tick, double t);
    const MrDamper& law() const { return m_law; }

private:
    DamperSettings m_s;
    MrDamper m_law;
};

/// Where a run's twin updates come from (runRths): asked before each tick, told after it.
/// Called on the loop's thread.
class TwinUpdateSource {
public:
    virtual ~TwinUpdateSource() = default;
    /// Before tick k: the next update to apply now, if any (called until false).
    virtual bool next(long k, TwinUpdate& out) = 0;
    /// After tick k: what it measured (xm [m]; the damper's load cell [N]).
    virtual void observe(long /*k*/, double /*deformation*/, double /*force*/) {}
    /// Before tick k, before next(): a decision the source made itself (a proposal made,
    /// superseded, rejected or refused: TwinProposals), for the run's events and observer;
    /// called until false.
    virtual bool nextEvent(long /*k*/, UpdateEvent& /*out*/) { return false; }
};

/// A fixed list of updates, each applied before its tick `due` (a run replayed from the
/// events of another: the same ticks, the same values).
class ScheduledTwinUpdates final : public TwinUpdateSource {
public:
    explicit ScheduledTwinUpdates(std::vector<TwinUpdate> updates);
    /// The updates applied in `events` (decision Applied), due at their step.
    static ScheduledTwinUpdates fromEvents(const std::vector<UpdateEvent>& events);
    bool next(long k, TwinUpdate& out) override;

private:
    std::deque<TwinUpdate> m_updates; // by due tick
};

/// Updates posted from another thread (the operator's, over the link), each applied before the
/// first tick the loop asks after it was posted. `blocking` false (the real-time pace): the
/// loop only tries the lock, so it never waits for the poster (a busy lock: the next tick).
class PostedTwinUpdates final : public TwinUpdateSource {
public:
    explicit PostedTwinUpdates(bool blocking) : m_blocking(blocking) {}
    void post(TwinUpdate u);
    bool next(long k, TwinUpdate& out) override;
    /// What was posted and never applied (the run ended first).
    std::vector<TwinUpdate> takeAll();

private:
    bool m_blocking;
    std::mutex m_mutex;
    std::deque<TwinUpdate> m_posted;
};

/// "damper twin updated before tick K (t = T s; SOURCE): c0 = ..., ..." or "damper twin update
/// refused before tick K (t = T s): WHY" (logs, the record's notes, summaries); a proposal's
/// event (TwinProposals) "damper twin proposal #N proposed | rejected | superseded before tick K
/// (t = T s): MESSAGE: c0 = ...".
std::string describeTwinUpdate(const UpdateEvent& e);

/// Several sources asked in the order added (e.g. the identification, then the operator's).
class TwinUpdateSources final : public TwinUpdateSource {
public:
    void add(TwinUpdateSource* s) { if (s) m_sources.push_back(s); }
    bool empty() const { return m_sources.empty(); }
    bool next(long k, TwinUpdate& out) override;
    void observe(long k, double deformation, double force) override;
    bool nextEvent(long k, UpdateEvent& out) override;

private:
    std::vector<TwinUpdateSource*> m_sources;
};

} // namespace hsmu::rths
