#include "gui/cli/RthsCommand.h"

#include "comms/rths/HostProbe.h"
#include "comms/rths/RealtimePacer.h"
#include "core/config/RthsConfig.h"
#include "core/groundmotion/AccelerationUnit.h"
#include "core/groundmotion/GroundMotionReader.h"
#include "core/record/RecordWriter.h"
#include "core/record/RthsRecord.h"
#include "core/rths/RthsReport.h"
#include "core/updating/TwinIdentification.h"
#include "comms/LinkAddress.h"
#include "core/util/SecretFile.h"
#include "gui/cli/ConsoleStreams.h"
#include "gui/cli/RthsRemote.h"

#include <QCommandLineParser>
#include <QDir>
#include <QFileInfo>

#include <cmath>

#include <fstream>
#include <memory>
#include <thread>

namespace hsmu::gui {

namespace {

int fail(const QString& message)
{
    ConsoleStreams::err() << "hsmu rths: " << message << Qt::endl;
    return 1;
}

/// --compensation NAME over the configuration's compensation (lead kept unless "none").
bool applyCompensation(const QString& name, rths::RthsSettings& s)
{
    auto& c = s.compensation;
    if (name == QLatin1String("default")) {
        c.type = rths::CompensationSettings::Type::Ats;
        c.fitToLoop = true;
        c.lead.enabled = true;
        return true;
    }
    if (name == QLatin1String("lead")) {
        c.type = rths::CompensationSettings::Type::None;
        c.lead.enabled = true;
        return true;
    }
    if (!rths::parseCompensationType(name.toStdString(), c.type))
        return false;
    if (c.type == rths::CompensationSettings::Type::None)
        c.lead.enabled = false;
    if (c.type == rths::CompensationSettings::Type::Feedforward ||
        c.type == rths::CompensationSettings::Type::Ats)
        c.fitToLoop = true;
    if (c.type == rths::CompensationSettings::Type::Polynomial && c.delay == 0.0)
        c.estimateDelay = true;
    return true;
}

/// `--controller tcp://HOST:PORT`: the console monitors the loop hsmu-controller --rths runs.
int monitorController(const QCommandLineParser& p, const RthsConfig& cfg, const rths::RthsSettings& s,
                      double duration, const QCommandLineOption& controllerOpt,
                      const QCommandLineOption& tokenFileOpt, const QCommandLineOption& everyOpt,
                      const QCommandLineOption& outOpt, const QCommandLineOption& updateOpt, bool resume)
{
    std::string error;
    const auto address = comms::LinkAddress::parse(p.value(controllerOpt).toStdString(), &error);
    if (!address)
        return fail(RthsCommand::tr("--controller: %1").arg(QString::fromStdString(error)));
    if (address->kind != comms::LinkAddress::Kind::Tcp)
        return fail(RthsCommand::tr("--controller: an RTHS loop is monitored over tcp://HOST:PORT (hsmu-controller --rths)"));
    RthsRemoteOptions o;
    o.host = QString::fromStdString(address->host);
    o.port = address->port;
    o.duration = duration;
    o.out = p.value(outOpt);
    o.resume = resume;
    if (p.isSet(tokenFileOpt)) {
        const auto secret = readSecretFile(p.value(tokenFileOpt).toStdString(), error);
        if (!secret)
            return fail(RthsCommand::tr("--token-file: %1").arg(QString::fromStdString(error)));
        o.token = QString::fromStdString(*secret);
    } else {
        o.token = qEnvironmentVariable("HSMU_CONTROLLER_TOKEN");
    }
    if (p.isSet(everyOpt)) {
        bool ok = false;
        o.decimation = p.value(everyOpt).toUInt(&ok);
        if (!ok || o.decimation == 0)
            return fail(RthsCommand::tr("--telemetry-every: expected a whole number >= 1, got '%1'").arg(p.value(everyOpt)));
    }
    for (const QString& u : p.values(updateOpt)) {
        RthsTimedUpdate parsed;
        if (!parseTimedUpdate(u, parsed))
            return fail(RthsCommand::tr("--update: expected T:NAME=VALUE[,NAME=VALUE...] (seconds, then the damper twin's parameters), got '%1'").arg(u));
        o.updates.push_back(parsed);
    }
    if (!QDir().mkpath(o.out))
        return fail(RthsCommand::tr("%1: cannot create the output folder").arg(o.out));
    const rths::Preflight pre = rths::preflight(cfg.partition(), s);
    ConsoleStreams::out() << RthsCommand::tr("pre-flight: %1").arg(QString::fromStdString(pre.message)) << Qt::endl;
    return runRthsOnController(cfg, s, pre, o);
}

// --probe-host: the pacer alone on this computer (comms/rths/HostProbe.h). Exit 0 with no
// deadline miss, 3 with misses (a script can gate a real-time test on it).
int probeHost(const QCommandLineParser& p, const QCommandLineOption& probeOpt, bool priority, double rate, double spinUs)
{
    bool ok = false;
    const double seconds = p.value(probeOpt).toDouble(&ok);
    if (!ok || !(seconds > 0.0) || seconds > 3600.0)
        return fail(RthsCommand::tr("--probe-host: expected seconds in (0, 3600], got '%1'").arg(p.value(probeOpt)));
    comms::MonotonicClock monotonic;
    comms::SpinningClock clock(monotonic, std::chrono::nanoseconds(std::int64_t(spinUs * 1e3)));
    comms::HostProbeResult r;
    std::string refused;
    std::thread loop([&] {
        if (priority)
            refused = comms::enterRealtimePriority(80);
        r = comms::probeHost(clock, 1.0 / rate, long(seconds * rate + 0.5));
    });
    loop.join();
    if (!refused.empty())
        ConsoleStreams::err() << RthsCommand::tr("hsmu rths: real-time priority not taken (%1); the probe ran at normal priority").arg(QString::fromStdString(refused)) << Qt::endl;
    ConsoleStreams::out() << RthsCommand::tr("host probe at %1 Hz (spin %2 us%3): %4")
                                 .arg(rate).arg(spinUs, 0, 'f', 0)
                                 .arg(priority && refused.empty() ? RthsCommand::tr(", SCHED_FIFO 80") : QString())
                                 .arg(QString::fromStdString(comms::describeHostProbe(r, 1.0 / rate))) << Qt::endl;
    return r.misses == 0 ? 0 : 3;
}

} // namespace

int RthsCommand::exec(const QStringList& arguments)
{
    QCommandLineParser p;
    p.setApplicationDescription(tr("Real-time hybrid simulation on the virtual lab's servo-hydraulic actuator."));
    p.addHelpOption();
    p.addPositionalArgument(QStringLiteral("rths"), tr("The subcommand."));
    p.addPositionalArgument(QStringLiteral("config"), tr("A configuration file or rths-benchmark-case-1 .. -4."));
    const QCommandLineOption outOpt(QStringLiteral("out"), tr("Output folder."), QStringLiteral("dir"));
    const QCommandLineOption gmOpt(QStringLiteral("ground-motion"), tr("Ground-motion record (m/s^2 unless the configuration says)."), QStringLiteral("file"));
    const QCommandLineOption scaleOpt(QStringLiteral("scale"), tr("Scale of the record."), QStringLiteral("factor"));
    const QCommandLineOption durationOpt(QStringLiteral("duration"), tr("Stop after T seconds."), QStringLiteral("seconds"));
    const QCommandLineOption paceOpt(QStringLiteral("pace"), tr("fast (simulated, default) or realtime (wall clock)."), QStringLiteral("pace"));
    const QCommandLineOption prioOpt(QStringLiteral("realtime-priority"), tr("Run the loop's thread under SCHED_FIFO (with --pace realtime)."));
    const QCommandLineOption spinOpt(QStringLiteral("spin-us"), tr("With --pace realtime: busy-wait the last N microseconds before each release (default: a quarter of the period, at most 100; 0: sleep only)."), QStringLiteral("us"));
    const QCommandLineOption compOpt(QStringLiteral("compensation"), tr("default, none, lead, polynomial, feedforward or ats."), QStringLiteral("type"));
    const QCommandLineOption perturbOpt(QStringLiteral("perturb"), tr("Draw the plant from the benchmark's distributions with this seed."), QStringLiteral("seed"));
    const QCommandLineOption seedOpt(QStringLiteral("seed"), tr("Sensor noise seed."), QStringLiteral("n"));
    const QCommandLineOption noNoiseOpt(QStringLiteral("no-noise"), tr("Sensors without noise."));
    const QCommandLineOption controllerOpt(QStringLiteral("controller"), tr("Monitor the loop run by hsmu-controller --rths at tcp://HOST:PORT."), QStringLiteral("address"));
    const QCommandLineOption tokenFileOpt(QStringLiteral("token-file"), tr("File whose first line is the controller's shared secret."), QStringLiteral("file"));
    const QCommandLineOption everyOpt(QStringLiteral("telemetry-every"), tr("With --controller: one telemetry frame every N ticks (default: about 128 per second)."), QStringLiteral("n"));
    const QCommandLineOption updateOpt(QStringLiteral("update"), tr("With --controller: at T seconds of the run, send new values of the damper twin's parameters (repeatable)."), QStringLiteral("T:name=value,..."));
    const QCommandLineOption resumeOpt(QStringLiteral("resume"), tr("With --controller: resume the controller's held run from the tick where it held instead of starting one."));
    const QCommandLineOption probeOpt(QStringLiteral("probe-host"), tr("Check this computer instead of running: release S seconds of empty ticks at the configuration's loop rate (with --realtime-priority and --spin-us as a run would) and report how late they come."), QStringLiteral("seconds"));
    p.addOptions({outOpt, gmOpt, scaleOpt, durationOpt, paceOpt, prioOpt, spinOpt, compOpt, perturbOpt, seedOpt, noNoiseOpt, controllerOpt, tokenFileOpt, everyOpt, updateOpt, resumeOpt, probeOpt});
    if (auto parsed = ConsoleStreams::parse(p, arguments))
        return parsed->isEmpty() ? 0 : fail(*parsed);
    const QStringList pos = p.positionalArguments();
    if (pos.size() != 2)
        return fail(tr("expected one CONFIG (a file or rths-benchmark-case-1 .. -4)"));
    if (!p.isSet(outOpt) && !p.isSet(probeOpt))
        return fail(tr("missing --out DIR"));
    if (p.isSet(probeOpt) && p.isSet(controllerOpt))
        return fail(tr("--probe-host checks this computer: run it on the controller's computer without --controller"));
    const QString pace = p.value(paceOpt).isEmpty() ? QStringLiteral("fast") : p.value(paceOpt);
    if (pace != QLatin1String("fast") && pace != QLatin1String("realtime"))
        return fail(tr("--pace: expected fast or realtime, got '%1'").arg(pace));
    const auto number = [&](const QCommandLineOption& o, double& out) {
        bool ok = true;
        if (p.isSet(o))
            out = p.value(o).toDouble(&ok);
        return ok && std::isfinite(out);
    };
    if (!p.isSet(controllerOpt) && p.isSet(updateOpt))
        return fail(tr("--update needs --controller: it sends the update to the loop hsmu-controller runs"));
    if (!p.isSet(controllerOpt) && p.isSet(resumeOpt))
        return fail(tr("--resume needs --controller: it resumes the held run hsmu-controller keeps (a local run is resumed in the console's RTHS view)"));
    if (p.isSet(controllerOpt))
        for (const QCommandLineOption* o : {&gmOpt, &scaleOpt, &paceOpt, &prioOpt, &spinOpt, &compOpt, &perturbOpt, &seedOpt, &noNoiseOpt})
            if (p.isSet(*o))
                return fail(tr("--%1 does not apply with --controller: the controller runs the loop of its own copy of the configuration").arg(o->names().constFirst()));
    try {
        RthsConfig cfg = loadRthsConfig(pos.at(1).toStdString());
        auto& s = cfg.settings;
        if (p.isSet(compOpt) && !applyCompensation(p.value(compOpt), s))
            return fail(tr("--compensation: expected default, none, lead, polynomial, feedforward or ats, got '%1'").arg(p.value(compOpt)));
        if (p.isSet(noNoiseOpt))
            s.sensors.noise = false;
        double seed = double(s.sensors.seed), scale = cfg.groundMotionScale, duration = 0.0;
        double spin = std::chrono::duration<double, std::micro>(comms::defaultSpinMargin(1.0 / s.rate)).count();
        if (!number(seedOpt, seed) || !number(scaleOpt, scale) || !number(durationOpt, duration))
            return fail(tr("--seed, --scale and --duration take numbers"));
        if (!number(spinOpt, spin) || spin < 0.0 || spin >= 1e6 / s.rate)
            return fail(tr("--spin-us: expected 0 up to the loop period (%1 us), got '%2'").arg(1e6 / s.rate, 0, 'f', 1).arg(p.value(spinOpt)));
        s.sensors.seed = std::uint64_t(seed);
        if (p.isSet(probeOpt))
            return probeHost(p, probeOpt, p.isSet(prioOpt), s.rate, spin);
        // The feedforward is fitted to the nominal plant (a lab knows only its model of it).
        rths::fitToNominalLoop(s);
        if (p.isSet(perturbOpt)) {
            double ps = 0.0;
            if (!number(perturbOpt, ps))
                return fail(tr("--perturb takes a seed"));
            PortableRandom random{std::uint64_t(ps)};
            s.plant = rths::perturbedPlant(s.plant, random);
        }
        if (p.isSet(controllerOpt))
            return monitorController(p, cfg, s, duration, controllerOpt, tokenFileOpt, everyOpt, outOpt, updateOpt,
                                     p.isSet(resumeOpt));
        const QString gmFile = p.isSet(gmOpt) ? p.value(gmOpt) : QString::fromStdString(cfg.groundMotionFile);
        if (gmFile.isEmpty())
            return fail(tr("no ground motion: give --ground-motion FILE"));
        if (!QFileInfo::exists(gmFile))
            return fail(tr("%1: the ground-motion record does not exist (give --ground-motion FILE)").arg(gmFile));
        const auto unit = parseAccelerationUnit(cfg.groundMotionUnit); // checked by the parser
        const GroundMotion ag = readGroundMotion(gmFile.toStdString(), GroundMotionFormat::Auto, unit).scaled(scale);

        const rths::Partition part = cfg.partition();
        const rths::Preflight pre = rths::preflight(part, s);
        auto& out = ConsoleStreams::out();
        out << tr("%1: %2 Hz loop, compensation %3%4").arg(QString::fromStdString(cfg.name)).arg(s.rate)
                   .arg(QString::fromLatin1(rths::compensationTypeName(s.compensation.type)))
                   .arg(s.compensation.lead.enabled ? tr(" + phase lead") : QString()) << Qt::endl;
        out << tr("pre-flight: %1").arg(QString::fromStdString(pre.message)) << Qt::endl;
        if (pre.refused)
            return fail(tr("refused in pre-flight: %1").arg(QString::fromStdString(pre.message)));

        if (!QDir().mkpath(p.value(outOpt)))
            return fail(tr("%1: cannot create the output folder").arg(p.value(outOpt)));
        const QString dir = p.value(outOpt);
        const auto floors = int(part.reference.m.rows());
        RecordStart start{cfg.raw.dump(), cfg.name, {}, 1.0 / s.rate};
        RecordWriter record((dir + QStringLiteral("/record.h5")).toStdString(), rths::rthsLayout(floors), start);
        rths::RthsRecordFeed feed(record, ag, floors, &record);
        // The damper's online identification (docs/rths.md, "A damper and its twin"): off the
        // loop's thread; the simulated pace waits for its offers (bit for bit), real time not.
        std::unique_ptr<rths::TwinIdentification> identification;
        if (s.damper.enabled && cfg.identification.enabled) {
            rths::TwinIdentificationSettings is = cfg.identification;
            is.wait = pace != QLatin1String("realtime");
            identification = std::make_unique<rths::TwinIdentification>(s.damper, is, s.rate);
        }
        rths::RthsRun run;
        comms::MonotonicClock monotonic;
        comms::SpinningClock clock(monotonic, std::chrono::nanoseconds(std::int64_t(spin * 1e3)));
        comms::RealtimePacer pacer(clock, 1.0 / s.rate, cfg.holdAfterMisses);
        std::string priority;
        if (pace == QLatin1String("realtime")) {
            std::thread loop([&] {
                if (p.isSet(prioOpt))
                    priority = comms::enterRealtimePriority(80);
                run = rths::runRths(part, ag, s, &pacer, duration, &feed, identification.get());
            });
            loop.join();
            if (!priority.empty())
                ConsoleStreams::err() << tr("hsmu rths: real-time priority not taken (%1); the loop ran at normal priority").arg(QString::fromStdString(priority)) << Qt::endl;
        } else {
            run = rths::runRths(part, ag, s, nullptr, duration, &feed, identification.get());
        }
        if (identification && !identification->failure().empty())
            ConsoleStreams::err() << QString::fromStdString(identification->failure()) << Qt::endl;
        identification.reset();
        for (const UpdateEvent& e : run.updates)
            out << QString::fromStdString(rths::describeTwinUpdate(e)) << Qt::endl;
        if (!run.hold.empty()) {
            // A deadline-miss hold is the pacer's; any other is a limit of the plant or command.
            const bool deadline = pace == QLatin1String("realtime") && cfg.holdAfterMisses > 0 &&
                                  pacer.misses() >= cfg.holdAfterMisses;
            record.writeAlarms({rths::rthsHoldAlarm(run, deadline)});
        }
        if (!record.finish())
            return fail(QString::fromStdString(record.error()));
        rths::writeRthsSteps((dir + QStringLiteral("/steps.csv")).toStdString(), run);
        nlohmann::json summary = rths::rthsSummary(run, s, pre);
        summary["name"] = cfg.name;
        summary["pace"] = pace.toStdString();
        summary["deadlineMisses"] = {{"count", pacer.misses()}, {"worstLateness_us", pacer.worstLateness() * 1e6},
                                     {"firstTick", pacer.firstMissTick()}, {"holdAfter", cfg.holdAfterMisses}};
        const std::string summaryPath = (dir + QStringLiteral("/summary.json")).toStdString();
        std::ofstream(summaryPath) << summary.dump(2) << '\n';

        QString table;
        for (int i = 0; i < 9; ++i)
            table += QStringLiteral("J%1 %2%3  ").arg(i + 1).arg(run.criteria.j[i], 0, 'f', 2).arg(i == 0 ? QStringLiteral(" ms") : QStringLiteral(" %"));
        out << tr("%1 ticks (%2 s); %3").arg(run.time.size()).arg(run.time.empty() ? 0.0 : run.time.back(), 0, 'f', 3).arg(table) << Qt::endl;
        out << tr("frequency evaluation: amplitude %1, delay %2 ms at %3 Hz; tracking indicator %4 m^2")
                   .arg(run.frequency.amplitude, 0, 'f', 3).arg(run.frequency.delay, 0, 'f', 2)
                   .arg(run.frequency.frequency, 0, 'f', 2).arg(run.trackingIndicator, 0, 'g', 3) << Qt::endl;
        if (pace == QLatin1String("realtime"))
            out << tr("deadline misses: %1 (worst %2 us late)").arg(pacer.misses()).arg(pacer.worstLateness() * 1e6, 0, 'f', 1) << Qt::endl;
        out << tr("outputs: %1/record.h5, %1/steps.csv, %1/summary.json").arg(dir) << Qt::endl;
        if (!run.hold.empty()) {
            ConsoleStreams::err() << tr("hsmu rths: %1").arg(QString::fromStdString(run.hold)) << Qt::endl;
            return 2;
        }
        return 0;
    } catch (const std::exception& e) {
        return fail(QString::fromStdString(e.what()));
    }
}

} // namespace hsmu::gui
