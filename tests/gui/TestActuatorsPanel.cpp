// The console's views of a multi-actuator specimen (gui/plots/ActuatorsPanel, SetupSketchView,
// the pre-flight's per-actuator limit lines; docs/console.md, "Actuators and setup"), offscreen,
// on real runs of the presets two-actuator-column-frame and inverted-v-brace-frame:
//  - every channel group (each actuator, each basic DOF, every deformation / force / stroke /
//    actuator force of an element) plots one curve per channel whose every point equals the
//    recorded StepRecord::channels value bit for bit; the line of values shows the last row's
//    values (6 significant digits) with their units; the axes name the units;
//  - the replay (the HDF5 record read back, RecordPlayback rows) shows the same values;
//  - the sketch: node j at the closed form of eq. K1 from the recorded measured deformations
//    and the stated scale (sketchScale of the largest displacement, computed here from the
//    records), 1e-12 m; the brace's three actuators drawn; a numerical element has no sketch;
//  - `hsmu run --plots` (PlotExporter::writeRunPlots) writes one PNG per group (19);
//  - the pre-flight lines: a force-controlled channel within its force limit (PASS, the
//    preset's 500 kN against 1000 kN) and one past it (FAIL, 1200 kN), both in the dialog.
// Units: kN, m, rad, s.

#include "RecordedRun.h"
#include "core/config/TestFactory.h"
#include "core/experimental/SetupSketch.h"
#include "core/record/RecordReader.h"
#include "gui/app/PreflightDialog.h"
#include "gui/app/PreflightReport.h"
#include "gui/plots/ActuatorsPanel.h"
#include "gui/plots/HistoryPlot.h"
#include "gui/plots/LivePlotsPanel.h"
#include "gui/plots/PlotExporter.h"
#include "gui/plots/PlotStyle.h"
#include "gui/plots/SetupSketchView.h"
#include "gui/replay/RecordPlayback.h"

#include <QComboBox>
#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QLabel>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <cmath>

using namespace hsmu;
using namespace hsmu::gui;

namespace {

// Every point of every curve of the shown group equals the rows' channel values.
void checkShownGroup(const ActuatorsPanel& a, const std::vector<StepRecord>& rows) {
    const ChannelGroup& g = a.groups()[std::size_t(a.shownGroup())];
    QCOMPARE(a.plot().graphCount(), int(g.channels.size()));
    for (int k = 0; k < a.plot().graphCount(); ++k) {
        const auto data = a.plot().graph(k)->data();
        QCOMPARE(data->size(), int(rows.size()));
        for (int i = 0; i < data->size(); ++i) {
            QCOMPARE(data->at(i)->key, rows[std::size_t(i)].time);
            const double want =
                rows[std::size_t(i)].channels[std::size_t(g.channels[std::size_t(k)])];
            if (data->at(i)->value != want)
                QFAIL(qPrintable(QStringLiteral("group %1, curve %2, row %3: %4 shown, %5 recorded")
                                     .arg(a.selector().itemText(a.shownGroup()))
                                     .arg(k)
                                     .arg(i)
                                     .arg(data->at(i)->value, 0, 'g', 17)
                                     .arg(want, 0, 'g', 17)));
        }
    }
    const std::vector<double> values = a.shownValues();
    QCOMPARE(int(values.size()), int(g.channels.size()));
    for (std::size_t k = 0; k < values.size(); ++k) {
        QCOMPARE(values[k], rows.back().channels[std::size_t(g.channels[k])]);
        QVERIFY2(a.values().text().contains(QString::number(values[k], 'g', 6)),
                 qPrintable(a.values().text()));
    }
}

int groupOf(const ActuatorsPanel& a, ChannelGroupKind kind, const std::string& element,
            const std::string& subject = {}) {
    for (std::size_t i = 0; i < a.groups().size(); ++i) {
        const ChannelGroup& g = a.groups()[i];
        if (g.kind == kind && g.element == element && (subject.empty() || g.subject == subject))
            return int(i);
    }
    return -1;
}

double peakOf(const std::vector<StepRecord>& rows, const std::array<int, 3>& c, double length) {
    double peak = 0.0;
    for (const StepRecord& r : rows)
        peak = std::max({peak, std::abs(r.channels[std::size_t(c[0])]),
                         std::abs(r.channels[std::size_t(c[1])]),
                         length * std::abs(r.channels[std::size_t(c[2])])});
    return peak;
}

} // namespace

class TestActuatorsPanel : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    recordedrun::Run m_column;

