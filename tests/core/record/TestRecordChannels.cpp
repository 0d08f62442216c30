// The record of a multi-DOF experimental element (docs/recording.md, "Element channels";
// core/experiment/ElementChannels.h): the preset two-actuator-column-frame (the left column a
// link2d specimen behind `expSetup NoTransformation 1 -dir 1 2 -sizeTrialOut 3 3`, a vertical
// actuator holding -500 kN in force control on the axial DOF, a lateral actuator in
// displacement control on the shear DOF, each an elastic / Bouc-Wen uniaxial material on the
// virtual lab) recorded by RecordWriter, steps.csv (StepCsvWriter), `hsmu export`
// (exportRecordCsv) and summary.json (RunStatistics + makeRunSummary). Checked:
//  - every basic DOF (commanded, deformation, force) and every actuator (command, stroke,
//    force) has its column, with its unit, in each output;
//  - the actuator columns equal the setup's transformation of the recorded basic
//    deformations (eq. S1; for NoTransformation the closed form s = (d_axial, d_shear)): the
//    commands those of the commanded ones, the strokes those of the measured ones, exactly
//    (1e-15 m); the basic forces q = J^T f (eq. S3; here q_axial = f_vertical, q_shear =
//    f_lateral, q_rot = 0) exactly;
//  - the force-controlled actuator's command and force columns equal its held force (-500 kN;
//    the lab's Newton stops at 1e-12 of the force) and its stroke the elastic closed form
//    -500 / 2e5 m (1e-12 relative);
//  - the HDF5 record, steps.csv (10 significant digits) and the export equal the steps the
//    test published (bit for bit / 1e-9 relative); summary.json's peaks the columns' peaks.
// Units: kN, m, rad, s.

#include "core/config/ConfigLoader.h"
#include "core/config/TestFactory.h"
#include "core/experiment/HybridTest.h"
#include "core/experimental/ExperimentalLink2d.h"
#include "core/output/RunStatistics.h"
#include "core/output/RunSummary.h"
#include "core/output/StepCsvWriter.h"
#include "core/record/RecordCsvExport.h"
#include "core/record/RecordReader.h"
#include "core/record/RecordWriter.h"
#include "core/structure/Structure.h"

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <fstream>
#include <sstream>

using namespace hsmu;

namespace {

const std::string kPreset = HSMU_SOURCE_DIR "/resources/presets/two-actuator-column-frame.json";
constexpr double kHeld = -500.0;   // [kN] the vertical actuator's held force
constexpr double kVerticalK = 2e5; // [kN/m] its elastic material

struct Recorder final : StepObserver {
    std::vector<StepRecord> records;
    void onStep(const StepRecord& r) override { records.push_back(r); }
};

std::vector<std::vector<std::string>> readCsv(const std::string& path) {
    std::ifstream in(path);
    std::vector<std::vector<std::string>> rows;
    std::string line;
    while (std::getline(in, line)) {
        std::vector<std::string> f;
        std::stringstream s(line);
        std::string x;
        while (std::getline(s, x, ','))
            f.push_back(x);
        rows.push_back(f);
    }
    return rows;
}

int columnOf(const std::vector<std::string>& header, const std::string& name) {
    for (std::size_t j = 0; j < header.size(); ++j)
        if (header[j] == name)
            return int(j);
    return -1;
}

} // namespace

class TestRecordChannels : public QObject {
    Q_OBJECT

private slots:
    void everyBasicDofAndActuatorRecorded();
};

