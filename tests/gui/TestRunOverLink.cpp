// `hsmu run --controller tcp://HOST:PORT` (the real binaries via QProcess): a bad address and
// an absent controller are clear errors within seconds; a run against a real hsmu-controller
// (as fast as possible, the same configuration and seed) writes the very steps.csv of the
// in-process run (to 1e-9), online model updating included.

#include "CliTestSupport.h"

#include <QDeadlineTimer>
#include <QElapsedTimer>
#include <QFile>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace clitest;

namespace {

const QString kConfig = QStringLiteral(HSMU_SOURCE_DIR "/resources/presets/paper-condition-3.json");

/// A real hsmu-controller; start() waits (bounded) for its "listening on ADDR:PORT" line.
class Controller {
public:
    explicit Controller(QStringList args) : m_args(std::move(args)) {
        m_process.setProgram(QStringLiteral(HSMU_CONTROLLER_EXE));
        m_process.setProcessChannelMode(QProcess::MergedChannels);
    }
    ~Controller() { stop(); }

    /// Listen on port (0: a free one); false if it did not within 30 s.
    bool start(quint16 port = 0) {
        QStringList args = m_args + QStringList{QStringLiteral("--port"), QString::number(port)};
        if (!args.contains(QStringLiteral("--state"))) // no default journal from another run
            args << QStringLiteral("--no-state-file");
        m_process.setArguments(args);
        m_process.start();
        if (!m_process.waitForStarted(30000))
            return false;
        const QRegularExpression re(QStringLiteral("listening on \\S+:(\\d+)"));
        QDeadlineTimer deadline(30000);
        while (!deadline.hasExpired() && m_process.state() == QProcess::Running) {
            if (!m_process.canReadLine() && !m_process.waitForReadyRead(200))
                continue;
            while (m_process.canReadLine()) {
                const QString line = QString::fromUtf8(m_process.readLine());
                m_log += line;
                if (const auto match = re.match(line); match.hasMatch()) {
                    m_port = quint16(match.captured(1).toUInt());
                    return true;
                }
            }
        }
        return false;
    }
    void kill() {
        m_process.kill(); // SIGKILL: no goodbye, no flush
        m_process.waitForFinished(10000);
        m_log += QString::fromUtf8(m_process.readAll());
    }
    void stop() {
        if (m_process.state() == QProcess::NotRunning)
            return;
        m_process.terminate();
        if (!m_process.waitForFinished(10000))
            kill();
    }
    quint16 port() const { return m_port; }
    QString log() { return m_log + QString::fromUtf8(m_process.readAll()); }

private:
    QStringList m_args;
    QProcess m_process;
    quint16 m_port = 0;
    QString m_log;
};

QStringList controllerArgs(const QString& config, const QString& pace) {
    return {QStringLiteral("--config"), config, QStringLiteral("--pace"), pace};
}

/// Largest difference between two CSVs of numbers with the same header (inf if the shapes
/// or headers differ; "nan" equals "nan").
double maxCsvDifference(const QStringList& a, const QStringList& b, QString* why) {
    if (a.size() != b.size() || a.isEmpty() || a.front() != b.front()) {
        *why =
            QStringLiteral("%1 vs %2 lines, headers %3")
                .arg(a.size())
                .arg(b.size())
                .arg(a.value(0) == b.value(0) ? QStringLiteral("equal") : QStringLiteral("differ"));
        return INFINITY;
    }
    const QStringList header = a.front().split(QLatin1Char(','));
    double worst = 0.0;
    for (qsizetype i = 1; i < a.size(); ++i) {
        const QStringList x = a[i].split(QLatin1Char(',')), y = b[i].split(QLatin1Char(','));
        if (x.size() != header.size() || y.size() != header.size())
            return INFINITY;
        for (qsizetype c = 0; c < x.size(); ++c) {
            const double p = x[c].toDouble(), q = y[c].toDouble();
            if (std::isnan(p) && std::isnan(q))
                continue;
            const double d = std::abs(p - q);
            if (!(d <= worst))
                *why = QStringLiteral("line %1, %2: %3 vs %4").arg(i).arg(header[c], x[c], y[c]);
            worst = std::isnan(d) ? INFINITY : std::max(worst, d);
        }
    }
    return worst;
}

} // namespace

