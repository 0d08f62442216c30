#pragma once
// RthsLink: the monitor's side of the RTHS protocol (docs/protocol.md, "RTHS monitoring"), one
// piece for `hsmu rths --controller` (RthsRemote) and the console's RTHS view (RthsSession):
// connect (LinkClient: token, heartbeats, silence timeout), hello, rths-start; then each frame
// as an event (telemetry, the end, a failure); hold and emergency hold; updates of the loop's
// damper twin (rths-update; the controller's decisions, rths-update-applied, and its refusals
// are kept for takeUpdates(), not events: a run goes on whatever becomes of an update).
// Thread rules: open / next / bye on one thread; hold() from any thread (LinkClient::send).

#include "comms/link/LinkClient.h"
#include "core/identification/ParameterUpdate.h"

#include <atomic>
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

namespace hsmu::gui {

class RthsLink {
public:
    static constexpr double kConnectTimeout = 10.0; ///< [s]
    static constexpr double kFrameTimeout = 1.0;    ///< [s] one wait (the link's silence timeout judges loss)

    /// Connect, hello with token, rths-start (decimation 0: the controller's default; duration
    /// 0: the whole record). False with *error; description: the controller's hello-ack text.
    /// resume: instead of rths-start, resume the controller's held run from the tick where it
    /// held (docs/protocol.md, "RTHS monitoring"), its decimation and duration kept; false with
    /// the controller's reason when it refuses (not held, a limit still breached).
    bool open(const std::string& host, std::uint16_t port, const std::string& token,
              unsigned decimation, double duration, std::string& description, std::string& error,
              bool resume = false);

    struct Event {
        enum class Kind { Telemetry, End, Failed } kind = Kind::Failed;
        comms::TelemetryMsg telemetry;
        comms::RthsEndMsg end;
        bool lost = false;  ///< Failed because the link was lost (error: the link's reason)
        std::string error;  ///< Failed: the link's reason, or the controller's error (translated)
    };
    /// The next telemetry frame or the end (waiting as long as the link lives: after its last
    /// tick the controller evaluates the run; heartbeats say it is still there).
    Event next();
    /// Ask the controller to hold the loop before its next tick; any thread.
    bool hold(const std::string& reason, bool emergency);
    /// Send new values of the damper twin's parameters (rths-update); any thread.
    bool update(const std::vector<std::string>& names, const std::vector<double>& values);
    /// What became of updates so far (applied or refused by the loop, each at its tick; refused
    /// by the controller at once: applied false, tick 0, the controller's reason); any thread.
    std::vector<comms::RthsUpdateAppliedMsg> takeUpdates();
    /// The controller's decision on an update as the local run's event (its step the tick;
    /// describeTwinUpdate() gives its sentence).
    static UpdateEvent eventOf(const comms::RthsUpdateAppliedMsg& u);
    /// Approve or reject the controller's proposal `id` (rths-decision; docs/rths.md,
    /// "Proposals approved by the console"); any thread. A refusal comes as a refused update.
    bool decide(std::uint32_t id, bool approve);
    /// The proposals' events so far (rths-proposal: proposed, superseded, rejected, refused,
    /// applied; each with its id and tick); any thread.
    std::vector<UpdateEvent> takeProposals();
    /// Give up: a next() in progress (or the next one) returns Failed ("abandoned"); any thread.
    void abandon();
    /// Say goodbye (after the end).
    void bye(const std::string& why);

private:
    comms::LinkClient m_link;
    std::atomic<bool> m_abandoned{false};
    std::mutex m_updatesMutex;
    std::vector<comms::RthsUpdateAppliedMsg> m_updates;
    std::vector<UpdateEvent> m_proposals; // guarded by m_updatesMutex
};

} // namespace hsmu::gui
