// MainWindow wiring: a preset loads and runs; the plots receive every step (the specimen's
// measured loop and its twin, each DOF's history); the emergency hold is always available.

#include "gui/app/ControlBar.h"
#include "gui/app/MainWindow.h"
#include "gui/app/TestController.h"
#include "gui/plots/HistoryPlot.h"
#include "gui/plots/HysteresisPlot.h"

#include <QAction>
#include <QtTest>

using namespace hsmu;
using namespace hsmu::gui;

class TestMainWindow : public QObject {
    Q_OBJECT
private slots:
    void presetRunsIntoThePlots() {
        MainWindow window;
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
        QVERIFY(hold->shortcuts().contains(QKeySequence(Qt::Key_Escape)));
        QCOMPARE(hold->shortcutContext(), Qt::ApplicationShortcut);
        for (RunState s : {RunState::Idle, RunState::Ready, RunState::Running, RunState::Paused,
                           RunState::Holding, RunState::Finished, RunState::Failed}) {
            bar->setRunState(s);
            QVERIFY(hold->isEnabled());
        }
        window.setSpeed(1.0);
        QVERIFY(window.loadConfiguration(QStringLiteral("sdof-bouc-wen")));
        window.startTest();
        QTRY_COMPARE_WITH_TIMEOUT(window.controller().state(), RunState::Running, 5000);
        hold->trigger();
        QTRY_COMPARE_WITH_TIMEOUT(window.controller().state(), RunState::Holding, 5000);
    }

    void badConfigurationIsReportedNotThrown() {
        MainWindow window;
        QString error;
        QVERIFY(!window.loadConfiguration(QStringLiteral("/nonexistent/config.json"), &error));
        QVERIFY2(error.contains(QStringLiteral("config.json")), qPrintable(error));
    }
};

QTEST_MAIN(TestMainWindow)
#include "TestMainWindow.moc"
