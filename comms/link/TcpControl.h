#pragma once
// TcpControl: an ExperimentalControl over the native protocol to hsmu-controller (or any
// controller speaking it; docs/protocol.md). Per step: setTarget sends Target(n, d),
// measure() waits for Measurement(n), commit() for Ack(Commit, n), where n = committedSteps()
// + 1 counts the specimen's steps. Every wait has a deadline (options.stepDeadline); the
// LinkClient underneath sends heartbeats and declares a silent link lost.
//
// Faults are returned, never thrown: a lost connection, a timeout, a malformed reply or an
// error frame (interlock, busy, wrong token ...) -> ControlResult::fault(reason). On a lost
// link or a timeout the connection is closed (a late reply can never be taken for a later
// step); the HybridTest then holds with every committed step kept, and sends nothing more.
// A commit whose acknowledgement is lost is settled inside commit() (the step is complete in
// the integrator by then): up to reconnectAttempts reconnections, then either the controller's
// step count shows the commit, or the step's target is re-sent and must measure the same
// before it is committed; only if that fails does commit() return a fault.
// resume() (operator action, or a headless retry policy calling resume()) reconnects with
// up to options.reconnectAttempts attempts, checks that the controller's specimen is where
// the test left it (same committed step, or one step ahead when the last commit's
// acknowledgement was lost), reconfigures and sends Resume; the held step is then retried
// with the same target, which the controller answers without a new trial, so the test
// continues without a jump and records every step exactly once.
// Emergency hold (out of band, docs/protocol.md "Emergency hold"): emergencyHold() may be
// called from any thread while the test worker is blocked in measure() or commit(): it
// posts a Hold frame to the link's io thread (written at once, behind only frames already
// posted, never behind a reply the worker waits for) and interrupts the worker's wait, which
// returns a fault naming the hold with the connection kept. The worker's hold() then takes
// the controller's Hold acknowledgements (skipping a measurement or commit acknowledgement
// that crossed them; the step is retried after resume and answered idempotently). Until
// resume() no target is sent and no reconnection attempted.
// Thread rules: one thread at a time (the test worker), except emergencyHold(); all calls
// bounded by deadlines.

#include "comms/protocol/Messages.h"
#include "core/config/LinkConfig.h"
#include "core/experimental/ActuatorChannel.h"
#include "core/experimental/ExperimentalControl.h"
#include "core/experimental/SafetyLimits.h"

#include <chrono>
#include <atomic>
#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace hsmu::comms {

class LinkClient;

struct TcpControlOptions {
    std::string token;               ///< shared secret for the hello ("" = none)
    double connectTimeout = LinkTimeouts::kConnect;    ///< [s] per connection attempt
    double stepDeadline = LinkTimeouts::kStepDeadline; ///< [s] for each reply of a step
    double heartbeatInterval = 0.25; ///< [s]
    double silenceTimeout = 5.0;     ///< [s] without any frame: the link is lost
    int reconnectAttempts = 3;       ///< attempts per reconnect() / resume() (at least 1)
    double reconnectDelay = 0.5;     ///< [s] between attempts
    bool freshSpecimen = false;      ///< prepare(): reset a specimen that has history
    std::uint64_t sessionId = 0;     ///< 0: makeControlFactory draws one per test
    /// A tls:// link's certificates (LinkClientOptions::tls); nullopt: plain TCP.
    std::optional<TlsSpec> tls;
    /// The specimen's actuator channels and their control modes, from the console's
    /// configuration (a link2d specimen's actuators); empty: one channel (Target /
    /// Measurement). Two or more: Targets / Measurements frames; a hello-ack reporting another
    /// channel count is refused (docs/protocol.md, "Several actuator channels").
    std::vector<ActuatorMode> channelModes;
};

class TcpControl final : public ExperimentalControl {
public:
    /// element: the specimen's name in the controller's configuration; limits: the console's
    /// limits for it (sent in Configure, the controller enforces the tighter of its own).
    TcpControl(std::string host, std::uint16_t port, std::string element,
               const SafetyLimits& limits, const TcpControlOptions& options);
    ~TcpControl() override;

