#pragma once
// SpecimenStation: one specimen on the virtual rig of hsmu-controller: the core
// VirtualSpecimen (its own true law, sensor noise, fracture event), the actuator dynamics
// and the predictor-corrector at the loop rate, the interlock, and the state journal.
// It answers the protocol's specimen messages; sockets and clocks live in ControllerServer.
//
// Step protocol (step indices count the specimen's committed steps, c = committedSteps()):
//   Target(c + 1, d)   checked against the interlock, then the command is corrected toward d
//                      (fast pace: at once on a simulated clock; real time: over the next
//                      ticks, and tick() returns the Measurement when d is reached);
//                      re-sent with the same d it answers the same measurement again
//                      (kFlagReplayed) without a new trial: nothing is measured twice.
//   Target(c, d)       the committed step again (its commit ack was lost): its measurement.
//   Commit(c + 1)      the specimen commits, the journal records it, then Ack(c + 1).
//   Commit(c)          a repeated commit: Ack(c), nothing else.
// The specimen is evaluated once per step, at the position the actuator holds when the step
// ends: a law's trial always starts from its committed state (HysteresisLaw), so with an ideal
// actuator every measurement equals the in-process VirtualSpecimen's for the same targets.
//
// Interlock (SafetyLimits): the element's `limits` and the specimen's `interlock` (the
// tighter of each), which no client can loosen: Configure may only tighten them (a limit of
// 0, negative, NaN or infinite leaves the configuration's). The predictor-corrector's command
// saturates at the deformation limit, so no command ever leaves it. A target past the deformation
// or increment limit (increment from the last committed target), an actuator position past the
// deformation limit at any tick, or a measured force past the force limit -> the station holds and
// answers Error(Interlock) whose text names the limit. Targets are refused (Error(Holding)) until
// Resume. N actuator channels (a link2d specimen): the station's specimen is a ChannelRig (its
// actuators' uniaxial materials or the whole specimen, each channel's limits) and its steps
// come as Targets and go as Measurements; commit, hold, resume, reset, the hello-ack, the
// step indices and the journal are the same as one channel's (a one-channel frame to it, or
// an N-channel one to a one-channel station, is a protocol violation). Each channel is an
// ActuatorLoop of its own (its predictor-corrector and its actuator model at the loop rate,
// its bound checked every tick: stroke on a displacement channel, force on a force channel),
// all on the one step clock: the targets arrive together, so a late Targets frame holds every
// channel for the same held ticks (each channel's loop counts its own: loop(i).heldTicks();
// totalHeldTicks() adds each step's held ticks once, as for one channel; the Measurements frame has
// no field for them), and the rig's lab is evaluated once per step at the values the actuators
// reached. A trip names the channel and puts every actuator back at its committed stroke and force
// (the rig's lab and each loop). The journal's `commits` line holds every channel's target, reached
// value and measurement (StateJournal.h). Thread rules: one thread (the controller's io thread).

#include "comms/controller/ActuatorLoop.h"
#include "comms/controller/ChannelRig.h"
#include "comms/controller/ControllerSettings.h"
#include "comms/controller/StateJournal.h"
#include "comms/protocol/Messages.h"
#include "core/config/TestConfig.h"

#include <memory>
#include <optional>
#include <string>

namespace hsmu::comms {

class SpecimenStation {
public:
    enum class Pace { RealTime, Fast };

    /// index: the element's position among the configuration's specimens (journal key).
    /// journal may be null (no state file). Throws ConfigError if the law cannot be built.
    SpecimenStation(int index, const ElementSpec& spec, const ControllerSettings& settings,
                    Pace pace, StateJournal* journal);
    ~SpecimenStation();

    /// Re-apply a journaled record at start-up (no journal write). False + error if the
    /// replayed specimen does not measure what was recorded.
    bool replay(const JournalRecord& r, std::string& error);

    const std::string& name() const { return m_spec.name; }
    /// committedSteps, lastCommittedTarget, holding, element, description, holdReason.
    HelloAckMsg status() const;

