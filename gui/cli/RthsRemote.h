#pragma once
// RthsRemote: `hsmu rths CONFIG --controller tcp://HOST:PORT --out DIR` (docs/cli.md,
// docs/rths.md "The loop on the controller"): the console as the monitor of the RTHS loop that
// hsmu-controller --rths runs. Connects (LinkClient: token, heartbeats, silence timeout), sends
// rths-start, writes every telemetry frame to DIR/telemetry.csv as it arrives, prints progress
// once per simulated second, holds the loop on SIGINT / SIGTERM (a hold frame, SignalHold), and
// at rths-end writes DIR/summary.json (the controller's J1..J9, peaks, deadline misses and hold,
// with the same keys as the local run's, plus "telemetry"). The controller is given the same
// configuration (its own copy: the run's settings are the controller's).
// Exit codes as `hsmu rths`: 0 ran out, 2 held, 1 failed (link, refusal).

#include "core/config/RthsConfig.h"
#include "core/rths/RthsReport.h"

#include <QString>

namespace hsmu::gui {

struct RthsRemoteOptions {
    QString host;
    quint16 port = 0;
    QString token;
    QString out;            ///< output folder
    unsigned decimation = 0; ///< 0: the controller's default
    double duration = 0.0;   ///< [s] 0: the whole record
};

int runRthsOnController(const RthsConfig& cfg, const rths::RthsSettings& settings,
                        const rths::Preflight& pre, const RthsRemoteOptions& options);

} // namespace hsmu::gui
