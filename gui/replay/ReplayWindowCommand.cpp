#include "gui/replay/ReplayWindowCommand.h"

#include "gui/app/WindowScreenshot.h"
#include "gui/cli/ConsoleStreams.h"
#include "gui/replay/ReplayWindow.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QTextStream>

#include <cmath>
#include <memory>

namespace hsmu::gui {

namespace {
int fail(const QString& message) {
    ConsoleStreams::err() << "hsmu replay: " << message << Qt::endl;
    return 1;
}
} // namespace

int ReplayWindowCommand::exec(const QStringList& arguments) {
    QCommandLineParser p;
    p.setApplicationDescription(tr("Replay a recorded test (an HDF5 run record) in a window."));
    p.addHelpOption();
    p.addPositionalArgument(QStringLiteral("replay"), tr("The subcommand."));
    p.addPositionalArgument(QStringLiteral("file"), tr("The run record (record.h5)."));
    const QCommandLineOption speedOpt(QStringLiteral("speed"),
                                      tr("Test seconds per wall second (default 1)."),
                                      QStringLiteral("factor"), QStringLiteral("1"));
    const QCommandLineOption playOpt(QStringLiteral("play"), tr("Start playing at once."));
    const QCommandLineOption shotOpt(QStringLiteral("screenshot"),
                                     tr("Grab the window into this PNG file, then quit."),
                                     QStringLiteral("file"));
    const QCommandLineOption shotAfterOpt(QStringLiteral("screenshot-after"),
                                          tr("Seconds before the screenshot (default 3)."),
                                          QStringLiteral("seconds"), QStringLiteral("3"));
    p.addOptions({speedOpt, playOpt, shotOpt, shotAfterOpt});
    if (!p.parse(arguments))
        return fail(p.errorText());
    if (p.isSet(QStringLiteral("help"))) {
        ConsoleStreams::out() << p.helpText() << Qt::flush;
        return 0;
    }
    const QStringList positional = p.positionalArguments(); // "replay", FILE
    if (positional.size() != 2)
        return fail(tr("expected one record file: hsmu replay FILE.h5"));
    bool ok = true;
    const double speed = p.value(speedOpt).toDouble(&ok);
    if (!ok || !std::isfinite(speed) || speed <= 0.0)
        return fail(tr("--speed: expected a positive number"));
    const double after = p.value(shotAfterOpt).toDouble(&ok);
    if (!ok || !std::isfinite(after) || after < 0.0)
        return fail(tr("--screenshot-after: expected a number of seconds"));

    QString error;
    std::unique_ptr<ReplayWindow> window(ReplayWindow::open(positional[1], nullptr, &error));
    if (!window)
        return fail(error);
    window->setSpeed(speed);
    window->show();
    if (p.isSet(playOpt))
        window->play();
    if (p.isSet(shotOpt))
        WindowScreenshot::schedule(*window, p.value(shotOpt), after, QStringLiteral("hsmu replay"));
    return QApplication::exec();
}

} // namespace hsmu::gui
