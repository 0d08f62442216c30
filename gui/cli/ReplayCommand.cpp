#include "gui/cli/ReplayCommand.h"

#include "core/config/ConfigLoader.h"
#include "core/offline/MeasuredDataCsv.h"
#include "core/offline/MethodComparison.h"
#include "core/offline/OfflineIdentification.h"
#include "core/offline/OfflineIdentificationReport.h"
#include "core/record/RecordReader.h"
#include "gui/cli/ConsoleStreams.h"
#include "gui/cli/MethodComparisonTable.h"
#include "gui/cli/SignalHold.h"
#include "gui/replay/Reidentification.h"

#include <QCommandLineParser>
#include <QDir>
#include <QTextStream>

#include <algorithm>
#include <atomic>
#include <optional>
#include <string_view>

namespace hsmu::gui {

namespace {

int fail(const QString& message) {
    ConsoleStreams::err() << "hsmu replay: " << message << Qt::endl;
    return 1;
}

struct ReplayOptions {
    QString record, import, units, columns, method, config, specimen, outDir;
    CalibrationOffsets offsets = CalibrationOffsets::Auto; ///< --offsets
};

std::optional<QString> parse(const QStringList& arguments, ReplayOptions& o) {
    QCommandLineParser p;
    p.setApplicationDescription(
        ReplayCommand::tr("Re-identify a recorded specimen, or imported measured data, offline."));
    p.addHelpOption();
    p.addPositionalArgument(QStringLiteral("replay"), ReplayCommand::tr("The subcommand."));
    p.addPositionalArgument(QStringLiteral("file"), ReplayCommand::tr("A run record (record.h5)."),
                            QStringLiteral("[FILE.h5]"));
    const QCommandLineOption identifyOpt(QStringLiteral("identify"),
                                         ReplayCommand::tr("Re-run the identification headless."));
    const QCommandLineOption importOpt(
        QStringLiteral("import"),
        ReplayCommand::tr("Measured data: CSV or text of time (or a sample index), deformation, "
                          "force with units."),
        QStringLiteral("csv"));
    const QCommandLineOption unitsOpt(
        QStringLiteral("units"),
        ReplayCommand::tr("Units of the imported columns time,deformation,force, e.g. s,mm,kN "
                          "(time: s, ms or step; deformation: m, cm, mm, in, ft, rad, mrad, "
                          "deg; force: N, kN, MN, lbf, kip, kgf, tonf, g or a moment such as "
                          "kN*m, kip*in)."),
        QStringLiteral("t,d,f"));
    const QCommandLineOption columnsOpt(
        QStringLiteral("columns"),
        ReplayCommand::tr("Positions (from 1) of the imported time, deformation and force "
                          "columns, e.g. 1,2,3; other columns are ignored."),
        QStringLiteral("t,d,f"));
    const QCommandLineOption methodOpt(QStringLiteral("method"),
                                       ReplayCommand::tr("ukf, nelder-mead, calibration (only the whole-history fit) or all "
                          "(the three, compared in one table)."),
                                       QStringLiteral("method"));
    const QCommandLineOption configOpt(
        QStringLiteral("config"),
        ReplayCommand::tr("JSON with \"model\" and/or \"updating\" settings to override."),
        QStringLiteral("json"));
    const QCommandLineOption specimenOpt(QStringLiteral("specimen"),
                                         ReplayCommand::tr("The recorded specimen to identify."),
                                         QStringLiteral("name"));
    const QCommandLineOption outOpt(QStringLiteral("out"), ReplayCommand::tr("Output directory."),
                                    QStringLiteral("dir"));
    const QCommandLineOption offsetsOpt(
        QStringLiteral("offsets"),
        ReplayCommand::tr("The calibration's deformation and force offsets: auto (fitted when "
                          "the data ask for them, the default), on or off."),
        QStringLiteral("mode"));
    p.addOptions({identifyOpt, importOpt, unitsOpt, columnsOpt, methodOpt, configOpt, specimenOpt,
                  outOpt, offsetsOpt});
    if (auto parsed = ConsoleStreams::parse(p, arguments))
        return parsed;
    const QStringList pos = p.positionalArguments();
    o.import = p.value(importOpt);
    if (pos.size() > 2)
        return ReplayCommand::tr("unexpected argument '%1'").arg(pos[2]);
    o.record = pos.size() == 2 ? pos[1] : QString();
    if (!o.import.isEmpty() && !o.record.isEmpty())
        return ReplayCommand::tr("give either FILE.h5 or --import DATA.csv, not both");
    if (o.import.isEmpty() && o.record.isEmpty())
        return ReplayCommand::tr("expected FILE.h5 (a run record) or --import DATA.csv");
    o.units = p.value(unitsOpt);
    if (!o.units.isEmpty() && o.import.isEmpty())
        return ReplayCommand::tr("--units applies to --import only (a record has its units)");
    o.columns = p.value(columnsOpt);
    if (!o.columns.isEmpty() && o.import.isEmpty())
        return ReplayCommand::tr("--columns applies to --import only");
    o.method = p.value(methodOpt);
    o.config = p.value(configOpt);
    o.specimen = p.value(specimenOpt);
    o.outDir = p.value(outOpt);
    if (p.isSet(offsetsOpt)) {
        const auto offsets = calibrationOffsetsFromName(p.value(offsetsOpt).toStdString());
        if (!offsets)
            return ReplayCommand::tr("--offsets: expected auto, on or off, found '%1'")
                .arg(p.value(offsetsOpt));
        o.offsets = *offsets;
    }
    if (o.outDir.isEmpty())
        return ReplayCommand::tr("missing --out DIR");
    return std::nullopt;
}

/// The last recorded online estimate, when the record identified this specimen by `method`.
ParameterValues onlineEstimate(const RecordData& d, const std::string& specimen,
                               const std::string& method) {
    ParameterValues v;
    if (!d.layout.updating || d.layout.updating->specimen != specimen ||
        d.layout.updating->method != method || d.rows() == 0)
        return v;
    for (std::size_t j = 0; j < d.layout.updating->parameters.size(); ++j)
        v[d.layout.updating->parameters[j]] = d.parameters(d.rows() - 1, Eigen::Index(j));
    return v;
}

QString num(double x) {
    return QString::number(x, 'g', 6);
}

/// The scales of a Bouc-Wen-class model's normalized parameters (uRef, fRef), from the values
/// when they hold them, else the model's configuration; nullopt for a law without them.
std::optional<std::pair<double, double>> scalesOf(const ParameterValues& values,
                                                  const IdentificationSettings& s) {
    const auto pick = [&](const char* name) -> std::optional<double> {
        if (const auto it = values.find(name); it != values.end())
            return it->second;
        if (const auto it = s.model.params.find(name); it != s.model.params.end())
            return it->second;
        return std::nullopt;
    };
    if (s.model.law != "boucWen" && s.model.law != "boucWenPinching")
        return std::nullopt;
    const std::optional<double> u = pick("uRef"), f = pick("fRef");
    return std::make_pair(u.value_or(1.0), f.value_or(1.0));
}

QString scalesText(const std::pair<double, double>& sc, const SpecimenHistory& h) {
    return ReplayCommand::tr("uRef %1 %2, fRef %3 %4")
        .arg(num(sc.first), QString::fromStdString(h.deformationUnits), num(sc.second),
             QString::fromStdString(h.forceUnits));
}

void printTable(const SpecimenHistory& h, const IdentificationSettings& s,
                const OfflineIdentificationResult& r, const ParameterValues& online,
                const QString& dir) {
    QTextStream& out = ConsoleStreams::out();
    out << ReplayCommand::tr("%1 identification of %2: %3 samples, dt %4 s")
               .arg(QString::fromStdString(r.method), QString::fromStdString(h.source))
               .arg(h.size())
               .arg(num(s.dt))
        << Qt::endl;
    // a calibration-only run's final model is the calibration's (its scales are not fitted)
    const bool calibrationOnly = r.method == "calibration" && r.calibration && r.calibration->ok;
    const auto finalScales =
        scalesOf(calibrationOnly ? r.calibration->parameters : r.finalEstimate, s);
    if (finalScales)
        out << ReplayCommand::tr("  normalized units (x = u / uRef, f = F / fRef), final model's "
                                 "scales: %1")
                   .arg(scalesText(*finalScales, h))
            << Qt::endl;
    out << QStringLiteral("  %1 %2 %3 %4 %5")
               .arg(ReplayCommand::tr("parameter"), -10)
               .arg(ReplayCommand::tr("unit"), -8)
               .arg(ReplayCommand::tr("initial"), 12)
               .arg(ReplayCommand::tr("final"), 12)
               .arg(ReplayCommand::tr("std"), 12);
    if (!online.empty())
        out << QStringLiteral(" %1").arg(ReplayCommand::tr("online"), 12);
    out << Qt::endl;
    for (const auto& name : r.parameterNames) {
        out << QStringLiteral("  %1 %2 %3 %4 %5")
                   .arg(QString::fromStdString(name), -10)
                   .arg(QString::fromStdString(
                            parameterUnit(s.model.law, name, h.deformationUnits, h.forceUnits)),
                        -8)
                   .arg(num(r.initial.at(name)), 12)
                   .arg(num(r.finalEstimate.at(name)), 12)
                   .arg(num(r.finalStddev.at(name)), 12);
        if (const auto it = online.find(name); it != online.end())
            out << QStringLiteral(" %1").arg(num(it->second), 12);
        out << Qt::endl;
    }
    out << ReplayCommand::tr("  final model over the whole history: RMS force error %1 %2 "
                             "(NRMSE %3 %; the initial model's %4 %)")
               .arg(num(r.finalRmsError), QString::fromStdString(h.forceUnits))
               .arg(QString::number(100.0 * r.finalNrmse, 'f', 2))
               .arg(QString::number(100.0 * r.initialNrmse, 'f', 2))
        << Qt::endl;
    if (r.fitError.size() > 0) // an online pass ran
        out << ReplayCommand::tr("  online model's prediction over the record (each sample with "
                                 "the estimate known before it): NRMSE %1 %")
                   .arg(QString::number(100.0 * r.auxiliaryNrmse, 'f', 2))
            << Qt::endl;
    if (!r.worseThanInitial.empty())
        out << ReplayCommand::tr("  warning: %1").arg(QString::fromStdString(r.worseThanInitial))
            << Qt::endl;
    if (r.refits > 0)
        out << ReplayCommand::tr("  Nelder-Mead fits accepted: %1").arg(r.refits) << Qt::endl;
    if (r.estimatorWarnings > 0)
        out << ReplayCommand::tr("  estimator warnings: %1 (see summary.json)")
                   .arg(r.estimatorWarnings)
            << Qt::endl;
    if (r.calibration && r.calibration->ok) {
        const CalibrationResult& c = *r.calibration;
        out << ReplayCommand::tr("  calibration over the whole history (%1 starts, %2 s): "
                                 "NRMSE %3 %")
                   .arg(c.startsTried)
                   .arg(QString::number(c.computeSeconds, 'f', 2))
                   .arg(QString::number(100.0 * c.nrmse, 'f', 2))
            << Qt::endl;
        if (const auto sc = scalesOf(c.parameters, s)) {
            const bool same = finalScales && num(finalScales->first) == num(sc->first) &&
                              num(finalScales->second) == num(sc->second);
            out << (same ? ReplayCommand::tr("    in the same scales: %1")
                         : ReplayCommand::tr("    in its own scales: %1 (its normalized values "
                                             "are not comparable with the table's above)"))
                           .arg(scalesText(*sc, h))
                << Qt::endl;
        }
        for (std::size_t i = 0; i < c.names.size(); ++i) {
            const auto k = Eigen::Index(i);
            const double sd = c.standardDeviation[k];
            out << QStringLiteral("    %1 %2 %3 %4")
                       .arg(QString::fromStdString(c.names[i]), -17)
                       .arg(QString::fromStdString(parameterUnit(s.model.law, c.names[i],
                                                                 h.deformationUnits,
                                                                 h.forceUnits)),
                            -8)
                       .arg(num(c.estimate[k]), 12)
                       .arg(c.onBound[i] ? ReplayCommand::tr("on its bound")
                                         : QStringLiteral("+- %1").arg(num(1.96 * sd)))
                << Qt::endl;
        }
        if (c.offsetTest.ran)
            out << (c.offsetTest.used
                        ? ReplayCommand::tr("    offsets fitted: NRMSE %1 % with them, %2 % "
                                            "without (criterion %3 < 0 over %4 branches)")
                        : ReplayCommand::tr("    offsets not needed: NRMSE %1 % with them, %2 % "
                                            "without (criterion %3 >= 0 over %4 branches)"))
                       .arg(QString::number(100.0 * c.offsetTest.nrmseWith, 'f', 2))
                       .arg(QString::number(100.0 * c.offsetTest.nrmseWithout, 'f', 2))
                       .arg(QString::number(c.offsetTest.criterion, 'f', 1))
                       .arg(c.offsetTest.branches)
                << Qt::endl;
    }
    if (!r.verdict.empty())
        out << ReplayCommand::tr("  verdict: %1").arg(QString::fromStdString(r.verdict))
            << Qt::endl;
    out << ReplayCommand::tr("  outputs: %1").arg(QDir::toNativeSeparators(dir)) << Qt::endl;
}

/// Progress on stderr once the work has run for 3 s, then every 5 s, and at once when a phase
/// starts after that (docs/cli.md).
class ProgressPrinter {
public:
    void print(const OfflineProgress& p) {
        if (p.elapsedSeconds < m_lastElapsed) // --method all: the next method's own clock
            m_nextReport = std::min(m_nextReport, 3.0);
        m_lastElapsed = p.elapsedSeconds;
        const bool newPhase = m_phase != p.phase;
        m_phase = p.phase;
        if (p.elapsedSeconds < m_nextReport && !(newPhase && p.elapsedSeconds >= 3.0))
            return;
        m_nextReport = p.elapsedSeconds + 5.0;
        const QString elapsed = QString::number(p.elapsedSeconds, 'f', 0);
        QTextStream& err = ConsoleStreams::err();
        if (m_phase == "online" && p.samplesDone > 0) {
            const double left =
                p.elapsedSeconds * double(p.samples - p.samplesDone) / double(p.samplesDone);
            err << ReplayCommand::tr("hsmu replay: %1 / %2 samples, %3 refits, %4 rejected, %5 s "
                                     "elapsed, about %6 s left")
                       .arg(p.samplesDone)
                       .arg(p.samples)
                       .arg(p.refits)
                       .arg(p.rejected)
                       .arg(elapsed)
                       .arg(QString::number(left, 'f', 0))
                << Qt::endl;
        } else if (m_phase == "calibration" && p.minimizations > 0) {
            err << ReplayCommand::tr("hsmu replay: calibrating over the whole history "
                                     "(minimization %1 of %2, %3 s elapsed)")
                       .arg(p.minimizationsDone)
                       .arg(p.minimizations)
                       .arg(elapsed)
                << Qt::endl;
        } else {
            err << ReplayCommand::tr("hsmu replay: %1 (%2 s elapsed)")
                       .arg(m_phase == "calibration"
                                ? ReplayCommand::tr("calibrating over the whole history")
                                : ReplayCommand::tr("final fit over the whole history"))
                       .arg(elapsed)
                << Qt::endl;
        }
    }

private:
    double m_nextReport = 3.0, m_lastElapsed = 0.0;
    std::string m_phase;
};

/// The identification (or, with --method all, the comparison), its files and its table.
int identifyAndReport(const ReplayOptions& o, const SpecimenHistory& history,
                      const IdentificationSettings& settings,
                      const std::optional<RecordReader>& reader,
                      const OfflineProgressCallback& progress) {
    if (o.method == QLatin1String("all")) {
        const MethodComparison c = compareMethods(history, settings, progress);
        writeMethodComparison(o.outDir.toStdString(), history, c);
        ConsoleStreams::out() << MethodComparisonTable::format(c, history, o.outDir) << Qt::flush;
        return 0;
    }
    const OfflineIdentificationResult r = identifyOffline(history, settings, progress);
    ParameterValues online;
    if (reader)
        online = onlineEstimate(reader->data(), settings.specimen, r.method);
    writeIdentificationReport(o.outDir.toStdString(), history, settings, r, online);
    printTable(history, settings, r, online, o.outDir);
    return 0;
}

/// The partial summary of an interrupted identification (writeInterruptedReport's figures).
void printInterrupted(const SpecimenHistory& h, const IdentificationSettings& s,
                      const OfflinePartial& p, const std::string& reason, const QString& dir) {
    QTextStream& out = ConsoleStreams::out();
    out << ReplayCommand::tr("%1 identification of %2 interrupted (%3) during the %4: %5 / %6 "
                             "samples done, %7 refits, %8 rejected")
               .arg(QString::fromStdString(p.method), QString::fromStdString(h.source),
                    QString::fromStdString(reason),
                    p.phase == "online"        ? ReplayCommand::tr("online pass")
                    : p.phase == "calibration" ? ReplayCommand::tr("calibration")
                                               : ReplayCommand::tr("final fit"))
               .arg(p.samplesDone)
               .arg(p.samples)
               .arg(p.refits)
               .arg(p.rejected)
        << Qt::endl;
    if (p.estimate.empty())
        out << ReplayCommand::tr("  no estimate yet") << Qt::endl;
    else
        out << ReplayCommand::tr("  parameters after sample %1:").arg(p.samplesDone) << Qt::endl;
    for (const std::string& name : p.parameterNames) { // the method's order
        const auto it = p.estimate.find(name);
        if (it == p.estimate.end())
            continue;
        const double v = it->second;
        out << QStringLiteral("  %1 %2 %3")
                   .arg(QString::fromStdString(name), -10)
                   .arg(QString::fromStdString(
                            parameterUnit(s.model.law, name, h.deformationUnits, h.forceUnits)),
                        -8)
                   .arg(num(v), 12)
            << Qt::endl;
    }
    out << ReplayCommand::tr("  partial summary: %1")
               .arg(QDir::toNativeSeparators(dir + QStringLiteral("/summary.json")))
        << Qt::endl;
}

} // namespace

int ReplayCommand::exec(const QStringList& arguments) {
    ReplayOptions o;
    if (auto error = parse(arguments, o))
        return error->isEmpty() ? 0 : fail(*error);
    SpecimenHistory history;
    IdentificationSettings settings;
    std::optional<RecordReader> reader;
    try {
        if (!o.import.isEmpty()) {
            MeasuredDataOptions options;
            if (!o.units.isEmpty())
                options.units = parseMeasuredDataUnits(o.units.toStdString());
            if (!o.columns.isEmpty())
                options.columns = parseMeasuredDataColumns(o.columns.toStdString());
            history = readMeasuredDataCsv(o.import.toStdString(), options);
            settings = defaultIdentificationSettings();
            settings.dt = history.meanStep() > 0.0 ? history.meanStep() : settings.dt;
        } else {
            reader.emplace(o.record.toStdString());
            const RecordData& d = reader->data();
            const TestConfig cfg =
                parseConfig(nlohmann::json::parse(d.meta.configuration), o.record.toStdString());
            settings = identificationSettingsFrom(cfg, o.specimen.toStdString());
            history = historyFromRecord(d, settings.specimen, o.record.toStdString());
        }
        const bool all = o.method == QLatin1String("all"); // each method set per row
        settings = withOverrides(settings, o.config, all ? QString() : o.method);
        settings.offsets = o.offsets;
        settings.online = !(o.method == QLatin1String("calibration") ||
                            (o.method.isEmpty() && calibrationOnlyByDefault(settings)));
    } catch (const std::exception& e) {
        return fail(QString::fromStdString(e.what()));
    }
    if (!QDir().mkpath(o.outDir))
        return fail(tr("%1: cannot create the output directory").arg(o.outDir));
    try {
        ProgressPrinter printer;
        const OfflineProgressCallback progress = [&printer](const OfflineProgress& p) {
            printer.print(p);
        };
        // SIGINT / SIGTERM cancel the work at its next check; a partial summary follows.
        std::atomic<bool> cancel{false};
        std::string interruption;
        SignalHold signalCancel([&](const std::string& why) {
            interruption = why; // before the flag: read after the cancel is seen
            cancel.store(true);
        });
        settings.cancel = &cancel;
        try {
            return identifyAndReport(o, history, settings, reader, progress);
        } catch (const OfflineCancelled& c) {
            writeInterruptedReport(o.outDir.toStdString(), history, settings, c.partial(),
                                   interruption);
            printInterrupted(history, settings, c.partial(), interruption, o.outDir);
            return 2;
        }
    } catch (const std::exception& e) {
        return fail(QString::fromStdString(e.what()));
    }
}

} // namespace hsmu::gui
