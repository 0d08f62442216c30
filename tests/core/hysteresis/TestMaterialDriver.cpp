// Tests of the material driver (core/hysteresis/MaterialDriver.h): history files in the
// accepted layouts, errors that name the file and line or point, exact elastic forces and
// an exactly round-tripping CSV writer. Files live in a QTemporaryDir.

#include "core/hysteresis/MaterialDriver.h"

#include "core/hysteresis/LinearElastic.h"
#include "core/hysteresis/MrDamper.h"

#include <cmath>
#include <QTemporaryDir>
#include <QtTest>

#include <fstream>
#include <sstream>
#include <stdexcept>

using namespace hsmu;

namespace {

// A law that fails from its third trial on, to exercise the driver's error path.
class FailingLaw final : public HysteresisLaw {
public:
    std::string lawName() const override { return "failing"; }
    LawStatus setTrialDeformation(double u) override {
        m_u = u;
        return ++m_trials >= 3 ? LawStatus::NoConvergence : LawStatus::Ok;
    }
    double trialDeformation() const override { return m_u; }
    double trialForce() const override { return m_u; }
    double trialTangent() const override { return 1.0; }
    double committedDeformation() const override { return m_u; }
    double committedForce() const override { return m_u; }
    double initialTangent() const override { return 1.0; }
    void commit() override {}
    void revert() override {}
    void revertToStart() override {}
    std::unique_ptr<HysteresisLaw> clone() const override {
        return std::make_unique<FailingLaw>(*this);
    }
    std::vector<std::string> parameterNames() const override { return {}; }
    double parameterValue(int) const override { return std::nan(""); }
    int setParameterValues(std::span<const int> indices, std::span<const double>,
                           bool) override {
        return indices.empty() ? -1 : 0;
    }

private:
    double m_u = 0.0;
    int m_trials = 0;
};

std::string writeFile(const QTemporaryDir& dir, const char* name, const std::string& text) {
    const std::string path = dir.filePath(QString::fromLatin1(name)).toStdString();
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

// The runtime_error message of reading `text` from a file, or "" if it was accepted.
std::string readError(const QTemporaryDir& dir, const std::string& text) {
    const std::string path = writeFile(dir, "bad.txt", text);
    try {
        readDeformationHistory(path);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return {};
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

} // namespace

class TestMaterialDriver : public QObject {
    Q_OBJECT

private slots:
    void readsOneColumn();
    void readsTwoColumnsWithHeader();
    void rejectsMalformedContent();
    void drivesElasticLawExactly();
    void reportsTheFailingPoint();
    void writesExactCsv();
    void drivesARateDependentLawWithItsTimes();
};

void TestMaterialDriver::readsOneColumn() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const auto path = writeFile(dir, "one.txt", "# rotation [rad]\n0\n0.5\n  -1.25e-3 \n\n+1\n");
    QVERIFY(readDeformationHistory(path) == (std::vector<double>{0.0, 0.5, -1.25e-3, 1.0}));
}

void TestMaterialDriver::readsTwoColumnsWithHeader() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    // Comma separated with blanks around fields, a header, CRLF endings and a UTF-8 BOM.
    const auto csv = writeFile(dir, "two.csv",
                               "\xEF\xBB\xBFtime,deformation\r\n0,0\r\n0.1, 0.002\r\n"
                               "# a comment\r\n0.2 ,\t-0.003\r\n");
    QVERIFY(readDeformationHistory(csv) == (std::vector<double>{0.0, 0.002, -0.003}));
    // Blank (space / tab) separated, two header lines.
    const auto tsv =
        writeFile(dir, "two.tsv", "Deformation history\nt\tu\n0\t0\n0.01   0.25\n0.02\t-0.5\n");
    QVERIFY(readDeformationHistory(tsv) == (std::vector<double>{0.0, 0.25, -0.5}));
    std::istringstream stream("1e-3\n2e-3\n");
    QVERIFY(parseDeformationHistory(stream, "stdin") == (std::vector<double>{1e-3, 2e-3}));
}

void TestMaterialDriver::rejectsMalformedContent() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const std::string word = readError(dir, "u\n0\n0.1\nabc\n");
    QVERIFY2(contains(word, "bad.txt") && contains(word, "line 4") && contains(word, "'abc'"),
             word.c_str());
    QVERIFY(contains(readError(dir, "0,1\n0.1,2\n0.2\n"), "line 3")); // column count
    QVERIFY(contains(readError(dir, "0,1,2\n"), "line 1"));           // three columns
    QVERIFY(contains(readError(dir, "0\n1x\n"), "line 2"));           // trailing garbage
    QVERIFY(contains(readError(dir, "0,1\n0.1,\n"), "line 2"));       // empty field
    QVERIFY(contains(readError(dir, "0\n1\nnan\n"), "line 3"));       // not finite
    QVERIFY(contains(readError(dir, "time,u\n# nothing\n"), "no deformation data"));
    try {
        readDeformationHistory(dir.filePath("missing.txt").toStdString());
        QFAIL("a missing file was accepted");
    } catch (const std::runtime_error& e) {
        QVERIFY(contains(e.what(), "missing.txt"));
    }
}

