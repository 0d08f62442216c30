// Issue 16 item 12: every console plot has scope tools: a cursor read-out, zoom / pan that
// turns autoscale off (a pinned window survives the live refresh), an autoscale toggle, the
// choice of channels and an export of the visible data as CSV. Checked on real plot widgets
// (offscreen) against the analytic series they were given.

#include "gui/plots/HistoryPlot.h"
#include "gui/plots/HysteresisPlot.h"
#include "gui/plots/LivePlotsPanel.h"
#include "gui/plots/PlotTools.h"

#include <QApplication>
#include <QFile>
#include <QMenu>
#include <QMouseEvent>
#include <QTemporaryDir>
#include <QWheelEvent>
#include <QtTest>

#include <cmath>

using namespace hsmu::gui;

class TestPlotTools : public QObject {
    Q_OBJECT
private slots:
    void historyPlotTools() {
        HistoryPlot plot;
        plot.resize(640, 400);
        plot.show();
        QVERIFY(QTest::qWaitForWindowExposed(&plot));
        plot.setChannels(QStringLiteral("test"), QStringLiteral("y [m]"), {});
        QVector<double> t(101), a(101), b(101);
        for (int i = 0; i <= 100; ++i) {
            t[i] = i / 10.0; // 0 .. 10 s, exact at 2.0 and 4.0
            a[i] = std::sin(t[i]);
            b[i] = 2.0 * std::cos(t[i]);
        }
        plot.addSeries(QStringLiteral("a"), t, a);
        plot.addSeries(QStringLiteral("b"), t, b);
        plot.refresh();
        plot.replot(QCustomPlot::rpImmediateRefresh);
        PlotTools* tools = PlotTools::of(plot);
        QVERIFY(tools);
        QVERIFY(tools->autoscale());
        QVERIFY(plot.xAxis->range().lower <= 0.0 && plot.xAxis->range().upper >= 10.0);

        // Cursor read-out: the nearest sample of each visible graph at the cursor's x.
        const QString r = tools->readout(2.02, 0.0);
        QVERIFY2(r.contains(QStringLiteral("a: %1 at 2").arg(std::sin(2.0), 0, 'g', 6)),
                 qPrintable(r));
        QVERIFY2(r.contains(QStringLiteral("b: %1 at 2").arg(2.0 * std::cos(2.0), 0, 'g', 6)),
                 qPrintable(r));
        const QPoint px(int(plot.xAxis->coordToPixel(3.0)), int(plot.yAxis->coordToPixel(0.5)));
        QMouseEvent move(QEvent::MouseMove, QPointF(px), plot.mapToGlobal(QPointF(px)),
                         Qt::NoButton, Qt::NoButton, Qt::NoModifier);
        QApplication::sendEvent(&plot, &move);
        QVERIFY2(tools->cursorText().contains(QStringLiteral("a: ")), qPrintable(tools->cursorText()));
        QVERIFY(tools->autoscale()); // hovering changes nothing

        // Zoom with the wheel: autoscale goes off; a pinned window survives refreshes.
        QWheelEvent wheel(QPointF(px), plot.mapToGlobal(QPointF(px)), QPoint(), QPoint(0, 120),
                          Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(&plot, &wheel);
        QVERIFY(!tools->autoscale());
        plot.xAxis->setRange(2.0, 4.0);
        plot.refresh();
        QCOMPARE(plot.xAxis->range().lower, 2.0);
        QCOMPARE(plot.xAxis->range().upper, 4.0);

        // Channels: hide b; export the visible data: a's 21 samples in [2, 4] s.
        tools->setChannelVisible(1, false);
        QVERIFY(!plot.graph(1)->visible());
        QTemporaryDir dir;
        const QString csv = dir.filePath(QStringLiteral("visible.csv"));
        int rows = 0;
        QString error;
        QVERIFY2(tools->exportVisibleCsv(csv, &error, &rows), qPrintable(error));
        QCOMPARE(rows, 21);
        QFile f(csv);
        QVERIFY(f.open(QIODevice::ReadOnly | QIODevice::Text));
        const QStringList lines = QString::fromUtf8(f.readAll()).split(QLatin1Char('\n'),
                                                                        Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 22);
        QVERIFY2(lines[0].startsWith(QStringLiteral("series,")), qPrintable(lines[0]));
        QVERIFY2(lines[0].endsWith(QStringLiteral(",y [m]")), qPrintable(lines[0]));
        const QStringList first = lines[1].split(QLatin1Char(','));
        QCOMPARE(first[0], QStringLiteral("a"));
        QCOMPARE(first[1].toDouble(), 2.0);
        QVERIFY(std::abs(first[2].toDouble() - std::sin(2.0)) <= 1e-5);
        QVERIFY(!tools->exportVisibleCsv(QStringLiteral("/nonexistent/dir/x.csv"), &error));
        QVERIFY2(error.contains(QStringLiteral("/nonexistent/dir/x.csv")), qPrintable(error));

        // Autoscale back on: the whole record again.
        tools->setAutoscale(true);
        QVERIFY(plot.xAxis->range().lower <= 0.0 && plot.xAxis->range().upper >= 10.0);

        // The context menu offers all of it.
        QMenu* menu = tools->buildMenu(&plot);
        QStringList texts;
        for (QAction* act : menu->actions())
            texts << act->text();
        QVERIFY(texts.contains(QStringLiteral("Autoscale")));
        QVERIFY(texts.contains(QStringLiteral("Channels")));
        QVERIFY(texts.contains(QStringLiteral("Export visible data as CSV...")));
        delete menu;
    }

    void everyLivePlotHasTheTools() {
        LivePlotsPanel panel;
        const QList<QCustomPlot*> plots = panel.findChildren<QCustomPlot*>();
        QVERIFY(plots.size() >= 3);
        for (QCustomPlot* p : plots)
            QVERIFY2(PlotTools::of(*p), qPrintable(p->objectName()));
    }
};

QTEST_MAIN(TestPlotTools)
#include "TestPlotTools.moc"
