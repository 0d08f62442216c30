// MeasuredDataCsv: the importer of measured specimen data (time, deformation, force with
// declared units). Conversions are checked against hand-computed values; every malformed
// file gives the exact message naming the line and what is wrong.

#include "core/offline/MeasuredDataCsv.h"

#include <QtTest>

#include <algorithm>
#include <filesystem>
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
    void labUnits();
    void extraColumnsNeedNamesOrColumnsOption();
    void commentHeaderAndSampleIndex();
    void loadInG();
    void sharedRecords_data();
    void sharedRecords();
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
    add("unknown unit", "time [s], deformation [yd], force [kN]\n0, 1, 2\n",
        "d.csv: line 1: unknown deformation unit 'yd' (expected m, cm, mm, in, ft, rad, mrad, "
        "deg)");
    add("unknown force unit", "time [s], deformation [in], force [lb]\n0, 1, 2\n",
        "d.csv: line 1: unknown force unit 'lb' (expected N, kN, MN, lbf, kip, kgf, tonf, g "
        "(the load in units of the specimen's weight), or a moment: a force unit times a "
        "length unit, e.g. kN m, N mm, kip in, lbf ft, tonf m)");
    add("unknown time unit", "time [min], deformation [in], force [kip]\n0, 1, 2\n",
        "d.csv: line 1: unknown time unit 'min' (expected s, ms, or step for a sample index)");
    add("rotation with a force", "time [s], deformation [rad], force [kN]\n0, 1, 2\n",
        "d.csv: line 1: deformation in rad needs a moment unit (a force unit times a length "
        "unit, e.g. kN m, N mm, kip in, lbf ft, tonf m), found 'kN'");
    add("length with a moment", "time [s], deformation [mm], force [kNm]\n0, 1, 2\n",
        "d.csv: line 1: deformation in mm needs a force unit (N, kN, MN, lbf, kip, kgf, tonf, "
        "g), found the moment unit 'kNm'");
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

void TestMeasuredDataCsv::labUnits() {
    // US and metric-technical units against hand-computed values (1 in = 0.0254 m, 1 kip =
    // 4.4482216152605 kN, 1 tonf = 9.80665 kN, 1 deg = pi / 180 rad).
    const SpecimenHistory us = read("time [s], displacement [in], force [kip]\n0, 2, 10\n");
    QCOMPARE(us.deformation[0], 0.0508);
    QCOMPARE(us.force[0], 44.482216152605);
    const SpecimenHistory rot = read("t (ms); rotation (deg); moment (kip in)\n5; 1.5; 100\n");
    QCOMPARE(rot.time[0], 0.005);
    QVERIFY(std::abs(rot.deformation[0] - 1.5 * M_PI / 180.0) <= 1e-17);
    QVERIFY(std::abs(rot.force[0] - 100.0 * 4.4482216152605 * 0.0254) <= 1e-13);
    QCOMPARE(rot.forceUnits, std::string("kN m"));
    const SpecimenHistory tonf =
        read("0 1.0 2.0\n", MeasuredDataUnits{"s", "cm", "tonf"});
    QCOMPARE(tonf.deformation[0], 0.01);
    QCOMPARE(tonf.force[0], 2.0 * 9.80665);
}

