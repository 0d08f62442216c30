// Issue 25, the "Confusing" items, on the lab's 1280x720 screen (an offscreen screen of that
// size, see main()). Each test reproduces one item:
//   12 an automatic reconnect (a real hsmu-controller killed and restarted) is the link's, not
//      the operator's, and the state is "holding" while it is pending, not "running"
//   16 empty plots before a test: time axes over the loaded test (not 0..5 or -3..3), no
//      numbers on an axis with nothing to scale, labels with units, the fit-error plot over
//      its threshold, no threshold field without updating, ranges reset by another preset
//   17 no clipped text: the safety-limit headers fit their columns (broken into lines), a
//      plot's y label stays out of its title row (es: fit error), in en, es and zh_CN
//   15 the Sites box shows each site's whole address (two labs on one host differ only in
//      the port), en, es, zh_CN
//   18 a one-column ground-motion file (values only) is asked for its own sample step, apart
//      from the integration step, and plotted with it

#include "core/util/Alarm.h"
#include "gui/app/AlarmList.h"
#include "gui/app/ConsoleSettings.h"
#include "gui/app/MainWindow.h"
#include "gui/app/SetupPanel.h"
#include "gui/app/TestController.h"
#include "gui/app/Translations.h"
#include "gui/plots/HistoryPlot.h"
#include "gui/plots/HysteresisPlot.h"
#include "gui/plots/LivePlotsPanel.h"
#include "gui/plots/ParameterPlot.h"
#include "gui/plots/PlotStyle.h"
#include "gui/plots/PlotTools.h"
#include "tests/comms/ControllerProcess.h"

#include <QApplication>
#include <QDoubleSpinBox>
#include <QFile>
#include <QHeaderView>
#include <QStyle>
#include <QTableWidget>
#include <QLineEdit>
#include <QScreen>
#include <QScrollBar>
#include <QSignalSpy>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace hsmu;
using namespace hsmu::gui;

namespace {

// Tick labels of a shown axis run together: adjacent labels closer than their own size
// (height for a vertical axis, the wider one's width for a horizontal one).
QString crammedTicks(QCustomPlot& plot, QCPAxis& axis) {
    if (!axis.visible() || !axis.tickLabels())
        return {};
    const QVector<double> ticks = axis.tickVector();
    const QVector<QString> labels = axis.tickVectorLabels();
    const QFontMetrics fm(axis.tickLabelFont());
    for (qsizetype i = 1; i < ticks.size(); ++i) {
        if (!axis.range().contains(ticks[i]) || !axis.range().contains(ticks[i - 1]))
            continue;
        const double gap = std::abs(axis.coordToPixel(ticks[i]) - axis.coordToPixel(ticks[i - 1]));
        const int need = axis.orientation() == Qt::Vertical
                             ? fm.ascent()
                             : std::max(fm.horizontalAdvance(labels[i]),
                                        fm.horizontalAdvance(labels[i - 1]));
        if (gap < need)
            return QStringLiteral("%1: '%2' and '%3' %4 px apart, need %5")
                .arg(plot.objectName(), labels[i - 1], labels[i])
                .arg(gap)
                .arg(need);
    }
    return {};
}

// A shown axis label names its unit ("Force [kN]"), or there is none.
QString unitless(QCustomPlot& plot, QCPAxis& axis) {
    const QString label = PlotStyle::axisLabel(plot, axis);
    if (!axis.visible() || label.isEmpty() || label.contains(QLatin1Char('[')))
        return {};
    return QStringLiteral("%1: '%2' has no unit").arg(plot.objectName(), label);
}

std::vector<QCustomPlot*> shownPlots(LivePlotsPanel& panel) {
    std::vector<QCustomPlot*> out;
    for (const auto& p : panel.plots())
        out.push_back(p.plot);
    for (ParameterPlot* p : panel.parameterPlots())
        out.push_back(p);
    return out;
}

} // namespace

