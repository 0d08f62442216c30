// ReplayWindow on a record written by a real run (RecordWriter): playing reaches the last
// step and the plotted data equal the record's datasets; scrubbing back and forth shows
// exactly the chosen rows; RecordPlayback paces rows by speed x wall time; bad files are
// refused with the reader's message, in the window API and by `hsmu replay` (real binary).
// Re-identify on a worker thread: the recorded settings give back the recorded parameter
// history (overlaid, to 1e-9 relative); Nelder-Mead adds curves of its name; a bad override
// is reported and changes nothing.

#include "RecordedRun.h"

#include "core/record/RecordReader.h"
#include "gui/plots/HistoryPlot.h"
#include "gui/plots/HysteresisPlot.h"
#include "gui/plots/LivePlotsPanel.h"
#include "gui/plots/ParameterPlot.h"
#include "gui/replay/RecordPlayback.h"
#include "gui/replay/ReplayWindow.h"
#include "gui/replay/ReplayPanels.h"
#include "gui/plots/PlotTools.h"

#include <QAction>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QProcess>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <memory>

using namespace hsmu;
using namespace hsmu::gui;

namespace {

constexpr double kDuration = 2.0; // [s] of paper-condition-3, dt 0.01 s: 201 rows

QVector<double> keys(const QCPGraph& g) {
    QVector<double> out;
    for (auto it = g.data()->constBegin(); it != g.data()->constEnd(); ++it)
        out << it->key;
    return out;
}

} // namespace

