// Live language switching (issue 16): the console's language changes from the settings without
// a restart. With a test loaded and alarms in the list, each language in turn (es, zh_CN,
// en) is installed as the settings dialog does (Translations::install); every piece of the
// window must then show the catalogue's text for that language: window title, dock titles,
// menus, tool bar, setup panel (labels, choices, group titles), pending-updates panel,
// alarm list (headers, severities, kinds, and a core alarm's message from its code), status
// bar. Each expected text is looked up in the catalogue and must differ from the English one
// (so the check cannot pass by staying English). Core's alarm messages: AlarmText maps
// their codes to the operator's language, the English text stays the fallback; a safety
// limit's refusal (the real SafetyLimits text inside a hold) is shown translated too.
// The plots (titles, axis labels, legends) follow without losing their data, and so does the
// replay window (title, menus, docks, tool bar, and its event list made from a record's
// language-neutral alarms and operator events).
#include <QAction>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDockWidget>
#include <QFormLayout>
#include <QLabel>
#include <QMenuBar>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeWidget>

#include "core/experiment/HybridTest.h"
#include "core/experimental/SafetyLimits.h"
#include "core/record/RecordWriter.h"
#include "core/util/Alarm.h"
#include "core/util/ReasonText.h"
#include "gui/app/PreflightDialog.h"
#include "gui/app/OperatorEvent.h"
#include "gui/plots/HistoryPlot.h"
#include "gui/plots/HysteresisPlot.h"
#include "gui/plots/LivePlotsPanel.h"
#include "gui/plots/PlotElementPicker.h"
#include "gui/plots/PlotStyle.h"
#include "gui/replay/ReplayPanels.h"
#include "gui/replay/ReplayWindow.h"
#include "RecordedRun.h"
#include "gui/app/AlarmList.h"
#include "gui/app/AlarmText.h"
#include "gui/app/ConsoleSettings.h"
#include "gui/app/ControlBar.h"
#include "gui/app/MainWindow.h"
#include "gui/app/PendingUpdatesPanel.h"
#include "gui/app/SettingsDialog.h"
#include "gui/app/SetupPanel.h"
#include "gui/app/TestController.h"
#include "gui/app/Translations.h"

using namespace hsmu;
using namespace hsmu::gui;

namespace {
QString catalogue(const char* context, const char* source, int n = -1) {
    return QCoreApplication::translate(context, source, nullptr, n);
}
QDockWidget* dock(QMainWindow& w, const char* name) {
    return w.findChild<QDockWidget*>(QString::fromLatin1(name));
}
QString title(const QCustomPlot& plot) {
    return plot.property("hsmuTitle").toString();
}
// core's real refusal of a measured force past its limit, as an element reports it.
std::string forceRefusal() {
    hsmu::SafetyLimits limits;
    limits.maxForce = 40.0;
    return "Bearing D: " + *limits.violationOfForce(-45.5);
}
// Its translation, made from the catalogue (the element's name stays).
QString forceRefusalShown() {
    return catalogue("AlarmText", "%1: %2")
        .arg(QStringLiteral("Bearing D"),
             catalogue("AlarmText", "measured force |F| = %1 exceeds the limit %2")
                 .arg(QStringLiteral("45.5"), QStringLiteral("40")));
}
} // namespace