class TestOperatorDay : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
        QVERIFY(m_dir.isValid());
        ConsoleSettings::setRecordDirectory(QString());
        ConsoleSettings::setControllerAddress(QString());
        QCOMPARE(QGuiApplication::primaryScreen()->availableGeometry().size(), QSize(1280, 720));
    }
    void cleanupTestCase() {
        Translations::install(*QCoreApplication::instance(), QStringLiteral("en"));
    }
    void init() { // each test reads English texts unless it chooses a language
        Translations::install(*QCoreApplication::instance(), QStringLiteral("en"));
    }

    // Item 12: automatic reconnects were logged as operator actions ("test resumed", kind
    // operator) and the state stayed "running" at 0 steps/s while held. The controller is
    // killed mid-test and started again on its port from its state file once the console
    // shows the reconnect.
    void automaticReconnectIsTheLinksNotTheOperators() {
        const QString state = m_dir.filePath(QStringLiteral("lab-state.txt"));
        ControllerProcess lab({QStringLiteral("--config"), QStringLiteral("sdof-bouc-wen"),
                               QStringLiteral("--pace"), QStringLiteral("fast"),
                               QStringLiteral("--state"), state});
        QVERIFY2(lab.start(), qPrintable(lab.log()));
        MainWindow window;
        window.setConfirmBeforeStart(false);
        window.setSpeed(1.0);
        window.show();
        window.setControllerAddress(QStringLiteral("tcp://127.0.0.1:%1").arg(lab.port()));
        QVERIFY(window.loadConfiguration(QStringLiteral("sdof-bouc-wen")));
        TestController& c = window.controller();
        std::vector<std::pair<RunState, QString>> states;
        connect(&c, &TestController::stateChanged, this,
                [&states](RunState s, const QString& m) { states.emplace_back(s, m); });
        std::vector<Alarm> alarms;
        connect(&c, &TestController::alarmRaised, this,
                [&alarms](const Alarm& a) { alarms.push_back(a); });
        window.startTest();
        QTRY_COMPARE_WITH_TIMEOUT(c.state(), RunState::Running, 10000);
        const qint64 before = c.recordsDelivered();
        QTRY_VERIFY_WITH_TIMEOUT(c.recordsDelivered() > before + 20, 10000);
        lab.kill();
        // The policy's backoff: holding, and saying so.
        QTRY_VERIFY_WITH_TIMEOUT(
            !states.empty() && states.back().first == RunState::Holding &&
                states.back().second.contains(QStringLiteral("reconnecting")),
            15000);
        QCOMPARE(c.state(), RunState::Holding);
        QVERIFY2(lab.start(lab.port()), qPrintable(lab.log()));
        auto restored = [&states] {
            for (const auto& [s, m] : states)
                if (s == RunState::Running && m.contains(QStringLiteral("restored")))
                    return true;
            return false;
        };
        auto history = [&states] {
            QStringList out;
            for (const auto& [s, m] : states)
                out << describe(s) + QStringLiteral(": ") + m;
            return out.join(QStringLiteral(" | "));
        };
        QTRY_VERIFY2_WITH_TIMEOUT(restored(), qPrintable(history() + lab.log()), 30000);
        const qint64 resumedAt = c.recordsDelivered();
        QTRY_VERIFY_WITH_TIMEOUT(
            c.recordsDelivered() > resumedAt + 20 || c.state() == RunState::Finished, 10000);
        int automatic = 0;
        for (const Alarm& a : alarms) {
            QVERIFY2(a.kind != AlarmKind::OperatorHold, a.message.c_str());
            automatic += a.code == "test-resumed-reconnect";
        }
        QVERIFY(automatic >= 1);
        // The event list says who: the link, not the operator.
        const QString events = window.findChild<AlarmList*>()->rowsText(QLatin1Char('\t'), false);
        QVERIFY2(events.contains(QStringLiteral("test resumed after an automatic reconnect")),
                 qPrintable(events));
        c.stop();
        QTRY_VERIFY_WITH_TIMEOUT(c.state() == RunState::Stopped || c.state() == RunState::Finished,
                                 20000);
    }

    // Item 16: empty plots before a test crammed their ticks, showed time from -3 to 3 s (or
    // QCustomPlot's 0..5), "Force" / "Deformation" without units and kept the last test's
    // ranges when another preset was loaded; a threshold field showed 0.001 with no updating.
    void emptyPlotsShowTheLoadedTest() {
        MainWindow window;
        window.resize(1280, 720);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        auto* panel = window.findChild<LivePlotsPanel*>();
        QVERIFY(panel);
        auto* threshold = window.findChild<QDoubleSpinBox*>(QStringLiteral("fitThreshold"));
        QVERIFY(threshold);
        QVERIFY2(threshold->isHidden(), "a fit-error threshold without updating");
        auto check = [&](const QString& when) {
            panel->refreshNow();
            QStringList problems;
            for (QCustomPlot* p : shownPlots(*panel)) {
                p->replot();
                // A parameter plot's y label is the parameter's name (its values are in the
                // law's normalized, dimensionless units, as the Parameters dock says).
                const bool parameter = qobject_cast<ParameterPlot*>(p) != nullptr;
                for (QCPAxis* a : {p->xAxis, p->yAxis, p->yAxis2}) {
                    problems << crammedTicks(*p, *a);
                    if (!(parameter && a == p->yAxis))
                        problems << unitless(*p, *a);
                    // No data and nothing to scale by: QCustomPlot's 0..5 with numbers.
                    if (a->tickLabels() && a->visible() && a->range().lower == 0.0 &&
                        a->range().upper == 5.0)
                        problems << QStringLiteral("%1: the default range 0..5").arg(p->objectName());
                }
            }
            problems.removeAll(QString());
            QVERIFY2(problems.isEmpty(), qPrintable(when + QStringLiteral(": ") +
                                                    problems.join(QStringLiteral("; "))));
        };
        check(QStringLiteral("no configuration"));

        QVERIFY(window.loadConfiguration(QStringLiteral("paper-condition-3")));
        QTRY_VERIFY_WITH_TIMEOUT(window.controller().updating().enabled, 5000);
        QVERIFY(!threshold->isHidden());
        check(QStringLiteral("paper-condition-3"));
        // The time axes span the record the test applies: 0 to its last sample (3000 steps
        // of 0.01 s, the record's 30 s).
        HistoryPlot& ground = panel->groundMotion();
        QVERIFY(ground.graph(0)->dataCount() > 100);
        const double end = (ground.graph(0)->data()->constEnd() - 1)->key;
        QVERIFY2(end > 29.0 && end < 31.0, qPrintable(QString::number(end)));
        for (QCustomPlot* p : std::initializer_list<QCustomPlot*>{
                 &panel->forceHistory(), &panel->displacementHistory(), &panel->tracking(),
                 &panel->fitError(), panel->parameterPlots().front()}) {
            QVERIFY2(p->xAxis->range().lower == 0.0 && std::abs(p->xAxis->range().upper - end) < 1e-9,
                     qPrintable(QStringLiteral("%1: %2..%3 s").arg(p->objectName())
                                    .arg(p->xAxis->range().lower).arg(p->xAxis->range().upper)));
            QVERIFY(p->xAxis->tickLabels());
        }
        // Nothing to scale the force by yet: no made-up numbers; the fit error spans 0 to its
        // threshold (0.1) with a margin.
        QVERIFY(!panel->forceHistory().yAxis->tickLabels());
        HistoryPlot& fit = panel->fitError();
        QCOMPARE(fit.threshold(), 0.1);
        QVERIFY(fit.yAxis->tickLabels());
        QVERIFY2(fit.yAxis->range().lower <= 0.0 && fit.yAxis->range().upper > 0.1 &&
                     fit.yAxis->range().upper < 0.2,
                 qPrintable(QStringLiteral("%1..%2").arg(fit.yAxis->range().lower)
                                .arg(fit.yAxis->range().upper)));

        // The operator zooms the force plot, then loads another preset: its ranges go.
        HistoryPlot& force = panel->forceHistory();
        PlotTools::attach(force)->setAutoscale(false);
        force.xAxis->setRange(3.0, 4.0);
        QVERIFY(window.loadConfiguration(QStringLiteral("sdof-bouc-wen")));
        QTRY_VERIFY(window.controller().state() == RunState::Ready);
        check(QStringLiteral("sdof-bouc-wen"));
        QVERIFY(PlotTools::autoscale(force));
        const double end2 = (ground.graph(0)->data()->constEnd() - 1)->key;
        QCOMPARE(force.xAxis->range().lower, 0.0);
        QVERIFY2(std::abs(force.xAxis->range().upper - end2) < 1e-9,
                 qPrintable(QStringLiteral("%1 vs %2").arg(force.xAxis->range().upper).arg(end2)));
        QVERIFY(threshold->isHidden() || window.controller().updating().enabled);
    }

    void textsAreNotClipped_data() {
        QTest::addColumn<QString>("language");
        for (const char* l : {"en", "es", "zh_CN"})
            QTest::newRow(l) << QString::fromLatin1(l);
    }
    // Item 17: "Max |Δd| per ste" in the safety-limit header; es: the fit-error plot's y label
    // ran up over its title.
    void textsAreNotClipped() {
        QFETCH(QString, language);
        QVERIFY(Translations::install(*QCoreApplication::instance(), language) ||
                language == QLatin1String("en"));
        MainWindow window;
        window.resize(1280, 720);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.loadConfiguration(QStringLiteral("paper-condition-3")));
        QTRY_VERIFY_WITH_TIMEOUT(window.controller().updating().enabled, 5000);
        QCoreApplication::processEvents();

        auto* limits = window.findChild<QTableWidget*>(QStringLiteral("limitsTable"));
        QVERIFY(limits && limits->isVisible());
        QHeaderView* header = limits->horizontalHeader();
        const QFontMetrics fm(header->font());
        const int margin = 2 * header->style()->pixelMetric(QStyle::PM_HeaderMargin, nullptr, header);
        QStringList problems;
        int lines = 1;
        for (int c = 0; c < limits->columnCount(); ++c) {
            const QString text = limits->horizontalHeaderItem(c)->text();
            lines = std::max(lines, int(text.count(QLatin1Char('\n'))) + 1);
            for (const QString& line : text.split(QLatin1Char('\n')))
                if (fm.horizontalAdvance(line) + margin > header->sectionSize(c))
                    problems << QStringLiteral("'%1' needs %2 px, its column has %3")
                                    .arg(line)
                                    .arg(fm.horizontalAdvance(line) + margin)
                                    .arg(header->sectionSize(c));
            // Nothing of the words is lost (only spaces became line breaks).
            if (QString(text).replace(QLatin1Char('\n'), QLatin1Char(' ')) !=
                limits->horizontalHeaderItem(c)->toolTip())
                problems << QStringLiteral("header '%1' is not its whole text '%2'")
                                .arg(text, limits->horizontalHeaderItem(c)->toolTip());
        }
        if (header->height() < lines * fm.height())
            problems << QStringLiteral("header %1 px tall for %2 lines").arg(header->height()).arg(lines);

        for (QCustomPlot* p : shownPlots(*window.findChild<LivePlotsPanel*>())) {
            p->replot();
            const auto* title = qobject_cast<QCPTextElement*>(
                p->property("hsmuTitleElement").value<QObject*>());
            const QString label = p->yAxis->label();
            if (!title || label.isEmpty())
                continue;
            const int c = p->axisRect()->rect().center().y();
            const int half = QFontMetrics(p->yAxis->labelFont()).horizontalAdvance(label) / 2;
            // The label's column (left of the data area) and the title's text side by side:
            // no overlap whatever their heights.
            const int titleHalf = QFontMetrics(title->font()).horizontalAdvance(title->text()) / 2;
            const bool besideTitle = title->outerRect().center().x() - titleHalf > p->axisRect()->rect().left();
            if (!besideTitle && c - half < title->outerRect().bottom())
                problems << QStringLiteral("%1: y label '%2' reaches up to %3 px, the title ends at %4")
                                .arg(p->objectName(), label)
                                .arg(c - half)
                                .arg(title->outerRect().bottom());
        }
        QVERIFY2(problems.isEmpty(), qPrintable(language + QStringLiteral(": ") +
                                                problems.join(QStringLiteral("; "))));
    }

    void siteAddressesAreWhole_data() { textsAreNotClipped_data(); }
    // Item 15: the Sites box cut both addresses to "tcp://127.0.0.1:51..." (ports hidden).
    void siteAddressesAreWhole() {
        QFETCH(QString, language);
        QVERIFY(Translations::install(*QCoreApplication::instance(), language) ||
                language == QLatin1String("en"));
        MainWindow window;
        window.resize(1280, 720);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.loadConfiguration(QStringLiteral("paper-bridge-two-labs")));
        QCoreApplication::processEvents();
        auto* sites = window.findChild<QTableWidget*>(QStringLiteral("sitesTable"));
        QVERIFY(sites && sites->isVisible());
        QVERIFY(sites->rowCount() >= 2);
        const QFontMetrics fm(sites->font());
        QStringList problems;
        for (int row = 0; row < sites->rowCount(); ++row) {
            const QString address = sites->item(row, 1)->text();
            // The item view's text margin each side (QCommonStyle: focus frame margin + 1).
            const int margin =
                2 * (sites->style()->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, sites) + 1);
            const int need = fm.horizontalAdvance(address) + margin;
            if (need > sites->columnWidth(1))
                problems << QStringLiteral("'%1' needs %2 px, its column has %3")
                                .arg(address).arg(need).arg(sites->columnWidth(1));
        }
        // The other columns stay in view beside it (no sideways scrolling).
        if (sites->horizontalScrollBar()->maximum() > 0)
            problems << QStringLiteral("the table scrolls sideways by %1 px")
                            .arg(sites->horizontalScrollBar()->maximum());
        QVERIFY2(problems.isEmpty(), qPrintable(language + QStringLiteral(": ") +
                                                problems.join(QStringLiteral("; "))));
    }

    // Item 18: "...needs the time step dt, and none was given" while the (integration) dt field
    // showed 0.01 s, and no field for the record's own step. 51 values of a 0.1 g ramp: with a
    // sample step of 0.02 s the plot ends at 1.0 s, 0.1 g.
    void oneColumnRecordAsksForItsSampleStep() {
        MainWindow window;
        window.show();
        QVERIFY(window.loadConfiguration(QStringLiteral("sdof-bouc-wen")));
        auto* setup = window.findChild<SetupPanel*>();
        auto* file = setup->findChild<QLineEdit*>(QStringLiteral("groundMotionFile"));
        auto* recordDt = setup->findChild<QDoubleSpinBox*>(QStringLiteral("recordTimeStep"));
        auto* dt = setup->findChild<QDoubleSpinBox*>(QStringLiteral("timeStep"));
        auto* plot = window.findChild<HistoryPlot*>(QStringLiteral("groundMotionPlot"));
        QVERIFY(file && plot && dt);
        QVERIFY2(recordDt, "no field for the record's own sample step");
        QVERIFY(recordDt->isVisible() && recordDt->isEnabled());
        QCOMPARE(recordDt->value(), 0.0); // the preset's synthetic record: from the file
        const QString values = m_dir.filePath(QStringLiteral("values.txt"));
        {
            QFile f(values);
            QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Text));
            for (int i = 0; i <= 50; ++i)
                f.write(QByteArray::number(0.002 * i) + '\n');
        }
        file->setText(values);
        file->setModified(true);
        emit file->editingFinished();
        QString status = setup->groundMotionStatus();
        QVERIFY2(status.contains(QStringLiteral("sample step")), qPrintable(status));
        QCOMPARE(dt->value(), 0.01); // the integration step is not the record's

        recordDt->setValue(0.02);
        emit recordDt->editingFinished();
        QCOMPARE(setup->groundMotionStatus(), QString());
        QCOMPARE(plot->graph(0)->dataCount(), 51);
        QVERIFY(std::abs(plot->graph(0)->data()->at(50)->key - 1.0) < 1e-9);
        QVERIFY(std::abs(plot->graph(0)->data()->at(50)->value - 0.1 * 9.80665) < 1e-9);
        QString error;
        const auto cfg = setup->edited(&error);
        QVERIFY2(cfg, qPrintable(error));
        QCOMPARE(cfg->groundMotion.dt, 0.02);
        QCOMPARE(cfg->analysis.dt, 0.01);
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
        TestOperatorDay test;
        QTEST_SET_MAIN_SOURCE_PATH
        result = QTest::qExec(&test, argc, argv);
    }
    std::remove(screens.c_str());
    return result;
}

#include "TestOperatorDay.moc"
