// Chosen and decimated numerical DOFs in the record (issue 27; docs/recording.md "Chosen and
// decimated DOFs", core/output/DofRecording.h, core/config/RecordConfig.h): one run recorded
// at once in full and with a choice of DOFs and a stride; the chosen record's DOF rows and
// columns equal the full record's corresponding ones exactly, every other dataset (elements,
// specimens, actuators, updating, alarms) equals the full record's whole, the export and the
// reader honour the choice, and asking to choose a specimen's channels is refused.

#include "RecordFixture.h"

#include "core/config/RecordConfig.h"
#include "core/config/ShearBuilding.h"
#include "core/record/RecordCsvExport.h"
#include "core/record/RecordError.h"
#include "core/record/RecordReader.h"

#include <QTemporaryDir>
#include <QtTest>

#include <hdf5.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

using namespace hsmu;
using namespace hsmu::testsupport;

namespace {

/// Identical bit patterns (NaN equal to NaN): "exactly", not within a tolerance.
bool same(double a, double b) {
    return (std::isnan(a) && std::isnan(b)) || a == b;
}

bool sameMatrix(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
    if (a.rows() != b.rows() || a.cols() != b.cols())
        return false;
    for (Eigen::Index i = 0; i < a.rows(); ++i)
        for (Eigen::Index j = 0; j < a.cols(); ++j)
            if (!same(a(i, j), b(i, j)))
                return false;
    return true;
}

std::vector<std::string> lines(const std::string& path) {
    std::ifstream in(path);
    std::vector<std::string> out;
    for (std::string line; std::getline(in, line);)
        out.push_back(line);
    return out;
}

/// Replaces the integer attribute `name` of the group /dofs in the record at `path` by
/// `values` (a scalar when `scalar`): a record damaged by hand or by another program.
bool rewriteDofsAttr(const std::string& path, const char* name, const std::vector<int>& values,
                     bool scalar) {
    const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    if (f < 0)
        return false;
    const hid_t g = H5Gopen2(f, "dofs", H5P_DEFAULT);
    bool ok = g >= 0 && H5Adelete(g, name) >= 0;
    if (ok) {
        const hsize_t n = values.size();
        const hid_t space = scalar ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &n, nullptr);
        const hid_t a = H5Acreate2(g, name, H5T_NATIVE_INT, space, H5P_DEFAULT, H5P_DEFAULT);
        ok = a >= 0 && H5Awrite(a, H5T_NATIVE_INT, values.data()) >= 0;
        H5Aclose(a);
        H5Sclose(space);
    }
    if (g >= 0)
        H5Gclose(g);
    H5Fclose(f);
    return ok;
}

/// Runs cfg to its end with two writers: the full record and one with `choice`.
void recordBoth(const TestConfig& cfg, const DofRecording& choice, const std::string& full,
                const std::string& chosen) {
    auto test = buildHybridTest(cfg);
    RecordStart start = recordStart(cfg);
    RecordWriter fullWriter(full, RunLayout::of(*test), start);
    start.dofRecording = choice;
    RecordWriter chosenWriter(chosen, RunLayout::of(*test), start);
    for (RecordWriter* w : {&fullWriter, &chosenWriter}) {
        w->trackAlarms(&test->alarms());
        test->addObserver(w);
    }
    QVERIFY(test->prepare());
    while (test->step() == HybridTest::StepResult::Advanced) {
    }
    QVERIFY2(fullWriter.finish(), fullWriter.error().c_str());
    QVERIFY2(chosenWriter.finish(), chosenWriter.error().c_str());
}

/// A 12-storey building for 0.1 s (101 steps): the full record and one keeping DOFs 0 and 11
/// every 10 steps.
void recordTwelveStoreys(const std::string& full, const std::string& chosen) {
    nlohmann::json j = shearBuildingConfig({12, true, false});
    j["analysis"]["duration"] = 0.1;
    recordBoth(parseConfig(j, "shear-building-12"), DofRecording{{0, 11}, 10}, full, chosen);
}

} // namespace

class TestRecordDofChoice : public QObject {
    Q_OBJECT
private slots:
    void chosenRecordEqualsTheFullRecordsRowsAndColumns_data();
    void chosenRecordEqualsTheFullRecordsRowsAndColumns();
    void exportWritesTheKeptRowsWithTheirTrueSteps();
    void parserReadsIndicesRangesAndNames();
    void specimenChannelsCannotBeChosen();
    void configurationBlock();
    void damagedChoiceIsRefused_data();
    void damagedChoiceIsRefused();
};

