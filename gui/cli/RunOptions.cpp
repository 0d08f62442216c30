#include "gui/cli/RunOptions.h"

#include "core/config/RecordConfig.h"
#include "core/util/SecretFile.h"
#include "gui/cli/ConsoleStreams.h"
#include "gui/cli/OverrideOptions.h"

#include <QCommandLineParser>
#include <QTextStream>

namespace hsmu::gui {

std::optional<QString> RunOptions::parse(const QStringList& arguments, RunOptions& options) {
    QCommandLineParser p;
    p.setApplicationDescription(tr("Run a hybrid test headless."));
    p.addHelpOption();
    p.addPositionalArgument(QStringLiteral("run"), tr("The subcommand."));
    p.addPositionalArgument(QStringLiteral("config"), tr("Configuration file or preset name."));
    const QCommandLineOption outOpt(QStringLiteral("out"), tr("Output directory."),
                                    QStringLiteral("dir"));
    const OverrideOptions overrides;
    const QCommandLineOption unstableOpt(QStringLiteral("allow-unstable"),
                                         tr("Run an explicit scheme past its stability limit."));
    const QCommandLineOption plotsOpt(QStringLiteral("plots"), tr("Write PNG plots."));
    const QCommandLineOption controllerOpt(
        QStringLiteral("controller"),
        tr("Actuator controller: builtin (in-process virtual specimens, the default), "
           "tcp://HOST:PORT (hsmu-controller or a lab controller, in the configuration's "
           "controller.protocol, native by default), simapp://HOST:PORT (an OpenFresco SimApp "
           "server) or generictcp://HOST:PORT (a server for OpenFresco's GenericTCP)."),
        QStringLiteral("address"), QStringLiteral("builtin"));
    // The token never comes from an argument (ps shows arguments to every user): --token is
    // kept, hidden, only to refuse it with the way that works (issue 26, D4).
    QCommandLineOption tokenOpt(QStringLiteral("token"), QString(), QStringLiteral("token"));
    tokenOpt.setFlags(QCommandLineOption::HiddenFromHelp);
    const QCommandLineOption tokenFileOpt(
        QStringLiteral("token-file"),
        tr("File whose first line is the controller's shared secret (readable by you only; "
           "else the environment variable HSMU_CONTROLLER_TOKEN)."),
        QStringLiteral("file"));
    const QCommandLineOption reconnectOpt(
        QStringLiteral("reconnect"),
        tr("After a lost link or a timeout, resume (and reconnect) up to N times before giving "
           "up (default 0: hold and exit 2)."),
        QStringLiteral("n"), QStringLiteral("0"));
    const QCommandLineOption approvalOpt(
        QStringLiteral("approval"),
        tr("Decision on update proposals of the onApproval policy: manual, approveAll or "
           "rejectAll (default: the configuration's)."),
        QStringLiteral("mode"));
    const QCommandLineOption csvOpt(
        QStringLiteral("csv"),
        tr("steps.csv: auto (written when a row has at most 200 values, the default), all or "
           "none; record.h5 holds every column either way."),
        QStringLiteral("mode"), QStringLiteral("auto"));
    const QCommandLineOption compressOpt(
        QStringLiteral("compress"),
        tr("Compress the record's per-step matrices: deflate level 1-9 with shuffle (default 0: "
           "uncompressed)."),
        QStringLiteral("level"), QStringLiteral("0"));
    const QCommandLineOption recordDofsOpt(
        QStringLiteral("record-dofs"),
        tr("Numerical DOFs the record keeps: indices, ranges and names, e.g. 0-9,100,Roof "
           "(default: every DOF). A specimen's channels are always recorded in full."),
        QStringLiteral("list"));
    const QCommandLineOption recordEveryOpt(
        QStringLiteral("record-every"),
        tr("Keep the numerical DOFs' rows of every N-th step only (default 1). A specimen's "
           "channels are always recorded at every step."),
        QStringLiteral("n"));
    p.addOption(outOpt);
    overrides.addTo(p);
    p.addOptions({unstableOpt, plotsOpt, controllerOpt, tokenOpt, tokenFileOpt, reconnectOpt,
                  approvalOpt, csvOpt, compressOpt, recordDofsOpt, recordEveryOpt});
    if (auto parsed = ConsoleStreams::parse(p, arguments))
        return parsed;
    const QStringList pos = p.positionalArguments();
    if (pos.size() != 2)
        return tr("expected exactly one CONFIG (a file or a preset name)");
    options.config = pos[1];
    options.outDir = p.value(outOpt);
    if (options.outDir.isEmpty())
        return tr("missing --out DIR");
    options.plots = p.isSet(plotsOpt);
    options.overrides.allowUnstable = p.isSet(unstableOpt);
    if (auto e = overrides.read(p, options.overrides))
        return e;

    std::string error;
    const auto address = comms::LinkAddress::parse(p.value(controllerOpt).toStdString(), &error);
    if (!address)
        return tr("--controller: %1").arg(QString::fromStdString(error));
    options.controller = *address;
    if (p.isSet(tokenOpt))
        return tr("--token is not accepted: arguments show in ps; put the token in a file "
                  "(--token-file FILE) or in the environment variable HSMU_CONTROLLER_TOKEN");
    const auto token = linkToken(p.value(tokenFileOpt).toStdString(), error);
    if (!token)
        return tr("--token-file: %1").arg(QString::fromStdString(error));
    options.token = QString::fromStdString(*token);
    bool ok = false;
    options.reconnect = p.value(reconnectOpt).toInt(&ok);
    if (!ok || options.reconnect < 0)
        return tr("--reconnect: expected a whole number >= 0, found '%1'")
            .arg(p.value(reconnectOpt));
    options.csv = p.value(csvOpt);
    if (!QStringList{QStringLiteral("auto"), QStringLiteral("all"), QStringLiteral("none")}
             .contains(options.csv))
        return tr("--csv: expected auto, all or none, found '%1'").arg(options.csv);
    options.deflate = p.value(compressOpt).toInt(&ok);
    if (!ok || options.deflate < 0 || options.deflate > 9)
        return tr("--compress: expected a whole number from 0 to 9, found '%1'")
            .arg(p.value(compressOpt));
    if (p.isSet(recordDofsOpt))
        options.recordDofs = p.value(recordDofsOpt);
    if (p.isSet(recordEveryOpt)) {
        options.recordEvery = p.value(recordEveryOpt).toInt(&ok);
        if (!ok || options.recordEvery < 1 || options.recordEvery > kMaxRecordEvery)
            return tr("--record-every: expected a whole number from 1 to %1, found '%2'")
                .arg(kMaxRecordEvery)
                .arg(p.value(recordEveryOpt));
    }
    if (p.isSet(approvalOpt)) {
        options.approval = p.value(approvalOpt);
        const QStringList modes{QStringLiteral("manual"), QStringLiteral("approveAll"),
                                QStringLiteral("rejectAll")};
        if (!modes.contains(options.approval))
            return tr("--approval: expected manual, approveAll or rejectAll, found '%1'")
                .arg(options.approval);
    }
    return std::nullopt;
}

} // namespace hsmu::gui
