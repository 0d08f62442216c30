#include "gui/app/ConsoleCommand.h"

#include "comms/link/ControlFactory.h"
#include "gui/app/MainWindow.h"
#include "gui/app/TestController.h"
#include "gui/app/WindowScreenshot.h"
#include "gui/cli/ConsoleStreams.h"
#include "gui/cli/OverrideOptions.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QTextStream>

#include <cmath>

namespace hsmu::gui {

namespace {
int fail(const QString& message) {
    ConsoleStreams::err() << "hsmu: " << message << Qt::endl;
    return 1;
}
} // namespace

int ConsoleCommand::exec(const QStringList& arguments) {
    QCommandLineParser p;
    p.setApplicationDescription(
        tr("HSMU Console: hybrid simulation with online model updating.\n"
           "Subcommands: run CONFIG --out DIR ..., compare CONFIG --out DIR ..., material --law "
           "... (see hsmu run --help, hsmu compare --help, docs/cli.md)."));
    p.addHelpOption();
    p.addVersionOption();
    const QCommandLineOption startOpt(QStringLiteral("start"),
                                      tr("Load a preset or configuration and start it."),
                                      QStringLiteral("config"));
    const QCommandLineOption gmOpt(QStringLiteral("ground-motion"),
                                   tr("Ground-motion record file."), QStringLiteral("file"));
    const QCommandLineOption recordDtOpt(
        QStringLiteral("record-dt"),
        tr("The record's own sample step [s] (a one-column file of values needs it)."),
        QStringLiteral("dt"));
    const QCommandLineOption speedOpt(QStringLiteral("speed"),
                                      tr("Test time per wall time (0: as fast as possible)."),
                                      QStringLiteral("factor"));
    const QCommandLineOption shotOpt(QStringLiteral("screenshot"),
                                     tr("Grab the window into this PNG file, then quit."),
                                     QStringLiteral("file"));
    const QCommandLineOption shotAfterOpt(QStringLiteral("screenshot-after"),
                                          tr("Seconds before the screenshot (default 4)."),
                                          QStringLiteral("seconds"), QStringLiteral("4"));
    const QCommandLineOption controllerOpt(
        QStringLiteral("controller"),
        tr("Actuator controller: builtin (the default) or tcp://HOST:PORT."),
        QStringLiteral("address"), QStringLiteral("builtin"));
    p.addOptions({startOpt, gmOpt, recordDtOpt, speedOpt, shotOpt, shotAfterOpt, controllerOpt});
    if (!p.parse(arguments))
        return fail(p.errorText());
    if (p.isSet(QStringLiteral("help"))) {
        ConsoleStreams::out() << p.helpText() << Qt::flush;
        return 0;
    }
    if (p.isSet(QStringLiteral("version"))) {
        ConsoleStreams::out() << QCoreApplication::applicationName() << ' '
                              << QCoreApplication::applicationVersion() << Qt::endl;
        return 0;
    }
    if (!p.positionalArguments().isEmpty())
        return fail(tr("unknown subcommand '%1' (expected run, compare or material)")
                        .arg(p.positionalArguments().front()));
    bool ok = true;
    const double after = p.value(shotAfterOpt).toDouble(&ok);
    if (!ok || !std::isfinite(after) || after < 0.0)
        return fail(tr("--screenshot-after: expected a number of seconds"));
    double speed = 1.0;
    if (p.isSet(speedOpt)) {
        speed = p.value(speedOpt).toDouble(&ok);
        if (!ok || !std::isfinite(speed))
            return fail(tr("--speed: expected a number"));
    }

    std::string linkError;
    const auto address =
        comms::LinkAddress::parse(p.value(controllerOpt).toStdString(), &linkError);
    if (!address)
        return fail(tr("--controller: %1").arg(QString::fromStdString(linkError)));

    ConfigOverrides overrides;
    overrides.groundMotionFile = p.value(gmOpt);
    if (auto e = OverrideOptions::number(p, recordDtOpt, overrides.recordDt, true))
        return fail(*e);
    MainWindow window(overrides);
    window.setSpeed(speed);
    if (p.isSet(controllerOpt))
        window.setControllerAddress(p.value(controllerOpt));
    window.show();
    if (p.isSet(startOpt)) {
        window.setConfirmBeforeStart(false); // --start is the operator's confirmation
        QString error;
        if (window.loadConfiguration(p.value(startOpt), &error))
            window.startTest();
        else
            ConsoleStreams::err() << "hsmu: " << error << Qt::endl;
    }
    if (p.isSet(shotOpt))
        WindowScreenshot::schedule(window, p.value(shotOpt), after, QStringLiteral("hsmu"));
    return QApplication::exec();
}

} // namespace hsmu::gui
