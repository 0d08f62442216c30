// Issue 25: the console an operator trusts on a long test day, on the lab's 1280x720 screen
// (an offscreen screen of that size, see main()). Each test reproduces one "Broken" item:
//   1  the link label follows each site's real state (a killed controller is "down", two labs
//      show their own sites, never the setup's unused 5600)
//   3  the wheel never changes a choice (combo box), and a focused field passing under the
//      pointer while the panel scrolls keeps its value; dialogs made later are guarded too;
//      a changed controller is flagged in pre-flight
//   4  a note added after the end is in the record and in the event list
//   5  the parameter plots redraw the bounds after an accepted edit
//   6  the cursor read-out goes when the pointer leaves and when another test is loaded; it
//      has an opaque background and stays inside its plot
//   7  a right click opens one context menu, holding every plot tool
//   8  the window fits the available screen geometry, also with a remembered larger one
//   9  the pre-flight's verdict (and every text of the dialog) is not clipped at 1280x720,
//      with the amber "Please check" box, in en, es and zh_CN
//   11 the parameter table's numbers fit their columns (no "0." / "0078312"), en, es, zh_CN

#include "core/record/RecordReader.h"
#include "gui/app/AlarmList.h"
#include "gui/app/ConsoleSettings.h"
#include "gui/app/MainWindow.h"
#include "gui/app/ParameterTableModel.h"
#include "gui/app/ParametersPanel.h"
#include "gui/app/PreflightChecks.h"
#include "gui/app/PreflightDialog.h"
#include "gui/app/SettingsDialog.h"
#include "gui/app/SetupPanel.h"
#include "gui/app/TestController.h"
#include "gui/app/Translations.h"
#include "gui/app/WheelGuard.h"
#include "gui/plots/HistoryPlot.h"
#include "gui/plots/LivePlotsPanel.h"
#include "gui/plots/ParameterPlot.h"
#include "gui/plots/PlotTools.h"
#include "tests/comms/ControllerProcess.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QContextMenuEvent>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QHeaderView>
#include <QLabel>
#include <QMenu>
#include <QMouseEvent>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QStandardPaths>
#include <QStyle>
#include <QTableView>
#include <QTemporaryDir>
#include <QWheelEvent>
#include <QtTest>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace hsmu;
using namespace hsmu::gui;

