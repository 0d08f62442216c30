// The console's written contract (docs/console.md), issue 16 items 8-10, 13, 14: clarity
// before a start (no placeholder values, the UKF preset's parameters and policy shown at
// load, the ground motion checked and plotted when chosen), long messages that do not widen
// the window, the layout at 1280x720, the pace down to 1/100 x and by wall time per step,
// the Test link button and a token that never reaches the settings file.

#include "gui/app/AlarmList.h"
#include "gui/app/ConsoleSettings.h"
#include "gui/app/ControlBar.h"
#include "gui/app/MainWindow.h"
#include "gui/app/PendingUpdatesPanel.h"
#include "gui/app/SetupPanel.h"
#include "gui/app/TestController.h"
#include "gui/plots/HistoryPlot.h"

#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTreeWidget>
#include <QtTest>

using namespace hsmu;
using namespace hsmu::gui;

class TestConsoleContract : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
        QVERIFY(m_records.isValid());
        ConsoleSettings::setRecordDirectory(m_records.path());
    }

    // Item 8: no values before a load; the UKF preset's updating shown before a start.
    void clarityBeforeTheStart() {
        MainWindow window;
        window.show();
        auto* body = window.findChild<QWidget*>(QStringLiteral("setupBody"));
        QVERIFY(body && body->isHidden()); // no "Scale 0.000", "dt 0.00001 s"
        QVERIFY(window.loadConfiguration(QStringLiteral("paper-condition-3")));
        QVERIFY(!body->isHidden());
        QTRY_VERIFY_WITH_TIMEOUT(window.controller().updating().enabled, 5000);
        QCOMPARE(window.controller().state(), RunState::Ready);
        for (QLabel* l : window.findChild<PendingUpdatesPanel*>()->findChildren<QLabel*>())
            QVERIFY2(!l->text().contains(QStringLiteral("No online model updating")),
                     qPrintable(l->text()));
        QVERIFY(!window.controller().updating().parameters.empty());
    }

    // Item 8: a ground motion is checked and plotted when chosen, before any Apply.
    void groundMotionCheckedAndPlottedWhenChosen() {
        MainWindow window;
        window.show();
        QVERIFY(window.loadConfiguration(QStringLiteral("sdof-bouc-wen")));
        auto* setup = window.findChild<SetupPanel*>();
        auto* file = setup->findChild<QLineEdit*>(QStringLiteral("groundMotionFile"));
        auto* plot = window.findChild<HistoryPlot*>(QStringLiteral("groundMotionPlot"));
        QVERIFY(file && plot);
        QTemporaryDir dir;
        // Two columns time [s], acceleration [g]: 0.5 s at 0.01 s, a 0.1 g ramp.
        const QString good = dir.filePath(QStringLiteral("ramp.txt"));
        {
            QFile f(good);
            QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Text));
            for (int i = 0; i <= 50; ++i)
                f.write(QStringLiteral("%1 %2\n").arg(i * 0.01).arg(0.002 * i).toUtf8());
        }
        file->setText(good);
        file->setModified(true);
        emit file->editingFinished();
        QCOMPARE(setup->groundMotionStatus(), QString());
        QCOMPARE(plot->graph(0)->dataCount(), 51);
        QVERIFY(std::abs(plot->graph(0)->data()->at(50)->value - 0.1 * 9.80665) < 1e-9);
        // A PNG: reported at once, clearly, naming the file; nothing else changes.
        const QString png = dir.filePath(QStringLiteral("photo.png"));
        {
            QFile f(png);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(QByteArray::fromHex("89504e470d0a1a0a0000000d49484452000000100000001008060000"));
        }
        file->setText(png);
        file->setModified(true);
        emit file->editingFinished();
        const QString status = setup->groundMotionStatus();
        QVERIFY2(status.contains(QStringLiteral("photo.png")) &&
                     status.contains(QStringLiteral("not a text file of numbers")),
                 qPrintable(status));
        QCOMPARE(plot->graph(0)->dataCount(), 51); // the last good record stays
        QCOMPARE(window.controller().state(), RunState::Ready);
    }

    // Items 9, 10: a 260-character path in an error does not widen the window; 1280x720.
    void longMessagesDoNotWidenTheWindow() {
        MainWindow window;
        window.resize(1280, 720);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.loadConfiguration(QStringLiteral("paper-condition-3")));
        const QString path = QStringLiteral("/nonexistent/") + QString(250, QLatin1Char('x')) +
                             QStringLiteral(".json");
        QVERIFY(path.size() >= 260);
        QString error;
        QVERIFY(!window.loadConfiguration(path, &error));
        QCoreApplication::processEvents();
        QTest::qWait(50);
        QCOMPARE(window.width(), 1280);
        QVERIFY(window.minimumSizeHint().width() <= 1280);
        auto* banner = window.findChild<QLabel*>(QStringLiteral("attentionText"));
        QVERIFY(banner && banner->isVisible());
        QVERIFY(banner->toolTip().contains(path)); // the full text is in the tool tip
        // The alarm dock shows more than three rows at 1280x720.
        auto* alarms = window.findChild<AlarmList*>();
        QVERIFY(alarms->viewport()->height() >= 4 * alarms->sizeHintForRow(0));
    }

    // Item 13: pace from 1/100 x real time, and seconds of wall time per step.
    void paceDownToOneHundredthAndWallTimePerStep() {
        MainWindow window;
        auto* bar = window.findChild<ControlBar*>();
        QVERIFY(window.loadConfiguration(QStringLiteral("sdof-bouc-wen")));
        const double dt = window.controller().config().analysis.dt;
        window.setSpeed(0.01);
        QCOMPARE(bar->speed(), 0.01);
        QCOMPARE(window.controller().effectiveSpeed(), 0.01);
        bar->setWallTimePerStep(2.0);
        QCOMPARE(bar->wallTimePerStep(), 2.0);
        QCOMPARE(window.controller().effectiveSpeed(), dt / 2.0);
        auto* wall = bar->findChild<QDoubleSpinBox*>(QStringLiteral("wallTimePerStep"));
        QVERIFY(wall);
        wall->setValue(0.5);
        QCOMPARE(window.controller().effectiveSpeed(), dt / 0.5);
        window.setSpeed(1.0);
        QCOMPARE(bar->wallTimePerStep(), 0.0);
        QCOMPARE(window.controller().effectiveSpeed(), 1.0);
    }

    // Item 13: Test link connects now (an absent controller is reported); the token field
    // is never written to the settings.
    void testLinkAndTokenNeverStored() {
        MainWindow window;
        window.show();
        QVERIFY(window.loadConfiguration(QStringLiteral("sdof-bouc-wen")));
        auto* setup = window.findChild<SetupPanel*>();
        auto* test = setup->findChild<QPushButton*>(QStringLiteral("testLink"));
        QVERIFY(test);
        test->click(); // built-in lab: prepared at once
        QTRY_VERIFY_WITH_TIMEOUT(window.controller().preflight().has_value(), 10000);
        QCOMPARE(window.controller().state(), RunState::Ready);
        auto* alarms = window.findChild<AlarmList*>();
        QVERIFY(!alarms->findItems(QStringLiteral("link tested"), Qt::MatchContains,
                                   AlarmList::Message)
                     .isEmpty());
        // A controller that is not there, with a token: Failed, said at once; no token stored.
        const QString secret = QStringLiteral("s3cret-token-4242");
        window.setControllerAddress(QStringLiteral("tcp://127.0.0.1:9"));
        auto* token = setup->findChild<QLineEdit*>(QStringLiteral("controllerToken"));
        QVERIFY(token && token->echoMode() == QLineEdit::Password);
        token->setText(secret);
        test->click();
        QTRY_COMPARE_WITH_TIMEOUT(window.controller().state(), RunState::Failed, 15000);
        QSettings settings;
        settings.sync();
        for (const QString& key : settings.allKeys())
            QVERIFY2(!settings.value(key).toString().contains(secret), qPrintable(key));
        QFile file(settings.fileName());
        if (file.open(QIODevice::ReadOnly))
            QVERIFY(!file.readAll().contains(secret.toUtf8()));
    }

    // Issue 25 item 2: one row per target; a renewed proposal takes its row in place (the
    // buttons stay under the mouse), shown against the estimate now; a button decides the
    // proposal shown when it was pressed; a stale one is marked and cannot be approved.
    void proposalsAreRenewedInPlaceAndShownAgainstTheEstimate() {
        PendingUpdatesPanel panel;
        panel.setEditable(true);
        panel.show();
        UpdatingSnapshot s;
        s.enabled = true;
        s.policy = ReporterPolicy::OnApproval;
        s.maxPending = 100;
        s.proposalInterval = 2.0;
        auto proposal = [](int id, const char* element, double k0) {
            UpdateProposal p;
            p.id = id;
            p.step = id * 10;
            p.time = id * 0.1;
            p.element = element;
            p.parameters = ParameterLayout({"k0"});
            p.proposed = {k0};
            p.current = {1.0};
            p.fitError = 0.0125;
            return p;
        };
        s.time = 0.55;
        s.pending = {proposal(5, "Element 2", 1.10)};
        s.latest["Element 2"] = {1.105};
        panel.setSnapshot(s);
        QPushButton* approve5 = panel.findChild<QPushButton*>(QStringLiteral("approve5"));
        QVERIFY(approve5 && approve5->isEnabled());
        const QTreeWidgetItem* top = panel.tree()->topLevelItem(0);
        QVERIFY2(top->text(0).startsWith(QStringLiteral("#5 Element 2 at t = 0.50 s (step 50)")),
                 qPrintable(top->text(0)));
        QVERIFY2(top->text(0).contains(QStringLiteral("fit error 0.0125")), qPrintable(top->text(0)));
        // The decision row right under the title (child 0), the parameters below it: current,
        // proposed, the estimate now, the change.
        QCOMPARE(top->child(1)->text(1), QStringLiteral("1"));
        QCOMPARE(top->child(1)->text(2), QStringLiteral("1.1"));
        QCOMPARE(top->child(1)->text(3), QStringLiteral("1.105"));
        QCOMPARE(top->child(1)->text(4), QStringLiteral("10.0"));
        QVERIFY2(panel.summary()->text().contains(QStringLiteral("1 update")) &&
                     panel.summary()->text().contains(QStringLiteral("every 2 s")),
                 qPrintable(panel.summary()->text()));

        // The operator presses Approve on #5; before the release #6 renews the row in place.
        QSignalSpy approved(&panel, &PendingUpdatesPanel::approveRequested);
        QSignalSpy rejected(&panel, &PendingUpdatesPanel::rejectRequested);
        emit approve5->pressed();
        s.time = 0.65;
        s.pending = {proposal(6, "Element 2", 1.12), proposal(7, "Element 3", 0.9)};
        s.latest["Element 2"] = {1.121};
        panel.setSnapshot(s);
        QCOMPARE(panel.shownProposals(), (QList<int>{6, 7})); // Element 2's row first, in place
        QCOMPARE(panel.findChild<QPushButton*>(QStringLiteral("approve6")), approve5); // the same
        QVERIFY(!panel.findChild<QPushButton*>(QStringLiteral("approve5")));
        QCOMPARE(panel.tree()->topLevelItem(0)->child(1)->text(2), QStringLiteral("1.12"));
        emit approve5->released();
        emit approve5->clicked();
        QCOMPARE(approved.count(), 1);
        QCOMPARE(approved.at(0).at(0).toInt(), 5); // what was shown at the press (refused later)
        approve5->click(); // pressed and released on #6
        QCOMPARE(approved.at(1).at(0).toInt(), 6);
        panel.findChild<QPushButton*>(QStringLiteral("reject7"))->click();
        QCOMPARE(rejected.count(), 1);
        QCOMPARE(rejected.at(0).at(0).toInt(), 7);

        // Decided targets leave; a proposal one interval old is stale: marked, not approvable.
        s.time = 2.61;
        s.pending = {proposal(6, "Element 2", 1.12)};
        panel.setSnapshot(s);
        QCOMPARE(panel.shownProposals(), (QList<int>{6}));
        QVERIFY2(panel.tree()->topLevelItem(0)->text(0).contains(QStringLiteral("stale")),
                 qPrintable(panel.tree()->topLevelItem(0)->text(0)));
        QVERIFY(!panel.findChild<QPushButton*>(QStringLiteral("approve6"))->isEnabled());
        QVERIFY(panel.findChild<QPushButton*>(QStringLiteral("reject6"))->isEnabled());
        QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete); // the old buttons
        QVERIFY(!panel.findChild<QPushButton*>(QStringLiteral("approve7")));
    }

    // Item 4 (follow-up): after Stop the one policy control stays usable for the next run
    // (it was greyed out, so the policy could only be changed by reloading the test); the
    // choice goes to no test (nothing is armed) and is the configuration of the next Start.
    void policyIsChosenBetweenRunsForTheNextRun() {
        ConsoleSettings::setControllerAddress(QString()); // the built-in lab (not a test's link)
        MainWindow window;
        window.setConfirmBeforeStart(false);
        window.setSpeed(5.0);
        window.show();
        QVERIFY(window.loadConfiguration(QStringLiteral("paper-condition-3")));
        auto* pending = window.findChild<PendingUpdatesPanel*>();
        auto* policy = pending->findChild<QComboBox*>(QStringLiteral("approvalPolicy"));
        QVERIFY(policy);
        TestController& c = window.controller();
        QTRY_VERIFY_WITH_TIMEOUT(c.updating().enabled && policy->isEnabled(), 5000);
        QCOMPARE(c.updating().policy, ReporterPolicy::EveryStep);
        QSignalSpy states(&c, &TestController::stateChanged);
        window.startTest();
        QTRY_VERIFY_WITH_TIMEOUT(c.state() == RunState::Running || c.state() == RunState::Failed,
                                 10000);
        QVERIFY2(c.state() == RunState::Running,
                 qPrintable(states.isEmpty() ? QString() : states.last().at(1).toString()));
        QVERIFY(policy->isEnabled()); // while running: the existing contract (applies at once)
        QTRY_VERIFY_WITH_TIMEOUT(c.recordsDelivered() >= 5, 20000);
        c.stop();
        QTRY_COMPARE_WITH_TIMEOUT(c.state(), RunState::Stopped, 5000);
        QVERIFY(policy->isEnabled()); // between runs: the next run's policy
        policy->setCurrentIndex(policy->findData(int(ReporterPolicy::OnApproval)));
        emit policy->activated(policy->currentIndex()); // as the operator's choice
        QVERIFY2(pending->summary()->text().contains(QStringLiteral("waiting for a decision")),
                 qPrintable(pending->summary()->text())); // the panel shows the choice
        QCOMPARE(c.state(), RunState::Stopped); // nothing armed by the choice
        QCOMPARE(c.updating().policy, ReporterPolicy::EveryStep); // the ended run is unchanged
        window.startTest(); // reloads the same test with the chosen policy
        QTRY_COMPARE_WITH_TIMEOUT(c.state(), RunState::Running, 10000);
        QCOMPARE(c.config().updating.policy, ReporterPolicy::OnApproval);
        QTRY_COMPARE_WITH_TIMEOUT(c.updating().policy, ReporterPolicy::OnApproval, 5000);
        QCOMPARE(policy->currentData().toInt(), int(ReporterPolicy::OnApproval));
        c.stop();
        QTRY_COMPARE_WITH_TIMEOUT(c.state(), RunState::Stopped, 5000);
    }

    // Issue 13: OpenSees' adapter element is offered in the setup panel with what it needs
    // (host and port OpenSees listens on; no token), and an adapter:// address round-trips.
    void adapterLinkIsOfferedInTheSetup() {
        MainWindow window;
        window.show();
        QVERIFY(window.loadConfiguration(QStringLiteral("sdof-bouc-wen")));
        auto* setup = window.findChild<SetupPanel*>();
        auto* kind = setup->findChild<QComboBox*>(QStringLiteral("controllerKind"));
        auto* host = setup->findChild<QLineEdit*>(QStringLiteral("controllerHost"));
        auto* port = setup->findChild<QSpinBox*>(QStringLiteral("controllerPort"));
        auto* token = setup->findChild<QLineEdit*>(QStringLiteral("controllerToken"));
        auto* note = setup->findChild<QLabel*>(QStringLiteral("linkNote"));
        QVERIFY(kind && host && port && token && note);
        const int adapter = kind->findData(QStringLiteral("adapter"));
        QVERIFY2(adapter >= 0, "no adapter entry");
        QVERIFY(note->isHidden());
        kind->setCurrentIndex(adapter);
        host->setText(QStringLiteral("127.0.0.1"));
        port->setValue(44094);
        QVERIFY(host->isEnabled() && port->isEnabled());
        QVERIFY(!token->isEnabled()); // OpenSees' adapter knows no token
        QVERIFY(note->isVisibleTo(setup));
        QVERIFY2(note->text().contains(QStringLiteral("element adapter")), qPrintable(note->text()));
        QCOMPARE(setup->controllerText(), QStringLiteral("adapter://127.0.0.1:44094"));
        QString error;
        const auto address = setup->controller(&error);
        QVERIFY2(address, qPrintable(error));
        QCOMPARE(address->kind, hsmu::comms::LinkAddress::Kind::Adapter);
        QCOMPARE(int(address->port), 44094);
        // Applied: the test's link is the adapter (it connects at the pre-flight).
        QVERIFY(window.applySetup());
        QCOMPARE(window.controller().controllerAddress().kind,
                 hsmu::comms::LinkAddress::Kind::Adapter);
        // And back: an adapter address (command line, settings) selects the entry.
        kind->setCurrentIndex(0);
        QVERIFY(note->isHidden());
        window.setControllerAddress(QStringLiteral("adapter://10.0.0.2:44095"));
        QCOMPARE(kind->currentIndex(), adapter);
        QCOMPARE(host->text(), QStringLiteral("10.0.0.2"));
        QCOMPARE(port->value(), 44095);
    }

private:
    QTemporaryDir m_records;
};

QTEST_MAIN(TestConsoleContract)
#include "TestConsoleContract.moc"
