#include "gui/cli/MaterialCommand.h"

#include "core/hysteresis/HysteresisLaw.h"
#include "core/hysteresis/LawFactory.h"
#include "core/hysteresis/MaterialDriver.h"
#include "gui/cli/ConsoleStreams.h"

#include <QCommandLineParser>
#include <QTextStream>

#include <cmath>
#include <iostream>
#include <map>
#include <sstream>

namespace hsmu::gui {

namespace {

int fail(const QString& message) {
    ConsoleStreams::err() << "hsmu material: " << message << Qt::endl;
    return 1;
}

QString knownLawList() {
    QStringList names;
    for (const std::string& n : knownLaws())
        names << QString::fromStdString(n);
    return names.join(QStringLiteral(", "));
}

} // namespace

int MaterialCommand::exec(const QStringList& arguments) {
    QCommandLineParser p;
    p.setApplicationDescription(tr("Drive one hysteresis law with a deformation history."));
    p.addHelpOption();
    p.addPositionalArgument(QStringLiteral("material"), tr("The subcommand."));
    const QCommandLineOption lawOpt(QStringLiteral("law"), tr("Law: %1.").arg(knownLawList()),
                                    QStringLiteral("name"));
    const QCommandLineOption paramOpt(QStringLiteral("param"), tr("A law parameter (repeatable)."),
                                      QStringLiteral("name=value"));
    const QCommandLineOption historyOpt(QStringLiteral("history"),
                                        tr("Deformation history (CSV or text)."),
                                        QStringLiteral("file"));
    const QCommandLineOption outOpt(QStringLiteral("out"), tr("Output CSV (default: stdout)."),
                                    QStringLiteral("file"));
    const QCommandLineOption dtOpt(
        QStringLiteral("dt"),
        tr("Time step [s] between the points of a one-column history (a rate-dependent law)."),
        QStringLiteral("seconds"));
    p.addOptions({lawOpt, paramOpt, historyOpt, outOpt, dtOpt});
    if (auto parsed = ConsoleStreams::parse(p, arguments))
        return parsed->isEmpty() ? 0 : fail(*parsed);
    if (p.positionalArguments().size() > 1)
        return fail(tr("unexpected argument '%1'").arg(p.positionalArguments().at(1)));
    if (!p.isSet(lawOpt))
        return fail(tr("missing --law (one of %1)").arg(knownLawList()));
    if (!p.isSet(historyOpt))
        return fail(tr("missing --history FILE"));

    std::map<std::string, double> params;
    for (const QString& item : p.values(paramOpt)) {
        const qsizetype eq = item.indexOf(QLatin1Char('='));
        bool ok = false;
        const double value = eq > 0 ? item.mid(eq + 1).trimmed().toDouble(&ok) : 0.0;
        if (eq <= 0 || !ok || !std::isfinite(value))
            return fail(tr("--param '%1': expected NAME=VALUE with a finite number").arg(item));
        params[item.left(eq).trimmed().toStdString()] = value;
    }
    double dt = 0.0;
    if (p.isSet(dtOpt)) {
        bool ok = false;
        dt = p.value(dtOpt).toDouble(&ok);
        if (!ok || !(dt > 0.0) || !std::isfinite(dt))
            return fail(tr("--dt '%1': expected a time step > 0 in seconds").arg(p.value(dtOpt)));
    }
    try {
        auto law = makeLaw(p.value(lawOpt).toStdString(), params);
        TimedHistory history = readTimedHistory(p.value(historyOpt).toStdString());
        if (dt > 0.0) {
            if (!history.time.empty())
                return fail(tr("--dt: the history has its own time column"));
            for (std::size_t i = 0; i < history.deformation.size(); ++i)
                history.time.push_back(double(i) * dt);
        }
        if (law->isRateDependent() && history.time.empty())
            return fail(tr("%1 is rate-dependent: give the history a time column (time, "
                           "deformation) or --dt")
                            .arg(QString::fromStdString(law->lawName())));
        const auto samples = driveLaw(*law, history.deformation, history.time);
        if (p.isSet(outOpt)) {
            writeMaterialCsv(p.value(outOpt).toStdString(), samples);
        } else {
            std::ostringstream csv;
            writeMaterialCsv(csv, samples);
            ConsoleStreams::out() << QString::fromStdString(csv.str()) << Qt::flush;
        }
    } catch (const std::exception& e) {
        return fail(QString::fromStdString(e.what()));
    }
    return 0;
}

} // namespace hsmu::gui
