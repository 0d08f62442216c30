// LivePlotsPanel fed a real run's StepRecords in ~30 Hz-like batches: every plot holds one
// point per row, the ± 2 sigma band equals estimate ± 2 sigma, the bounds and the fit-error
// threshold are the configuration's, every axis names its unit; exports are valid PNG, SVG
// and PDF files; `hsmu run --plots` draws the same panel (PlotExporter::writeRunPlots).

#include "RecordedRun.h"

#include "gui/plots/HistoryPlot.h"
#include "gui/plots/HysteresisPlot.h"
#include "gui/plots/LivePlotsPanel.h"
#include "gui/plots/PlotStyle.h"
#include "gui/plots/ParameterPlot.h"
#include "gui/plots/PlotExporter.h"

#include <QFile>
#include <QImage>
#include <QTemporaryDir>
#include <QXmlStreamReader>
#include <QtTest>

#include <algorithm>
#include <cmath>

using namespace hsmu;
using namespace hsmu::gui;

namespace {

constexpr double kDuration = 3.0; // [s] of paper-condition-3 (dt 0.01 s: 301 rows)

/// Feeds rows in batches of `batch` (as the TestController's drain would).
void feed(LivePlotsPanel& panel, const std::vector<StepRecord>& rows, std::size_t batch) {
    for (std::size_t i = 0; i < rows.size(); i += batch) {
        const auto end = rows.begin() + std::ptrdiff_t(std::min(rows.size(), i + batch));
        panel.appendRecords(std::vector<StepRecord>(rows.begin() + std::ptrdiff_t(i), end));
        panel.refresh();
    }
}

int elementIndex(const RunLayout& layout, const std::string& name) {
    for (std::size_t i = 0; i < layout.elements.size(); ++i)
        if (layout.elements[i].name == name)
            return int(i);
    return -1;
}

/// Whether the image has at least `minimum` pixels that are neither white nor near-white.
bool hasInk(const QImage& image, int minimum) {
    int count = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            if (qGray(image.pixel(x, y)) < 200 && ++count >= minimum)
                return true;
    return false;
}

QByteArray head(const QString& path, int n) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.read(n) : QByteArray();
}

} // namespace

class TestLivePlotsPanel : public QObject {
    Q_OBJECT
private:
    recordedrun::Run m_run;

private slots:
    void initTestCase() {
        m_run = recordedrun::run(QStringLiteral("paper-condition-3"), kDuration);
    }

    void everyPlotHoldsEveryRow() {
        const auto& rows = m_run.records;
        QCOMPARE(int(rows.size()), 301); // 3 s / 0.01 s steps + the initial state
        LivePlotsPanel panel;
        panel.configure(m_run.layout, m_run.config);
        panel.resize(1280, 800);
        panel.show();
        feed(panel, rows, 37);
        const int n = int(rows.size());
        QCOMPARE(panel.rowsShown(), qint64(n));

        // Hysteresis: specimen (measured), its numerical twin, the auxiliary model.
        HysteresisPlot& loop = panel.hysteresis();
        QCOMPARE(loop.plottableCount(), 3);
        for (int i = 0; i < 3; ++i)
            QCOMPARE(qobject_cast<QCPCurve*>(loop.plottable(i))->dataCount(), n);
        QVERIFY(loop.plottable(0)->name().contains(QStringLiteral("measured")));
        QVERIFY(loop.plottable(2)->name().contains(QStringLiteral("auxiliary")));
        // The auxiliary curve is F_aux against the specimen's measured deformation.
        const int specimen = elementIndex(m_run.layout, m_run.layout.updating->specimen);
        QVERIFY(specimen >= 0);
        auto aux = qobject_cast<QCPCurve*>(loop.plottable(2))->data();
        const StepRecord& mid = rows[150];
        QCOMPARE(aux->at(150)->key, mid.elements[std::size_t(specimen)].deformation);
        QCOMPARE(aux->at(150)->value, mid.updating.auxiliaryForce);

        QCOMPARE(panel.forceHistory().graphCount(), 2);
        QCOMPARE(panel.forceHistory().graph(1)->dataCount(), n);
        QCOMPARE(panel.displacementHistory().graphCount(), int(m_run.layout.dofNames.size()));
        QCOMPARE(panel.displacementHistory().graph(0)->dataCount(), n);
        // Tracking: commanded, measured, the actuator's command, held ticks (right axis).
        QCOMPARE(panel.tracking().graphCount(), 4);
        QCOMPARE(panel.tracking().graph(0)->dataCount(), n);
        QCOMPARE(panel.tracking().graph(0)->data()->at(150)->value,
                 mid.elements[std::size_t(specimen)].commanded);
        QCOMPARE(panel.tracking().graph(2)->data()->at(150)->value,
                 mid.elements[std::size_t(specimen)].actuator.commanded);
        QCOMPARE(panel.tracking().graph(3)->valueAxis(), panel.tracking().yAxis2);
        QCOMPARE(panel.fitError().graph(0)->dataCount(), n);

        // Ground motion: the whole applied record (t <= 3 s at its own 0.02 s interval) with
        // the cursor at the last row.
        QCOMPARE(panel.groundMotion().graphCount(), 1);
        const int samples = panel.groundMotion().graph(0)->dataCount();
        QVERIFY2(samples >= 151 && samples <= 301, qPrintable(QString::number(samples)));
        QCOMPARE(panel.groundMotion().timeCursor(), rows.back().time);

        // One plot per identified parameter, each with every row.
        const auto& names = m_run.layout.updating->parameters;
        QCOMPARE(panel.parameterPlots().size(), names.size());
        for (ParameterPlot* p : panel.parameterPlots())
            QCOMPARE(p->estimateGraph()->dataCount(), n);
    }