void TestMeasuredDataCsv::extraColumnsNeedNamesOrColumnsOption() {
    // No header: exactly time, deformation, force.
    QCOMPARE(QString::fromStdString(error("0 1 2 3\n", MeasuredDataUnits{"s", "mm", "N"})),
             QStringLiteral("d.csv: line 1: expected 3 values (time, deformation, force), "
                            "found 4 (pick the time, deformation and force columns with "
                            "--columns T,D,F or name them in a header)"));
    // A header naming the three: other columns are ignored.
    const SpecimenHistory named =
        read("time_s displacement_mm force_N velocity_mm_s raw_force_N\n0 1 2 3 4\n0.1 2 3 4 5\n");
    QCOMPARE(named.size(), 2);
    QCOMPARE(named.deformation[1], 2e-3);
    QCOMPARE(named.force[1], 3e-3);
    // --columns picks by position; the header's names then only give the units.
    MeasuredDataOptions o;
    o.columns = parseMeasuredDataColumns("1, 5, 3");
    std::istringstream in("time_s displacement_mm force_N velocity_mm_s raw_dist_mm\n0 1 2 3 4\n");
    const SpecimenHistory picked = readMeasuredDataCsv(in, "d.csv", o);
    QCOMPARE(picked.deformation[0], 4e-3);
    QCOMPARE(picked.force[0], 2e-3);
    // --columns without a header: units from --units; rows may have more values.
    o.columns = parseMeasuredDataColumns("2,4,3");
    o.units = MeasuredDataUnits{"s", "m", "kN"};
    std::istringstream bare("9 0.5 7 8 9\n9 1.5 7 8 9\n");
    const SpecimenHistory b = readMeasuredDataCsv(bare, "d.csv", o);
    QCOMPARE(b.time[1], 1.5);
    QCOMPARE(b.deformation[0], 8.0);
    QCOMPARE(b.force[0], 7.0);
    for (const char* bad : {"1,2", "0,1,2", "1,1,2", "a,b,c"}) {
        try {
            parseMeasuredDataColumns(bad);
            QFAIL(bad);
        } catch (const MeasuredDataError& e) {
            QVERIFY(std::string(e.what()).find("--columns: expected three different column "
                                               "numbers") == 0);
        }
    }
    o.columns = parseMeasuredDataColumns("1,2,7");
    std::istringstream shortRow("0 1 2\n");
    try {
        readMeasuredDataCsv(shortRow, "d.csv", o);
        QFAIL("no error");
    } catch (const MeasuredDataError& e) {
        QCOMPARE(std::string(e.what()),
                 std::string("d.csv: line 1: no column 7 (force): the row has 3 values"));
    }
}

void TestMeasuredDataCsv::commentHeaderAndSampleIndex() {
    // "# columns:" names them; words past the row's values are commentary; a sample index
    // ("k", "step") is the time in s.
    const SpecimenHistory h = read("# a record\n"
                                   "# columns: k  displacement_cm  force_tonf  (see notes)\n"
                                   "0 0.0 0.0\n1 -2.5 1.0\n");
    QCOMPARE(h.time[1], 1.0);
    QCOMPARE(h.deformation[1], -0.025);
    QCOMPARE(h.force[1], 9.80665);
    QCOMPARE(QString::fromStdString(error("# columns: step displacement_mm force_kN\n0 1 2\n0 1 2\n")),
             QStringLiteral("d.csv: line 3: time 0 s does not increase (previous 0 s)"));
    // A sample index and a time: the time is used.
    const SpecimenHistory both = read("step, time [ms], force [kN], deformation [mm]\n"
                                      "0, 5, 1, 2\n1, 15, 1, 2\n");
    QCOMPARE(both.time[1], 0.015);
    // An index with --units "step".
    const SpecimenHistory s = read("3 1 2\n4 1 2\n", MeasuredDataUnits{"step", "mm", "kN"});
    QCOMPARE(s.time[0], 3.0);
}

void TestMeasuredDataCsv::loadInG() {
    // g: the load in units of the specimen's weight, kept as written and labelled W.
    const SpecimenHistory h = read("# columns: k displacement_m lateral_load_g\n0 0.001 0.25\n");
    QCOMPARE(h.force[0], 0.25);
    QCOMPARE(h.forceUnits, std::string("W"));
    QCOMPARE(h.deformationUnits, std::string("m"));
}

