#pragma once
// RthsServer: hsmu-controller --rths CONFIG (docs/rths.md, "The loop on the controller";
// docs/protocol.md, "RTHS monitoring"). The whole RTHS loop (numerical substructure,
// compensator, servo-hydraulic plant, PID: core's runRths, the same code as `hsmu rths`) runs
// on a thread of the controller, paced by the RealtimePacer at the real-time pace (under
// SCHED_FIFO with realTimePriority) or as fast as it goes at the fast pace; the console is a
// monitor over the native protocol:
//
//   - one monitor at a time (hello, token as ControllerServer; another gets Error(Busy));
//   - rths-start starts a run (one at a time; a new run after the last one ended);
//   - hold and emergency-hold hold the loop before its next tick (ack'ed); the run's rths-end
//     says so; resume goes on from the held tick (RthsRunner; a limit still breached refuses
//     it: Error(holding), the run stays held); a new rths-start gives the held run up;
//   - telemetry: one frame every `decimation` ticks (TelemetryFeed's bounded ring, drained by
//     the io thread every kPoll; a slow or absent monitor loses frames, counted, never the
//     loop's time); rths-end with the summary when the run ends;
//   - with recordDirectory, every tick of a run goes to a record.h5 on this machine (the same
//     RthsRecordFeed and RecordWriter as `hsmu rths --out`), a hold as its critical alarm;
//     a record that cannot be created refuses the run (Error) before it starts;
//   - the monitor's link lost during a run: the loop holds (holdOnMonitorLoss, the default)
//     or goes on, logged on stderr either way;
//   - with a damper twin (RthsSettings::damper): rths-update from the monitor is checked at
//     once (checkTwinUpdate: refused with Error(UpdateRefused), nothing applied) and applied
//     before the loop's next tick; the online identification (job.identification) offers its
//     estimates alike; every decision goes to the monitor (rths-update-applied), to stderr and
//     to the record's notes, with its tick;
//   - with the identification's "approve": its estimates are proposals (TwinProposals): each
//     one's fate goes to the monitor (rths-proposal), which approves or rejects it
//     (rths-decision: approved, checked and applied before the loop's next tick).
// Thread rules: construct, listen() and run() on one thread; stop() from any thread.

#include "core/groundmotion/GroundMotion.h"
#include "core/rths/Partition.h"
#include "core/rths/RthsLoop.h"
#include "core/updating/TwinIdentification.h"

#include <cstdint>
#include <memory>
#include <string>

namespace hsmu::comms {

struct RthsServerOptions {
    std::string bind = "127.0.0.1";
    std::uint16_t port = 0;
    std::string token;         ///< "" accepts any hello
    double idleTimeout = 10.0; ///< [s] the monitor's silence before its link is dropped
    bool realTime = true;      ///< false: the fast (simulated) pace
    int realTimePriority = 0;  ///< SCHED_FIFO priority of the loop's thread (1..99); 0: normal
    double spinMicros = -1.0;  ///< busy-wait before each release [us] (SpinningClock); 0: sleep; < 0: defaultSpinMargin
    bool quiet = false;
    bool holdOnMonitorLoss = true; ///< --monitor-loss hold (default) | continue
    /// --record DIR: each run's every tick through core's RthsRecord writer to DIR/record.h5
    /// (the Nth run of this server, N >= 2: DIR/record-N.h5); "" = no record
    std::string recordDirectory;
};

/// The run: what `hsmu rths` would run for the same configuration.
struct RthsJob {
    std::string name;
    rths::Partition partition;
    GroundMotion groundMotion;
    rths::RthsSettings settings; ///< prepared (fitToNominalLoop)
    int holdAfterMisses = 10;    ///< deadline misses before the pacer holds; 0: never
    rths::TwinIdentificationSettings identification; ///< of the damper's twin (wait: the fast pace)
    std::string configuration;   ///< the configuration's JSON as given (the record keeps it)
};

class RthsServer {
public:
    RthsServer(const RthsServerOptions& options, RthsJob job);
    ~RthsServer();
    RthsServer(const RthsServer&) = delete;
    RthsServer& operator=(const RthsServer&) = delete;

    bool listen(std::string& error);
    std::uint16_t port() const;
    /// Serve until stop(), SIGINT or SIGTERM (a running loop is held first, and joined).
    void run();
    void stop();
    /// "RTHS loop 'NAME', 1024 Hz, 3073 ticks" for the listening line.
    std::string describe() const;

private:
    struct Impl;
    std::unique_ptr<Impl> d;
};

} // namespace hsmu::comms