    void sigmaBandAndReferenceLines() {
        LivePlotsPanel panel;
        panel.configure(m_run.layout, m_run.config);
        feed(panel, m_run.records, 50);
        panel.refreshNow(); // the budget may have postponed the last redraw
        const auto& names = m_run.layout.updating->parameters;
        const ParameterBoundsMap table = tableIIIBounds();
        for (std::size_t j = 0; j < names.size(); ++j) {
            const ParameterPlot& p = *panel.parameterPlots()[j];
            for (const int k : {0, 100, 300}) {
                const StepRecord& r = m_run.records[std::size_t(k)];
                const double v = r.updating.parameters[j], s = r.updating.stddev[j];
                QVERIFY2(s > 0.0, names[j].c_str()); // a UKF estimate has a spread
                QCOMPARE(p.estimateGraph()->data()->at(k)->value, v);
                QVERIFY(std::abs(p.upperBandGraph()->data()->at(k)->value - (v + 2.0 * s)) <=
                        1e-12 * (std::abs(v) + 1.0));
                QVERIFY(std::abs(p.lowerBandGraph()->data()->at(k)->value - (v - 2.0 * s)) <=
                        1e-12 * (std::abs(v) + 1.0));
            }
            // Bounds: the preset's, else Table III (the UKF's defaults).
            const auto cfgBound = m_run.config.updating.bounds.find(names[j]);
            const ParameterBounds b = cfgBound != m_run.config.updating.bounds.end()
                                          ? cfgBound->second
                                          : table.at(names[j]);
            QVERIFY(p.lowerBoundLine()->visible() && p.upperBoundLine()->visible());
            QCOMPARE(p.lowerBoundLine()->point1->coords().y(), b.lower);
            QCOMPARE(p.upperBoundLine()->point2->coords().y(), b.upper);
            // The bounds stay in view after a refresh.
            QVERIFY(p.yAxis->range().contains(b.lower) && p.yAxis->range().contains(b.upper));
        }
        QCOMPARE(panel.fitError().threshold(), m_run.config.updating.inspector.threshold);
        QVERIFY(panel.fitError().yAxis->range().contains(panel.fitError().threshold()));
    }

    void redrawsAreCoalescedWithinTheBudget() {
        LivePlotsPanel panel;
        panel.configure(m_run.layout, m_run.config);
        panel.refreshNow();
        const int before = panel.redraws();
        QVERIFY(panel.redrawIntervalMs() >= LivePlotsPanel::kMinIntervalMs);
        QVERIFY(panel.redrawIntervalMs() <= LivePlotsPanel::kMaxIntervalMs);
        // Many batches right after a redraw: none is drawn at once, all in one later redraw.
        for (std::size_t i = 0; i < 10; ++i) {
            panel.appendRecords({m_run.records[i]});
            panel.refresh();
        }
        QCOMPARE(panel.redraws(), before);
        QTRY_COMPARE_WITH_TIMEOUT(panel.redraws(), before + 1, 5000);
        QTest::qWait(2 * LivePlotsPanel::kMaxIntervalMs); // nothing else was asked for
        QCOMPARE(panel.redraws(), before + 1);
        QCOMPARE(panel.displacementHistory().graph(0)->dataCount(), 10);
    }

