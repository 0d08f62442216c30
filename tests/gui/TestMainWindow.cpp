// MainWindow wiring: a preset loads and runs; the plots receive every step (the specimen's
// measured loop and its twin, each DOF's history); the emergency hold is always available;
// Start goes through the pre-flight confirmation; the parameters table's edits reach the
// updater; critical alarms demand attention until acknowledged; settings are remembered.

#include "core/record/RecordReader.h"
#include "gui/app/AlarmList.h"
#include "gui/app/ConsoleSettings.h"
#include "gui/app/ControlBar.h"
#include "gui/app/MainWindow.h"
#include "gui/app/ParameterTableModel.h"
#include "gui/app/ParametersPanel.h"
#include "gui/app/PendingUpdatesPanel.h"
#include "gui/app/PreflightDialog.h"
#include "gui/app/SettingsDialog.h"
#include "gui/app/SetupPanel.h"
#include "gui/app/TestController.h"
#include "gui/app/Translations.h"
#include "gui/app/WheelGuard.h"
#include "gui/plots/HistoryPlot.h"
#include "gui/plots/HysteresisPlot.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QMessageBox>
#include <QScrollArea>
#include <QScrollBar>
#include <QWheelEvent>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace hsmu;
using namespace hsmu::gui;

class TestMainWindow : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true); // QSettings in a test location
        QSettings().clear();
        QVERIFY(m_records.isValid());
        ConsoleSettings::setRecordDirectory(m_records.path());
    }

    void presetRunsIntoThePlots() {
        MainWindow window;
        window.setConfirmBeforeStart(false);
        window.setSpeed(0.0);
        window.show();
        QString error;
        QVERIFY2(window.loadConfiguration(QStringLiteral("paper-condition-3"), &error),
                 qPrintable(error));
        auto* hysteresis = window.findChild<HysteresisPlot*>();
        auto* history = window.findChild<HistoryPlot*>(QStringLiteral("displacementPlot"));
        QVERIFY(hysteresis && history);
        // specimen (measured) + numerical twin + the auxiliary model of the UKF updating
        QCOMPARE(hysteresis->plottableCount(), 3);
        QVERIFY(hysteresis->plottable(0)->name().contains(QStringLiteral("Element 1")));
        QVERIFY(hysteresis->plottable(1)->name().contains(QStringLiteral("Element 2")));
        QVERIFY(hysteresis->plottable(2)->name().contains(QStringLiteral("auxiliary")));
        QCOMPARE(history->graphCount(), 2);
        QVERIFY(hysteresis->xAxis->label().contains(QStringLiteral("rad")));
        QVERIFY(hysteresis->yAxis->label().contains(QStringLiteral("kN m")));

        window.startTest();
        QTRY_COMPARE_WITH_TIMEOUT(window.controller().state(), RunState::Finished, 30000);
        const int rows = int(window.controller().recordsDelivered());
        QVERIFY(rows > 100);
        auto* loop = qobject_cast<QCPCurve*>(hysteresis->plottable(0));
        QVERIFY(loop);
        QCOMPARE(loop->dataCount(), rows);
        QCOMPARE(history->graph(0)->dataCount(), rows);
        QVERIFY(hysteresis->xAxis->range().size() > 0.0);

        // The console recorded every delivered row into its HDF5 record.
        const QString record = window.controller().recordPath();
        QVERIFY(record.startsWith(m_records.path()));
        QCOMPARE(RecordReader(record.toStdString()).rows(), rows);
        auto* recording = window.findChild<QLabel*>(QStringLiteral("statusRecording"));
        QVERIFY(recording && recording->toolTip() == record);
        QVERIFY(recording->text().endsWith(QStringLiteral("/record.h5")));

        // Start again after the end: the test is reloaded and the plots restart.
        window.startTest();
        QTRY_COMPARE_WITH_TIMEOUT(window.controller().state(), RunState::Finished, 30000);
        QCOMPARE(qobject_cast<QCPCurve*>(hysteresis->plottable(0))->dataCount(), rows);
    }

    void emergencyHoldIsAlwaysEnabled() {
        MainWindow window;
        auto* bar = window.findChild<ControlBar*>();
        QVERIFY(bar);
        QAction* hold = bar->emergencyHoldAction();
        QVERIFY(hold->isEnabled());
        QCOMPARE(hold->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_H));
        QVERIFY(!hold->shortcuts().contains(QKeySequence(Qt::Key_Escape))); // no accidents
        QVERIFY(hold->text().contains(hold->shortcut().toString(QKeySequence::NativeText)));
        QCOMPARE(hold->shortcutContext(), Qt::ApplicationShortcut);
        for (RunState s : {RunState::Idle, RunState::Ready, RunState::Running, RunState::Paused,
                           RunState::Holding, RunState::Finished, RunState::Failed}) {
            bar->setRunState(s);
            QVERIFY(hold->isEnabled());
        }
        window.setConfirmBeforeStart(false);
        window.setSpeed(1.0);
        QVERIFY(window.loadConfiguration(QStringLiteral("sdof-bouc-wen")));
        window.startTest();
        QTRY_COMPARE_WITH_TIMEOUT(window.controller().state(), RunState::Running, 5000);
        hold->trigger();
        QTRY_COMPARE_WITH_TIMEOUT(window.controller().state(), RunState::Holding, 5000);
    }

    void startWaitsForThePreflightConfirmation() {
        MainWindow window;
        window.setSpeed(0.0);
        window.show();
        QVERIFY(window.loadConfiguration(QStringLiteral("paper-condition-3")));
        window.startTest();
        QTRY_VERIFY_WITH_TIMEOUT(window.preflightDialog() != nullptr, 10000);
        PreflightDialog* dialog = window.preflightDialog();
        QVERIFY(!dialog->startButton()->isEnabled()); // zero offsets not yet confirmed
        QTest::qWait(100);
        QCOMPARE(window.controller().state(), RunState::Ready);
        QCOMPARE(window.controller().recordsCommitted(), qint64(1)); // step 0 only
        auto* verdict = dialog->findChild<QLabel*>(QStringLiteral("stabilityVerdict"));
        QVERIFY(verdict && verdict->text().contains(QStringLiteral("Stable")));
        auto* specimens = dialog->findChild<QTableWidget*>(QStringLiteral("preflightSpecimens"));
        QVERIFY(specimens && specimens->rowCount() == 1);
        QCOMPARE(specimens->item(0, 0)->text(), QStringLiteral("Element 1"));
        QVERIFY(specimens->item(0, 1)->text().endsWith(QStringLiteral(" rad")));  // max |d|
        QVERIFY(specimens->item(0, 2)->text().endsWith(QStringLiteral(" kN m"))); // max |F|
        // Cancel: nothing starts; Start again shows the same check.
        dialog->reject();
        QTRY_VERIFY_WITH_TIMEOUT(window.preflightDialog() == nullptr, 5000);
        QTest::qWait(100);
        QCOMPARE(window.controller().state(), RunState::Ready);
        window.startTest();
        QTRY_VERIFY_WITH_TIMEOUT(window.preflightDialog() != nullptr, 5000);
        dialog = window.preflightDialog();
        dialog->zeroConfirmation()->setChecked(true);
        QVERIFY(dialog->startButton()->isEnabled());
        dialog->startButton()->click();
        QTRY_COMPARE_WITH_TIMEOUT(window.controller().state(), RunState::Finished, 30000);
    }

    // Issue 16 item 1: a hold while the pre-flight is open leaves nothing armed; Resume
    // cannot drive the test; no run folder is left behind (item 16).
    void emergencyHoldDuringThePreflightStartsNothing() {
        QTemporaryDir records;
        ConsoleSettings::setRecordDirectory(records.path());
        MainWindow window;
        window.setSpeed(0.0);
        window.show();
        QVERIFY(window.loadConfiguration(QStringLiteral("sdof-bouc-wen")));
        window.startTest();
        QTRY_VERIFY_WITH_TIMEOUT(window.preflightDialog() != nullptr, 10000);
        auto* bar = window.findChild<ControlBar*>();
        QAction* hold = bar->emergencyHoldAction();
        QVERIFY(window.preflightDialog()->actions().contains(hold)); // alive over the dialog
        hold->trigger();
        QVERIFY(window.preflightDialog() == nullptr); // closed at once
        auto* alarms = window.findChild<AlarmList*>();
        QTRY_VERIFY_WITH_TIMEOUT(
            !alarms->findItems(QStringLiteral("nothing is armed"), Qt::MatchContains,
                               AlarmList::Message)
                 .isEmpty(),
            5000);
        const QTreeWidgetItem* event =
            alarms->findItems(QStringLiteral("nothing is armed"), Qt::MatchContains,
                              AlarmList::Message)
                .front();
        QCOMPARE(event->text(AlarmList::Step), QStringLiteral("0"));
        QCOMPARE(event->text(AlarmList::Time), QStringLiteral("0.00"));
        QCOMPARE(window.controller().state(), RunState::Ready);
        QAction* resume = nullptr;
        for (QAction* a : bar->actions())
            if (a->text() == QStringLiteral("Resume"))
                resume = a;
        QVERIFY(resume && !resume->isEnabled());
        window.controller().resume(); // even if asked directly: nothing drives
        QTest::qWait(200);
        QCOMPARE(window.controller().state(), RunState::Ready);
        QCOMPARE(window.controller().recordsCommitted(), qint64(1)); // step 0 only
        QVERIFY(QDir(records.path()).entryList(QDir::Dirs | QDir::NoDotAndDotDot).isEmpty());
        // Start again: the pre-flight is shown again and must be confirmed.
        window.startTest();
        QTRY_VERIFY_WITH_TIMEOUT(window.preflightDialog() != nullptr, 10000);
        window.preflightDialog()->reject();
        QTRY_VERIFY_WITH_TIMEOUT(window.preflightDialog() == nullptr, 5000);
        QCOMPARE(window.controller().state(), RunState::Ready);
        QVERIFY(QDir(records.path()).entryList(QDir::Dirs | QDir::NoDotAndDotDot).isEmpty());
        ConsoleSettings::setRecordDirectory(m_records.path());
    }

    // Issue 16 item 2: the wheel over an unfocused field scrolls, it does not edit.
    void wheelEditsOnlyTheFocusedField() {
        MainWindow window;
        window.resize(1280, 720);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.loadConfiguration(QStringLiteral("paper-condition-3")));
        auto* setup = window.findChild<SetupPanel*>();
        auto* scale = setup->findChild<QDoubleSpinBox*>(QStringLiteral("groundMotionScale"));
        auto* dt = setup->findChild<QDoubleSpinBox*>(QStringLiteral("timeStep"));
        QVERIFY(scale && dt);
        const double before = scale->value();
        auto wheel = [](QWidget* w, int delta = 120) {
            const QPointF at(w->width() / 2.0, w->height() / 2.0);
            QWheelEvent e(at, w->mapToGlobal(at), QPoint(), QPoint(0, delta), Qt::NoButton,
                          Qt::NoModifier, Qt::NoScrollPhase, false);
            QApplication::sendEvent(w, &e);
        };
        QCOMPARE(scale->focusPolicy(), Qt::StrongFocus);
        QVERIFY(!scale->hasFocus());
        wheel(scale);
        wheel(dt);
        QCOMPARE(scale->value(), before);
        QCOMPARE(dt->value(), 0.01);
        // ... and the panel scrolls under the wheel: the scroll area hands the wheel to its
        // scroll bar, which the guard must leave alone (it swallowed it: nothing scrolled).
        auto* scroll = qobject_cast<QScrollArea*>(
            window.findChild<QDockWidget*>(QStringLiteral("setupDock"))->widget());
        QVERIFY(scroll);
        QTRY_VERIFY(scroll->verticalScrollBar()->maximum() > 0); // laid out
        const int top = scroll->verticalScrollBar()->value();
        wheel(scroll->viewport(), -120);
        QVERIFY2(scroll->verticalScrollBar()->value() > top, "the wheel did not scroll the panel");
        QCOMPARE(dt->value(), 0.01);
        QVERIFY(!setup->isDirty());
        scale->setFocus();
        QTRY_VERIFY(scale->hasFocus());
        QTest::qWait(WheelGuard::kScrollGestureMs + 100); // the panel's scrolling is over
        wheel(scale);
        QVERIFY(scale->value() > before); // focused: the wheel edits, as expected
    }

    // Issue 16 item 2: the pre-flight flags what changed since the last run and unusual values.
    void preflightFlagsChangesAndUnusualValues() {
        MainWindow window;
        window.setSpeed(0.0);
        window.show();
        QVERIFY(window.loadConfiguration(QStringLiteral("sdof-bouc-wen")));
        window.startTest();
        QTRY_VERIFY_WITH_TIMEOUT(window.preflightDialog() != nullptr, 10000);
        window.preflightDialog()->zeroConfirmation()->setChecked(true);
        window.preflightDialog()->startButton()->click();
        QTRY_COMPARE_WITH_TIMEOUT(window.controller().state(), RunState::Finished, 30000);
        // Scale x40 and dt / 1000 (what a wheel accident did): both flagged, with old -> new.
        auto* setup = window.findChild<SetupPanel*>();
        auto* scale = setup->findChild<QDoubleSpinBox*>(QStringLiteral("groundMotionScale"));
        auto* dt = setup->findChild<QDoubleSpinBox*>(QStringLiteral("timeStep"));
        const double dt0 = dt->value();
        scale->setValue(scale->value() * 40.0);
        dt->setValue(dt0 / 1000.0);
        window.startTest();
        QTRY_VERIFY_WITH_TIMEOUT(window.preflightDialog() != nullptr, 10000);
        auto* flagged = window.preflightDialog()->findChild<QLabel*>(
            QStringLiteral("preflightWarnings"));
        QVERIFY(flagged);
        const QString text = flagged->text();
        QVERIFY2(text.contains(QStringLiteral("Unusual step count")), qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("Unusual PGA")), qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("ground motion scale [-] 1 -> 40")),
                 qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("time step dt [s] %1 -> ").arg(dt0)),
                 qPrintable(text));
        window.preflightDialog()->reject();
    }

    // Issue 16 item 3: Stop and Quit ask first while a test runs; "end and keep data".
    void stopAndQuitAskWhileATestRuns() {
        MainWindow window;
        window.setConfirmBeforeStart(false);
        window.setSpeed(1.0);
        window.show();
        QVERIFY(window.loadConfiguration(QStringLiteral("sdof-bouc-wen")));
        window.startTest();
        TestController& c = window.controller();
        QTRY_COMPARE_WITH_TIMEOUT(c.state(), RunState::Running, 5000);
        QAction* stop = window.findChild<QAction*>(QStringLiteral("stopTest"));
        QVERIFY(stop && stop->isEnabled());
        stop->trigger();
        QVERIFY(window.confirmation());
        QCOMPARE(window.confirmation()->objectName(), QStringLiteral("stopConfirmation"));
        QTest::qWait(100);
        QCOMPARE(c.state(), RunState::Running); // nothing ended yet
        window.confirmation()->findChild<QPushButton*>(QStringLiteral("continueTest"))->click();
        QTRY_VERIFY(window.confirmation() == nullptr);
        QTest::qWait(100);
        QCOMPARE(c.state(), RunState::Running);
        // Quit (Ctrl+Q / the window's close) asks too.
        QVERIFY(!window.close());
        QVERIFY(window.isVisible());
        QVERIFY(window.confirmation());
        QCOMPARE(window.confirmation()->objectName(), QStringLiteral("quitConfirmation"));
        window.confirmation()->findChild<QPushButton*>(QStringLiteral("continueTest"))->click();
        QTRY_VERIFY(window.confirmation() == nullptr);
        QCOMPARE(c.state(), RunState::Running);
        stop->trigger();
        QVERIFY(window.confirmation());
        window.confirmation()->findChild<QPushButton*>(QStringLiteral("confirmEnd"))->click();
        QTRY_COMPARE_WITH_TIMEOUT(c.state(), RunState::Stopped, 5000);
        QVERIFY(window.close()); // nothing runs: no question
    }

    void parameterTableEditsReachTheUpdater() {
        MainWindow window;
        window.setConfirmBeforeStart(false);
        window.setSpeed(5.0);
        window.show();
        QVERIFY(window.loadConfiguration(QStringLiteral("paper-condition-3")));
        TestController& c = window.controller();
        window.startTest();
        QTRY_VERIFY_WITH_TIMEOUT(c.recordsDelivered() >= 50, 20000);
        c.pause();
        QTRY_COMPARE_WITH_TIMEOUT(c.state(), RunState::Paused, 5000);
        auto* panel = window.findChild<ParametersPanel*>();
        QVERIFY(panel);
        ParameterTableModel* model = panel->model();
        QTRY_COMPARE_WITH_TIMEOUT(model->rowCount(), 7, 5000);
        int row = -1;
        for (int r = 0; r < model->rowCount(); ++r)
            if (model->index(r, ParameterTableModel::Name).data() == QStringLiteral("gamma"))
                row = r;
        QVERIFY(row >= 0);
        QVERIFY(model->flags(model->index(row, ParameterTableModel::Upper)) & Qt::ItemIsEditable);
        QVERIFY(model->setData(model->index(row, ParameterTableModel::Upper), 2.25, Qt::EditRole));
        QTRY_COMPARE_WITH_TIMEOUT(c.updating().parameter("gamma")->bounds.upper, 2.25, 5000);
        QCOMPARE(c.updating().parameter("gamma")->bounds.lower, 0.0);
        // The table shows what the updater reports back.
        QTRY_COMPARE_WITH_TIMEOUT(
            model->index(row, ParameterTableModel::Upper).data(Qt::EditRole).toDouble(), 2.25,
            5000);
        QVERIFY(model->setData(model->index(row, ParameterTableModel::Locked), Qt::Checked,
                               Qt::CheckStateRole));
        QTRY_VERIFY_WITH_TIMEOUT(c.updating().parameter("gamma")->locked, 5000);
        QCOMPARE(model->index(row, ParameterTableModel::Locked).data(Qt::CheckStateRole).toInt(),
                 int(Qt::Checked));
        // Not a number: refused, nothing sent.
        QSignalSpy refused(model, &ParameterTableModel::editRefused);
        QVERIFY(!model->setData(model->index(row, ParameterTableModel::Lower),
                                QStringLiteral("abc"), Qt::EditRole));
        QCOMPARE(refused.count(), 1);
        c.stop();
        QTRY_COMPARE_WITH_TIMEOUT(c.state(), RunState::Stopped, 5000);
        QVERIFY(
            !(model->flags(model->index(row, ParameterTableModel::Upper)) & Qt::ItemIsEditable));
    }

    void setupEditsRebuildTheTestAndLockWhileRunning() {
        MainWindow window;
        window.setConfirmBeforeStart(false);
        window.setSpeed(5.0);
        window.show();
        QVERIFY(window.loadConfiguration(QStringLiteral("paper-condition-3")));
        auto* setup = window.findChild<SetupPanel*>();
        auto* dt = setup->findChild<QDoubleSpinBox*>(QStringLiteral("timeStep"));
        auto* scale = setup->findChild<QDoubleSpinBox*>(QStringLiteral("groundMotionScale"));
        auto* limits = setup->findChild<QTableWidget*>(QStringLiteral("limitsTable"));
        // Issue 16 items 4-7: one policy control (the Pending updates panel's).
        QVERIFY(!setup->findChild<QComboBox*>(QStringLiteral("setupPolicy")));
        auto* policy = window.findChild<PendingUpdatesPanel*>()->findChild<QComboBox*>(
            QStringLiteral("approvalPolicy"));
        QVERIFY(dt && scale && limits && policy);
        QTRY_VERIFY_WITH_TIMEOUT(policy->isEnabled(), 5000);
        QCOMPARE(dt->value(), 0.01);
        QCOMPARE(limits->rowCount(), 1);
        QCOMPARE(limits->item(0, 0)->text(), QStringLiteral("Element 1"));
        QVERIFY(!setup->isDirty());
        dt->setValue(0.005);
        scale->setValue(0.5);
        limits->item(0, 2)->setText(QStringLiteral("35"));
        policy->setCurrentIndex(policy->findData(int(ReporterPolicy::OnApproval)));
        emit policy->activated(policy->currentIndex()); // as the operator's choice
        QVERIFY(setup->isDirty());
        // A limit that is not a number is refused with the element named; nothing is built.
        limits->item(0, 1)->setText(QStringLiteral("abc"));
        QString error;
        QVERIFY(!setup->edited(&error));
        QVERIFY2(error.contains(QStringLiteral("Element 1")), qPrintable(error));
        limits->item(0, 1)->setText(QStringLiteral("0")); // 0 = no limit
        const auto cfg = setup->edited(&error);
        QVERIFY2(cfg, qPrintable(error));
        QCOMPARE(cfg->analysis.dt, 0.005);
        QCOMPARE(cfg->groundMotion.scale, 0.5);
        const ElementSpec* e1 = nullptr;
        for (const ElementSpec& e : cfg->elements)
            if (e.name == "Element 1")
                e1 = &e;
        QVERIFY(e1);
        QCOMPARE(e1->limits.maxForce, 35.0);
        QVERIFY(std::isinf(e1->limits.maxDeformation));

        // Start applies the edits first; the setup is read-only while the test runs.
        window.startTest();
        TestController& c = window.controller();
        QTRY_COMPARE_WITH_TIMEOUT(c.state(), RunState::Running, 10000);
        QCOMPARE(c.config().analysis.dt, 0.005);
        QVERIFY(!setup->isDirty());
        QVERIFY(!dt->isEnabled());
        QVERIFY(!limits->isEnabled());
        // The operator's policy survived the reload of the Start (it reverted before).
        QCOMPARE(c.config().updating.policy, ReporterPolicy::OnApproval);
        QCOMPARE(policy->currentData().toInt(), int(ReporterPolicy::OnApproval));

        // Approve a pending update with the panel's button.
        QTRY_VERIFY_WITH_TIMEOUT(c.recordsDelivered() >= 50, 20000);
        c.pause();
        QTRY_COMPARE_WITH_TIMEOUT(c.state(), RunState::Paused, 5000);
        auto* pending = window.findChild<PendingUpdatesPanel*>();
        // One proposal for the one target (renewed every interval, never a queue).
        const auto queueIds = [&c] {
            QList<int> ids;
            for (const UpdateProposal& p : c.updating().pending)
                ids.push_back(p.id);
            return ids;
        };
        QTRY_VERIFY_WITH_TIMEOUT(pending->shownProposals().size() == 1 &&
                                     pending->shownProposals() == queueIds(),
                                 5000);
        // Reject it; the next one comes after one proposal interval of running; approve it.
        const int rejectedId = pending->shownProposals().front();
        pending->findChild<QPushButton*>(QStringLiteral("reject%1").arg(rejectedId))->click();
        QTRY_VERIFY_WITH_TIMEOUT(!pending->shownProposals().contains(rejectedId), 5000);
        c.resume();
        QTRY_VERIFY_WITH_TIMEOUT(!pending->shownProposals().isEmpty(), 20000);
        c.pause();
        QTRY_COMPARE_WITH_TIMEOUT(c.state(), RunState::Paused, 5000);
        QTRY_VERIFY_WITH_TIMEOUT(pending->shownProposals() == queueIds(), 5000);
        const int id = pending->shownProposals().front();
        auto* approve = pending->findChild<QPushButton*>(QStringLiteral("approve%1").arg(id));
        QVERIFY(approve && approve->isEnabled());
        QCOMPARE(c.updating().appliedUpdates, 0);
        approve->click();
        QTRY_COMPARE_WITH_TIMEOUT(c.updating().appliedUpdates, 1, 5000);
        QTRY_VERIFY_WITH_TIMEOUT(!pending->shownProposals().contains(id), 5000);
        const int approvedAt = c.updating().step;
        c.singleStep(); // the approved update is written with the next committed step
        QTRY_VERIFY_WITH_TIMEOUT(c.updating().step > approvedAt, 5000);
        // The approval is in the event list with its time and step.
        auto* alarms = window.findChild<AlarmList*>();
        QTRY_VERIFY_WITH_TIMEOUT(
            !alarms->findItems(QStringLiteral("update #%1 approved").arg(id), Qt::MatchContains,
                               AlarmList::Message)
                 .isEmpty(),
            5000);
        const QTreeWidgetItem* approved =
            alarms->findItems(QStringLiteral("update #%1 approved").arg(id), Qt::MatchContains,
                              AlarmList::Message)
                .front();
        QVERIFY(approved->text(AlarmList::Step).toInt() > 0);
        QVERIFY(!approved->text(AlarmList::Time).isEmpty());
        // A policy change during the run is an event too (the one control, live).
        policy->setCurrentIndex(policy->findData(int(ReporterPolicy::EveryStep)));
        emit policy->activated(policy->currentIndex());
        QTRY_COMPARE_WITH_TIMEOUT(c.updating().policy, ReporterPolicy::EveryStep, 5000);
        c.stop();
        QTRY_COMPARE_WITH_TIMEOUT(c.state(), RunState::Stopped, 5000);
        QVERIFY(dt->isEnabled());

        // The record: the approved update in /updating/events, the policy in force in the
        // configuration and the notes, and every operator action as a language-neutral note.
        const RecordData data = RecordReader(c.recordPath().toStdString()).data();
        std::vector<RecordedUpdate> applied, rejected;
        for (const RecordedUpdate& e : data.updateEvents) {
            if (e.decision == "applied")
                applied.push_back(e);
            else if (e.decision == "rejected")
                rejected.push_back(e);
            else
                QCOMPARE(e.decision, std::string("superseded")); // renewed proposals
        }
        QCOMPARE(int(applied.size()), 1);
        QCOMPARE(applied.front().step, approved->text(AlarmList::Step).toInt());
        QCOMPARE(applied.front().proposal, id);
        QCOMPARE(int(rejected.size()), 1); // the rejection is in the record too
        QCOMPARE(rejected.front().proposal, rejectedId);
        QCOMPARE(rejected.front().element, std::string("Element 2"));
        QVERIFY2(data.meta.configuration.find("\"onApproval\"") != std::string::npos,
                 data.meta.configuration.c_str());
        QVERIFY2(data.meta.operatorNotes.find("updating = onApproval") != std::string::npos,
                 data.meta.operatorNotes.c_str());
        QStringList actions;
        for (const RecordNote& n : data.notes) {
            const QString t = QString::fromStdString(n.text);
            QVERIFY2(t.startsWith(QStringLiteral("operator-event action=")), qPrintable(t));
            QVERIFY2(t.contains(QStringLiteral("; wall=20")), qPrintable(t));
            actions << t.section(QLatin1Char(';'), 0, 0).section(QLatin1Char('='), 1);
        }
        QVERIFY2(actions.contains(QStringLiteral("updating-policy")), qPrintable(actions.join(',')));
        bool policyEvent = false;
        for (const RecordNote& n : data.notes)
            policyEvent = policyEvent ||
                          n.text.find("action=updating-policy; old=onApproval; new=everyStep;") !=
                              std::string::npos;
        QVERIFY(policyEvent);
        QVERIFY2(actions.contains(QStringLiteral("start")), qPrintable(actions.join(',')));
        QVERIFY2(actions.contains(QStringLiteral("pause")), qPrintable(actions.join(',')));
        QVERIFY2(actions.contains(QStringLiteral("approve-update")), qPrintable(actions.join(',')));
        QVERIFY2(actions.contains(QStringLiteral("stop")), qPrintable(actions.join(',')));
    }

    void criticalAlarmDemandsAttentionUntilAcknowledged() {
        MainWindow window;
        window.show();
        auto* alarms = window.findChild<AlarmList*>();
        auto* banner = window.findChild<QWidget*>(QStringLiteral("attentionBanner"));
        QVERIFY(alarms && banner);
        QVERIFY(!banner->isVisible());
        alarms->addAlarm({1.5, 150, AlarmSeverity::Warning, AlarmKind::FitError, "fit"});
        QVERIFY(!banner->isVisible());
        alarms->addAlarm({2.0, 200, AlarmSeverity::Critical, AlarmKind::Fracture, "fracture"});
        QVERIFY(banner->isVisible());
        QCOMPARE(alarms->unacknowledgedCritical(), 1);
        QTreeWidgetItem* item = alarms->topLevelItem(alarms->topLevelItemCount() - 1);
        QCOMPARE(item->text(AlarmList::Time), QStringLiteral("2.00"));
        QCOMPARE(item->text(AlarmList::Message), QStringLiteral("fracture"));
        QVERIFY(item->background(AlarmList::Message).style() != Qt::NoBrush);
        alarms->acknowledgeAll();
        QCOMPARE(alarms->unacknowledgedCritical(), 0);
        QVERIFY(!banner->isVisible());
        QCOMPARE(item->background(AlarmList::Message).style(), Qt::NoBrush);
    }

    void settingsAreRemembered() {
        QSettings().clear();
        ConsoleSettings::setRecordDirectory(QString()); // not recorded
        QTemporaryDir dir;
        const QString file = dir.filePath(QStringLiteral("my-test.json"));
        QVERIFY(QFile::copy(QStringLiteral(":/presets/sdof-bouc-wen.json"), file));
        QByteArray state;
        {
            MainWindow window;
            window.show();
            QVERIFY(window.loadConfiguration(file));
            auto* alarmDock = window.findChild<QDockWidget*>(QStringLiteral("alarmDock"));
            QVERIFY(alarmDock);
            alarmDock->setFloating(true);
            auto* setup = window.findChild<SetupPanel*>();
            // Every protocol round-trips through the panel (docs/openfresco.md).
            for (const char* a : {"simapp://127.0.0.1:7001", "generictcp://10.0.0.2:7002",
                                  "builtin"}) {
                setup->setControllerAddress(QString::fromLatin1(a));
                QCOMPARE(setup->controllerText(), QString::fromLatin1(a));
            }
            setup->setControllerAddress(QStringLiteral("tcp://127.0.0.1:5999"));
            QVERIFY(window.applySetup()); // the address is remembered when applied
            window.close();
        }
        QCOMPARE(ConsoleSettings::recentFiles().value(0), QFileInfo(file).absoluteFilePath());
        QCOMPARE(ConsoleSettings::controllerAddress(), QStringLiteral("tcp://127.0.0.1:5999"));
        QVERIFY(!ConsoleSettings::windowState().isEmpty());
        MainWindow again;
        auto* alarmDock = again.findChild<QDockWidget*>(QStringLiteral("alarmDock"));
        QVERIFY(alarmDock->isFloating()); // the layout came back
        QCOMPARE(again.findChild<SetupPanel*>()->controllerText(),
                 QStringLiteral("tcp://127.0.0.1:5999"));
        // Languages: the embedded catalogues (translations/hsmu_en.ts -> :/i18n/hsmu_en.qm).
        QVERIFY(Translations::available().contains(QStringLiteral("en")));
        QVERIFY(Translations::install(*QCoreApplication::instance(), QStringLiteral("en")));
        QVERIFY(!Translations::install(*QCoreApplication::instance(), QStringLiteral("xx")));
        SettingsDialog dialog;
        QComboBox* language = dialog.languageBox();
        const int en = language->findData(QStringLiteral("en"));
        QVERIFY(en > 0); // after "System default"
        language->setCurrentIndex(en);
        dialog.store();
        QCOMPARE(ConsoleSettings::language(), QStringLiteral("en"));
        QSettings().clear();
        ConsoleSettings::setRecordDirectory(m_records.path());
    }

    void badConfigurationIsReportedNotThrown() {
        MainWindow window;
        QString error;
        QVERIFY(!window.loadConfiguration(QStringLiteral("/nonexistent/config.json"), &error));
        QVERIFY2(error.contains(QStringLiteral("config.json")), qPrintable(error));
    }

private:
    QTemporaryDir m_records;
};

QTEST_MAIN(TestMainWindow)
#include "TestMainWindow.moc"
