#include "gui/cli/ExportCommand.h"

#include "core/record/RecordCsvExport.h"
#include "core/record/RecordReader.h"
#include "gui/cli/ConsoleStreams.h"

#include <QCommandLineParser>
#include <QDir>
#include <QTextStream>

namespace hsmu::gui {

namespace {

int fail(const QString& message) {
    ConsoleStreams::err() << "hsmu export: " << message << Qt::endl;
    return 1;
}

} // namespace

int ExportCommand::exec(const QStringList& arguments) {
    QCommandLineParser p;
    p.setApplicationDescription(tr("Write a run record (HDF5) as CSV files, one per group."));
    p.addHelpOption();
    p.addPositionalArgument(QStringLiteral("export"), tr("The subcommand."));
    p.addPositionalArgument(QStringLiteral("file"), tr("The record (record.h5)."));
    const QCommandLineOption csvOpt(QStringLiteral("csv"), tr("Output directory for the CSVs."),
                                    QStringLiteral("dir"));
    const QCommandLineOption unitsOpt(
        QStringLiteral("units"),
        tr("Units of the CSV columns, e.g. length=in,force=kip,rotation=deg,moment=kip*in,"
           "time=ms (length: m, cm, mm, in, ft; force: N, kN, MN, lbf, kip, kgf, tonf; "
           "rotation: rad, mrad, deg; moment: a force unit times a length unit; time: s, ms). "
           "Default: kN, m, s, rad."),
        QStringLiteral("key=unit,..."));
    p.addOption(csvOpt);
    p.addOption(unitsOpt);
    if (auto parsed = ConsoleStreams::parse(p, arguments))
        return parsed->isEmpty() ? 0 : fail(*parsed);
    const QStringList pos = p.positionalArguments();
    if (pos.size() != 2)
        return fail(tr("expected exactly one FILE.h5"));
    if (!p.isSet(csvOpt) || p.value(csvOpt).isEmpty())
        return fail(tr("missing --csv DIR"));
    const QString dir = p.value(csvOpt);
    ExportUnits units;
    try {
        if (p.isSet(unitsOpt))
            units = parseExportUnits(p.value(unitsOpt).toStdString());
    } catch (const std::exception& e) {
        return fail(QString::fromStdString(e.what()));
    }
    if (!QDir().mkpath(dir))
        return fail(tr("%1: cannot create the output directory").arg(dir));
    try {
        const RecordReader reader(pos[1].toStdString());
        const auto files = exportRecordCsv(reader.data(), dir.toStdString(), units);
        ConsoleStreams::out() << tr("%1 steps, %2 alarms; written:")
                                     .arg(reader.rows())
                                     .arg(reader.data().alarms.size())
                              << Qt::endl;
        for (const std::string& f : files)
            ConsoleStreams::out() << "  " << QDir::toNativeSeparators(QString::fromStdString(f))
                                  << Qt::endl;
    } catch (const std::exception& e) {
        return fail(QString::fromStdString(e.what()));
    }
    return 0;
}

} // namespace hsmu::gui