    std::string description() const override;
    /// Connect, hello, (reset when freshSpecimen), configure.
    ControlResult prepare(double dt) override;
    ControlResult setTarget(double d) override;
    ControlResult measure(ControlMeasurement& out) override;
    /// Sends the commit (no wait); commit() then awaits its acknowledgement. A failed send is
    /// left to commit(), which settles it (reconnect) as for any lost commit.
    ControlResult beginCommit() override;
    ControlResult commit() override;
    void hold(const std::string& reason) override;
    void resume() override;
    bool connected() const override { return linkUp(); }
    /// Target sent -> measurement frame decoded on the link's io thread [s].
    double replyLatency() const override { return m_latency; }
    /// Any thread: Hold frame posted at once, the worker's wait interrupted (see the header).
    void emergencyHold(const std::string& reason) override;
    /// The specimen's committed steps and last committed target as its controller reported
    /// them in the hello-ack (0 after a reset).
    std::optional<PriorLoading> priorLoading() const override;
    /// Reset (docs/protocol.md): hsmu-controller gives a new virtual specimen at step 0; a
    /// controller of a real rig refuses it (the fault names its answer). Nothing is sent when
    /// the specimen has no committed steps.
    ControlResult freshSpecimen() override;
    /// commanded, measured (deformation), held ticks and flags of the last measurement frame
    /// (N channels: the first channel's command and stroke, and the flags).
    std::optional<ActuatorChannels> actuatorChannels() const override;

    // N channels (TcpControlChannels.cpp): one Targets frame per step, one Measurements back;
    // the same step indices, commits, holds, reconnection and idempotent re-sends as one
    // channel. One channel: the base's mapping onto setTarget / measure.
    int channelCount() const override;
    ControlResult setTargets(const Eigen::VectorXd& commands) override;
    ControlResult measureChannels(Eigen::VectorXd& strokes, Eigen::VectorXd& forces) override;
    /// The last Measurements frame (N channels).
    const MeasurementsMsg& lastMeasurements() const { return m_lastN; }

    /// Close any connection and connect again (up to reconnectAttempts attempts).
    ControlResult reconnect();
    bool linkUp() const;
    /// Why the link went down last ("" if it never did).
    const std::string& linkError() const { return m_linkError; }
    /// The specimen's committed steps as the console knows them.
    std::uint64_t committedSteps() const { return m_committed; }
    /// The last measurement frame (held ticks, flags).
    const MeasurementMsg& lastMeasurement() const { return m_last; }
    int reconnects() const { return m_reconnects; }

private:
    bool multiChannel() const { return !m_opt.channelModes.empty(); }
    /// Why no target may be sent now (emergency, holding, link down), if any.
    std::optional<ControlResult> targetRefusal() const;
    /// Send the step's target as it stands (m_sentTarget or m_sentTargets).
    ControlResult sendTarget();
    /// Wait for the step's Measurement (or Measurements) frame into m_last (m_lastN).
    ControlResult receiveMeasurement();
    /// The hello-ack's channel count against the configuration's; a fault if they differ.
    ControlResult checkChannels(const HelloAckMsg& ack);
    ControlResult handshake(bool initial);
    ControlResult await(MessageType acked, double timeout);
    ControlResult linkFault(const std::string& what);
    ControlResult recoverCommit(const std::string& why);
    ControlResult refused(const ErrorMsg& e);
    /// Reset, its acknowledgement, then step count 0.
    ControlResult sendReset();
    /// A receive that failed: the emergency hold's fault (link kept) or a link fault.
    ControlResult noReply(const std::string& what, const std::string& error);
    bool emergency() const { return m_emergency.load(std::memory_order_acquire); }
    std::string emergencyText() const;
    void takeEmergencyAcks(int count);
    std::string where() const;
    /// Why the link is down: m_linkError, or the link's own close reason when it closed on its
    /// own (the controller closed it, a read failed) between two of the console's calls.
    std::string downReason() const;

    std::unique_ptr<LinkClient> m_link;
    std::string m_host;
    std::uint16_t m_port;
    std::string m_element;
    SafetyLimits m_limits;
    TcpControlOptions m_opt;
    double m_dt = 0.0;
    std::uint64_t m_committed = 0;
    bool m_awaitingMeasurement = false;
    bool m_holding = false;
    std::string m_holdReason;
    std::string m_controllerDescription;
    std::string m_linkError;
    MeasurementMsg m_last;
    int m_reconnects = 0;
    bool m_connectFailed = false;
    std::uint64_t m_controllerCommitted = 0; // as of the last hello-ack
    double m_lastCommittedTarget = 0.0;      // as of the first hello-ack (or 0 after a reset)
    double m_sentTarget = 0.0;
    std::vector<ChannelTarget> m_sentTargets; // N channels
    MeasurementsMsg m_lastN;                  // N channels
    bool m_commitSent = false;
    std::chrono::steady_clock::time_point m_targetSentAt{};
    double m_latency = std::numeric_limits<double>::quiet_NaN();
    bool m_measured = false; // m_last holds a measurement
    // Emergency hold: written by any thread.
    std::atomic<bool> m_emergency{false};
    std::atomic<int> m_emergencyHoldsSent{0};
    mutable std::mutex m_emergencyMutex;
    std::string m_emergencyReason;
};

} // namespace hsmu::comms
