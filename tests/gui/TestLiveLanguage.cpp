// Live language switching (issue 16): the console's language changes from the settings without
// a restart. With a test loaded and alarms in the list, each language in turn (es, zh_CN,
// en) is installed as the settings dialog does (Translations::install); every piece of the
// window must then show the catalogue's text for that language: window title, dock titles,
// menus, tool bar, setup panel (labels, choices, group titles), pending-updates panel,
// alarm list (headers, severities, kinds, and a core alarm's message from its code), status
// bar. Each expected text is looked up in the catalogue and must differ from the English one
// (so the check cannot pass by staying English). Core's alarm messages: AlarmText maps
// their codes to the operator's language, the English text stays the fallback.
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

#include "core/util/Alarm.h"
#include "gui/app/AlarmList.h"
#include "gui/app/AlarmText.h"
#include "gui/app/ConsoleSettings.h"
#include "gui/app/ControlBar.h"
#include "gui/app/MainWindow.h"
#include "gui/app/PendingUpdatesPanel.h"
#include "gui/app/SettingsDialog.h"
#include "gui/app/SetupPanel.h"
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
            QVERIFY2(window.windowTitle().startsWith(
                         catalogue("hsmu::gui::MainWindow", "HSMU Console - %1").section('%', 0, 0)),
                     qPrintable(window.windowTitle()));
            if (!english)
                window.grab().save(QDir::temp().filePath(
                    QStringLiteral("hsmu-live-language-%1.png").arg(code))); // for a look
        }
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