class TestRunOverLink : public QObject {
    Q_OBJECT
private slots:
    void malformedAddressIsAnError() {
        QTemporaryDir dir;
        const Result r = hsmu({QStringLiteral("run"), QStringLiteral("paper-condition-3"),
                               QStringLiteral("--out"), dir.path(), QStringLiteral("--controller"),
                               QStringLiteral("udp://somewhere")});
        QVERIFY2(r.exitCode == 1, qPrintable(report(r)));
        QVERIFY2(r.err.contains(QStringLiteral("udp://somewhere")) &&
                     r.err.contains(QStringLiteral("tcp://HOST:PORT")),
                 qPrintable(r.err));
    }

    void absentControllerFailsFast() {
        QTemporaryDir dir;
        QElapsedTimer timer;
        timer.start();
        const Result r = hsmu({QStringLiteral("run"), QStringLiteral("paper-condition-3"),
                               QStringLiteral("--out"), dir.path(), QStringLiteral("--controller"),
                               QStringLiteral("tcp://127.0.0.1:1"), QStringLiteral("--duration"),
                               QStringLiteral("1")},
                              60000);
        QVERIFY2(r.exitCode == 1, qPrintable(report(r)));
        QVERIFY2(r.err.contains(QStringLiteral("cannot start")) &&
                     r.err.contains(QStringLiteral("127.0.0.1:1")),
                 qPrintable(r.err));
        QVERIFY2(timer.elapsed() < 30000, qPrintable(QString::number(timer.elapsed())));
    }

    // D4 (issue 26): the console's token, like the controller's, never comes from an argument
    // (ps shows arguments to every user): --token is refused; --token-file (mode 0600) or
    // HSMU_CONTROLLER_TOKEN carry it.
    void tokenComesFromAFileOrTheEnvironment() {
        QTemporaryDir dir;
        const QString tokenFile = dir.filePath(QStringLiteral("token"));
        QFile f(tokenFile);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("lab-secret-7f3a\n");
        f.close();
        QFile::setPermissions(tokenFile, QFile::ReadOwner | QFile::WriteOwner);
        Controller controller(controllerArgs(kConfig, QStringLiteral("fast")) +
                              QStringList{QStringLiteral("--token-file"), tokenFile});
        QVERIFY2(controller.start(), qPrintable(controller.log()));
        const QString address = QStringLiteral("tcp://127.0.0.1:%1").arg(controller.port());
        const auto run = [&](const QStringList& extra, const QString& out,
                             const QList<QPair<QString, QString>>& env = {}) {
            return hsmu(QStringList{QStringLiteral("run"), kConfig, QStringLiteral("--controller"),
                                    address, QStringLiteral("--duration"), QStringLiteral("0.2"),
                                    QStringLiteral("--out"), dir.filePath(out)} +
                            extra,
                        120000, env);
        };
        const Result argv = run({QStringLiteral("--token"), QStringLiteral("lab-secret-7f3a")},
                                QStringLiteral("argv"));
        QVERIFY2(argv.exitCode == 1 && argv.err.contains(QStringLiteral("--token-file")) &&
                     argv.err.contains(QStringLiteral("HSMU_CONTROLLER_TOKEN")) &&
                     argv.err.contains(QStringLiteral("ps")),
                 qPrintable(report(argv)));
        const Result file =
            run({QStringLiteral("--token-file"), tokenFile}, QStringLiteral("file"));
        QVERIFY2(file.exitCode == 0, qPrintable(report(file) + controller.log()));
        const Result env =
            run({}, QStringLiteral("env"),
                {{QStringLiteral("HSMU_CONTROLLER_TOKEN"), QStringLiteral("lab-secret-7f3a")}});
        QVERIFY2(env.exitCode == 0, qPrintable(report(env) + controller.log()));
        const Result wrong =
            run({}, QStringLiteral("wrong"),
                {{QStringLiteral("HSMU_CONTROLLER_TOKEN"), QStringLiteral("guess")}});
        QVERIFY2(wrong.exitCode == 1 && wrong.err.contains(QStringLiteral("wrong token")),
                 qPrintable(report(wrong)));
        QFile::setPermissions(tokenFile, QFile::ReadOwner | QFile::WriteOwner | QFile::ReadGroup);
        const Result open =
            run({QStringLiteral("--token-file"), tokenFile}, QStringLiteral("open"));
        QVERIFY2(open.exitCode == 1 && open.err.contains(QStringLiteral("chmod 600")),
                 qPrintable(report(open)));
    }