void TestRecordDofChoice::chosenRecordEqualsTheFullRecordsRowsAndColumns_data() {
    QTest::addColumn<QString>("preset");
    QTest::addColumn<QString>("list");
    QTest::addColumn<int>("every");
    // A specimen with UKF updating (2 DOFs): one DOF every 7 steps; a 12-storey building:
    // indices, a range and a name, every 5 steps; every DOF every 3 steps; a choice alone.
    QTest::newRow("condition-3, DOF 1 every 7") << "paper-condition-3"
                                                << "1" << 7;
    QTest::newRow("shear-building-12, 0-3,S9,11 every 5") << "shear-building-12"
                                                          << "0-3,S9,11" << 5;
    QTest::newRow("shear-building-12, every DOF every 3") << "shear-building-12"
                                                          << "0-11" << 3;
    QTest::newRow("shear-building-12, 2,5 every step") << "shear-building-12"
                                                       << "2, 5" << 1;
}

void TestRecordDofChoice::chosenRecordEqualsTheFullRecordsRowsAndColumns() {
    QFETCH(QString, preset);
    QFETCH(QString, list);
    QFETCH(int, every);
    const TestConfig cfg = preset.startsWith("shear")
                               ? parseConfig(
                                     [] {
                                         nlohmann::json j = shearBuildingConfig({12, true, false});
                                         j["analysis"]["duration"] = 0.4; // 401 rows
                                         return j;
                                     }(),
                                     "shear-building-12")
                               : condition3(2.0);
    DofRecording choice{configDofList(cfg, list.toStdString()), every};
    QTemporaryDir dir;
    const std::string full = dir.filePath("full.h5").toStdString();
    const std::string chosen = dir.filePath("chosen.h5").toStdString();
    recordBoth(cfg, choice, full, chosen);
    if (QTest::currentTestFailed())
        return;
    const RecordReader fr(full), cr(chosen);
    const RecordData &f = fr.data(), &c = cr.data();
    QVERIFY(f.meta.dofRecording.full());
    QVERIFY(f.dofSteps.empty());
    QCOMPARE(c.meta.dofRecording.dofs, choice.dofs);
    QCOMPARE(c.meta.dofRecording.every, every);

    // Everything but /dofs: the same rows, whole.
    QVERIFY(f.rows() > 100);
    QCOMPARE(c.steps, f.steps);
    QVERIFY(sameMatrix(c.time, f.time));
    QVERIFY(sameMatrix(c.groundAcceleration, f.groundAcceleration));
    for (auto m : {&RecordData::deformation, &RecordData::force, &RecordData::commanded,
                   &RecordData::actuatorCommanded, &RecordData::actuatorMeasured,
                   &RecordData::heldTicks, &RecordData::actuatorFlags, &RecordData::parameters,
                   &RecordData::stddev, &RecordData::tracking, &RecordData::siteRoundTrip})
        QVERIFY(sameMatrix(c.*m, f.*m));
    QCOMPARE(c.layout.dofNames, f.layout.dofNames); // every DOF's name, kept or not
    QCOMPARE(c.layout.elements.size(), f.layout.elements.size());
    QVERIFY(sameMatrix(c.auxiliaryForce, f.auxiliaryForce));
    QCOMPARE(c.appliedUpdates, f.appliedUpdates);
    QCOMPARE(c.alarms.size(), f.alarms.size());
    QCOMPARE(c.updateEvents.size(), f.updateEvents.size());

    // /dofs: the steps that are multiples of `every`, the chosen columns, exactly.
    std::vector<int> wanted;
    for (const int s : f.steps)
        if (s % every == 0)
            wanted.push_back(s);
    QCOMPARE(c.dofRows(), int(wanted.size()));
    for (int k = 0; k < c.dofRows(); ++k)
        QCOMPARE(c.dofStep(k), wanted[std::size_t(k)]);
    const int nKept = choice.dofs.empty() ? int(f.layout.dofNames.size()) : int(choice.dofs.size());
    QCOMPARE(int(c.u.cols()), nKept);
    for (int i = 0; i < f.rows(); ++i) {
        const int k = c.dofRowOf(i);
        QCOMPARE(k >= 0, f.steps[std::size_t(i)] % every == 0);
        if (k < 0)
            continue;
        QVERIFY(same(c.dofTime(k), f.time(i)));
        for (int j = 0; j < nKept; ++j) {
            const int dof = c.dofIndex(j);
            QCOMPARE(c.dofColumn(dof), j);
            QVERIFY2(same(c.u(k, j), f.u(i, dof)) && same(c.v(k, j), f.v(i, dof)) &&
                         same(c.a(k, j), f.a(i, dof)),
                     ("row " + std::to_string(i) + ", DOF " + std::to_string(dof)).c_str());
        }
    }
    // A DOF left out: no column, and the reason names it and the options.
    for (int dof = 0; dof < int(f.layout.dofNames.size()); ++dof)
        if (c.dofColumn(dof) < 0) {
            const std::string why = c.dofNotRecorded(dof);
            QVERIFY2(why.find("'" + f.layout.dofNames[std::size_t(dof)] + "'") !=
                             std::string::npos &&
                         why.find("--record-dofs") != std::string::npos &&
                         why.find("record.dofs") != std::string::npos,
                     why.c_str());
        }
}