void TestMeasuredDataCsv::sharedRecords_data() {
    // Each shared record as it is, with only its own units (from its "# columns:" line), against
    // its README's sanity ranges converted here: rows, deformation [m], force [kN or W].
    QTest::addColumn<QString>("file");
    QTest::addColumn<int>("rows");
    QTest::addColumn<double>("dMin");
    QTest::addColumn<double>("dMax");
    QTest::addColumn<double>("fMin");
    QTest::addColumn<double>("fMax");
    QTest::addColumn<double>("dTol"); // the README's rounding
    QTest::addColumn<double>("fTol");
    QTest::addColumn<QString>("forceUnits");
    const double tonf = 9.80665;
    QTest::newRow("HDRB (cm, tonf)") << "hysteresis/isolator-hdrb-gallardo2023/hdrb_test.txt"
                                     << 26372 << -0.230222 << 0.230174 << -39.8345 * tonf
                                     << 37.2695 * tonf << 0.5e-6 << 0.5e-4 * tonf << "kN";
    QTest::newRow("CLT SPC1 (mm, kN)")
        << "hysteresis/clt-steel-plate-connection-tannert-spc1/spc1.txt" << 33028 << -0.08458
        << 0.08453 << -52.46 << 51.41 << 0.5e-5 << 0.5e-2 << "kN";
    QTest::newRow("MR damper 0 V (s, mm, N)")
        << "hysteresis/mr-damper-labcontrol-utfpr/mr_damper_4p1_0V.txt" << 3001 << -0.0131225
        << 0.0120925 << -0.132433 << 0.140289 << 0.5e-7 << 0.5e-6 << "kN";
    QTest::newRow("MR damper 0.88 V (s, mm, N)")
        << "hysteresis/mr-damper-labcontrol-utfpr/mr_damper_4p2_0p88V.txt" << 1501
        << -0.0200925 << 0.0200925 << -0.321601 << 0.321601 << 0.5e-7 << 0.5e-6 << "kN";
    QTest::newRow("Soesianawati (m, kN)")
        << "hysteresis/rc-column-soesianawati-unit1/soesianawati_unit1.txt" << 548 << -0.078242
        << 0.078448 << -186.22 << 199.59 << 0.5e-6 << 0.5e-2 << "kN";
    QTest::newRow("Gill (m, g)") << "rc-column-gill1979/rc_column_force_disp.txt" << 481
                                 << -0.030656 << 0.030654 << -0.41036 << 0.42353 << 0.5e-6
                                 << 0.5e-5 << "W";
}

void TestMeasuredDataCsv::sharedRecords() {
    QFETCH(QString, file);
    QFETCH(int, rows);
    QFETCH(double, dMin);
    QFETCH(double, dMax);
    QFETCH(double, fMin);
    QFETCH(double, fMax);
    QFETCH(double, dTol);
    QFETCH(double, fTol);
    QFETCH(QString, forceUnits);
    const std::string path = std::string(HSMU_SHARED_DATA_DIR) + "/" + file.toStdString();
    if (!std::filesystem::exists(path))
        QSKIP(qPrintable("shared record absent: " + QString::fromStdString(path)));
    const SpecimenHistory h = readMeasuredDataCsv(path);
    QCOMPARE(h.size(), rows);
    QCOMPARE(h.problem(), std::string());
    const auto [d0, d1] = std::minmax_element(h.deformation.begin(), h.deformation.end());
    const auto [f0, f1] = std::minmax_element(h.force.begin(), h.force.end());
    const auto near = [](double a, double b, double tol) { return std::abs(a - b) <= tol; };
    QVERIFY2(near(*d0, dMin, dTol) && near(*d1, dMax, dTol),
             qPrintable(QStringLiteral("%1 .. %2").arg(*d0, 0, 'g', 10).arg(*d1, 0, 'g', 10)));
    QVERIFY2(near(*f0, fMin, fTol) && near(*f1, fMax, fTol),
             qPrintable(QStringLiteral("%1 .. %2").arg(*f0, 0, 'g', 10).arg(*f1, 0, 'g', 10)));
    QCOMPARE(QString::fromStdString(h.deformationUnits), QStringLiteral("m"));
    QCOMPARE(QString::fromStdString(h.forceUnits), forceUnits);
}

QTEST_APPLESS_MAIN(TestMeasuredDataCsv)
#include "TestMeasuredDataCsv.moc"
