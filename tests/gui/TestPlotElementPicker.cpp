// Issue 25 item 15 (first half): two labs: the Parameters dock said "UKF on Bearing D" while
// the hysteresis and tracking plots showed Bearing C, and D's loop could not be shown. Each
// per-element plot (hysteresis, force, tracking) has an element picker: by default the element
// the Parameters dock identifies; picking another plots that element's whole history (checked
// point by point against the rows the console received); the pick is kept across a re-load
// while its element exists and reset when it does not; titles and read-outs name the element;
// the wheel never changes a picker (item 3's rule). The two-lab bridge preset runs against two
// real hsmu-controller processes, on the lab's 1280x720 screen (offscreen, see main()).

#include "core/experiment/StepRecord.h"
#include "gui/app/ConsoleSettings.h"
#include "gui/app/MainWindow.h"
#include "gui/app/TestController.h"
#include "gui/app/Translations.h"
#include "gui/plots/HistoryPlot.h"
#include "gui/plots/HysteresisPlot.h"
#include "gui/plots/LivePlotsPanel.h"
#include "gui/plots/PlotElementPicker.h"
#include "gui/plots/PlotStyle.h"
#include "gui/plots/PlotTools.h"
#include "tests/comms/ControllerProcess.h"

#include <nlohmann/json.hpp>

#include <QApplication>
#include <QComboBox>
#include <QLabel>
#include <QScreen>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QWheelEvent>
#include <QtTest>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace hsmu;
using namespace hsmu::gui;

namespace {

int indexOf(const RunLayout& layout, const std::string& name) {
    for (std::size_t i = 0; i < layout.elements.size(); ++i)
        if (layout.elements[i].name == name)
            return int(i);
    return -1;
}

// The loop curve (first plottable) against the rows' samples of element e: "" if equal.
QString loopDiffers(HysteresisPlot& plot, const std::vector<StepRecord>& rows, int e) {
    auto* curve = qobject_cast<QCPCurve*>(plot.plottable(0));
    if (!curve)
        return QStringLiteral("no loop curve");
    if (curve->data()->size() != int(rows.size()))
        return QStringLiteral("%1 points for %2 rows").arg(curve->data()->size()).arg(rows.size());
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const QCPCurveData& p = *(curve->data()->constBegin() + qsizetype(k));
        const ElementSample& s = rows[k].elements[std::size_t(e)];
        if (p.key != s.deformation || p.value != s.force)
            return QStringLiteral("step %1: (%2, %3), the element's (%4, %5)")
                .arg(rows[k].step).arg(p.key).arg(p.value).arg(s.deformation).arg(s.force);
    }
    return {};
}

// Graph g of a history plot against value(row): "" if equal at every step.
template <class F>
QString historyDiffers(HistoryPlot& plot, int g, const std::vector<StepRecord>& rows, F value) {
    const auto data = plot.graph(g)->data();
    if (data->size() != int(rows.size()))
        return QStringLiteral("%1 points for %2 rows").arg(data->size()).arg(rows.size());
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const QCPGraphData& p = *(data->constBegin() + qsizetype(k));
        const double v = value(rows[k]);
        if (p.key != rows[k].time || !(p.value == v || (std::isnan(p.value) && std::isnan(v))))
            return QStringLiteral("step %1: %2, expected %3").arg(rows[k].step).arg(p.value).arg(v);
    }
    return {};
}

QStringList items(const PlotElementPicker& picker) {
    QStringList out;
    for (int i = 0; i < picker.comboBox()->count(); ++i)
        out << picker.comboBox()->itemText(i);
    return out;
}

void wheelOver(QWidget* w, int delta) {
    const QPointF at(w->width() / 2.0, w->height() / 2.0);
    QWheelEvent e(at, w->mapToGlobal(at), QPoint(), QPoint(0, delta), Qt::NoButton,
                  Qt::NoModifier, Qt::NoScrollPhase, false);
    QCoreApplication::sendEvent(w, &e);
}

nlohmann::json twoLabs() {
    std::ifstream in(std::string(HSMU_SOURCE_DIR) +
                     "/resources/presets/paper-bridge-two-labs.json");
    return nlohmann::json::parse(in);
}

} // namespace

