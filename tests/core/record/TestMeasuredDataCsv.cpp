// MeasuredDataCsv: the importer of measured specimen data (time, deformation, force with
// declared units). Conversions are checked against hand-computed values; every malformed
// file gives the exact message naming the line and what is wrong.

#include "core/identification/MeasuredDataCsv.h"

#include <QtTest>

#include <sstream>

using namespace hsmu;

namespace {

SpecimenHistory read(const std::string& text,
                     const std::optional<MeasuredDataUnits>& units = std::nullopt) {
    std::istringstream in(text);
    return readMeasuredDataCsv(in, "d.csv", units);
}

std::string error(const std::string& text,
                  const std::optional<MeasuredDataUnits>& units = std::nullopt) {
    try {
        read(text, units);
    } catch (const MeasuredDataError& e) {
        return e.what();
    }
    return "no error";
}

} // namespace

class TestMeasuredDataCsv : public QObject {
    Q_OBJECT
private slots:
    void headerUnitsConvert();
    void columnsInAnyOrderAndMoments();
    void explicitUnitsReplaceTheHeaders();
    void malformedFilesNameLineAndProblem_data();
    void malformedFilesNameLineAndProblem();
    void unitsOption();
};

void TestMeasuredDataCsv::headerUnitsConvert() {
    const SpecimenHistory h = read("\xEF\xBB\xBF# a comment\n"
                                   "time [ms], deformation [mm], force [N]\n"
                                   "\n"
                                   "10, 1.5, -250\n"
                                   "20, -2e1, 1000.5\n");
    QCOMPARE(h.size(), 2);
    QCOMPARE(h.time[0], 0.01);
    QCOMPARE(h.time[1], 0.02);
    QCOMPARE(h.deformation[0], 1.5e-3);
    QCOMPARE(h.deformation[1], -0.02);
    QCOMPARE(h.force[0], -0.25);
    QCOMPARE(h.force[1], 1.0005);
    QCOMPARE(h.deformationUnits, std::string("m"));
    QCOMPARE(h.forceUnits, std::string("kN"));
    QCOMPARE(h.meanStep(), 0.01);
    QCOMPARE(h.problem(), std::string());
}

void TestMeasuredDataCsv::columnsInAnyOrderAndMoments() {
    const SpecimenHistory h = read("Moment (kN m); t (s); Rotation (mrad)\n"
                                   "12.5; 0.5; 3\n"
                                   "-1; 1.0; -4\n");
    QCOMPARE(h.time[0], 0.5);
    QCOMPARE(h.deformation[0], 3e-3);
    QCOMPARE(h.force[0], 12.5);
    QCOMPARE(h.force[1], -1.0);
    QCOMPARE(h.deformationUnits, std::string("rad"));
    QCOMPARE(h.forceUnits, std::string("kN m"));
    const SpecimenHistory nmm = read("time [s]\tdeformation [rad]\tforce [N*mm]\n0\t0.01\t2e6\n");
    QCOMPARE(nmm.force[0], 2.0); // 2e6 N mm = 2 kN m
}

void TestMeasuredDataCsv::explicitUnitsReplaceTheHeaders() {
    const MeasuredDataUnits units{"s", "m", "kN"};
    const SpecimenHistory h = read("time [ms], deformation [mm], force [N]\n1, 2, 3\n", units);
    QCOMPARE(h.time[0], 1.0);
    QCOMPARE(h.deformation[0], 2.0);
    QCOMPARE(h.force[0], 3.0);
    // No header: columns time, deformation, force; whitespace separated.
    const SpecimenHistory bare = read("0.1 5 7\n0.2 6 8\n", MeasuredDataUnits{"s", "mm", "kN"});
    QCOMPARE(bare.deformation[1], 6e-3);
    QCOMPARE(bare.force[1], 8.0);
}

void TestMeasuredDataCsv::malformedFilesNameLineAndProblem_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("message");
    const std::string h = "time [s], deformation [mm], force [kN]\n";
    const auto add = [](const char* name, const std::string& text, const std::string& message) {
        QTest::newRow(name) << QString::fromStdString(text) << QString::fromStdString(message);
    };
    add("too few values", h + "0, 1, 2\n\n0.1, 2\n",
        "d.csv: line 4: expected 3 values (time, deformation, force), found 2");
    add("not a number", h + "0, abc, 2\n",
        "d.csv: line 2: column 2 (deformation): 'abc' is not a number");
    add("time goes back", h + "0.2, 1, 2\n0.1, 1, 2\n",
        "d.csv: line 3: time 0.1 s does not increase (previous 0.2 s)");
    add("unknown unit", "time [s], deformation [in], force [kN]\n0, 1, 2\n",
        "d.csv: line 1: unknown deformation unit 'in' (expected m, mm, cm, rad, mrad)");
    add("rotation with a force", "time [s], deformation [rad], force [kN]\n0, 1, 2\n",
        "d.csv: line 1: deformation in rad needs a moment unit (kNm, Nm, kNmm, Nmm), "
        "found 'kN'");
    add("length with a moment", "time [s], deformation [mm], force [kNm]\n0, 1, 2\n",
        "d.csv: line 1: deformation in mm needs a force unit (kN, N, MN), found the moment "
        "unit 'kNm'");
    add("no unit", "time [s], deformation, force [kN]\n0, 1, 2\n",
        "d.csv: line 1: no unit for the deformation (write e.g. 'time [s], deformation "
        "[mm], force [kN]' in the header, or give the units explicitly: --units s,mm,kN)");
    add("no header, no units", "0, 1, 2\n",
        "d.csv: line 1: no unit for the time (write e.g. 'time [s], deformation [mm], "
        "force [kN]' in the header, or give the units explicitly: --units s,mm,kN)");
    add("unknown column", "time [s], stroke [mm], force [kN]\n",
        "d.csv: line 1: column 2: unknown column 'stroke' (expected time, deformation or "
        "force)");
    add("column twice", "time [s], force [kN], moment [kNm]\n",
        "d.csv: line 1: column 3: 'moment' names the force a second time");
    add("no rows", h + "# nothing\n",
        "d.csv: no data rows (expected lines of time, deformation, force)");
    add("infinite", h + "0, inf, 1\n",
        "d.csv: line 2: column 2 (deformation): the value is not finite");
}

void TestMeasuredDataCsv::malformedFilesNameLineAndProblem() {
    QFETCH(QString, text);
    QFETCH(QString, message);
    QCOMPARE(QString::fromStdString(error(text.toStdString())), message);
}

void TestMeasuredDataCsv::unitsOption() {
    const MeasuredDataUnits u = parseMeasuredDataUnits("ms, mm ,N");
    QCOMPARE(u.time, std::string("ms"));
    QCOMPARE(u.deformation, std::string("mm"));
    QCOMPARE(u.force, std::string("N"));
    try {
        parseMeasuredDataUnits("s,mm");
        QFAIL("no error");
    } catch (const MeasuredDataError& e) {
        QCOMPARE(std::string(e.what()), std::string("--units: expected three units "
                                                    "TIME,DEFORMATION,FORCE, e.g. s,mm,kN; "
                                                    "found 's,mm'"));
    }
    try {
        readMeasuredDataCsv("/nonexistent/d.csv");
        QFAIL("no error");
    } catch (const MeasuredDataError& e) {
        QCOMPARE(std::string(e.what()),
                 std::string("/nonexistent/d.csv: cannot be opened (no such file or no "
                             "permission)"));
    }
}

QTEST_APPLESS_MAIN(TestMeasuredDataCsv)
#include "TestMeasuredDataCsv.moc"