    Message configure(const ConfigureMsg& m);
    /// A measurement or an error now, or nullopt: the step is under way (real time), tick()
    /// delivers its measurement.
    std::optional<Message> target(const TargetMsg& m);
    /// The step of an N-channel specimen: its Measurements or an error now, or nullopt: the
    /// step is under way (real time), tick() delivers its Measurements.
    std::optional<Message> targets(const TargetsMsg& m);
    /// The N-channel specimen (nullptr for one channel).
    const ChannelRig* rig() const { return m_rig.get(); }
    /// One tick of the loop (real time). A Measurement(s) when a step ends, an Error when the
    /// interlock trips, else nullopt.
    std::optional<Message> tick();
    /// True when tick() has work (a step is being predicted, waited for or corrected).
    bool needsTicks() const;
    Message commit(const CommitMsg& m);
    Message hold(const std::string& reason);
    Message resume();
    /// A new console session is admitted: a hold that a console asked for (Hold) belonged to
    /// the previous session and ends here (the new session arms through its own pre-flight);
    /// an interlock or fault trip stays (the hello-ack reports it). True if one was released.
    bool releaseConsoleHold();
    /// A fresh specimen (virgin law, step count 0), recorded in the journal.
    Message reset();

    std::uint64_t committedSteps() const { return m_committed; }
    /// The specimen law's initial tangent and its algorithmic tangent at the last trial (force
    /// per deformation): the stiffness an OpenFresco element server reports (actions 12, 13).
    double initialStiffness() const;
    double tangentStiffness() const;
    /// Ticks of one integration step (the loop runs at settings.rate).
    const ControllerSettings& settings() const { return m_settings; }
    bool holding() const { return m_holding; }
    const std::string& holdReason() const { return m_holdReason; }
    long totalHeldTicks() const { return m_totalHeld; }
    int interlockTrips() const { return m_trips; }
    /// The largest |command| ever given to the actuator (NaN counts as infinite): what the
    /// limits property test checks against limits().maxDeformation.
    double peakCommand() const { return m_loops.front().peakCommand(); }
    /// Channel i's loop (0 for one channel).
    const ActuatorLoop& loop(int i) const { return m_loops.at(static_cast<std::size_t>(i)); }
    /// The limits in force: the configuration's (element `limits`, specimen `interlock`, the
    /// tighter), tightened by the last Configure.
    const SafetyLimits& limits() const { return m_limits; }

private:
    struct Trial {
        bool valid = false;
        std::uint64_t step = 0;
        double target = 0.0, achieved = 0.0;
        MeasurementMsg measurement;
    };
    void makeSpecimen();
    void makeLoops();
    void beginStep();
    /// The admitted step's targets, one per loop: corrected at once (fast pace, simulated
    /// clock) and measured, or under way (real time: nullopt).
    std::optional<Message> startStep(std::uint64_t step, const std::vector<double>& targets);
    /// One tick of every loop with its bound; an error on a trip (naming the channel).
    std::optional<Message> advance();
    Message finishStep();
    // The N-channel parts (SpecimenStationChannels.cpp).
    Message finishChannels();
    Message commitChannels(const CommitMsg& m);
    bool replayChannels(const JournalRecord& r, std::string& error);
    /// Every loop back at its committed value (a hold of the rig).
    void holdLoops();
    Message trip(ErrorCode code, const std::string& reason);
    Message journal(const JournalRecord& r);

    int m_index;
    ElementSpec m_spec;
    ControllerSettings m_settings;
    Pace m_pace;
    StateJournal* m_journal;
    std::unique_ptr<VirtualSpecimen> m_specimen; // one channel
    std::unique_ptr<ChannelRig> m_rig;           // N channels
    std::vector<ActuatorLoop> m_loops;           // one per actuator channel
    SafetyLimits m_limits;
    double m_dt = 0.0;
    bool m_configured = false;
    std::uint64_t m_committed = 0;
    Trial m_trial, m_last; // uncommitted measured trial; last committed step
    bool m_pending = false;
    std::uint64_t m_pendingStep = 0;
    bool m_holding = false;
    bool m_consoleHold = false; ///< the hold came from a console's Hold, not from a trip
    std::string m_holdReason;
    long m_totalHeld = 0;
    int m_trips = 0;
};

} // namespace hsmu::comms