    void linkRunEqualsBuiltinRun() {
        Controller controller(controllerArgs(kConfig, QStringLiteral("fast")));
        QVERIFY2(controller.start(), qPrintable(controller.log()));
        QTemporaryDir dir;
        const QString builtin = dir.filePath(QStringLiteral("builtin"));
        const QString linked = dir.filePath(QStringLiteral("tcp"));
        const Result a = hsmu({QStringLiteral("run"), kConfig, QStringLiteral("--duration"),
                               QStringLiteral("2"), QStringLiteral("--out"), builtin});
        QVERIFY2(a.exitCode == 0, qPrintable(report(a)));
        const QString address = QStringLiteral("tcp://127.0.0.1:%1").arg(controller.port());
        const Result b =
            hsmu({QStringLiteral("run"), kConfig, QStringLiteral("--controller"), address,
                  QStringLiteral("--reconnect"), QStringLiteral("2"), QStringLiteral("--duration"),
                  QStringLiteral("2"), QStringLiteral("--out"), linked});
        QVERIFY2(b.exitCode == 0, qPrintable(report(b) + controller.log()));
        QVERIFY2(b.err.contains(address), qPrintable(b.err));

        const QStringList x = readLines(builtin + QStringLiteral("/steps.csv"));
        const QStringList y = readLines(linked + QStringLiteral("/steps.csv"));
        QCOMPARE(x.size(), 202);
        QVERIFY(x.front().contains(QStringLiteral("param_k0"))); // updating ran on both
        QString why;
        const double diff = maxCsvDifference(x, y, &why);
        QVERIFY2(diff <= 1e-9, qPrintable(QStringLiteral("%1 (%2)").arg(diff).arg(why)));
        QCOMPARE(readJson(linked + QStringLiteral("/summary.json"))
                     .value(QStringLiteral("state"))
                     .toString(),
                 QStringLiteral("finished"));
    }

    void reconnectPolicyRidesOutAControllerRestart() {
        // Real-time pace (about 10 ms per step): the controller is killed (SIGKILL) a third
        // of the way through and restarted from its state file 2.5 s later, after the link
        // code's own retries gave up; the headless policy resumes until it is back.
        QTemporaryDir dir;
        const QString state = dir.filePath(QStringLiteral("controller-state.txt"));
        Controller controller(controllerArgs(kConfig, QStringLiteral("realtime")) +
                              QStringList{QStringLiteral("--state"), state});
        QVERIFY2(controller.start(), qPrintable(controller.log()));
        const quint16 port = controller.port();
        const QString builtin = dir.filePath(QStringLiteral("builtin"));
        const QString linked = dir.filePath(QStringLiteral("tcp"));
        const Result a = hsmu({QStringLiteral("run"), kConfig, QStringLiteral("--duration"),
                               QStringLiteral("3"), QStringLiteral("--out"), builtin});
        QVERIFY2(a.exitCode == 0, qPrintable(report(a)));

        QProcess run;
        run.start(QStringLiteral(HSMU_EXE),
                  {QStringLiteral("run"), kConfig, QStringLiteral("--controller"),
                   QStringLiteral("tcp://127.0.0.1:%1").arg(port), QStringLiteral("--reconnect"),
                   QStringLiteral("20"), QStringLiteral("--duration"), QStringLiteral("3"),
                   QStringLiteral("--out"), linked});
        QVERIFY(run.waitForStarted(30000));
        QString err;
        QDeadlineTimer deadline(60000);
        while (!deadline.hasExpired() && !err.contains(QStringLiteral(" 30 %"))) {
            run.waitForReadyRead(100);
            err += QString::fromUtf8(run.readAllStandardError());
            if (run.state() == QProcess::NotRunning)
                break;
        }
        QVERIFY2(err.contains(QStringLiteral(" 30 %")), qPrintable(err));
        controller.kill();
        QTest::qWait(2500);
        QVERIFY2(controller.start(port), qPrintable(controller.log()));
        QVERIFY(run.waitForFinished(120000));
        err += QString::fromUtf8(run.readAllStandardError());
        QVERIFY2(run.exitStatus() == QProcess::NormalExit && run.exitCode() == 0,
                 qPrintable(err + controller.log()));
        QVERIFY2(err.contains(QStringLiteral("(attempt 1 of 20)")), qPrintable(err));

        QString why;
        const double diff =
            maxCsvDifference(readLines(builtin + QStringLiteral("/steps.csv")),
                             readLines(linked + QStringLiteral("/steps.csv")), &why);
        QVERIFY2(diff <= 1e-9, qPrintable(QStringLiteral("%1 (%2)").arg(diff).arg(why)));
    }
};

QTEST_GUILESS_MAIN(TestRunOverLink)
#include "TestRunOverLink.moc"