class TestLiveLanguage : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
        ConsoleSettings::setRecordDirectory(QString()); // nothing recorded
    }

    void cleanupTestCase() { Translations::install(*QCoreApplication::instance(), QStringLiteral("en")); }

    void everyPieceFollowsALanguageChange() {
        QVERIFY(Translations::install(*QCoreApplication::instance(), QStringLiteral("en")));
        MainWindow window;
        window.resize(1280, 720);
        window.show();
        QVERIFY(window.loadConfiguration(QStringLiteral("paper-condition-3")));
        auto* alarms = window.findChild<AlarmList*>();
        // A core alarm made from a template (code + arguments), shown before the change.
        alarms->addAlarm(Alarm(1.5, 150, AlarmSeverity::Critical, AlarmKind::OperatorHold,
                               "test held: operator hold", "test-held", {"operator hold"}));
        QTreeWidgetItem* held = alarms->topLevelItem(alarms->topLevelItemCount() - 1);
        // A limit's refusal: core's English text inside a hold (what HybridTest raises).
        const std::string refusal = forceRefusal();
        alarms->addAlarm(Alarm(2.0, 200, AlarmSeverity::Critical, AlarmKind::LimitExceeded,
                               "test held: " + refusal, "test-held", {refusal}));
        QTreeWidgetItem* limit = alarms->topLevelItem(alarms->topLevelItemCount() - 1);
        QCOMPARE(limit->text(AlarmList::Message),
                 QStringLiteral("test held: Bearing D: measured force |F| = 45.5 exceeds the "
                                "limit 40"));
        // An operator event: shown again from its language-neutral record text.
        alarms->addEvent(OperatorEvent::now(150, 1.5, OperatorEvent::kPause, "running", "paused"));
        QTreeWidgetItem* paused = alarms->topLevelItem(alarms->topLevelItemCount() - 1);
        alarms->addEvent(
            OperatorEvent::now(150, 1.5, OperatorEvent::kPolicy, "everyStep", "onApproval"));
        QTreeWidgetItem* policy = alarms->topLevelItem(alarms->topLevelItemCount() - 1);
        auto* plots = window.findChild<LivePlotsPanel*>();
        QVERIFY(plots);
        HistoryPlot& ground = plots->groundMotion();
        QVERIFY(ground.graphCount() >= 1);
        const int groundPoints = ground.graph(0)->dataCount();
        QVERIFY(groundPoints > 100); // the whole record, shown at load
        QCOMPARE(held->text(AlarmList::Message), QStringLiteral("test held: operator hold"));
        auto* controls = window.findChild<ControlBar*>();
        auto* setup = window.findChild<SetupPanel*>();
        auto* kind = setup->findChild<QComboBox*>(QStringLiteral("controllerKind"));
        auto* pending = window.findChild<PendingUpdatesPanel*>();
        QAction* stop = controls->findChild<QAction*>(QStringLiteral("stopTest"));
        QVERIFY(stop && kind && pending);

        for (const QString& code : {QStringLiteral("es"), QStringLiteral("zh_CN"),
                                    QStringLiteral("en")}) {
            QVERIFY2(Translations::install(*QCoreApplication::instance(), code), qPrintable(code));
            QCoreApplication::processEvents(); // LanguageChange is posted to the windows
            const bool english = code == QLatin1String("en");
            // Compare with the catalogue; outside English it must differ from the source.
            const auto expect = [&](const QString& shown, const char* context,
                                    const char* source) {
                const QString want = catalogue(context, source);
                QVERIFY2(shown == want, qPrintable(QStringLiteral("%1: '%2' shown, '%3' expected")
                                                       .arg(code, shown, want)));
                if (!english)
                    QVERIFY2(want != QLatin1String(source),
                             qPrintable(code + QStringLiteral(": untranslated ") + source));
            };
            expect(dock(window, "setupDock")->windowTitle(), "hsmu::gui::MainWindow", "Test setup");
            expect(dock(window, "alarmDock")->windowTitle(), "hsmu::gui::MainWindow",
                   "Alarms and events");
            expect(window.menuBar()->actions().front()->text(), "hsmu::gui::MainWindow", "&File");
            expect(stop->text(), "hsmu::gui::ControlBar", "Stop...");
            expect(kind->itemText(0), "hsmu::gui::SetupPanel", "built-in virtual lab");
            expect(kind->itemText(kind->findData(QStringLiteral("adapter"))),
                   "hsmu::gui::SetupPanel", "OpenSees adapter element (numerical substructure)");
            auto* form = qobject_cast<QFormLayout*>(kind->parentWidget()->layout());
            QVERIFY(form);
            expect(qobject_cast<QLabel*>(form->labelForField(kind))->text(),
                   "hsmu::gui::SetupPanel", "Specimens driven by:");
            expect(setup->findChild<QPushButton*>(QStringLiteral("applySetup"))->text(),
                   "hsmu::gui::SetupPanel", "Apply (reload the test)");
            expect(pending->findChild<QComboBox*>(QStringLiteral("approvalPolicy"))->itemText(0),
                   "hsmu::gui::PendingUpdatesPanel", "every step");
            expect(alarms->headerItem()->text(AlarmList::Message), "hsmu::gui::AlarmList",
                   "Message");
            expect(held->text(AlarmList::Severity), "hsmu::gui::AlarmList", "critical");
            expect(held->text(AlarmList::Kind), "hsmu::gui::AlarmList", "operator");
            // The core alarm's message from its code, the reason translated too.
            const QString message = catalogue("AlarmText", "test held: %1")
                                        .arg(catalogue("AlarmText", "operator hold"));
            QCOMPARE(held->text(AlarmList::Message), message);
            if (!english)
                QVERIFY(message != QLatin1String("test held: operator hold"));
            expect(window.findChild<QLabel*>(QStringLiteral("statusState"))->text(),
                   "RunState", "ready");
            expect(limit->text(AlarmList::Kind), "hsmu::gui::AlarmList", "limit exceeded");
            const QString pausedText = catalogue("OperatorEvent", "paused by the operator");
            QVERIFY2(paused->text(AlarmList::Message).startsWith(pausedText),
                     qPrintable(code + QStringLiteral(": ") + paused->text(AlarmList::Message)));
            if (!english)
                QVERIFY(pausedText != QLatin1String("paused by the operator"));
            // The record's policy names in the operator's words.
            QVERIFY2(policy->text(AlarmList::Message)
                         .contains(catalogue("hsmu::gui::PendingUpdatesPanel",
                                             "on the operator's approval")),
                     qPrintable(code + QStringLiteral(": ") + policy->text(AlarmList::Message)));
            const QString refusalShown =
                catalogue("AlarmText", "test held: %1").arg(forceRefusalShown());
            QCOMPARE(limit->text(AlarmList::Message), refusalShown);
            if (!english)
                QVERIFY2(!refusalShown.contains(QLatin1String("exceeds the limit")),
                         qPrintable(refusalShown));
            // Plots: titles, axis labels and legends, the data kept.
            HistoryPlot& displacement = plots->displacementHistory();
            expect(title(displacement), "hsmu::gui::HistoryPlot", "Displacement history");
            expect(PlotStyle::axisLabel(displacement, *displacement.yAxis), "hsmu::gui::HistoryPlot", "Displacement [m]");
            expect(PlotStyle::axisLabel(displacement, *displacement.xAxis), "hsmu::gui::HistoryPlot", "Time [s]");
            expect(title(ground), "hsmu::gui::HistoryPlot", "Ground motion");
            expect(ground.graph(0)->name(), "hsmu::gui::HistoryPlot", "Ground acceleration");
            QCOMPARE(ground.graph(0)->dataCount(), groundPoints);
            HistoryPlot& tracking = plots->tracking();
            QVERIFY(tracking.graphCount() == 4);
            expect(tracking.graph(0)->name(), "hsmu::gui::HistoryPlot", "commanded");
            expect(PlotStyle::axisLabel(tracking, *tracking.yAxis2), "hsmu::gui::HistoryPlot", "Held ticks [-]");
            HysteresisPlot& loop = plots->hysteresis();
            const QString loopTitle = title(loop);
            const QString shown = plots->hysteresisPicker().elementName();
            QVERIFY2(loopTitle ==
                         catalogue("hsmu::gui::HysteresisPlot", "Hysteresis of %1").arg(shown),
                     qPrintable(code + QStringLiteral(": ") + loopTitle));
            const QString rotation =
                catalogue("hsmu::gui::HysteresisPlot", "Rotation [%1]").section('%', 0, 0);
            const QString deformation =
                catalogue("hsmu::gui::HysteresisPlot", "Deformation [%1]").section('%', 0, 0);
            QVERIFY2(PlotStyle::axisLabel(loop, *loop.xAxis).startsWith(rotation) ||
                         PlotStyle::axisLabel(loop, *loop.xAxis).startsWith(deformation),
                     qPrintable(code + QStringLiteral(": ") + PlotStyle::axisLabel(loop, *loop.xAxis)));
            if (!english)
                QVERIFY(!PlotStyle::axisLabel(loop, *loop.xAxis).startsWith(QLatin1String("Rotation")) &&
                        !PlotStyle::axisLabel(loop, *loop.xAxis).startsWith(QLatin1String("Deformation")));
            QVERIFY2(window.windowTitle().startsWith(
                         catalogue("hsmu::gui::MainWindow", "HSMU Console - %1").section('%', 0, 0)),
                     qPrintable(window.windowTitle()));
            if (!english)
                window.grab().save(QDir::temp().filePath(
                    QStringLiteral("hsmu-live-language-%1.png").arg(code))); // for a look
        }
    }

    // The replay window follows a language change: its own texts, and its event list made from
    // the record's language-neutral texts (a hold by a safety limit, an operator event).
    void replayWindowFollowsALanguageChange() {
        QVERIFY(Translations::install(*QCoreApplication::instance(), QStringLiteral("en")));
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("record.h5"));
        {
            TestConfig cfg = PresetLibrary::load(QStringLiteral("paper-condition-3"));
            cfg.analysis.duration = 0.5;
            std::unique_ptr<HybridTest> test = buildHybridTest(cfg);
            RecordWriter writer(path.toStdString(), RunLayout::of(*test),
                                RecordStart{cfg.raw.dump(), cfg.name, {}, cfg.analysis.dt});
            writer.trackAlarms(&test->alarms());
            test->addObserver(&writer);
            QVERIFY(test->prepare());
            while (test->step() == HybridTest::StepResult::Advanced) {
                if (test->currentStep() == 20) {
                    test->hold(forceRefusal()); // the record holds core's English text
                    writer.addNote(test->time(), 20,
                                   OperatorEvent::now(20, test->time(), OperatorEvent::kPause,
                                                      "running", "paused")
                                       .recordText());
                    test->resume();
                }
            }
            test->removeObserver(&writer);
            QVERIFY(writer.finish());
        }
        QString error;
        std::unique_ptr<ReplayWindow> w(ReplayWindow::open(path, nullptr, &error));
        QVERIFY2(w, qPrintable(error));
        w->show();
        ReplayEventList& events = w->events();
        const auto row = [&](const QString& english) -> QTreeWidgetItem* {
            for (int i = 0; i < events.topLevelItemCount(); ++i)
                if (events.topLevelItem(i)->text(ReplayEventList::Text).startsWith(english))
                    return events.topLevelItem(i);
            return nullptr;
        };
        QTreeWidgetItem* held = row(QStringLiteral("test held: Bearing D: measured force"));
        QTreeWidgetItem* paused = row(QStringLiteral("paused by the operator"));
        QVERIFY(held && paused);
        const int plotsPoints = w->findChild<HistoryPlot*>(QStringLiteral("groundMotionPlot"))
                                    ->graph(0)
                                    ->dataCount();
        for (const QString& code : {QStringLiteral("es"), QStringLiteral("zh_CN"),
                                    QStringLiteral("en")}) {
            QVERIFY2(Translations::install(*QCoreApplication::instance(), code), qPrintable(code));
            QCoreApplication::processEvents();
            const bool english = code == QLatin1String("en");
            const auto expect = [&](const QString& shown, const QString& want,
                                    const char* source) {
                QVERIFY2(shown == want, qPrintable(QStringLiteral("%1: '%2' shown, '%3' expected")
                                                       .arg(code, shown, want)));
                if (!english)
                    QVERIFY2(!shown.startsWith(QString::fromLatin1(source).section('%', 0, 0)),
                             qPrintable(code + QStringLiteral(": untranslated ") + source));
            };
            const char* ctx = "hsmu::gui::ReplayWindow";
            QVERIFY2(w->windowTitle().startsWith(
                         catalogue(ctx, "HSMU Replay - %1 (%2)").section('%', 0, 0)),
                     qPrintable(w->windowTitle()));
            expect(w->menuBar()->actions().front()->text(), catalogue(ctx, "&File"), "&File");
            expect(dock(*w, "replayEventsDock")->windowTitle(),
                   catalogue(ctx, "Events, alarms and notes"), "Events, alarms and notes");
            expect(dock(*w, "replayReadoutDock")->windowTitle(),
                   catalogue(ctx, "Values at the cursor"), "Values at the cursor");
            expect(events.headerItem()->text(ReplayEventList::Text),
                   catalogue("hsmu::gui::ReplayEventList", "Event, alarm or note"),
                   "Event, alarm or note");
            expect(w->readout().item(0, 0)->text(),
                   catalogue("hsmu::gui::ReplayReadout", "step"), "step");
            QCOMPARE(w->readout().value(QStringLiteral("step")).isEmpty(), false);
            expect(held->text(ReplayEventList::Text),
                   catalogue("AlarmText", "test held: %1").arg(forceRefusalShown()),
                   "test held: %1");
            QVERIFY(paused->text(ReplayEventList::Text)
                        .startsWith(catalogue("OperatorEvent", "paused by the operator")));
            expect(paused->text(ReplayEventList::Kind),
                   catalogue("hsmu::gui::ReplayEventList", "operator"), "operator");
            auto* replayed = w->findChild<HistoryPlot*>(QStringLiteral("displacementPlot"));
            expect(PlotStyle::axisLabel(*replayed, *replayed->yAxis),
                   catalogue("hsmu::gui::HistoryPlot", "Displacement [m]"), "Displacement [m]");
            QCOMPARE(w->findChild<HistoryPlot*>(QStringLiteral("groundMotionPlot"))
                         ->graph(0)
                         ->dataCount(),
                     plotsPoints);
        }
    }

    // core's other fixed texts in the list follow a language change too (issue 16): a link
    // fault without a code (comms' English text, nested), an identifier's message inside an
    // estimator alarm, and a console message made from a configuration reader's error. Each
    // is stored language-neutral and shown again in the new language (before: the link fault
    // and the reader's error stayed English, the console message kept the language it was
    // shown in).
    void coreTextsInTheListFollowALanguageChange() {
        QVERIFY(Translations::install(*QCoreApplication::instance(), QStringLiteral("en")));
        MainWindow window;
        window.resize(1280, 720);
        window.show();
        QVERIFY(window.loadConfiguration(QStringLiteral("paper-condition-3")));
        auto* alarms = window.findChild<AlarmList*>();
        const auto last = [alarms] { return alarms->topLevelItem(alarms->topLevelItemCount() - 1); };
        QTemporaryDir dir;
        const QString missing = dir.filePath(QStringLiteral("no-such-test.json"));
        QString error;
        QVERIFY(!window.loadConfiguration(missing, &error));
        QTreeWidgetItem* cannotLoad = last();
        const std::string where = "tcp://127.0.0.1:9";
        const std::string within = reasonText("no-connection-within", {"127.0.0.1:9", "2"});
        const std::string linkFault = reasonText("link-fault", {where, within});
        alarms->addAlarm(
            Alarm(0.5, 50, AlarmSeverity::Critical, AlarmKind::ControlFault, linkFault));
        QTreeWidgetItem* link = last();
        const std::string rejected =
            reasonText("prediction-rejected", {reasonText("ukf-state-not-finite")});
        alarms->addAlarm(Alarm(0.6, 60, AlarmSeverity::Warning, AlarmKind::EstimatorRejected,
                               reasonText("estimator-rejected", {rejected}), "estimator-rejected",
                               {rejected}));
        QTreeWidgetItem* estimator = last();
        QCOMPARE(link->text(AlarmList::Message), QString::fromStdString(linkFault));

        for (const QString& code : {QStringLiteral("es"), QStringLiteral("zh_CN"),
                                    QStringLiteral("en")}) {
            QVERIFY(Translations::install(*QCoreApplication::instance(), code));
            QCoreApplication::processEvents();
            const bool english = code == QLatin1String("en");
            const QString linkShown =
                catalogue("AlarmText", "link to %1: %2")
                    .arg(QString::fromStdString(where),
                         catalogue("AlarmText", "no connection to %1 within %2 s")
                             .arg(QStringLiteral("127.0.0.1:9"), QStringLiteral("2")));
            QCOMPARE(link->text(AlarmList::Message), linkShown);
            QCOMPARE(link->toolTip(AlarmList::Message), linkShown);
            const QString estimatorShown =
                catalogue("AlarmText", "identification step rejected: %1")
                    .arg(catalogue("AlarmText", "prediction rejected: %1")
                             .arg(catalogue("AlarmText", "the state is not finite")));
            QCOMPARE(estimator->text(AlarmList::Message), estimatorShown);
            const QString cannotOpen = catalogue("AlarmText", "cannot open the configuration file");
            const QString loadShown =
                catalogue("hsmu::gui::MainWindow", "cannot load %1: %2")
                    .arg(missing, catalogue("AlarmText", "%1: %2").arg(missing, cannotOpen));
            QCOMPARE(cannotLoad->text(AlarmList::Message), loadShown);
            if (!english) {
                QVERIFY2(!linkShown.contains(QLatin1String("no connection")), qPrintable(linkShown));
                QVERIFY2(!estimatorShown.contains(QLatin1String("rejected")),
                         qPrintable(estimatorShown));
                QVERIFY2(!loadShown.contains(QLatin1String("cannot")), qPrintable(loadShown));
            } else {
                QCOMPARE(linkShown, QString::fromStdString(linkFault));
            }
        }
    }

    // A refused operator command follows a language change like the other entries (before:
    // "this test has no model updating" kept the language it was shown in): the worker sends
    // the refusal's template and arguments, the list redraws it from them.
    void refusedCommandsFollowALanguageChange() {
        QVERIFY(Translations::install(*QCoreApplication::instance(), QStringLiteral("es")));
        MainWindow window;
        window.show();
        auto* alarms = window.findChild<AlarmList*>();
        const auto find = [alarms](const QString& text) -> QTreeWidgetItem* {
            for (int i = 0; i < alarms->topLevelItemCount(); ++i)
                if (alarms->topLevelItem(i)->text(AlarmList::Message) == text)
                    return alarms->topLevelItem(i);
            return nullptr;
        };
        const char* ctx = "hsmu::gui::TestWorker";
        const char* noUpdating = "this test has no model updating";
        const char* badBounds = "%1: the lower bound must be a number not above the upper bound";
        // A refusal without arguments (a test without updating) ...
        QVERIFY(window.loadConfiguration(QStringLiteral("sdof-bouc-wen")));
        window.controller().setFitThreshold(0.2);
        QTRY_VERIFY_WITH_TIMEOUT(find(catalogue(ctx, noUpdating)), 5000);
        QTreeWidgetItem* refused = find(catalogue(ctx, noUpdating));
        for (const QString& code : {QStringLiteral("zh_CN"), QStringLiteral("en")}) {
            QVERIFY(Translations::install(*QCoreApplication::instance(), code));
            QCoreApplication::processEvents();
            QCOMPARE(refused->text(AlarmList::Message), catalogue(ctx, noUpdating));
            if (code != QLatin1String("en"))
                QVERIFY(catalogue(ctx, noUpdating) != QLatin1String(noUpdating));
        }
        QCOMPARE(refused->text(AlarmList::Message), QString::fromLatin1(noUpdating));
        // One with an argument (bounds the wrong way round), on a test with updating.
        QVERIFY(Translations::install(*QCoreApplication::instance(), QStringLiteral("es")));
        QVERIFY(window.loadConfiguration(QStringLiteral("paper-condition-3")));
        QTRY_VERIFY_WITH_TIMEOUT(window.controller().updating().enabled, 5000);
        window.controller().setParameterBounds(QStringLiteral("k0"), 2.0, 1.0);
        const auto bounds = [&] { return catalogue(ctx, badBounds).arg(QStringLiteral("k0")); };
        QTRY_VERIFY_WITH_TIMEOUT(find(bounds()), 5000);
        refused = find(bounds());
        for (const QString& code : {QStringLiteral("zh_CN"), QStringLiteral("en")}) {
            QVERIFY(Translations::install(*QCoreApplication::instance(), code));
            QCoreApplication::processEvents();
            QCOMPARE(refused->text(AlarmList::Message), bounds());
            if (code != QLatin1String("en"))
                QVERIFY(!bounds().contains(QLatin1String("lower bound")));
        }
        QCOMPARE(refused->text(AlarmList::Message),
                 QStringLiteral("k0: the lower bound must be a number not above the upper bound"));
    }

    // Pre-flight names what drives each specimen in the operator's language (before: "virtual
    // specimen (boucWen law, force noise std 0, ideal actuator)" in every language).
    void preflightDescribesTheControlInTheOperatorsLanguage() {
        QVERIFY(Translations::install(*QCoreApplication::instance(), QStringLiteral("es")));
        MainWindow window;
        window.setSpeed(0.0);
        window.show();
        QVERIFY(window.loadConfiguration(QStringLiteral("paper-condition-3")));
        window.startTest();
        QTRY_VERIFY_WITH_TIMEOUT(window.preflightDialog() != nullptr, 10000);
        auto* control = window.preflightDialog()->findChild<QLabel*>(
            QStringLiteral("preflightControl"));
        QVERIFY(control);
        const QString text = control->text();
        const QString start =
            catalogue("AlarmText", "virtual specimen (%1 law, force noise std %2, %3 actuator)")
                .section(QLatin1Char('%'), 0, 0);
        QVERIFY2(text.contains(start) && !text.contains(QLatin1String("virtual specimen")) &&
                     !text.contains(QLatin1String("actuator")),
                 qPrintable(text));
        window.preflightDialog()->reject();
        QTRY_VERIFY_WITH_TIMEOUT(window.preflightDialog() == nullptr, 5000);
        QVERIFY(Translations::install(*QCoreApplication::instance(), QStringLiteral("en")));
    }

    // The settings dialog switches at once (no restart) and stores the choice.
    void settingsDialogSwitchesLive() {
        QVERIFY(Translations::install(*QCoreApplication::instance(), QStringLiteral("en")));
        ConsoleSettings::setLanguage(QStringLiteral("en"));
        ControlBar bar;
        QAction* stop = bar.findChild<QAction*>(QStringLiteral("stopTest"));
        QCOMPARE(stop->text(), QStringLiteral("Stop..."));
        SettingsDialog dialog;
        auto* language = dialog.findChild<QComboBox*>(QStringLiteral("languageBox"));
        language->setCurrentIndex(language->findData(QStringLiteral("es")));
        dialog.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok)->click();
        QCoreApplication::processEvents();
        QCOMPARE(ConsoleSettings::language(), QStringLiteral("es"));
        QCOMPARE(stop->text(), catalogue("hsmu::gui::ControlBar", "Stop..."));
        QVERIFY(stop->text() != QLatin1String("Stop..."));
    }

    // Unknown codes and wrong argument counts fall back to core's English text.
    void alarmTextFallsBackToEnglish() {
        QVERIFY(Translations::install(*QCoreApplication::instance(), QStringLiteral("es")));
        QCOMPARE(AlarmText::describe("no-such-code", {}, QStringLiteral("english")),
                 QStringLiteral("english"));
        QCOMPARE(AlarmText::describe("fit-error", {QStringLiteral("12.0")},
                                     QStringLiteral("english")),
                 QStringLiteral("english"));
        const QString fit = AlarmText::describe(
            "fit-error", {QStringLiteral("12.5"), QStringLiteral("10.0")}, QStringLiteral("e"));
        QVERIFY2(fit.contains(QStringLiteral("12.5")) && fit.contains(QStringLiteral("10.0")) &&
                     !fit.startsWith(QStringLiteral("model error")),
                 qPrintable(fit));
    }
};

QTEST_MAIN(TestLiveLanguage)
#include "TestLiveLanguage.moc"