namespace {

void wheel(QWidget* w, int delta) {
    const QPointF at(w->width() / 2.0, w->height() / 2.0);
    QWheelEvent e(at, w->mapToGlobal(at), QPoint(), QPoint(0, delta), Qt::NoButton,
                  Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(w, &e);
}

QString linkText(const MainWindow& window) {
    const auto* link = window.findChild<QLabel*>(QStringLiteral("statusLink"));
    return link ? link->text() : QStringLiteral("<no link label>");
}

QList<QMenu*> visibleMenus() {
    QList<QMenu*> menus;
    for (QWidget* w : QApplication::topLevelWidgets())
        if (auto* m = qobject_cast<QMenu*>(w); m && m->isVisible())
            menus << m;
    return menus;
}

// A label shows all its text: a wrapped one gets the height its words need at its width, an
// unwrapped one the width of its text.
QString clipped(const QLabel* l) {
    if (l->text().isEmpty() || !l->isVisible())
        return {};
    if (l->wordWrap()) {
        const int need = l->heightForWidth(l->width());
        if (l->height() + 1 < need)
            return QStringLiteral("'%1': %2 px tall, needs %3").arg(l->text()).arg(l->height()).arg(need);
    } else if (l->width() + 1 < l->sizeHint().width()) {
        return QStringLiteral("'%1': %2 px wide, needs %3")
            .arg(l->text())
            .arg(l->width())
            .arg(l->sizeHint().width());
    }
    return {};
}

nlohmann::json preset(const char* name) {
    std::ifstream in(std::string(HSMU_SOURCE_DIR) + "/resources/presets/" + name + ".json");
    return nlohmann::json::parse(in);
}

} // namespace

class TestOperatorConsole : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
        QVERIFY(m_dir.isValid());
        ConsoleSettings::setRecordDirectory(QString()); // nothing recorded unless a test asks
        ConsoleSettings::setControllerAddress(QString());
        QCOMPARE(QGuiApplication::primaryScreen()->availableGeometry().size(), QSize(1280, 720));
    }
    void cleanupTestCase() {
        Translations::install(*QCoreApplication::instance(), QStringLiteral("en"));
    }
    void init() {
        // A window remembers the last controller: each test starts on the built-in lab.
        ConsoleSettings::setControllerAddress(QString());
    }

    // Item 1: a killed controller is "down" in the link label (it said "connected", state
    // "running", next to "sites: controller down").
    void linkLabelShowsAKilledControllerDown() {
        ControllerProcess lab({QStringLiteral("--config"), QStringLiteral("sdof-bouc-wen"),
                               QStringLiteral("--pace"), QStringLiteral("fast")});
        QVERIFY2(lab.start(), qPrintable(lab.log()));
        const QString address = QStringLiteral("tcp://127.0.0.1:%1").arg(lab.port());
        MainWindow window;
        window.setConfirmBeforeStart(false);
        window.setSpeed(1.0);
        window.show();
        window.setControllerAddress(address);
        QVERIFY(window.loadConfiguration(QStringLiteral("sdof-bouc-wen")));
        QVERIFY2(linkText(window).contains(QStringLiteral("connects at start")),
                 qPrintable(linkText(window)));
        window.startTest();
        TestController& c = window.controller();
        QTRY_COMPARE_WITH_TIMEOUT(c.state(), RunState::Running, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(linkText(window).contains(address + QStringLiteral(" connected")),
                                 5000);
        const qint64 before = c.recordsDelivered();
        QTRY_VERIFY_WITH_TIMEOUT(c.recordsDelivered() > before + 20, 10000);
        lab.kill();
        QTRY_VERIFY2_WITH_TIMEOUT(linkText(window).contains(QStringLiteral(" down")),
                                  qPrintable(linkText(window)), 10000);
        QVERIFY2(!linkText(window).contains(QStringLiteral("connected")),
                 qPrintable(linkText(window)));
        c.stop();
        QTRY_COMPARE_WITH_TIMEOUT(c.state(), RunState::Stopped, 20000);
    }

    // Item 1: two labs: each site by its name and state; nothing about the setup's own
    // controller (tcp://127.0.0.1:5600, where nothing listens).
    void linkLabelShowsEachLab() {
        const std::string config = m_dir.filePath(QStringLiteral("two-labs.json")).toStdString();
        {
            nlohmann::json j = preset("paper-bridge-two-labs");
            j["analysis"]["duration"] = 4.0;
            std::ofstream(config) << j.dump(2);
        }
        const QStringList args{QStringLiteral("--config"), QString::fromStdString(config),
                               QStringLiteral("--pace"), QStringLiteral("fast")};
        ControllerProcess labD(args), labC(args);
        QVERIFY2(labD.start(), qPrintable(labD.log()));
        QVERIFY2(labC.start(), qPrintable(labC.log()));
        nlohmann::json j = preset("paper-bridge-two-labs");
        j["analysis"]["duration"] = 4.0;
        for (auto& site : j["sites"])
            site["address"] = "tcp://127.0.0.1:" +
                              std::to_string(site["name"] == "Lab D" ? labD.port() : labC.port());
        const QString path = m_dir.filePath(QStringLiteral("two-labs-console.json"));
        std::ofstream(path.toStdString()) << j.dump(2);

        MainWindow window;
        window.setConfirmBeforeStart(false);
        window.setSpeed(1.0);
        window.show();
        window.setControllerAddress(QStringLiteral("tcp://127.0.0.1:5600"));
        QVERIFY(window.loadConfiguration(path));
        window.startTest();
        TestController& c = window.controller();
        QTRY_COMPARE_WITH_TIMEOUT(c.state(), RunState::Running, 10000);
        QTRY_VERIFY2_WITH_TIMEOUT(
            linkText(window).contains(QStringLiteral("Lab D connected")) &&
                linkText(window).contains(QStringLiteral("Lab C connected")),
            qPrintable(linkText(window)), 10000);
        QVERIFY2(!linkText(window).contains(QStringLiteral("5600")), qPrintable(linkText(window)));
        const auto* link = window.findChild<QLabel*>(QStringLiteral("statusLink"));
        QVERIFY2(link->toolTip().contains(QStringLiteral(":%1").arg(labD.port())) &&
                     link->toolTip().contains(QStringLiteral(":%1").arg(labC.port())),
                 qPrintable(link->toolTip()));
        labC.kill();
        QTRY_VERIFY2_WITH_TIMEOUT(linkText(window).contains(QStringLiteral("Lab C down")),
                                  qPrintable(linkText(window)), 10000);
        c.stop();
        QTRY_VERIFY_WITH_TIMEOUT(c.state() == RunState::Stopped || c.state() == RunState::Finished,
                                 20000);
    }

    // Item 3: the wheel rolled to scroll the setup panel switched the controller box.
    void wheelChangesNoChoiceAndNoFieldWhileScrolling() {
        MainWindow window;
        window.resize(1280, 720);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.loadConfiguration(QStringLiteral("paper-condition-3")));
        auto* setup = window.findChild<SetupPanel*>();
        auto* kind = setup->findChild<QComboBox*>(QStringLiteral("controllerKind"));
        auto* dt = setup->findChild<QDoubleSpinBox*>(QStringLiteral("timeStep"));
        QVERIFY(kind && dt);
        // The operator chose the controller with a click (the box keeps the focus) ...
        kind->setFocus();
        QTRY_VERIFY(kind->hasFocus());
        const int chosen = kind->currentIndex();
        // ... and later rolls the wheel over it: a choice never changes with the wheel.
        wheel(kind, -120);
        wheel(kind, 120);
        wheel(kind, 120);
        QCOMPARE(kind->currentIndex(), chosen);
        QCOMPARE(kind->focusPolicy(), Qt::StrongFocus);

        // A focused field that passes under the pointer while the panel scrolls keeps its value.
        auto* scroll = qobject_cast<QScrollArea*>(
            window.findChild<QDockWidget*>(QStringLiteral("setupDock"))->widget());
        QVERIFY(scroll);
        dt->setFocus();
        QTRY_VERIFY(dt->hasFocus());
        const double step = dt->value();
        wheel(scroll->viewport(), -120); // scrolling the panel ...
        wheel(dt, -120);                 // ... the field comes under the pointer
        wheel(dt, -120);
        QCOMPARE(dt->value(), step);
        // Once the scrolling has stopped, the focused field takes the wheel, as expected.
        QTest::qWait(WheelGuard::kScrollGestureMs + 100);
        wheel(dt, 120);
        QVERIFY(dt->value() > step);
        QVERIFY(setup->isDirty());

        // Widgets made after the window (a dialog's choices) are guarded too.
        SettingsDialog settings(&window);
        settings.show();
        auto* language = settings.findChild<QComboBox*>(QStringLiteral("languageBox"));
        QVERIFY(language);
        const int lang = language->currentIndex();
        wheel(language, -120);
        wheel(language, 120);
        QCOMPARE(language->currentIndex(), lang);
        QCOMPARE(language->focusPolicy(), Qt::StrongFocus);

        // A changed controller is flagged in pre-flight against the last confirmed run.
        QVariantMap last{{QStringLiteral("controller"), QStringLiteral("tcp://127.0.0.1:5600")}};
        QVariantMap now{{QStringLiteral("controller"), QStringLiteral("builtin")}};
        const QStringList flagged = PreflightChecks::warnings({}, now, last);
        QVERIFY2(flagged.join(QLatin1Char('|')).contains(QStringLiteral("controller")) &&
                     flagged.join(QLatin1Char('|')).contains(QStringLiteral("5600")),
                 qPrintable(flagged.join(QLatin1Char('|'))));
    }

    // Item 4: a note after the end was silently lost (no event, nothing in the record).
    void noteAfterTheEndIsRecorded() {
        QTemporaryDir records;
        ConsoleSettings::setRecordDirectory(records.path());
        MainWindow window;
        ConsoleSettings::setRecordDirectory(QString());
        window.setConfirmBeforeStart(false);
        window.setSpeed(0.0);
        window.show();
        QVERIFY(window.loadConfiguration(QStringLiteral("sdof-bouc-wen")));
        window.startTest();
        TestController& c = window.controller();
        QTRY_COMPARE_WITH_TIMEOUT(c.state(), RunState::Finished, 60000);
        const QString record = c.recordPath();
        QVERIFY(!record.isEmpty());
        const int steps = RecordReader(record.toStdString()).data().steps.back();
        c.addNote(QStringLiteral("after the end: specimen inspected, crack at the weld"));
        auto* alarms = window.findChild<AlarmList*>();
        QTRY_VERIFY_WITH_TIMEOUT(!alarms->findItems(QStringLiteral("crack at the weld"),
                                                    Qt::MatchContains, AlarmList::Message)
                                      .isEmpty(),
                                 5000);
        const RecordData data = RecordReader(record.toStdString()).data();
        bool found = false;
        for (const RecordNote& n : data.notes)
            if (n.text == "after the end: specimen inspected, crack at the weld") {
                found = true;
                QCOMPARE(n.step, steps); // at the last committed step
            }
        QVERIFY2(found, "the note is not in the record");
        QCOMPARE(data.rows(), steps + 1); // the record is otherwise unchanged and readable
    }

    // Item 5: after an accepted bound edit the plots still showed the old bounds.
    void boundEditRedrawsTheBoundLines() {
        MainWindow window;
        window.setConfirmBeforeStart(false);
        window.setSpeed(1.0);
        window.show();
        QVERIFY(window.loadConfiguration(QStringLiteral("paper-condition-3")));
        auto* k0 = window.findChild<ParameterPlot*>(QStringLiteral("parameterPlot_k0"));
        QVERIFY(k0);
        QCOMPARE(k0->lowerBoundLine()->point1->coords().y(), 0.7);
        QCOMPARE(k0->upperBoundLine()->point1->coords().y(), 1.4);
        window.startTest();
        TestController& c = window.controller();
        QTRY_COMPARE_WITH_TIMEOUT(c.state(), RunState::Running, 10000);
        c.pause();
        QTRY_COMPARE_WITH_TIMEOUT(c.state(), RunState::Paused, 5000);
        c.setParameterBounds(QStringLiteral("k0"), 0.95, 1.05);
        QTRY_VERIFY_WITH_TIMEOUT(c.updating().parameter("k0") &&
                                     c.updating().parameter("k0")->bounds.lower == 0.95,
                                 5000);
        QTRY_COMPARE_WITH_TIMEOUT(k0->lowerBoundLine()->point1->coords().y(), 0.95, 2000);
        QCOMPARE(k0->upperBoundLine()->point1->coords().y(), 1.05);
        c.resume();
        QTest::qWait(300);
        QCOMPARE(k0->lowerBoundLine()->point1->coords().y(), 0.95);
        c.stop();
        QTRY_COMPARE_WITH_TIMEOUT(c.state(), RunState::Stopped, 10000);
    }

    // Item 6: the read-out stayed after the pointer left and after another test was loaded
    // ("Element 1: 3.34629 at 15.09" over the bridge); in small plots it had no background
    // and was cut at the left.
    void cursorReadoutLeavesAndStaysInsideItsPlot() {
        MainWindow window;
        window.setConfirmBeforeStart(false);
        window.setSpeed(0.0);
        window.resize(1280, 720);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.loadConfiguration(QStringLiteral("paper-condition-3")));
        window.startTest();
        QTRY_COMPARE_WITH_TIMEOUT(window.controller().state(), RunState::Finished, 60000);
        auto* panel = window.findChild<LivePlotsPanel*>();
        panel->refreshNow();
        HistoryPlot& force = panel->forceHistory(); // a small plot at 1280x720
        PlotTools* tools = PlotTools::of(force);
        QVERIFY(tools);
        const QRect area = force.axisRect()->rect();
        const QPoint at(area.left() + 3, area.center().y()); // near the left edge
        QMouseEvent move(QEvent::MouseMove, QPointF(at), force.mapToGlobal(QPointF(at)),
                         Qt::NoButton, Qt::NoButton, Qt::NoModifier);
        QApplication::sendEvent(&force, &move);
        QVERIFY2(tools->cursorText().contains(QStringLiteral("Element 1")),
                 qPrintable(tools->cursorText()));
        QLabel* box = tools->cursorLabel();
        QVERIFY(box && box->isVisible());
        const QRect r = box->geometry();
        QVERIFY2(force.rect().contains(r),
                 qPrintable(QStringLiteral("read-out at (%1,%2 %3x%4) in a %5x%6 plot")
                                .arg(r.x()).arg(r.y()).arg(r.width()).arg(r.height())
                                .arg(force.width()).arg(force.height())));
        // An opaque white box: what is under it (the traces) does not show through.
        const QImage image = box->grab().toImage();
        QCOMPARE(image.pixelColor(image.width() / 2, image.height() - 3).alpha(), 255);
        QVERIFY(QColor(image.pixelColor(image.width() - 3, image.height() / 2)).lightness() > 240);
        // The pointer leaves: the read-out goes.
        QEvent leave(QEvent::Leave);
        QApplication::sendEvent(&force, &leave);
        QVERIFY(tools->cursorText().isEmpty());
        QVERIFY(!box->isVisible());
        // Another test loaded: nothing from the old one stays on its plots.
        QApplication::sendEvent(&force, &move);
        QVERIFY(!tools->cursorText().isEmpty());
        QVERIFY(window.loadConfiguration(QStringLiteral("paper-bridge")));
        QVERIFY2(tools->cursorText().isEmpty(), qPrintable(tools->cursorText()));
        QVERIFY(!box->isVisible());
    }

    // Item 7: a right click opened two menus on top of each other.
    void oneContextMenuWithEveryPlotTool() {
        MainWindow window;
        window.resize(1280, 720);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.loadConfiguration(QStringLiteral("paper-condition-3")));
        HistoryPlot& plot = window.findChild<LivePlotsPanel*>()->displacementHistory();
        int menus = -1;
        QStringList texts;
        QTimer::singleShot(300, this, [&] {
            const QList<QMenu*> shown = visibleMenus();
            menus = int(shown.size());
            for (QMenu* m : shown) {
                for (QAction* a : m->actions())
                    texts << a->text();
                m->close();
            }
        });
        const QPoint at = plot.axisRect()->rect().center();
        QContextMenuEvent e(QContextMenuEvent::Mouse, at, plot.mapToGlobal(at));
        QApplication::sendEvent(&plot, &e);
        QTRY_VERIFY_WITH_TIMEOUT(menus >= 0, 5000);
        QCOMPARE(menus, 1);
        for (const QString& want :
             {QStringLiteral("Autoscale"), QStringLiteral("Channels"),
              QStringLiteral("Export visible data as CSV..."), QStringLiteral("Export this plot..."),
              QStringLiteral("Export all plots...")})
            QVERIFY2(texts.contains(want), qPrintable(texts.join(QLatin1Char('|'))));
    }

    // Item 8: a 1500x920 window on a 1280x720 screen, and again on relaunch.
    void windowFitsTheScreen() {
        const QRect available = QGuiApplication::primaryScreen()->availableGeometry();
        {
            QSettings().remove(QStringLiteral("window"));
            MainWindow first;
            first.show();
            QVERIFY(QTest::qWaitForWindowExposed(&first));
            QTRY_VERIFY2(available.contains(first.frameGeometry()),
                         qPrintable(QStringLiteral("%1x%2+%3+%4")
                                        .arg(first.frameGeometry().width())
                                        .arg(first.frameGeometry().height())
                                        .arg(first.frameGeometry().x())
                                        .arg(first.frameGeometry().y())));
            QVERIFY(first.statusBar()->isVisible());
            // A bigger remembered window (another screen, an older version) ...
            first.setMinimumSize(0, 0);
            first.resize(1500, 920);
            first.move(40, 40);
            first.close(); // remembered
        }
        MainWindow again; // ... still fits on the next start
        again.show();
        QVERIFY(QTest::qWaitForWindowExposed(&again));
        QTRY_VERIFY2(available.contains(again.frameGeometry()),
                     qPrintable(QStringLiteral("%1x%2+%3+%4")
                                    .arg(again.frameGeometry().width())
                                    .arg(again.frameGeometry().height())
                                    .arg(again.frameGeometry().x())
                                    .arg(again.frameGeometry().y())));
        const QRect bar(again.statusBar()->mapToGlobal(QPoint(0, 0)), again.statusBar()->size());
        QVERIFY(available.contains(bar));
    }

    // Item 9: with the amber box, the stability verdict was cut at 1280x720.
    void preflightTextsAreNotClipped_data() {
        QTest::addColumn<QString>("language");
        QTest::newRow("en") << QStringLiteral("en");
        QTest::newRow("es") << QStringLiteral("es");
        QTest::newRow("zh_CN") << QStringLiteral("zh_CN");
    }
    void preflightTextsAreNotClipped() {
        QFETCH(QString, language);
        QVERIFY(Translations::install(*QCoreApplication::instance(), language));
        MainWindow window;
        window.setSpeed(0.0);
        window.resize(1280, 720);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.loadConfiguration(QStringLiteral("paper-condition-3")));
        // The last confirmed run had another scale: the pre-flight flags it (the amber box).
        QVariantMap last;
        last[QStringLiteral("scale")] = QStringLiteral("0.5");
        ConsoleSettings::setLastRun(QString::fromStdString(window.controller().config().name),
                                    last);
        auto* setup = window.findChild<SetupPanel*>();
        setup->findChild<QDoubleSpinBox*>(QStringLiteral("groundMotionScale"))->setValue(3.0);
        window.startTest();
        QTRY_VERIFY_WITH_TIMEOUT(window.preflightDialog() != nullptr, 10000);
        PreflightDialog* d = window.preflightDialog();
        QTRY_VERIFY(d->isVisible());
        QTest::qWait(50);
        QCoreApplication::processEvents();
        auto* flagged = d->findChild<QLabel*>(QStringLiteral("preflightWarnings"));
        QVERIFY(flagged && flagged->isVisible());
        const QRect available = d->screen()->availableGeometry();
        QVERIFY2(available.contains(d->frameGeometry()),
                 qPrintable(QStringLiteral("%1x%2").arg(d->frameGeometry().width()).arg(d->frameGeometry().height())));
        QStringList problems;
        for (const QLabel* l : d->findChildren<QLabel*>())
            if (const QString why = clipped(l); !why.isEmpty())
                problems << why;
        for (const QCheckBox* b : d->findChildren<QCheckBox*>())
            if (b->isVisible() && b->width() + 1 < b->sizeHint().width())
                problems << QStringLiteral("'%1': %2 px wide, needs %3")
                                .arg(b->text()).arg(b->width()).arg(b->sizeHint().width());
        QVERIFY2(problems.isEmpty(), qPrintable(language + QStringLiteral(": ") +
                                                problems.join(QStringLiteral("; "))));
        auto* verdict = d->findChild<QLabel*>(QStringLiteral("stabilityVerdict"));
        QVERIFY(verdict && verdict->isVisible());
        // The checks scroll if they must: the verdict can be brought into view entirely.
        auto* scroll = d->findChild<QScrollArea*>(QStringLiteral("preflightScroll"));
        QVERIFY(scroll);
        scroll->ensureWidgetVisible(verdict, 0, 0);
        const QRect inView(verdict->mapTo(scroll->viewport(), QPoint(0, 0)), verdict->size());
        QVERIFY(scroll->viewport()->rect().contains(inView));
        d->reject();
    }

    // Item 11: es: a sigma of 0.0078312 wrapped as "0." / "0078312".
    void parameterNumbersFitTheirColumns_data() {
        preflightTextsAreNotClipped_data();
    }
    void parameterNumbersFitTheirColumns() {
        QFETCH(QString, language);
        QVERIFY(Translations::install(*QCoreApplication::instance(), language));
        ParametersPanel panel;
        panel.resize(440, 420); // the right dock's width at 1280x720
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        UpdatingSnapshot s;
        s.enabled = true;
        s.method = "UKF";
        s.specimen = "Element 1";
        s.canLock = true;
        for (const char* name : {"k0", "alpha", "n", "beta", "gamma", "deltaNu", "deltaEta"}) {
            ParameterState p;
            p.name = name;
            p.value = 0.0098123456;
            p.sigma = 0.0078312345;
            p.bounds = {0.001, 0.05}; // as configured (paper-condition-3's alpha)
            s.parameters.push_back(p);
        }
        panel.setSnapshot(s);
        QTableView* table = panel.table();
        QCoreApplication::processEvents();
        QVERIFY(!table->wordWrap()); // a number is never broken over two lines
        const QFontMetrics fm(table->font());
        // The delegate's text margins (QStyledItemDelegate: PM_FocusFrameHMargin + 1 a side).
        const int margins =
            2 * (table->style()->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, table) + 1);
        QStringList problems;
        for (int row = 0; row < table->model()->rowCount(); ++row)
            for (int col = 0; col < table->model()->columnCount(); ++col) {
                const QString text = table->model()->index(row, col).data().toString();
                const int need = fm.horizontalAdvance(text) + margins;
                if (!text.isEmpty() && need > table->columnWidth(col))
                    problems << QStringLiteral("'%1' needs %2 px, its column has %3")
                                    .arg(text).arg(need).arg(table->columnWidth(col));
            }
        QVERIFY2(problems.isEmpty(), qPrintable(language + QStringLiteral(": ") +
                                                problems.join(QStringLiteral("; "))));
        QVERIFY(table->horizontalScrollBar()->maximum() == 0 ||
                !table->horizontalScrollBar()->isVisible());
    }
};

int main(int argc, char** argv) {
    // The lab's laptop: an offscreen screen of 1280x720 (Qt's offscreen platform reads the
    // screens from a JSON file).
    const std::string screens = (std::filesystem::temp_directory_path() /
                                 ("hsmu-screen-1280x720-" + std::to_string(getpid()) + ".json"))
                                    .string();
    std::ofstream(screens) << R"({"screens": [{"name": "laptop", "x": 0, "y": 0, "width": 1280,)"
                              R"( "height": 720, "logicalDpi": 96, "logicalBaseDpi": 96,)"
                              R"( "dpr": 1}]})";
    qputenv("QT_QPA_PLATFORM", QByteArray("offscreen:configfile=") + screens.c_str());
    int result = 0;
    {
        QApplication app(argc, argv);
        TestOperatorConsole test;
        QTEST_SET_MAIN_SOURCE_PATH
        result = QTest::qExec(&test, argc, argv);
    }
    std::remove(screens.c_str());
    return result;
}

#include "TestOperatorConsole.moc"
