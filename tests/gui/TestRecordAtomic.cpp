// D10 (issue 26): a record.h5 that exists always reads. `hsmu run` is killed (SIGKILL, no
// chance to clean up) the moment record.h5 appears in its output folder; the file must then
// open as an HSMU record (its header complete), never "not an HSMU record" (a zero-byte or
// half-written file, as before the record was created under a temporary name).
#include "core/record/RecordError.h"
#include "core/record/RecordReader.h"

#include "CliTestSupport.h"

#include <QDeadlineTimer>
#include <QFileInfo>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <csignal>

using namespace hsmu;

class TestRecordAtomic : public QObject {
    Q_OBJECT
private slots:
    void recordThatExistsAlwaysReads() {
        constexpr int kTrials = 20; // before the fix, 1 to 3 trials in 5 found a damaged file
        for (int trial = 0; trial < kTrials; ++trial) {
            QTemporaryDir dir;
            const QString record = dir.filePath(QStringLiteral("record.h5"));
            QProcess run;
            run.start(QStringLiteral(HSMU_EXE),
                      {QStringLiteral("run"), QStringLiteral("paper-condition-3"),
                       QStringLiteral("--duration"), QStringLiteral("5"), QStringLiteral("--out"),
                       dir.path()});
            QVERIFY(run.waitForStarted(30000));
            // Poll (no sleep) until the file is there, then kill at once.
            QDeadlineTimer deadline(60000);
            while (!QFileInfo::exists(record) && run.state() == QProcess::Running &&
                   !deadline.hasExpired()) {
            }
            ::kill(static_cast<pid_t>(run.processId()), SIGKILL);
            QVERIFY(run.waitForFinished(30000));
            QVERIFY2(QFileInfo::exists(record), "the run ended before its record appeared");
            try {
                RecordReader reader(record.toStdString());
                QVERIFY(reader.data().meta.dt > 0.0);
            } catch (const RecordError& e) {
                QFAIL(qPrintable(QStringLiteral("trial %1: %2").arg(trial).arg(e.what())));
            }
        }
    }
};

QTEST_GUILESS_MAIN(TestRecordAtomic)
#include "TestRecordAtomic.moc"