private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        m_column = recordedrun::run(QStringLiteral("two-actuator-column-frame"), 2.0,
                                    m_dir.filePath(QStringLiteral("column.h5")));
        QCOMPARE(int(m_column.records.size()), 201);
        QVERIFY(!m_column.layout.channels.empty());
    }

    void everyGroupShowsTheRecordedValues() {
        LivePlotsPanel panel;
        panel.resize(1000, 900);
        panel.configure(m_column.layout, m_column.config);
        panel.appendRecords(m_column.records);
        panel.refreshNow();
        ActuatorsPanel& a = panel.actuators();
        QVERIFY(a.hasChannels());
        QVERIFY(a.isVisibleTo(&panel));
        // Column L: 3 DOFs + 2 actuators + 4; Column R and the beam (numerical): 3 DOFs + 2
        QCOMPARE(int(a.groups().size()), 9 + 5 + 5);
        QCOMPARE(a.selector().count(), int(a.groups().size()));
        // The first view is the first actuator's tracking: the vertical one, force-controlled
        QCOMPARE(a.shownGroup(), groupOf(a, ChannelGroupKind::Actuator, "Column L", "vertical"));
        QVERIFY(PlotStyle::axisLabel(a.plot(), *a.plot().yAxis)
                    .contains(QLatin1String("[kN]"))); // command, force
        QVERIFY(PlotStyle::axisLabel(a.plot(), *a.plot().yAxis2)
                    .contains(QLatin1String("[m]"))); // stroke
        checkShownGroup(a, m_column.records);
        // the vertical actuator holds the axial load: its command is -500 kN at every step > 0
        QCOMPARE(a.shownValues()[0], -500.0);
        for (int i = 0; i < int(a.groups().size()); ++i) {
            a.showGroup(i);
            checkShownGroup(a, m_column.records);
        }
        a.showGroup(groupOf(a, ChannelGroupKind::Actuator, "Column L", "lateral"));
        QVERIFY(PlotStyle::axisLabel(a.plot(), *a.plot().yAxis).contains(QLatin1String("[m]")));
        QVERIFY(PlotStyle::axisLabel(a.plot(), *a.plot().yAxis2).contains(QLatin1String("[kN]")));
        QVERIFY(a.values().text().contains(QLatin1String(" m")));
        // Every stroke of the element in one plot, one curve per actuator
        a.showGroup(groupOf(a, ChannelGroupKind::Strokes, "Column L"));
        QCOMPARE(a.plot().graphCount(), 2);
        // The export and redraw lists know the plot
        bool listed = false;
        for (const auto& p : panel.plots())
            listed = listed || p.plot == &a.plot();
        QVERIFY(listed);
    }

    void sketchIsTheClosedForm() {
        LivePlotsPanel panel;
        panel.resize(1000, 900);
        panel.configure(m_column.layout, m_column.config);
        panel.appendRecords(m_column.records);
        ActuatorsPanel& a = panel.actuators();
        a.showGroup(groupOf(a, ChannelGroupKind::Actuator, "Column L", "lateral"));
        const SetupSketchView& s = a.sketch();
        QVERIFY(s.isVisibleTo(&panel));
        QVERIFY(s.deformed().drawable);
        const auto c = basicDeformationChannels(m_column.layout.channels, "Column L");
        const double m = sketchScale(peakOf(m_column.records, c, 3.0), 3.0);
        QVERIFY(m > 1.0);
        QCOMPARE(s.scale(), m);
        const StepRecord& last = m_column.records.back();
        const double axial = last.channels[std::size_t(c[0])];
        const double shear = last.channels[std::size_t(c[1])];
        // eq. K1 for a column (phi = 90 deg): e = (0, 1), n = (-1, 0)
        const Eigen::Vector2d want(-m * shear, 3.0 + m * axial);
        QVERIFY2((s.deformed().nodeJ - want).norm() < 1e-12,
                 qPrintable(QStringLiteral("node j (%1, %2), expected (%3, %4)")
                                .arg(s.deformed().nodeJ.x())
                                .arg(s.deformed().nodeJ.y())
                                .arg(want.x())
                                .arg(want.y())));
        QVERIFY(s.caption().contains(QStringLiteral("x%1").arg(m)));
        // a numerical element has no setup to draw
        a.showGroup(groupOf(a, ChannelGroupKind::BasicDof, "Column R", "shear"));
        QVERIFY(!s.isVisibleTo(&panel));
        // the picture is painted (offscreen) without trouble
        a.showGroup(groupOf(a, ChannelGroupKind::Actuator, "Column L", "lateral"));
        QVERIFY(!a.sketch().grab().isNull());
    }

    void replayShowsTheChannels() {
        auto data = std::make_shared<const RecordData>(
            RecordReader(m_dir.filePath(QStringLiteral("column.h5")).toStdString()).data());
        std::vector<StepRecord> rows;
        for (int i = 0; i < data->rows(); ++i)
            rows.push_back(RecordPlayback::rowAt(*data, i));
        QCOMPARE(int(rows.size()), int(m_column.records.size()));
        for (std::size_t i = 0; i < rows.size(); ++i)
            QVERIFY(rows[i].channels == m_column.records[i].channels);
        LivePlotsPanel panel;
        panel.configure(data->layout,
                        PlotReferences::ofConfigurationJson(data->meta.configuration));
        panel.appendRecords(rows);
        ActuatorsPanel& a = panel.actuators();
        QVERIFY(a.hasChannels());
        for (int i = 0; i < int(a.groups().size()); ++i) {
            a.showGroup(i);
            checkShownGroup(a, m_column.records);
        }
        a.showGroup(groupOf(a, ChannelGroupKind::Actuator, "Column L", "lateral"));
        QVERIFY(a.sketch().deformed().drawable); // the record's configuration has the setup
    }

    void braceSketchHasThreeActuators() {
        const recordedrun::Run brace =
            recordedrun::run(QStringLiteral("inverted-v-brace-frame"), 1.0);
        LivePlotsPanel panel;
        panel.configure(brace.layout, brace.config);
        panel.appendRecords(brace.records);
        ActuatorsPanel& a = panel.actuators();
        QCOMPARE(a.groups()[std::size_t(a.shownGroup())].subject, std::string("horizontal"));
        checkShownGroup(a, brace.records);
        const SetupSketch& s = a.sketch().deformed();
        QVERIFY(s.drawable);
        int actuators = 0;
        for (const SketchSegment& seg : s.segments)
            actuators += seg.part == SketchPart::Actuator ? 1 : 0;
        QCOMPARE(actuators, 3);
        QVERIFY(a.sketch().caption().contains(QLatin1String("InvertedVBrace2d")));
    }

    void runPlotsHaveEveryGroup() {
        // `hsmu run --plots`: one PNG per basic DOF and actuator group
        const QString dir = m_dir.filePath(QStringLiteral("plots"));
        QVERIFY(QDir().mkpath(dir));
        QStringList errors;
        const QStringList files = PlotExporter::writeRunPlots(
            dir, m_column.layout, m_column.records, &errors, PlotReferences::of(m_column.config));
        QVERIFY2(errors.isEmpty(), qPrintable(errors.join(QLatin1Char(' '))));
        QStringList channels;
        for (const QString& f : files)
            if (QFileInfo(f).fileName().startsWith(QLatin1String("channels_")))
                channels << QFileInfo(f).fileName();
        QCOMPARE(channels.size(), 19);
        for (const char* name :
             {"channels_Column_L_actuator_lateral.png", "channels_Column_L_actuator_vertical.png",
              "channels_Column_L_shear.png", "channels_Column_L_strokes.png",
              "channels_Beam_rotation.png"})
            QVERIFY2(channels.contains(QLatin1String(name)), name);
        QVERIFY(
            !QImage(QDir(dir).filePath(QStringLiteral("channels_Column_L_actuator_lateral.png")))
                 .isNull());
    }

    void preflightLinesPassAndFail() {
        // the preset, prepared: its vertical actuator's 500 kN against the 1000 kN limit
        TestConfig cfg = PresetLibrary::load(QStringLiteral("two-actuator-column-frame"));
        cfg.analysis.duration = 1.0;
        auto test = buildHybridTest(cfg);
        QVERIFY(test->prepare());
        PreflightReport report = preflightOf(*test, false);
        QCOMPARE(int(report.specimens.size()), 1);
        QCOMPARE(int(report.specimens[0].actuatorLimits.size()), 6); // 2 actuators x 3 limits
        QVERIFY(!report.hasExceededActuatorLimit());
        // a second specimen whose force-controlled actuator holds more than its limit
        SpecimenPreflight past = report.specimens[0];
        past.element = "Column X";
        ActuatorChannelSpec heavy;
        heavy.name = "vertical";
        heavy.mode = ActuatorMode::Force;
        heavy.heldForce = -1200.0;
        heavy.limits.maxForce = 1000.0;
        past.actuatorLimits = actuatorLimitLines({heavy}, 1.0);
        report.specimens.push_back(past);
        QVERIFY(report.hasExceededActuatorLimit());

        PreflightDialog d(report);
        QStringList lines;
        for (const QLabel* l : d.findChildren<QLabel*>(QStringLiteral("actuatorLimitLine")))
            lines << l->text();
        QCOMPARE(lines.size(), 9);
        const auto has = [&lines](const QString& text) {
            for (const QString& l : lines)
                if (l.contains(text))
                    return true;
            return false;
        };
        QVERIFY2(
            has(QStringLiteral("PASS  Column L, actuator 'vertical' (force control): force |F| "
                               "up to 500 kN (t = 0 s), within the limit 1000 kN")),
            qPrintable(lines.join(QLatin1Char('\n'))));
        QVERIFY2(
            has(QStringLiteral("FAIL  Column X, actuator 'vertical' (force control): force |F| "
                               "reaches 1200 kN (t = 0 s), past the limit 1000 kN")),
            qPrintable(lines.join(QLatin1Char('\n'))));
        QVERIFY(
            has(QStringLiteral("Column L, actuator 'lateral' (displacement control): stroke |s| "
                               "limit 0.2 m, checked at every step")));
    }
};

QTEST_MAIN(TestActuatorsPanel)
#include "TestActuatorsPanel.moc"