class TestPlotElementPicker : public QObject {
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
        Translations::install(*QCoreApplication::instance(), QStringLiteral("en"));
    }

    void twoLabsPlotTheIdentifiedElementAndThePickedOne() {
        const std::string config = m_dir.filePath(QStringLiteral("two-labs.json")).toStdString();
        {
            nlohmann::json j = twoLabs();
            j["analysis"]["duration"] = 4.0;
            std::ofstream(config) << j.dump(2);
        }
        const QStringList args{QStringLiteral("--config"), QString::fromStdString(config),
                               QStringLiteral("--pace"), QStringLiteral("fast"),
                               QStringLiteral("--no-state-file")};
        ControllerProcess labD(args), labC(args);
        QVERIFY2(labD.start(), qPrintable(labD.log()));
        QVERIFY2(labC.start(), qPrintable(labC.log()));
        nlohmann::json j = twoLabs();
        j["analysis"]["duration"] = 4.0;
        for (auto& site : j["sites"])
            site["address"] = "tcp://127.0.0.1:" +
                              std::to_string(site["name"] == "Lab D" ? labD.port() : labC.port());
        const QString path = m_dir.filePath(QStringLiteral("two-labs-console.json"));
        std::ofstream(path.toStdString()) << j.dump(2);

        MainWindow window;
        window.setConfirmBeforeStart(false);
        window.setSpeed(0.0);
        window.resize(1280, 720);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.loadConfiguration(path));
        TestController& c = window.controller();
        const RunLayout& layout = c.layout();
        QVERIFY(layout.updating);
        QCOMPARE(layout.updating->specimen, std::string("Bearing D"));
        const int d = indexOf(layout, "Bearing D"), cIdx = indexOf(layout, "Bearing C");
        QVERIFY(d >= 0 && cIdx >= 0);
        auto* panel = window.findChild<LivePlotsPanel*>();
        QVERIFY(panel);

        // The default views agree with the Parameters dock: Bearing D everywhere.
        auto dockSays = [&window](const QString& text) {
            for (const QLabel* l : window.findChild<QWidget*>(QStringLiteral("parametersPanel"))
                                       ->findChildren<QLabel*>())
                if (l->text().contains(text))
                    return true;
            return false;
        };
        QTRY_VERIFY(dockSays(QStringLiteral("on Bearing D")));
        PlotElementPicker& hp = panel->hysteresisPicker();
        PlotElementPicker& fp = panel->forcePicker();
        PlotElementPicker& tp = panel->trackingPicker();
        for (PlotElementPicker* p : {&hp, &fp, &tp}) {
            QVERIFY2(p->isVisible(), "two specimens: each per-element plot offers a choice");
            QCOMPARE(p->element(), d);
            QCOMPARE(p->elementName(), QStringLiteral("Bearing D"));
        }
        QCOMPARE(items(tp), (QStringList{QStringLiteral("Bearing C"), QStringLiteral("Bearing D")}));
        QCOMPARE(items(hp), (QStringList{QStringLiteral("Bearing A"), QStringLiteral("Bearing B"),
                                         QStringLiteral("Bearing C"), QStringLiteral("Bearing D")}));
        QVERIFY(panel->hysteresis().property("hsmuTitle").toString().contains(QStringLiteral("Bearing D")));
        QVERIFY(panel->tracking().property("hsmuTitle").toString().contains(QStringLiteral("Bearing D")));

        std::vector<StepRecord> rows;
        connect(&c, &TestController::recordsArrived, this,
                [&rows](const std::vector<StepRecord>& r) { rows.insert(rows.end(), r.begin(), r.end()); });
        window.startTest();
        QTRY_COMPARE_WITH_TIMEOUT(c.state(), RunState::Finished, 60000);
        QCoreApplication::processEvents();
        QVERIFY(rows.size() > 100);
        QCOMPARE(panel->rowsShown(), qint64(rows.size()));
        QCOMPARE(loopDiffers(panel->hysteresis(), rows, d), QString());

        // The wheel over a picker changes nothing (it scrolls, as over every combo).
        QComboBox* hc = hp.comboBox();
        wheelOver(hc, -120);
        wheelOver(hc, 120);
        QCOMPARE(hp.element(), d);
        // The operator picks Bearing C with the keyboard: its loop, from the first step.
        hc->setFocus(Qt::TabFocusReason);
        QTest::keyClick(hc, Qt::Key_Up);
        QCOMPARE(hp.elementName(), QStringLiteral("Bearing C"));
        QCOMPARE(loopDiffers(panel->hysteresis(), rows, cIdx), QString());
        QVERIFY2(panel->hysteresis().property("hsmuTitle").toString().contains(QStringLiteral("Bearing C")),
                 qPrintable(panel->hysteresis().property("hsmuTitle").toString()));
        for (int i = 0; i < panel->hysteresis().plottableCount(); ++i) // no auxiliary model of D
            QVERIFY(!panel->hysteresis().plottable(i)->name().contains(QStringLiteral("auxiliary")));
        QVERIFY(PlotTools::attach(panel->hysteresis())
                    ->readout(0.0, 0.0)
                    .startsWith(QStringLiteral("Bearing C\n")));
        // The others keep theirs until picked.
        QCOMPARE(tp.element(), d);
        QCOMPARE(historyDiffers(panel->tracking(), 1, rows,
                                [d](const StepRecord& r) { return r.elements[std::size_t(d)].deformation; }),
                 QString());
        QComboBox* tc = tp.comboBox();
        tc->setFocus(Qt::TabFocusReason);
        QTest::keyClick(tc, Qt::Key_Up);
        QCOMPARE(tp.elementName(), QStringLiteral("Bearing C"));
        QVERIFY(panel->tracking().property("hsmuTitle").toString().contains(QStringLiteral("Bearing C")));
        const auto ci = std::size_t(cIdx);
        QCOMPARE(historyDiffers(panel->tracking(), 0, rows,
                                [ci](const StepRecord& r) { return r.elements[ci].commanded; }),
                 QString());
        QCOMPARE(historyDiffers(panel->tracking(), 1, rows,
                                [ci](const StepRecord& r) { return r.elements[ci].deformation; }),
                 QString());
        const double t = rows[rows.size() / 2].time;
        const QString readout = PlotTools::attach(panel->tracking())->readout(t, 0.0);
        QVERIFY2(readout.startsWith(QStringLiteral("Bearing C\n")), qPrintable(readout));
        QComboBox* fc = fp.comboBox();
        fc->setFocus(Qt::TabFocusReason);
        QTest::keyClick(fc, Qt::Key_Up);
        QCOMPARE(fp.elementName(), QStringLiteral("Bearing C"));
        QCOMPARE(historyDiffers(panel->forceHistory(), 0, rows,
                                [ci](const StepRecord& r) { return r.elements[ci].force; }),
                 QString());

        // Loaded again: the picks stay (their element exists) ...
        QVERIFY(window.loadConfiguration(path));
        QCOMPARE(hp.elementName(), QStringLiteral("Bearing C"));
        QCOMPARE(tp.elementName(), QStringLiteral("Bearing C"));
        // ... another test without them: its own default, no choice to offer ...
        QVERIFY(window.loadConfiguration(QStringLiteral("sdof-bouc-wen")));
        QCOMPARE(hp.elementName(), QStringLiteral("Spring"));
        QCOMPARE(tp.elementName(), QStringLiteral("Spring"));
        QVERIFY(!hp.isVisible() && !tp.isVisible());
        // ... and the two labs again show the identified element (the pick was reset).
        QVERIFY(window.loadConfiguration(path));
        QCOMPARE(hp.elementName(), QStringLiteral("Bearing D"));
        QCOMPARE(tp.elementName(), QStringLiteral("Bearing D"));
        QCOMPARE(fp.elementName(), QStringLiteral("Bearing D"));
    }

    // The pickers' words fit at 1280x720 in every language (the label and the element names).
    void pickersAreNotClipped_data() {
        QTest::addColumn<QString>("language");
        QTest::newRow("en") << QStringLiteral("en");
        QTest::newRow("es") << QStringLiteral("es");
        QTest::newRow("zh_CN") << QStringLiteral("zh_CN");
    }
    void pickersAreNotClipped() {
        QFETCH(QString, language);
        QVERIFY(Translations::install(*QCoreApplication::instance(), language));
        MainWindow window;
        window.resize(1280, 720);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.loadConfiguration(QStringLiteral("paper-bridge-two-labs")));
        QCoreApplication::processEvents();
        auto* panel = window.findChild<LivePlotsPanel*>();
        QStringList problems;
        for (PlotElementPicker* p :
             {&panel->hysteresisPicker(), &panel->forcePicker(), &panel->trackingPicker()}) {
            if (!p->isVisible()) {
                problems << p->objectName() + QStringLiteral(" hidden");
                continue;
            }
            for (const QLabel* l : p->findChildren<QLabel*>())
                if (l->width() + 1 < l->sizeHint().width())
                    problems << QStringLiteral("'%1': %2 px, needs %3")
                                    .arg(l->text()).arg(l->width()).arg(l->sizeHint().width());
            const QComboBox* box = p->comboBox();
            if (box->width() + 1 < box->sizeHint().width())
                problems << QStringLiteral("%1's list: %2 px, needs %3")
                                .arg(p->objectName()).arg(box->width()).arg(box->sizeHint().width());
        }
        Translations::install(*QCoreApplication::instance(), QStringLiteral("en"));
        QVERIFY2(problems.isEmpty(), qPrintable(language + QStringLiteral(": ") +
                                                problems.join(QStringLiteral("; "))));
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
        TestPlotElementPicker test;
        QTEST_SET_MAIN_SOURCE_PATH
        result = QTest::qExec(&test, argc, argv);
    }
    std::remove(screens.c_str());
    return result;
}

#include "TestPlotElementPicker.moc"
