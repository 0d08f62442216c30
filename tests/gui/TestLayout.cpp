// Layout at 1280x720 (issue 16, item 9/10/11): with a test loaded, in English and in Spanish
// (the longest texts), every dock's content fits its dock: the setup panel's minimum size
// hint is not wider than the viewport of its scroll area (nothing clipped on the right, no
// "Examinar" button cut off), and no panel of the right dock area asks for more than the
// dock's width (the area keeps its designed 440 px, the plots the rest). Fails on the
// console before the fix: setup panel 514 px for a 441 px dock (en), 566 for 524 (es). Long texts are wrapped or elided with the full text in their tool tip.
// No plot's legend overlaps its data area (item 10: the see-through legends inside the axis
// rect covered part of the small history and tracking traces).
#include <QAction>
#include <QDockWidget>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QSettings>
#include <QStandardPaths>
#include <QTest>
#include <QScrollBar>
#include <QTreeWidget>

#include "gui/app/AttentionBanner.h"
#include "gui/app/ConsoleSettings.h"
#include "gui/app/ControlBar.h"
#include "gui/app/MainWindow.h"
#include "gui/app/PendingUpdatesPanel.h"
#include "gui/app/TestController.h"
#include "gui/app/SetupPanel.h"
#include "gui/app/Translations.h"
#include "gui/plots/HistoryPlot.h"
#include "gui/plots/PlotStyle.h"

#include <qcustomplot.h>

#include <cmath>

using namespace hsmu;
using namespace hsmu::gui;

namespace {
constexpr int kRightDockWidth = 460; // [px] the window sizes the right docks to 440 px
} // namespace