void TestRecordChannels::everyBasicDofAndActuatorRecorded() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    std::ifstream in(kPreset);
    TestConfig cfg = parseConfig(nlohmann::json::parse(in), "frame.json");
    cfg.analysis.duration = 4.0;
    auto test = buildHybridTest(cfg);
    const RunLayout layout = RunLayout::of(*test);
    const std::string h5 = dir.filePath("record.h5").toStdString();
    const std::string steps = dir.filePath("steps.csv").toStdString();
    RecordStart start;
    start.configuration = cfg.raw.dump();
    start.configName = cfg.name;
    start.dt = test->dt();
    RecordWriter writer(h5, layout, start);
    StepCsvWriter csv(steps, layout);
    RunStatistics stats(layout);
    Recorder rec;
    for (StepObserver* o : std::initializer_list<StepObserver*>{&writer, &csv, &stats, &rec})
        test->addObserver(o);
    QVERIFY(test->prepare());
    while (test->step() == HybridTest::StepResult::Advanced) {
    }
    QCOMPARE(test->state(), HybridTest::State::Finished);
    QVERIFY2(writer.finish(), writer.error().c_str());
    csv.finish();

    // The layout: Column L 3 x 3 basic + 2 x 3 actuator channels, Column R and the beam 3 x 2.
    QCOMPARE(layout.channels.size(), std::size_t(15 + 6 + 6));
    const auto channel = [&](const std::string& element, const std::string& name) {
        for (std::size_t j = 0; j < layout.channels.size(); ++j)
            if (layout.channels[j].element == element && layout.channels[j].name == name)
                return int(j);
        return -1;
    };
    const int ac = channel("Column L", "axial commanded"),
              ad = channel("Column L", "axial deformation"),
              af = channel("Column L", "axial force"), sc = channel("Column L", "shear commanded"),
              sd = channel("Column L", "shear deformation"),
              sf = channel("Column L", "shear force"),
              rc = channel("Column L", "rotation commanded"),
              rd = channel("Column L", "rotation deformation"),
              rf = channel("Column L", "rotation force"),
              vc = channel("Column L", "vertical command"),
              vs = channel("Column L", "vertical stroke"),
              vf = channel("Column L", "vertical force"),
              lc = channel("Column L", "lateral command"),
              ls = channel("Column L", "lateral stroke"), lf = channel("Column L", "lateral force"),
              raf = channel("Column R", "axial force"),
              rsd = channel("Column R", "shear deformation");
    for (int j : {ac, ad, af, sc, sd, sf, rc, rd, rf, vc, vs, vf, lc, ls, lf, raf, rsd})
        QVERIFY(j >= 0);
    QCOMPARE(layout.channels[std::size_t(vc)].unit, std::string("kN")); // force control
    QCOMPARE(layout.channels[std::size_t(lc)].unit, std::string("m"));
    QCOMPARE(layout.channels[std::size_t(rf)].unit, std::string("kN m"));
    QCOMPARE(layout.channels[std::size_t(rd)].unit, std::string("rad"));

    // The record read back equals what the test published, bit for bit.
    const RecordData d = RecordReader(h5).data();
    QCOMPARE(d.rows(), int(rec.records.size()));
    QCOMPARE(d.layout.channels.size(), layout.channels.size());
    for (std::size_t j = 0; j < layout.channels.size(); ++j) {
        QCOMPARE(d.layout.channels[j].element, layout.channels[j].element);
        QCOMPARE(d.layout.channels[j].name, layout.channels[j].name);
        QCOMPARE(d.layout.channels[j].unit, layout.channels[j].unit);
    }
    QCOMPARE(d.channels.cols(), Eigen::Index(layout.channels.size()));
    for (int i = 0; i < d.rows(); ++i)
        for (Eigen::Index j = 0; j < d.channels.cols(); ++j)
            QCOMPARE(d.channels(i, j), rec.records[std::size_t(i)].channels[std::size_t(j)]);

    // The setup's transformation of the recorded basic deformations, and the held force.
    const auto& x = static_cast<const ExperimentalLink2d&>(*test->structure().element("Column L"));
    double peakStroke = 0.0, peakShear = 0.0;
    for (int i = 1; i < d.rows(); ++i) {
        const auto c = [&](int j) { return d.channels(i, j); };
        Eigen::VectorXd sCmd, sMeas;
        QVERIFY(x.setup().strokes(Eigen::Vector3d(c(ac), c(sc), c(rc)), sCmd).ok);
        QVERIFY(x.setup().strokes(Eigen::Vector3d(c(ad), c(sd), c(rd)), sMeas).ok);
        QVERIFY(std::abs(c(lc) - sCmd[1]) <= 1e-15 && std::abs(c(lc) - c(sc)) <= 1e-15);
        QVERIFY(std::abs(c(ls) - sMeas[1]) <= 1e-15 && std::abs(c(ls) - c(sd)) <= 1e-15);
        QVERIFY(std::abs(c(vs) - sMeas[0]) <= 1e-15 && std::abs(c(vs) - c(ad)) <= 1e-15);
        QCOMPARE(c(vc), kHeld);
        QVERIFY2(std::abs(c(vf) - kHeld) <= 1e-12 * std::abs(kHeld),
                 qPrintable(QString::number(c(vf))));
        QVERIFY(std::abs(c(vs) - kHeld / kVerticalK) <= 1e-12 * std::abs(kHeld / kVerticalK));
        QCOMPARE(c(af), c(vf)); // q = J^T f, J the selection of NoTransformation
        QCOMPARE(c(sf), c(lf));
        QCOMPARE(c(rf), 0.0);
        QCOMPARE(c(raf), kHeld); // the numerical twin's held axial load
        // The primary column (shear) is the element's one column.
        QCOMPARE(d.deformation(i, 0), c(sd));
        QCOMPARE(d.force(i, 0), c(sf));
        QCOMPARE(d.commanded(i, 0), c(sc));
        QCOMPARE(d.deformation(i, 1), c(rsd));
        peakStroke = std::max(peakStroke, std::abs(c(ls)));
        peakShear = std::max(peakShear, std::abs(c(lf)));
    }
    qInfo("peak lateral stroke %.6g m, peak lateral force %.6g kN over %d steps", peakStroke,
          peakShear, d.rows() - 1);
    QVERIFY(peakStroke > 0.005); // past the column's yield (about 0.005 m)

    // hsmu export: channels.csv, one column per channel with its unit.
    const std::string out = dir.filePath("csv").toStdString();
    QVERIFY(QDir().mkpath(QString::fromStdString(out)));
    exportRecordCsv(d, out);
    const auto exported = readCsv(out + "/channels.csv");
    QCOMPARE(exported.size(), std::size_t(d.rows() + 1));
    const int ev = columnOf(exported[0], "Column L vertical force [kN]");
    const int el = columnOf(exported[0], "Column L lateral stroke [m]");
    const int em = columnOf(exported[0], "Column L rotation force [kN m]");
    QVERIFY(ev >= 0 && el >= 0 && em >= 0);
    for (int i = 0; i < d.rows(); ++i) {
        const auto& row = exported[std::size_t(i + 1)];
        QCOMPARE(std::stod(row[std::size_t(ev)]), d.channels(i, vf));
        QCOMPARE(std::stod(row[std::size_t(el)]), d.channels(i, ls));
    }

    // steps.csv: the same columns after the others, 10 significant digits.
    const auto rows = readCsv(steps);
    QCOMPARE(rows.size(), std::size_t(d.rows() + 1));
    QCOMPARE(rows[0].size(), StepCsvWriter::columnCount(layout));
    const int cv = columnOf(rows[0], "Column_L_vertical_force_kN");
    const int cl = columnOf(rows[0], "Column_L_lateral_stroke_m");
    const int cm = columnOf(rows[0], "Column_L_rotation_force_kNm");
    QVERIFY(cv >= 0 && cl >= 0 && cm >= 0);
    for (int i = 1; i < d.rows(); ++i) {
        const auto& row = rows[std::size_t(i + 1)];
        QVERIFY(std::abs(std::stod(row[std::size_t(cv)]) - d.channels(i, vf)) <= 1e-9 * 500.0);
        QVERIFY(std::abs(std::stod(row[std::size_t(cl)]) - d.channels(i, ls)) <=
                1e-9 * std::abs(d.channels(i, ls)) + 1e-300);
    }

    // summary.json: the peak of each channel.
    const nlohmann::json summary = makeRunSummary(*test, stats, RunInfo{});
    const nlohmann::json& peaks = summary.at("peak_channels").at("Column L");
    QCOMPARE(peaks.at("vertical force").at("unit").get<std::string>(), std::string("kN"));
    QVERIFY(std::abs(peaks.at("vertical force").at("value").get<double>() - 500.0) <= 1e-9);
    QCOMPARE(peaks.at("lateral stroke").at("value").get<double>(), peakStroke);
    QCOMPARE(peaks.at("lateral force").at("value").get<double>(), peakShear);
}

QTEST_GUILESS_MAIN(TestRecordChannels)
#include "TestRecordChannels.moc"