void TestRecordDofChoice::exportWritesTheKeptRowsWithTheirTrueSteps() {
    QTemporaryDir dir;
    const std::string full = dir.filePath("full.h5").toStdString();
    const std::string chosen = dir.filePath("chosen.h5").toStdString();
    recordTwelveStoreys(full, chosen);
    const RecordReader fr(full), cr(chosen);
    const std::string fullDir = dir.filePath("full").toStdString();
    const std::string chosenDir = dir.filePath("chosen").toStdString();
    QVERIFY(QDir().mkpath(QString::fromStdString(fullDir)));
    QVERIFY(QDir().mkpath(QString::fromStdString(chosenDir)));
    exportRecordCsv(fr.data(), fullDir);
    exportRecordCsv(cr.data(), chosenDir);
    // Every table but dofs.csv: the same bytes.
    for (const char* file : {"steps.csv", "elements.csv", "alarms.csv"})
        QCOMPARE(lines(chosenDir + "/" + file), lines(fullDir + "/" + file));
    const auto f = lines(fullDir + "/dofs.csv"), c = lines(chosenDir + "/dofs.csv");
    QCOMPARE(int(f.size()), 1 + 101);
    QCOMPARE(int(c.size()), 1 + 11); // steps 0, 10, ..., 100
    QCOMPARE(QString::fromStdString(c[0]),
             QStringLiteral("step,time [s],u S1 [m],u S12 [m],v S1 [m/s],v S12 [m/s],"
                            "a S1 [m/s^2],a S12 [m/s^2]"));
    for (int k = 0; k <= 10; ++k) {
        // The full export's row of step 10 k, columns step, time, u S1 ... u S12 (2 + 12 each).
        QStringList fr = QString::fromStdString(f[std::size_t(1 + 10 * k)]).split(',');
        const QStringList cr = QString::fromStdString(c[std::size_t(1 + k)]).split(',');
        QCOMPARE(cr.size(), 8);
        QCOMPARE(cr[0], QString::number(10 * k));
        const QStringList expected{fr[0], fr[1], fr[2], fr[13], fr[14], fr[25], fr[26], fr[37]};
        QCOMPARE(cr, expected);
    }
}

void TestRecordDofChoice::parserReadsIndicesRangesAndNames() {
    const std::vector<std::string> names{"Ground", "First", "2", "Roof"};
    QCOMPARE(parseDofList("3, 0-1", names, {}), (std::vector<int>{0, 1, 3}));
    QCOMPARE(parseDofList("Roof,First,1", names, {}), (std::vector<int>{1, 3}));
    QCOMPARE(parseDofList("2", names, {}), (std::vector<int>{2})); // digits: an index
    QVERIFY(parseDofList("0-3", names, {}).empty());               // every DOF
    QCOMPARE(describeDofList({0, 1, 2, 5, 7, 8}), std::string("0-2,5,7-8"));
    QCOMPARE(describeDofList({}), std::string("all"));
    const struct {
        const char* list;
        const char* says;
    } bad[] = {{"", "empty DOF list"},     {"1,,2", "empty item"},
               {"4", "out of range 0..3"}, {"2-9", "out of range 0..3"},
               {"3-1", "runs backwards"},  {"Attic", "no DOF named 'Attic'"},
               {"-1", "no DOF named '-1'"}};
    for (const auto& b : bad) {
        try {
            parseDofList(b.list, names, {});
            QFAIL(b.list);
        } catch (const std::invalid_argument& e) {
            QVERIFY2(std::string(e.what()).find(b.says) != std::string::npos, e.what());
        }
    }
}

void TestRecordDofChoice::specimenChannelsCannotBeChosen() {
    const TestConfig cfg = condition3(0.1); // Element 1 is the specimen
    try {
        configDofList(cfg, "0,Element 1");
        QFAIL("a specimen accepted as a DOF to choose");
    } catch (const std::invalid_argument& e) {
        const std::string why = e.what();
        QVERIFY2(why.find("'Element 1' is a specimen") != std::string::npos &&
                     why.find("always recorded in full at every step") != std::string::npos,
                 why.c_str());
    }
}