class TestLayout : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
        ConsoleSettings::setRecordDirectory(QString()); // nothing recorded
    }
    void cleanupTestCase() {
        Translations::install(*QCoreApplication::instance(), QStringLiteral("en"));
    }

    // The attention banner is red (its white text was drawn on the window's grey: a style
    // sheet background needs WA_StyledBackground on a plain QWidget).
    void attentionBannerIsRed() {
        QWidget window; // a child, as in the main window (a top-level paints differently)
        auto* banner = new AttentionBanner(&window);
        window.resize(600, 60);
        banner->setGeometry(0, 0, 600, 40);
        banner->setAttention(1, QStringLiteral("test held: operator hold"));
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        const QColor corner = window.grab().toImage().pixelColor(2, 2);
        QVERIFY2(corner.red() > 150 && corner.green() < 80 && corner.blue() < 80,
                 qPrintable(corner.name()));
    }

    // Tick labels never run together in a small plot at 1280x720 (seen by hand: "0
    // 0.0250.050.075 0.1" under a 0.1 s history, "0.2 0 -0.2 -0.4" piled up on a 40 px axis).
    void tickLabelsDoNotRunTogether() {
        HistoryPlot plot;
        plot.setChannels(QStringLiteral("Moment history"), QStringLiteral("Moment [kN m]"),
                         {{QStringLiteral("Element 1"), {}, false}});
        plot.setMinimumSize(100, 80); // as LivePlotsPanel's small cells
        plot.resize(208, 110);        // the fit-error cell at 1280x720
        plot.show();
        QVERIFY(QTest::qWaitForWindowExposed(&plot));
        QVector<double> t, v;
        for (int i = 0; i <= 10; ++i) {
            t << 0.01 * i;
            v << 0.3 * std::sin(i);
        }
        plot.graph(0)->setData(t, v);
        plot.xAxis->setRange(-0.005, 0.105); // 0.1 s with the 5 % margins
        plot.yAxis->setRange(-0.45, 0.3);
        plot.replot(QCustomPlot::rpImmediateRefresh);
        plot.replot(QCustomPlot::rpImmediateRefresh);
        for (QCPAxis* axis : {plot.xAxis, plot.yAxis}) {
            const QVector<double> ticks = axis->tickVector();
            const QVector<QString> labels = axis->tickVectorLabels();
            // Time keeps at least two labels; a 35 px tall value axis may keep only one.
            QVERIFY(ticks.size() >= (axis->orientation() == Qt::Horizontal ? 2 : 1));
            const QFontMetrics fm(axis->tickLabelFont());
            for (qsizetype i = 1; i < ticks.size(); ++i) {
                const double gap = std::abs(axis->coordToPixel(ticks[i]) -
                                            axis->coordToPixel(ticks[i - 1]));
                const bool horizontal = axis->orientation() == Qt::Horizontal;
                const double need = horizontal ? 0.5 * (fm.horizontalAdvance(labels[i]) +
                                                        fm.horizontalAdvance(labels[i - 1])) +
                                                     4
                                               : fm.ascent() + 2; // digits: no descent
                QVERIFY2(gap >= need,
                         qPrintable(QStringLiteral("'%1' and '%2' are %3 px apart, need %4")
                                        .arg(labels[i - 1], labels[i])
                                        .arg(gap)
                                        .arg(need)));
            }
        }
    }

    void setupPanelFitsItsDockAt1280x720_data() {
        QTest::addColumn<QString>("language");
        QTest::addColumn<QString>("preset");
        for (const char* language : {"en", "es", "zh_CN"})
            for (const char* preset : {"paper-condition-3", "paper-bridge-two-labs"})
                QTest::addRow("%s %s", language, preset)
                    << QString::fromLatin1(language) << QString::fromLatin1(preset);
    }
    void setupPanelFitsItsDockAt1280x720() {
        QFETCH(QString, language);
        QFETCH(QString, preset);
        QVERIFY(Translations::install(*QCoreApplication::instance(), language));
        MainWindow window;
        window.resize(1280, 720);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.loadConfiguration(preset));
        QCoreApplication::processEvents();
        QCOMPARE(window.width(), 1280); // nothing widened the window
        auto* setup = window.findChild<SetupPanel*>();
        auto* scroll = qobject_cast<QScrollArea*>(
            window.findChild<QDockWidget*>(QStringLiteral("setupDock"))->widget());
        QVERIFY(setup && scroll);
        const int available = scroll->viewport()->width();
        const int needed = setup->minimumSizeHint().width();
        // Every dock of the right area (setup, parameters, pending updates) fits the width
        // the window gives it (440 px by design, the plots keep the rest): no panel's minimum
        // (a long translation, a long choice) widens the area.
        for (QDockWidget* d : window.findChildren<QDockWidget*>()) {
            if (window.dockWidgetArea(d) != Qt::RightDockWidgetArea)
                continue;
            const int min = d->widget()->minimumSizeHint().width();
            QVERIFY2(min <= d->width() && d->width() <= kRightDockWidth,
                     qPrintable(QStringLiteral("%1: dock %2 is %3 px wide, its content needs %4")
                                    .arg(language, d->objectName())
                                    .arg(d->width())
                                    .arg(min)));
        }
        qInfo("%s %s: setup panel needs %d px, its dock shows %d px", qPrintable(language),
              qPrintable(preset), needed, available);
        QVERIFY2(needed <= available,
                 qPrintable(QStringLiteral("%1: the setup panel needs %2 px, the dock shows %3")
                                .arg(language).arg(needed).arg(available)));
        QCOMPARE(setup->width(), available); // laid out to the viewport, not clipped
        // Plots: a vertical axis label longer than its axis is cut with "..." (the whole
        // label in the tool tip), never clipped at both ends ("eleración del suelo [m/").
        int legends = 0;
        for (QCustomPlot* plot : window.findChildren<QCustomPlot*>()) {
            if (!plot->isVisible())
                continue;
            plot->replot(QCustomPlot::rpImmediateRefresh); // laid out at its size
            plot->replot(QCustomPlot::rpImmediateRefresh); // labels cut to the new layout
            // Item 10: a legend never covers the traces: it lies outside the axis rect (the
            // data area), in the small history, tracking and parameter plots too.
            if (plot->legend->visible() && plot->legend->itemCount() > 0) {
                ++legends;
                const QRect data = plot->axisRect()->rect();
                const QRect box = plot->legend->outerRect();
                QVERIFY2(!box.intersects(data),
                         qPrintable(QStringLiteral("%1: %2's legend (%3,%4 %5x%6) covers its "
                                                   "data area (%7,%8 %9x%10)")
                                        .arg(language, plot->objectName())
                                        .arg(box.x()).arg(box.y()).arg(box.width())
                                        .arg(box.height())
                                        .arg(data.x()).arg(data.y()).arg(data.width())
                                        .arg(data.height())));
                // And it is itself inside the plot (its outer rect may reach 2 px past the
                // bottom edge of a cramped plot: its empty margin, no text).
                QVERIFY2(plot->rect().adjusted(0, 0, 0, 2).contains(box),
                         qPrintable(QStringLiteral("%1: %2's legend (%3,%4 %5x%6) is not inside "
                                                   "the plot (%7x%8)")
                                        .arg(language, plot->objectName())
                                        .arg(box.x()).arg(box.y()).arg(box.width())
                                        .arg(box.height())
                                        .arg(plot->width()).arg(plot->height())));
            }
            for (QCPAxis* axis : {plot->yAxis, plot->yAxis2}) {
                if (!axis->visible() || axis->label().isEmpty())
                    continue;
                const int length = QFontMetrics(axis->labelFont()).horizontalAdvance(axis->label());
                // Centred on the axis, the label must end inside the plot at both ends.
                const int centre = plot->axisRect()->rect().center().y();
                const int room = 2 * std::min(centre, plot->height() - centre);
                QVERIFY2(length <= room,
                         qPrintable(QStringLiteral("%1: '%2' is %3 px, %4 px of %5 show it")
                                        .arg(language, axis->label())
                                        .arg(length)
                                        .arg(room)
                                        .arg(plot->objectName())));
                const QString full = PlotStyle::axisLabel(*plot, *axis);
                if (full != axis->label())
                    QVERIFY2(plot->toolTip().contains(full), qPrintable(plot->toolTip()));
            }
        }
        QVERIFY(legends >= 2); // the history and hysteresis plots of a loaded test
        // The control bar fits the window (item 13): with the pseudo-dynamic pace chosen, the
        // field for the seconds of wall time per step and the emergency hold are on the bar,
        // not behind its overflow button (before: the field was hidden at 1280 px).
        auto* bar = window.findChild<ControlBar*>();
        bar->setWallTimePerStep(2.0);
        QCoreApplication::processEvents();
        for (const char* name : {"wallTimePerStep", "emergencyHold"}) {
            QWidget* w = bar->findChild<QWidget*>(QString::fromLatin1(name));
            if (!w) // an action: its button
                w = bar->widgetForAction(bar->findChild<QAction*>(QString::fromLatin1(name)));
            QVERIFY2(w, name);
            const QRect r(w->mapTo(bar, QPoint(0, 0)), w->size());
            QVERIFY2(w->isVisible() && bar->rect().contains(r),
                     qPrintable(QStringLiteral("%1: %2 is not on the control bar (%3 px wide)")
                                    .arg(language, QString::fromLatin1(name))
                                    .arg(bar->width())));
        }
        bar->setSpeed(1.0);
        // Every push button shows its whole text (e.g. "Examinar..." beside the file field).
        for (QPushButton* b : setup->findChildren<QPushButton*>()) {
            if (!b->isVisibleTo(setup))
                continue;
            const int textWidth = b->fontMetrics().horizontalAdvance(b->text());
            QVERIFY2(b->width() >= textWidth,
                     qPrintable(QStringLiteral("%1: button '%2' is %3 px for %4 px of text")
                                    .arg(language, b->text())
                                    .arg(b->width())
                                    .arg(textWidth)));
            const QPoint right = b->mapTo(setup, QPoint(b->width(), 0));
            QVERIFY2(right.x() <= setup->width(),
                     qPrintable(language + QStringLiteral(": button '") + b->text() +
                                QStringLiteral("' reaches past the panel")));
        }
    }

    // Item 10 (follow-up): at 1280x720 the pending-updates list was about 60 px tall and the
    // oldest proposal's Approve / Reject had to be scrolled to. They lie inside the visible
    // viewport of the list, unscrolled, in every language, for a proposal of the UKF preset
    // (five parameters) with a newer one queued below it.
    void approveAndRejectVisibleAt1280x720_data() {
        QTest::addColumn<QString>("language");
        for (const char* language : {"en", "es", "zh_CN"})
            QTest::addRow("%s", language) << QString::fromLatin1(language);
    }
    void approveAndRejectVisibleAt1280x720() {
        QFETCH(QString, language);
        QVERIFY(Translations::install(*QCoreApplication::instance(), language));
        MainWindow window;
        window.resize(1280, 720);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.loadConfiguration(QStringLiteral("paper-condition-3")));
        QTRY_VERIFY_WITH_TIMEOUT(window.controller().updating().enabled, 5000);
        auto* pending = window.findChild<PendingUpdatesPanel*>();
        UpdatingSnapshot s = window.controller().updating();
        s.policy = ReporterPolicy::OnApproval;
        const std::vector<std::string> names = {"k0", "fy", "alpha", "beta", "n"};
        for (int id : {12, 13}) {
            UpdateProposal p;
            p.id = id;
            p.step = 10 * id;
            p.time = 0.1 * id;
            p.element = id == 12 ? "Element 2" : "Element 4"; // one proposal per target
            p.parameters = ParameterLayout(names);
            p.proposed.assign(names.size(), 1.05);
            p.current.assign(names.size(), 1.0);
            p.fitError = 0.02;
            s.pending.push_back(p);
        }
        pending->setSnapshot(s);
        pending->setEditable(true);
        QCoreApplication::processEvents();
        QTest::qWait(20); // the item widgets are placed by the view's delayed layout
        QCoreApplication::processEvents();
        QTreeWidget* tree = pending->tree();
        QVERIFY(tree->isVisible());
        QCOMPARE(tree->verticalScrollBar()->value(), 0); // nothing scrolled
        const QRect view = tree->viewport()->rect();
        for (const QString& name : {QStringLiteral("approve12"), QStringLiteral("reject12")}) {
            auto* b = pending->findChild<QPushButton*>(name);
            QVERIFY2(b, qPrintable(name));
            const QRect r(b->mapTo(tree->viewport(), QPoint(0, 0)), b->size());
            QVERIFY2(b->isVisible() && view.contains(r),
                     qPrintable(QStringLiteral("%1: %2 at (%3,%4 %5x%6) is outside the list's "
                                               "visible %7x%8 px")
                                    .arg(language, name)
                                    .arg(r.x()).arg(r.y()).arg(r.width()).arg(r.height())
                                    .arg(view.width()).arg(view.height())));
        }
        qInfo("%s: pending list viewport %d px tall", qPrintable(language), view.height());
    }
};

QTEST_MAIN(TestLayout)
#include "TestLayout.moc"