    void everyAxisNamesItsUnit() {
        LivePlotsPanel panel;
        panel.configure(m_run.layout, m_run.config);
        QVERIFY(PlotStyle::axisLabel(panel.hysteresis(), *panel.hysteresis().xAxis).contains(QStringLiteral("[rad]")));
        QVERIFY(PlotStyle::axisLabel(panel.hysteresis(), *panel.hysteresis().yAxis).contains(QStringLiteral("[kN m]")));
        QVERIFY(PlotStyle::axisLabel(panel.forceHistory(), *panel.forceHistory().yAxis).contains(QStringLiteral("[kN m]")));
        QVERIFY(PlotStyle::axisLabel(panel.displacementHistory(), *panel.displacementHistory().yAxis).contains(QStringLiteral("[m]")));
        QVERIFY(PlotStyle::axisLabel(panel.groundMotion(), *panel.groundMotion().yAxis).contains(QStringLiteral("[m/s²]")));
        QVERIFY(PlotStyle::axisLabel(panel.tracking(), *panel.tracking().yAxis).contains(QStringLiteral("[rad]")));
        QVERIFY(PlotStyle::axisLabel(panel.fitError(), *panel.fitError().yAxis).contains(QStringLiteral("[-]")));
        for (const LivePlotsPanel::NamedPlot& p : panel.plots())
            if (p.plot != &panel.hysteresis())
                QVERIFY2(PlotStyle::axisLabel(*p.plot, *p.plot->xAxis) == QStringLiteral("Time [s]"),
                         qPrintable(p.fileBase));
        for (ParameterPlot* p : panel.parameterPlots())
            QCOMPARE(PlotStyle::axisLabel(*p, *p->xAxis), QStringLiteral("Time [s]"));
    }

    void exportsValidPngSvgAndPdf() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        LivePlotsPanel panel;
        panel.configure(m_run.layout, m_run.config);
        feed(panel, m_run.records, 100);
        const int expected = int(panel.plots().size() + panel.parameterPlots().size());
        QCOMPARE(expected, 6 + 7);
        for (const QString& suffix :
             {QStringLiteral("png"), QStringLiteral("svg"), QStringLiteral("pdf")}) {
            QStringList errors;
            const QStringList files = panel.exportAll(dir.path(), suffix, &errors);
            QVERIFY2(errors.isEmpty(), qPrintable(errors.join(QLatin1Char('\n'))));
            QCOMPARE(files.size(), expected);
        }
        const QString png = dir.filePath(QStringLiteral("hysteresis.png"));
        QCOMPARE(head(png, 8), QByteArray("\x89PNG\r\n\x1a\n", 8));
        const QImage image(png);
        QCOMPARE(image.size(), QSize(PlotExporter::kWidth, PlotExporter::kHeight));
        QVERIFY(hasInk(image, 2000));

        QFile svg(dir.filePath(QStringLiteral("hysteresis.svg")));
        QVERIFY(svg.open(QIODevice::ReadOnly));
        QXmlStreamReader xml(&svg);
        QString root;
        int paths = 0;
        while (!xml.atEnd()) {
            if (xml.readNext() == QXmlStreamReader::StartElement) {
                if (root.isEmpty())
                    root = xml.name().toString();
                paths +=
                    xml.name() == QLatin1String("path") || xml.name() == QLatin1String("polyline");
            }
        }
        QVERIFY2(!xml.hasError(), qPrintable(xml.errorString()));
        QCOMPARE(root, QStringLiteral("svg"));
        QVERIFY2(paths > 10, qPrintable(QString::number(paths)));

        QFile pdf(dir.filePath(QStringLiteral("parameter_k0.pdf")));
        QVERIFY(pdf.open(QIODevice::ReadOnly));
        const QByteArray bytes = pdf.readAll();
        QVERIFY(bytes.startsWith("%PDF-"));
        QVERIFY(bytes.trimmed().endsWith("%%EOF"));
        QVERIFY(bytes.size() > 1000);

        QString why;
        QVERIFY(!PlotExporter::saveAs(panel.hysteresis(), dir.filePath(QStringLiteral("x.bmp")),
                                      400, 300, &why));
        QVERIFY2(why.contains(QStringLiteral("png, svg or pdf")), qPrintable(why));
        QVERIFY(!QFile::exists(dir.filePath(QStringLiteral("x.bmp"))));
    }

    void runPlotsUseThePanel() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QStringList errors;
        const QStringList files = PlotExporter::writeRunPlots(
            dir.path(), m_run.layout, m_run.records, &errors, PlotReferences::of(m_run.config));
        QVERIFY2(errors.isEmpty(), qPrintable(errors.join(QLatin1Char('\n'))));
        for (const char* name :
             {"plots.png", "hysteresis.png", "force.png", "displacement.png", "ground_motion.png",
              "tracking.png", "fit_error.png", "parameters.png", "hysteresis_Element_1.png",
              "hysteresis_Element_2.png"}) {
            const QString path = dir.filePath(QString::fromLatin1(name));
            QVERIFY2(files.contains(path), name);
            QVERIFY2(hasInk(QImage(path), 1000), name);
        }
        const QImage whole(dir.filePath(QStringLiteral("plots.png")));
        QCOMPARE(whole.size(), QSize(PlotExporter::kPanelWidth, PlotExporter::kPanelHeight));
    }
};

QTEST_MAIN(TestLivePlotsPanel)
#include "TestLivePlotsPanel.moc"