void TestMaterialDriver::drivesElasticLawExactly() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const auto path = writeFile(dir, "h.csv", "time,u\n0,0\n1,0.75\n2,-1.5\n3,1e-7\n");
    LinearElastic law(2.5);
    const auto samples = driveLaw(law, readDeformationHistory(path));
    QCOMPARE(samples.size(), std::size_t(4));
    for (const MaterialSample& s : samples) {
        QVERIFY(s.force == 2.5 * s.deformation); // exact: one multiplication
        QVERIFY(s.tangent == 2.5);
    }
    QVERIFY(law.committedDeformation() == 1e-7); // every point was committed
}

void TestMaterialDriver::reportsTheFailingPoint() {
    FailingLaw law;
    try {
        driveLaw(law, {0.0, 0.1, 0.2, 0.3});
        QFAIL("a failing law was not reported");
    } catch (const std::runtime_error& e) {
        QVERIFY2(contains(e.what(), "point 2") && contains(e.what(), "no convergence") &&
                     contains(e.what(), "failing"),
                 e.what());
    }
}

void TestMaterialDriver::writesExactCsv() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const std::vector<MaterialSample> samples{
        {0.1, 1.0 / 3.0, 2.0}, {-1e-300, 6.02214076e23, 0.0}, {1.0 + 1e-15, -0.0, 5e-324}};
    const std::string path = dir.filePath("out.csv").toStdString();
    writeMaterialCsv(path, samples);
    std::ifstream in(path);
    std::string line;
    QVERIFY(std::getline(in, line));
    QCOMPARE(line, std::string("deformation,force,tangent"));
    for (const MaterialSample& s : samples) {
        QVERIFY(std::getline(in, line));
        double d = 0, f = 0, k = 0;
        char c1 = 0, c2 = 0;
        std::istringstream fields(line);
        QVERIFY(fields >> d >> c1 >> f >> c2 >> k);
        QVERIFY(c1 == ',' && c2 == ',');
        QVERIFY2(d == s.deformation && f == s.force && k == s.tangent, line.c_str());
    }
    QVERIFY(!std::getline(in, line));
    std::ostringstream text;
    writeMaterialCsv(text, {{0.1, 0.2, 0.3}});
    QCOMPARE(text.str(), std::string("deformation,force,tangent\n0.10000000000000001,"
                                     "0.20000000000000001,0.29999999999999999\n"));
}

void TestMaterialDriver::drivesARateDependentLawWithItsTimes() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const std::string timed =
        writeFile(dir, "timed.csv", "time [s], deformation [m]\n0, 0.001\n0.01, 0.002\n0.03, 0.004\n");
    const TimedHistory h = readTimedHistory(timed);
    QVERIFY((h.time == std::vector<double>{0.0, 0.01, 0.03}));
    QVERIFY((h.deformation == std::vector<double>{0.001, 0.002, 0.004}));
    QVERIFY(readTimedHistory(writeFile(dir, "one.csv", "0.1\n0.2\n")).time.empty());
    // mrDamper with the hysteresis off: force = c0 c1 / (c0 + c1) v + k1 u, the velocity from
    // the times; the first point reached quasi-statically.
    MrDamperParameters p;
    p.alpha = 0.0;
    p.c0 = 3.0;
    p.c1 = 6.0;
    p.k1 = 10.0;
    MrDamper law(p);
    const std::vector<MaterialSample> out = driveLaw(law, h.deformation, h.time);
    QCOMPARE(out.size(), std::size_t(3));
    QVERIFY(std::abs(out[0].force - 10.0 * 0.001) < 1e-15);
    QVERIFY(std::abs(out[1].force - (2.0 * 0.001 / 0.01 + 10.0 * 0.002)) < 1e-12);
    QVERIFY(std::abs(out[2].force - (2.0 * 0.002 / 0.02 + 10.0 * 0.004)) < 1e-12);
    QVERIFY(std::abs(out[2].tangent - (2.0 / 0.02 + 10.0)) < 1e-12);
    // No times, or times that do not increase: refused, naming the law or the point.
    MrDamper again(p);
    try {
        driveLaw(again, h.deformation);
        QFAIL("a rate-dependent law was driven without times");
    } catch (const std::runtime_error& e) {
        QVERIFY(std::string(e.what()).find("mrDamper is rate-dependent") != std::string::npos);
    }
    try {
        driveLaw(again, h.deformation, {0.0, 0.01, 0.01});
        QFAIL("a repeated time was accepted");
    } catch (const std::runtime_error& e) {
        QVERIFY(std::string(e.what()).find("at point 2") != std::string::npos);
    }
    // A rate-independent law ignores the times.
    LinearElastic elastic(2.0);
    QCOMPARE(driveLaw(elastic, h.deformation, h.time)[2].force, 0.008);
}

QTEST_APPLESS_MAIN(TestMaterialDriver)
#include "TestMaterialDriver.moc"
