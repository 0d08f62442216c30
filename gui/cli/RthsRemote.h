#pragma once
// RthsRemote: `hsmu rths CONFIG --controller tcp://HOST:PORT --out DIR` (docs/cli.md,
// docs/rths.md "The loop on the controller"): the console as the monitor of the RTHS loop that
// hsmu-controller --rths runs. Connects (LinkClient: token, heartbeats, silence timeout), sends
// rths-start, writes every telemetry frame to DIR/telemetry.csv as it arrives, prints progress
// once per simulated second, holds the loop on SIGINT / SIGTERM (a hold frame, SignalHold), and
// at rths-end writes DIR/summary.json (the controller's J1..J9, peaks, deadline misses and hold,
// with the same keys as the local run's, plus "telemetry"). The controller is given the same
// configuration (its own copy: the run's settings are the controller's).
// With --update T:NAME=VALUE[,...] it sends rths-update (the damper twin's parameters) when the
// telemetry first reaches T s, prints what the controller made of each (applied before tick K,
// or refused with the reason) and lists them in summary.json ("twin": {"updates"}).
// With --resume it sends resume instead of rths-start: the controller's held run goes on from
// the tick where it held (telemetry.csv from there; summary.json the whole run's); a refusal
// (no held run, a limit still breached) is an error naming the controller's reason.
// Exit codes as `hsmu rths`: 0 ran out, 2 held, 1 failed (link, refusal).

#include "core/config/RthsConfig.h"
#include "core/rths/RthsReport.h"

#include <QString>

#include <string>
#include <vector>

namespace hsmu::gui {

/// `--update T:NAME=VALUE[,NAME=VALUE...]`: new values of the damper twin's parameters, sent
/// when the telemetry's time first reaches T [s].
struct RthsTimedUpdate {
    double time = 0.0;
    std::vector<std::string> names;
    std::vector<double> values;
};
/// Parse one --update value; false when it is not T:NAME=VALUE[,NAME=VALUE...] with numbers.
bool parseTimedUpdate(const QString& text, RthsTimedUpdate& out);

struct RthsRemoteOptions {
    QString host;
    quint16 port = 0;
    QString token;
    QString out;            ///< output folder
    unsigned decimation = 0; ///< 0: the controller's default
    double duration = 0.0;   ///< [s] 0: the whole record
    std::vector<RthsTimedUpdate> updates; ///< in the order given
    bool resume = false; ///< --resume: the controller's held run goes on (no rths-start)
};

int runRthsOnController(const RthsConfig& cfg, const rths::RthsSettings& settings,
                        const rths::Preflight& pre, const RthsRemoteOptions& options);

} // namespace hsmu::gui