class TestReplayWindow : public QObject {
    Q_OBJECT
private:
    QTemporaryDir m_dir;
    QString m_record;
    recordedrun::Run m_run;

private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        m_record = m_dir.filePath(QStringLiteral("record.h5"));
        m_run = recordedrun::run(QStringLiteral("paper-condition-3"), kDuration, m_record);
        QCOMPARE(int(m_run.records.size()), 201);
    }

    void playReachesTheLastStepWithTheRecordsData() {
        QString error;
        std::unique_ptr<ReplayWindow> w(ReplayWindow::open(m_record, nullptr, &error));
        QVERIFY2(w, qPrintable(error));
        const RecordReader reader(m_record.toStdString());
        const RecordData& d = reader.data();
        QCOMPARE(w->rowCount(), d.rows());
        QCOMPARE(w->rowsShown(), 1); // the initial state
        w->show();
        QSignalSpy finished(w.get(), &ReplayWindow::finished);
        w->setSpeed(50.0); // 2 s of test in ~40 ms of wall time
        w->play();
        QVERIFY(w->isPlaying());
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 20000);
        QVERIFY(!w->isPlaying());
        QCOMPARE(w->rowsShown(), d.rows());
        QCOMPARE(w->playback().step(), d.steps.back());
        QCOMPARE(d.steps.back(), 200);

        // The plotted data are the datasets, row for row.
        const LivePlotsPanel& panel = w->panel();
        const int n = d.rows();
        const int specimen = 0; // Element 1, the specimen of paper-condition-3
        QVERIFY(d.layout.elements[specimen].experimental);
        auto loop = qobject_cast<QCPCurve*>(panel.hysteresis().plottable(0))->data();
        QCOMPARE(loop->size(), n);
        for (int i = 0; i < n; ++i) {
            QCOMPARE(loop->at(i)->key, d.deformation(i, specimen));
            QCOMPARE(loop->at(i)->value, d.force(i, specimen));
        }
        for (int j = 0; j < int(d.u.cols()); ++j) {
            const QCPGraph& g = *panel.displacementHistory().graph(j);
            QCOMPARE(g.dataCount(), n);
            for (int i = 0; i < n; ++i) {
                QCOMPARE(g.data()->at(i)->key, d.time(i));
                QCOMPARE(g.data()->at(i)->value, d.u(i, j));
            }
        }
        for (int p = 0; p < int(d.parameters.cols()); ++p) {
            const ParameterPlot& plot = *panel.parameterPlots()[std::size_t(p)];
            QCOMPARE(plot.estimateGraph()->dataCount(), n);
            for (int i = 0; i < n; ++i) {
                QCOMPARE(plot.estimateGraph()->data()->at(i)->value, d.parameters(i, p));
                QCOMPARE(plot.upperBandGraph()->data()->at(i)->value,
                         d.parameters(i, p) + 2.0 * d.stddev(i, p));
            }
        }
        const QCPGraph& fit = *panel.fitError().graph(0);
        for (int i = 0; i < n; ++i)
            QCOMPARE(fit.data()->at(i)->value, d.fitError(i));
        // The tracking plot's actuator command is /elements/actuator/commanded (NaN at step 0).
        QCOMPARE(d.actuatorCommanded.rows(), n);
        const QCPGraph& actuator = *panel.tracking().graph(2);
        QCOMPARE(actuator.dataCount(), n);
        for (int i = 1; i < n; ++i)
            QCOMPARE(actuator.data()->at(i)->value, d.actuatorCommanded(i, specimen));
        QVERIFY(std::isnan(actuator.data()->at(0)->value));
        // The whole ground motion from the record, the cursor at the last step's time.
        const QCPGraph& ground = *panel.groundMotion().graph(0);
        QCOMPARE(ground.dataCount(), n);
        for (int i = 0; i < n; ++i)
            QCOMPARE(ground.data()->at(i)->value, d.groundAcceleration(i));
        QCOMPARE(panel.groundMotion().timeCursor(), d.time(n - 1));
        // And the record equals the live run's rows (what the console showed).
        QCOMPARE(d.force(n - 1, specimen), m_run.records.back().elements[specimen].force);
    }

    void scrubShowsExactlyTheChosenRows() {
        QString error;
        std::unique_ptr<ReplayWindow> w(ReplayWindow::open(m_record, nullptr, &error));
        QVERIFY2(w, qPrintable(error));
        const int n = w->rowCount();
        QSignalSpy moved(w.get(), &ReplayWindow::positionChanged);
        w->seek(n); // forward to the end
        QCOMPARE(w->rowsShown(), n);
        QCOMPARE(w->panel().displacementHistory().graph(0)->dataCount(), n);
        w->seek(57); // back: the plots are refilled with rows 0 .. 56
        QCOMPARE(w->rowsShown(), 57);
        const QCPGraph& g = *w->panel().displacementHistory().graph(0);
        QCOMPARE(g.dataCount(), 57);
        QCOMPARE(keys(g).front(), 0.0);
        QCOMPARE(g.data()->at(56)->value, m_run.records[56].u(0));
        QCOMPARE(w->playback().step(), 56);
        QCOMPARE(w->panel().groundMotion().timeCursor(), m_run.records[56].time);
        w->seek(n + 100); // clamped
        QCOMPARE(w->rowsShown(), n);
        QCOMPARE(moved.count(), 3);
        QCOMPARE(moved.last().at(0).toInt(), n);
    }

    // A record of DOF 2 every 4 steps (issue 27, docs/recording.md "Chosen and decimated
    // DOFs") replays: every row of the elements, the kept DOF at its kept steps (the plot
    // joins them); the window's CSV lists the kept DOF only.
    void decimatedRecordReplays() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("decimated.h5"));
        {
            TestConfig cfg = PresetLibrary::load(QStringLiteral("paper-condition-3"));
            cfg.analysis.duration = kDuration;
            std::unique_ptr<HybridTest> test = buildHybridTest(cfg);
            RecordStart start{cfg.raw.dump(), cfg.name, {}, cfg.analysis.dt};
            start.dofRecording = DofRecording{{1}, 4};
            RecordWriter writer(path.toStdString(), RunLayout::of(*test), start);
            test->addObserver(&writer);
            QVERIFY(test->prepare());
            while (test->step() == HybridTest::StepResult::Advanced) {
            }
            test->removeObserver(&writer);
            QVERIFY(writer.finish());
        }
        QString error;
        std::unique_ptr<ReplayWindow> w(ReplayWindow::open(path, nullptr, &error));
        QVERIFY2(w, qPrintable(error));
        w->show();
        const int n = w->rowCount();
        QCOMPARE(n, 201);
        w->seek(n);
        QCOMPARE(w->rowsShown(), n);
        // The plot joins the kept rows (a line through isolated points between NaN gaps
        // would draw nothing): DOF 2 at steps 0, 4, ..., 200, DOF 1 not at all.
        const QCPGraph& dof1 = *w->panel().displacementHistory().graph(0);
        const QCPGraph& dof2 = *w->panel().displacementHistory().graph(1);
        QCOMPARE(dof2.dataCount(), 51);
        for (int k : {0, 1, 2, 49, 50}) {
            const StepRecord& r = m_run.records[std::size_t(4 * k)];
            QCOMPARE(dof2.data()->at(k)->key, r.time);
            QCOMPARE(dof2.data()->at(k)->value, r.u(1));
        }
        QCOMPARE(dof1.dataCount(), 0); // DOF 1 was not kept
        const QString csv = dir.filePath(QStringLiteral("window.csv"));
        int rows = 0;
        QVERIFY2(w->exportWindowCsv(csv, &error, &rows), qPrintable(error));
        QFile f(csv);
        QVERIFY(f.open(QIODevice::ReadOnly | QIODevice::Text));
        const QString header = QString::fromUtf8(f.readLine());
        QVERIFY2(header.startsWith(QStringLiteral("step,t [s],ag [m/s^2],u DOF 2 [m],d ")),
                 qPrintable(header));
    }

    void playbackPacesRowsBySpeed() {
        auto data = std::make_shared<const RecordData>(RecordReader(m_record.toStdString()).data());
        RecordPlayback pb(data);
        pb.setSpeed(2.0);
        // 0.25 s of wall time at 2x: test time 0 .. 0.5 s, i.e. rows t = 0, 0.01, ..., 0.50.
        std::vector<StepRecord> rows = pb.advance(0.25);
        QCOMPARE(int(rows.size()), 51);
        QCOMPARE(rows.back().step, 50);
        rows = pb.advance(0.1); // 0.2 s more: t = 0.51 .. 0.70
        QCOMPARE(int(rows.size()), 20);
        QCOMPARE(rows.front().step, 51);
        pb.setSpeed(-1.0); // refused: the speed stays 2
        QCOMPARE(pb.speed(), 2.0);
        rows = pb.advance(100.0);
        QCOMPARE(rows.back().step, 200);
        QVERIFY(pb.atEnd());
        QVERIFY(pb.advance(1.0).empty());
    }

    void badFilesAreRefusedWithAReason() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString text = dir.filePath(QStringLiteral("notes.h5"));
        QFile t(text);
        QVERIFY(t.open(QIODevice::WriteOnly));
        t.write("time,force\n0,1\n");
        t.close();
        const QString truncated = dir.filePath(QStringLiteral("truncated.h5"));
        QFile whole(m_record);
        QVERIFY(whole.open(QIODevice::ReadOnly));
        const QByteArray bytes = whole.readAll();
        QFile cut(truncated);
        QVERIFY(cut.open(QIODevice::WriteOnly));
        cut.write(bytes.left(bytes.size() / 3));
        cut.close();
        const QString missing = dir.filePath(QStringLiteral("missing.h5"));

        for (const QString& path : {missing, text, truncated}) {
            QString error;
            std::unique_ptr<ReplayWindow> w(ReplayWindow::open(path, nullptr, &error));
            QVERIFY2(!w, qPrintable(path));
            QVERIFY2(error.startsWith(path), qPrintable(error));
        }
        QString error;
        ReplayWindow::open(text, nullptr, &error);
        QVERIFY2(error.contains(QStringLiteral("not an HSMU record")), qPrintable(error));
        // The same off the GUI thread (the File > Open path): the error, and a good record.
        QVERIFY(!ReplayWindow::openInBackground(truncated, nullptr, &error));
        QVERIFY2(error.startsWith(truncated), qPrintable(error));
        std::unique_ptr<ReplayWindow> good(ReplayWindow::openInBackground(m_record, nullptr, &error));
        QVERIFY2(good && good->rowCount() == 201, qPrintable(error));

        // The command: exit code 1 and the reason on stderr, no window left open.
        QProcess p;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
        p.setProcessEnvironment(env);
        p.start(QStringLiteral(HSMU_EXE), {QStringLiteral("replay"), truncated});
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitCode(), 1);
        const QString err = QString::fromLocal8Bit(p.readAllStandardError());
        QVERIFY2(err.contains(QStringLiteral("hsmu replay: ")) && err.contains(truncated),
                 qPrintable(err));
    }

    void reidentifyWithTheRecordedSettingsGivesTheRecordedHistory() {
        QString error;
        std::unique_ptr<ReplayWindow> w(ReplayWindow::open(m_record, nullptr, &error));
        QVERIFY2(w, qPrintable(error));
        const RecordReader reader(m_record.toStdString());
        const RecordData& d = reader.data();
        QVERIFY(d.layout.updating);
        const int n = d.rows();
        QSignalSpy done(w.get(), &ReplayWindow::reidentified);
        QSignalSpy failed(w.get(), &ReplayWindow::reidentificationFailed);
        w->reidentify(QString(), QString()); // the recorded method and settings
        QVERIFY(w->isReidentifying());
        QTRY_COMPARE_WITH_TIMEOUT(done.count() + failed.count(), 1, 60000);
        QVERIFY2(failed.isEmpty(), failed.isEmpty() ? "" : qPrintable(failed[0][0].toString()));
        QVERIFY(!w->isReidentifying());
        const QString curve = ReplayWindow::reidentifiedCurveName(
            QString::fromStdString(d.layout.updating->method));
        QCOMPARE(done[0][0].toString(), curve);
        const auto& plots = w->panel().parameterPlots();
        QCOMPARE(int(plots.size()), int(d.parameters.cols()));
        for (int p = 0; p < int(plots.size()); ++p) {
            const QCPGraph* g = plots[std::size_t(p)]->overlayGraph(curve);
            QVERIFY(g);
            // Named in the panel's note under the plots, not in a third legend row (issue 25
            // item 17, reidentifiedCurveKeepsEveryPlotReadable).
            QVERIFY(!plots[std::size_t(p)]->legend->hasItemWithPlottable(g));
            QCOMPARE(g->data()->size(), n - 1); // rows 1 .. N-1: row 0 is no measurement
            QCOMPARE(g->data()->at(0)->key, d.time[1]);
            for (int k = 0; k < n - 1; ++k) { // same settings, same history
                const double recorded = d.parameters(k + 1, p);
                QVERIFY2(std::abs(g->data()->at(k)->value - recorded) <=
                             1e-9 * std::abs(recorded),
                         qPrintable(QStringLiteral("parameter %1 sample %2").arg(p).arg(k)));
            }
            QCOMPARE(g->pen().color() == plots[std::size_t(p)]->estimateGraph()->pen().color(),
                     false);
        }
    }

    // Issue 25 item 16: at step 0 (one row) the time plots showed -3 to 3 s (QCustomPlot
    // centres a span of its own on a single sample) and a flat 0 with crammed made-up ticks.
    // They span the record (0 to its last time) and show no numbers for a flat value.
    void firstRowShowsTheRecordsTimeSpan() {
        QString error;
        std::unique_ptr<ReplayWindow> w(ReplayWindow::open(m_record, nullptr, &error));
        QVERIFY2(w, qPrintable(error));
        w->resize(1280, 720);
        w->show();
        QVERIFY(QTest::qWaitForWindowExposed(w.get()));
        w->seek(1);
        QCOMPARE(w->rowsShown(), 1);
        w->panel().refreshNow();
        const QCPGraph* record = w->panel().groundMotion().graph(0);
        QVERIFY(record->dataCount() > 100);
        const double end = (record->data()->constEnd() - 1)->key;
        QVERIFY(std::abs(end - kDuration) < 0.05);
        for (QCustomPlot* p : std::initializer_list<QCustomPlot*>{
                 &w->panel().forceHistory(), &w->panel().displacementHistory(),
                 &w->panel().fitError(), w->panel().parameterPlots().front()}) {
            QVERIFY2(std::abs(p->xAxis->range().lower) < 1e-9 &&
                         std::abs(p->xAxis->range().upper - end) < 1e-9,
                     qPrintable(QStringLiteral("%1: %2..%3 s").arg(p->objectName())
                                    .arg(p->xAxis->range().lower).arg(p->xAxis->range().upper)));
        }
        // The force at step 0 is one value (0): nothing to scale the axis by; nor the held
        // ticks beside the tracking (none reported yet: QCustomPlot's 0..5 was shown).
        QVERIFY(!w->panel().forceHistory().yAxis->tickLabels());
        HistoryPlot& tracking = w->panel().tracking();
        QVERIFY(tracking.yAxis2->visible());
        QVERIFY(!tracking.yAxis2->tickLabels());
        // The fit error (one value) spans 0 and its threshold.
        HistoryPlot& fit = w->panel().fitError();
        QVERIFY(std::isfinite(fit.threshold()));
        QVERIFY(fit.yAxis->range().contains(fit.threshold()) && fit.yAxis->range().contains(0.0));
        QVERIFY(fit.yAxis->range().size() < 3.0 * fit.threshold());
    }

    // Issue 25 item 17: after Re-identify the k0 plot shrank to a strip and its legend was cut
    // (a third entry, "re-identified (UKF)", wrapped the legend into rows under a small plot).
    // In a 1280x720 window every parameter plot keeps its data area, a shown legend lies
    // whole inside its plot, and the overlaid curve is named once, under the plots.
    void reidentifiedCurveKeepsEveryPlotReadable() {
        QString error;
        std::unique_ptr<ReplayWindow> w(ReplayWindow::open(m_record, nullptr, &error));
        QVERIFY2(w, qPrintable(error));
        w->resize(1280, 720);
        w->show();
        QVERIFY(QTest::qWaitForWindowExposed(w.get()));
        QSignalSpy done(w.get(), &ReplayWindow::reidentified);
        QSignalSpy failed(w.get(), &ReplayWindow::reidentificationFailed);
        w->reidentify(QString(), QString());
        QTRY_COMPARE_WITH_TIMEOUT(done.count() + failed.count(), 1, 60000);
        QVERIFY2(failed.isEmpty(), failed.isEmpty() ? "" : qPrintable(failed[0][0].toString()));
        QCoreApplication::processEvents();
        const auto& plots = w->panel().parameterPlots();
        QVERIFY(plots.size() >= 2);
        int tallest = 0;
        for (ParameterPlot* p : plots) {
            p->replot();
            tallest = std::max(tallest, p->axisRect()->rect().height());
        }
        QVERIFY(tallest >= 20);
        for (ParameterPlot* p : plots) {
            const int h = p->axisRect()->rect().height();
            QVERIFY2(4 * h >= 3 * tallest, qPrintable(QStringLiteral("%1: data area %2 px tall, "
                                                                     "the tallest %3 px")
                                                          .arg(p->objectName()).arg(h).arg(tallest)));
            if (p->legend->visible())
                QVERIFY2(p->rect().contains(p->legend->outerRect()),
                         qPrintable(p->objectName() + QStringLiteral(": legend cut")));
        }
        auto* note = w->findChild<QLabel*>(QStringLiteral("overlayNote"));
        QVERIFY(note && note->isVisible());
        QVERIFY2(note->text().contains(done[0][0].toString().toHtmlEscaped()),
                 qPrintable(note->text()));
    }

    void nelderMeadReidentificationAddsItsCurves() {
        QString error;
        std::unique_ptr<ReplayWindow> w(ReplayWindow::open(m_record, nullptr, &error));
        QVERIFY2(w, qPrintable(error));
        QSignalSpy done(w.get(), &ReplayWindow::reidentified);
        QSignalSpy failed(w.get(), &ReplayWindow::reidentificationFailed);
        w->reidentify(QStringLiteral("nelderMead"), QString());
        w->reidentify(QStringLiteral("ukf"), QString()); // ignored: one at a time
        QTRY_COMPARE_WITH_TIMEOUT(done.count() + failed.count(), 1, 60000);
        QVERIFY2(failed.isEmpty(), failed.isEmpty() ? "" : qPrintable(failed[0][0].toString()));
        const QString nm = ReplayWindow::reidentifiedCurveName(QStringLiteral("Nelder-Mead"));
        QCOMPARE(done[0][0].toString(), nm);
        QCOMPARE(nm, QStringLiteral("re-identified (Nelder-Mead)"));
        const QString ukf = ReplayWindow::reidentifiedCurveName(QStringLiteral("UKF"));
        for (const ParameterPlot* plot : w->panel().parameterPlots()) {
            const QCPGraph* g = plot->overlayGraph(nm);
            QVERIFY(g);
            QCOMPARE(g->name(), nm);
            QCOMPARE(g->data()->size(), w->rowCount() - 1);
            QVERIFY(!plot->overlayGraph(ukf)); // the second request was ignored
        }
        // Playing back (clearData on a seek backwards) keeps the overlays.
        w->seek(w->rowCount());
        w->seek(1);
        for (const ParameterPlot* plot : w->panel().parameterPlots())
            QCOMPARE(plot->overlayGraph(nm)->data()->size(), w->rowCount() - 1);
    }

    void badOverrideIsReportedAndChangesNothing() {
        QString error;
        std::unique_ptr<ReplayWindow> w(ReplayWindow::open(m_record, nullptr, &error));
        QVERIFY2(w, qPrintable(error));
        const QString missing = m_dir.filePath(QStringLiteral("no-such-override.json"));
        QSignalSpy done(w.get(), &ReplayWindow::reidentified);
        QSignalSpy failed(w.get(), &ReplayWindow::reidentificationFailed);
        w->reidentify(QStringLiteral("ukf"), missing);
        QTRY_COMPARE_WITH_TIMEOUT(failed.count(), 1, 60000);
        QCOMPARE(done.count(), 0);
        QVERIFY(failed[0][0].toString().contains(QStringLiteral("cannot be opened")));
        for (const ParameterPlot* plot : w->panel().parameterPlots())
            QVERIFY(!plot->overlayGraph(ReplayWindow::reidentifiedCurveName(QStringLiteral("UKF"))));
    }

    // Issue 16 item 15: event / alarm / note list with jump-to, the numeric read-out of the
    // cursor step, exports (CSV of the shown time window, PNG / SVG / PDF of the plots), a
    // menu with Close and keyboard shortcuts.
    void eventsReadoutExportsAndMenu() {
        // A record with an operator note at step 50 and an operator event at step 120.
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("noted.h5"));
        {
            TestConfig cfg = PresetLibrary::load(QStringLiteral("paper-condition-3"));
            cfg.analysis.duration = kDuration;
            std::unique_ptr<HybridTest> test = buildHybridTest(cfg);
            RecordWriter writer(path.toStdString(), RunLayout::of(*test),
                                RecordStart{cfg.raw.dump(), cfg.name, {}, cfg.analysis.dt});
            writer.trackAlarms(&test->alarms());
            test->addObserver(&writer);
            QVERIFY(test->prepare());
            while (test->step() == HybridTest::StepResult::Advanced) {
                if (test->currentStep() == 50)
                    writer.addNote(test->time(), 50, "crack at the base");
                if (test->currentStep() == 120)
                    writer.addNote(test->time(), 120,
                                   "operator-event action=pause; old=running; new=paused; "
                                   "wall=2026-01-01T00:00:00.000Z");
            }
            test->removeObserver(&writer);
            QVERIFY(writer.finish());
        }
        QString error;
        std::unique_ptr<ReplayWindow> w(ReplayWindow::open(path, nullptr, &error));
        QVERIFY2(w, qPrintable(error));
        w->show();
        ReplayEventList& events = w->events();
        const QList<QTreeWidgetItem*> crack =
            events.findItems(QStringLiteral("crack"), Qt::MatchContains, ReplayEventList::Text);
        QCOMPARE(crack.size(), 1);
        QCOMPARE(crack.front()->text(ReplayEventList::Step), QStringLiteral("50"));
        QCOMPARE(crack.front()->text(ReplayEventList::Kind), QStringLiteral("note"));
        const QList<QTreeWidgetItem*> pause =
            events.findItems(QStringLiteral("paused by the operator (wall time 2026-01-01T00:00:00"),
                             Qt::MatchContains, ReplayEventList::Text); // shown translated
        QCOMPARE(pause.size(), 1);
        QCOMPARE(pause.front()->text(ReplayEventList::Kind), QStringLiteral("operator"));
        // Jump to the note: steps 0..50 shown, the read-out shows step 50.
        emit events.itemActivated(crack.front(), 0);
        QCOMPARE(w->rowsShown(), 51);
        QCOMPARE(w->readout().value(QStringLiteral("step")), QStringLiteral("50"));
        const double dt = m_run.config.analysis.dt;
        QCOMPARE(w->readout().value(QStringLiteral("t [s]")).toDouble(), 50 * dt);
        QCOMPARE(w->readout().value(QStringLiteral("u %1 [m]").arg(QString::fromStdString(
                                        m_run.layout.dofNames.front())))
                     .toDouble(),
                 QString::number(m_run.records[50].u[0], 'g', 6).toDouble());
        // Keyboard: Right steps forward, Left back.
        w->activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(w.get()));
        QTest::keyClick(w.get(), Qt::Key_Right);
        QCOMPARE(w->rowsShown(), 52);
        QTest::keyClick(w.get(), Qt::Key_Left);
        QCOMPARE(w->rowsShown(), 51);

        // CSV of the time window shown (zoomed to 0.20 .. 0.40 s): 21 rows, t column exact.
        auto* disp = w->panel().findChild<HistoryPlot*>(QStringLiteral("displacementPlot"));
        QVERIFY(disp);
        PlotTools::of(*disp)->setAutoscale(false);
        disp->xAxis->setRange(20 * dt, 40 * dt);
        const QString csv = dir.filePath(QStringLiteral("window.csv"));
        int rows = 0;
        QVERIFY2(w->exportWindowCsv(csv, &error, &rows), qPrintable(error));
        QCOMPARE(rows, 21);
        QFile f(csv);
        QVERIFY(f.open(QIODevice::ReadOnly | QIODevice::Text));
        const QStringList lines =
            QString::fromUtf8(f.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 22);
        QVERIFY(lines[0].startsWith(QStringLiteral("step,t [s],ag [m/s^2],u ")));
        QCOMPARE(lines[1].section(QLatin1Char(','), 0, 0), QStringLiteral("20"));

        // Plots as SVG and PDF: one file per plot.
        const QList<QCustomPlot*> plots = w->panel().findChildren<QCustomPlot*>();
        for (const QString& format : {QStringLiteral("svg"), QStringLiteral("pdf")}) {
            QStringList errors;
            const QStringList files =
                ReplayExport::exportPlots(plots, dir.path(), format, &errors);
            QVERIFY2(errors.isEmpty(), qPrintable(errors.join(QLatin1Char('\n'))));
            QCOMPARE(files.size(), plots.size());
            for (const QString& file : files)
                QVERIFY(QFileInfo(file).size() > 100);
        }

        // The menu closes the window (Ctrl+W).
        auto* close = w->findChild<QAction*>(QStringLiteral("closeReplay"));
        QVERIFY(close);
        QVERIFY(close->shortcuts().contains(QKeySequence(Qt::CTRL | Qt::Key_W)));
        close->trigger();
        QVERIFY(!w->isVisible());
    }

    void commandScreenshotOfARecord() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString png = dir.filePath(QStringLiteral("replay.png"));
        QProcess p;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
        p.setProcessEnvironment(env);
        p.start(QStringLiteral(HSMU_EXE),
                {QStringLiteral("replay"), m_record, QStringLiteral("--play"),
                 QStringLiteral("--speed"), QStringLiteral("50"), QStringLiteral("--screenshot"),
                 png, QStringLiteral("--screenshot-after"), QStringLiteral("1")});
        QVERIFY(p.waitForFinished(60000));
        QVERIFY2(p.exitCode() == 0, p.readAllStandardError().constData());
        const QImage image(png);
        QVERIFY2(!image.isNull() && image.width() >= 640 && image.height() >= 400, qPrintable(png));
    }
};

QTEST_MAIN(TestReplayWindow)
#include "TestReplayWindow.moc"
