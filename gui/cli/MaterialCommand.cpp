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
    p.addOptions({lawOpt, paramOpt, historyOpt, outOpt});
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
    try {
        auto law = makeLaw(p.value(lawOpt).toStdString(), params);
        const auto history = readDeformationHistory(p.value(historyOpt).toStdString());
        const auto samples = driveLaw(*law, history);
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
