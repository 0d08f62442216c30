#include "gui/cli/RthsRemote.h"

#include "gui/cli/RthsLink.h"
#include "gui/cli/ConsoleStreams.h"
#include "gui/cli/RthsCommand.h"
#include "gui/cli/SignalHold.h"

#include <cstdio>
#include <fstream>

namespace hsmu::gui {

namespace {

int fail(const QString& message) {
    ConsoleStreams::err() << "hsmu rths: " << message << Qt::endl;
    return 1;
}

/// The controller's end as the local run's summary (rthsSummary's keys), ticks from the end.
nlohmann::json summaryOf(const comms::RthsEndMsg& end, const rths::RthsSettings& s,
                         const rths::Preflight& pre) {
    rths::RthsRun run;
    for (int i = 0; i < 9; ++i)
        run.criteria.j[std::size_t(i)] = end.j[i];
    run.hold = end.hold;
    run.peakForce = end.peakForce;
    run.peakStroke = end.peakStroke;
    run.peakVelocity = end.peakVelocity;
    run.trackingIndicator = end.trackingIndicator;
    run.frequency.amplitude = end.frequencyAmplitude;
    run.frequency.delay = end.frequencyDelay;
    run.frequency.frequency = end.frequency;
    nlohmann::json j = rths::rthsSummary(run, s, pre);
    j["ticks"] = end.ticks;
    j["deadlineMisses"] = {{"count", end.misses}, {"worstLateness_us", end.worstLateness * 1e6}};
    return j;
}

} // namespace

bool parseTimedUpdate(const QString& text, RthsTimedUpdate& out) {
    const qsizetype colon = text.indexOf(QLatin1Char(':'));
    if (colon <= 0)
        return false;
    bool ok = false;
    out = {};
    out.time = text.left(colon).toDouble(&ok);
    if (!ok || !(out.time >= 0.0))
        return false;
    for (const QString& pair : text.mid(colon + 1).split(QLatin1Char(','))) {
        const qsizetype eq = pair.indexOf(QLatin1Char('='));
        if (eq <= 0)
            return false;
        out.names.push_back(pair.left(eq).trimmed().toStdString());
        out.values.push_back(pair.mid(eq + 1).toDouble(&ok));
        if (!ok)
            return false;
    }
    return !out.names.empty();
}

int runRthsOnController(const RthsConfig& cfg, const rths::RthsSettings& s,
                        const rths::Preflight& pre, const RthsRemoteOptions& o) {
    const std::string dir = o.out.toStdString();
    std::ofstream csv(dir + "/telemetry.csv");
    if (!csv)
        return fail(RthsCommand::tr("%1/telemetry.csv: cannot be written").arg(o.out));
    csv << "tick,time_s,desired_m,command_m,measured_m,force_N,misses,worstLateness_us,dropped,holding\n";
    RthsLink link;
    std::string error, description;
    if (!link.open(o.host.toStdString(), o.port, o.token.toStdString(), o.decimation, o.duration, description, error,
                   o.resume))
        return fail(QString::fromStdString(error));
    auto& out = ConsoleStreams::out();
    out << RthsCommand::tr("controller: %1").arg(QString::fromStdString(description)) << Qt::endl;
    SignalHold holdOnSignal([&link](const std::string& why) { link.hold(why + " by hsmu rths", false); });
    long frames = 0;
    double lastPrinted = -1.0;
    char row[512];
    std::size_t nextUpdate = 0;
    nlohmann::json updates = nlohmann::json::array();
    const auto reportUpdates = [&] {
        for (const comms::RthsUpdateAppliedMsg& u : link.takeUpdates()) {
            const UpdateEvent e = RthsLink::eventOf(u);
            (u.applied ? out : ConsoleStreams::err()) << QString::fromStdString(rths::describeTwinUpdate(e)) << Qt::endl;
            nlohmann::json values = nlohmann::json::object();
            for (std::size_t i = 0; i < u.names.size() && i < u.values.size(); ++i)
                values[u.names[i]] = u.values[i];
            updates.push_back({{"tick", u.tick}, {"applied", u.applied}, {"message", u.message}, {"parameters", values}});
        }
    };
    for (;;) {
        const RthsLink::Event ev = link.next();
        reportUpdates();
        if (ev.kind == RthsLink::Event::Kind::Failed && ev.lost)
            return fail(RthsCommand::tr("the link to the controller was lost: %1 (the controller holds the loop per its --monitor-loss policy); %2 telemetry frames in %3/telemetry.csv")
                            .arg(QString::fromStdString(ev.error)).arg(frames).arg(o.out));
        if (ev.kind == RthsLink::Event::Kind::Failed)
            return fail(QString::fromStdString(ev.error));
        if (ev.kind == RthsLink::Event::Kind::Telemetry) {
            const comms::TelemetryMsg* t = &ev.telemetry;
            ++frames;
            std::snprintf(row, sizeof row, "%llu,%.17g,%.17g,%.17g,%.17g,%.17g,%llu,%.3f,%llu,%d\n",
                          static_cast<unsigned long long>(t->tick), t->time, t->desired, t->command,
                          t->measured, t->force, static_cast<unsigned long long>(t->misses),
                          t->worstLateness * 1e6, static_cast<unsigned long long>(t->dropped),
                          t->holding ? 1 : 0);
            csv << row;
            for (; nextUpdate < o.updates.size() && t->time >= o.updates[nextUpdate].time; ++nextUpdate)
                link.update(o.updates[nextUpdate].names, o.updates[nextUpdate].values);
            if (t->time >= lastPrinted + 1.0) {
                lastPrinted = t->time;
                out << RthsCommand::tr("t = %1 s: desired %2 mm, measured %3 mm, %4 deadline misses")
                           .arg(t->time, 0, 'f', 2).arg(t->desired * 1e3, 0, 'f', 3)
                           .arg(t->measured * 1e3, 0, 'f', 3).arg(t->misses) << Qt::endl;
            }
        } else {
            const comms::RthsEndMsg* end = &ev.end;
            reportUpdates();
            link.bye("run ended");
            csv.close();
            nlohmann::json summary = summaryOf(*end, s, pre);
            summary["name"] = cfg.name;
            summary["pace"] = "controller";
            summary["controller"] = o.host.toStdString() + ":" + std::to_string(o.port);
            summary["telemetry"] = {{"received", frames}, {"sent", end->telemetrySent}, {"dropped", end->telemetryDropped}};
            if (!updates.empty())
                summary["twin"] = {{"updates", updates}};
            std::ofstream(dir + "/summary.json") << summary.dump(2) << '\n';
            QString table;
            for (int i = 0; i < 9; ++i)
                table += QStringLiteral("J%1 %2%3  ").arg(i + 1).arg(end->j[i], 0, 'f', 2).arg(i == 0 ? QStringLiteral(" ms") : QStringLiteral(" %"));
            out << RthsCommand::tr("%1 ticks on the controller; %2").arg(end->ticks).arg(table) << Qt::endl;
            out << RthsCommand::tr("deadline misses: %1 (worst %2 us late); telemetry %3 received, %4 dropped")
                       .arg(end->misses).arg(end->worstLateness * 1e6, 0, 'f', 1).arg(frames).arg(end->telemetryDropped) << Qt::endl;
            out << RthsCommand::tr("outputs: %1/telemetry.csv, %1/summary.json").arg(o.out) << Qt::endl;
            if (!end->hold.empty()) {
                ConsoleStreams::err() << RthsCommand::tr("hsmu rths: %1").arg(QString::fromStdString(end->hold)) << Qt::endl;
                return 2;
            }
            return 0;
        }
    }
}

} // namespace hsmu::gui