void TestRecordDofChoice::configurationBlock() {
    const std::string path =
        std::string(HSMU_SOURCE_DIR) + "/resources/presets/paper-condition-3.json";
    std::ifstream in(path);
    const nlohmann::json base = nlohmann::json::parse(in);
    nlohmann::json j = base;
    j["record"] = {{"dofs", nlohmann::json::array({1})}, {"every", 4}};
    const TestConfig ok = parseConfig(j, path);
    QCOMPARE(ok.record.dofs, (std::vector<int>{1}));
    QCOMPARE(ok.record.every, 4);
    QVERIFY(parseConfig(base, path).record.full());
    const struct {
        nlohmann::json record;
        const char* says;
    } bad[] = {
        {{{"elements", "none"}}, "record.elements: not accepted: a specimen's channels"},
        {{{"specimens", {{"every", 10}}}}, "always recorded in full at every step"},
        {{{"dofs", "Element 1"}}, "record.dofs: 'Element 1' is a specimen"},
        {{{"dofs", "0-5"}}, "record.dofs: DOF index '0-5' out of range 0..1"},
        {{{"every", 0}}, "record.every"},
        {{{"dofs", 3.5}}, "record.dofs: expected a list"},
        {{{"stride", 2}}, "stride"},
    };
    for (const auto& b : bad) {
        nlohmann::json d = base;
        d["record"] = b.record;
        try {
            parseConfig(d, path);
            QFAIL(b.record.dump().c_str());
        } catch (const ConfigError& e) {
            QVERIFY2(std::string(e.what()).find(b.says) != std::string::npos, e.what());
        }
    }
}

void TestRecordDofChoice::damagedChoiceIsRefused_data() {
    QTest::addColumn<QString>("attribute");
    QTest::addColumn<QList<int>>("values");
    QTest::addColumn<QString>("message"); // after "PATH: "
    const QString indices = QStringLiteral("damaged record (/dofs dof_indices)");
    QTest::newRow("indices descending") << "dof_indices" << QList<int>{11, 0} << indices;
    QTest::newRow("index out of range") << "dof_indices" << QList<int>{0, 12} << indices;
    QTest::newRow("index repeated") << "dof_indices" << QList<int>{0, 0} << indices;
    QTest::newRow("index negative") << "dof_indices" << QList<int>{-1, 11} << indices;
    QTest::newRow("every 0") << "every" << QList<int>{0}
                             << "damaged record (/dofs every or dof_indices)";
    QTest::newRow("every negative") << "every" << QList<int>{-10}
                                    << "damaged record (/dofs every or dof_indices)";
    // Valid choices that are not the record's: its columns or its metadata checksum disagree.
    const QString checksum = QStringLiteral("damaged record (the metadata checksum does not "
                                            "match: attributes or names were altered)");
    QTest::newRow("other valid indices") << "dof_indices" << QList<int>{0, 5} << checksum;
    QTest::newRow("three indices for two columns")
        << "dof_indices" << QList<int>{0, 5, 11}
        << "damaged record (/dofs/u has an unexpected shape)";
    QTest::newRow("every 5 for every 10") << "every" << QList<int>{5} << checksum;
}

/// A record whose choice attributes were damaged after it was written is refused with the
/// reason, never read with the wrong columns or steps (the chosen record of 12 DOFs keeps
/// DOFs 0 and 11 every 10 steps).
void TestRecordDofChoice::damagedChoiceIsRefused() {
    QFETCH(QString, attribute);
    QFETCH(QList<int>, values);
    QFETCH(QString, message);
    QTemporaryDir dir;
    const std::string full = dir.filePath("full.h5").toStdString();
    const std::string chosen = dir.filePath("chosen.h5").toStdString();
    recordTwelveStoreys(full, chosen);
    QVERIFY(RecordReader(chosen).data().meta.dofRecording.every == 10); // readable as written
    const std::vector<int> v(values.begin(), values.end());
    QVERIFY(rewriteDofsAttr(chosen, attribute.toUtf8().constData(), v, attribute == "every"));
    try {
        const RecordReader damaged(chosen);
        QFAIL("a damaged choice was read");
    } catch (const RecordError& e) {
        const QString what = QString::fromUtf8(e.what());
        qInfo("%s", e.what());
        QCOMPARE(what, QString::fromStdString(chosen) + ": " + message);
    }
}

QTEST_APPLESS_MAIN(TestRecordDofChoice)
#include "TestRecordDofChoice.moc"
