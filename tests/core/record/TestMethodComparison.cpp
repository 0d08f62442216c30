// `hsmu replay --method all` in core (MethodComparison.h): the calibration, the UKF and
// Nelder-Mead on the same history. Each row's NRMSE must equal the single-method run's
// (identifyOffline with that method, as `hsmu replay --method M` runs it), bit for bit; on a
// synthetic Bouc-Wen specimen (known parameters, no noise) the calibration recovers it and is
// recommended or within 5 % of the best; on the Gill 1979 column (../shared/data; QSKIP where
// absent) the rows match the single runs too. The files: comparison.csv reads back the rows.

#include "core/hysteresis/LawFactory.h"
#include "core/offline/MethodComparison.h"
#include "core/offline/OfflineIdentification.h"

#include <QtTest>

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

using namespace hsmu;

namespace {

/// A Bouc-Wen spring (m, kN) with known parameters under a sine growing to 4 uRef over 10 s.
SpecimenHistory synthetic() {
    const std::map<std::string, double> truth{
        {"k0", 1.0},        {"alpha", 0.03}, {"n", 2.0},      {"beta", 2.5},
        {"gamma", 0.5},     {"A0", 1.0},     {"deltaA", 0.0}, {"deltaNu", 0.03},
        {"deltaEta", 0.03}, {"uRef", 0.02},  {"fRef", 20.0}};
    auto law = makeLaw("boucWen", truth);
    SpecimenHistory h;
    for (int k = 1; k <= 1000; ++k) {
        const double t = 0.01 * k;
        const double u = 4.0 * 0.02 * (t / 10.0) * std::sin(2.0 * std::numbers::pi * t);
        if (law->setTrialDeformation(u) != LawStatus::Ok)
            throw std::runtime_error("the synthetic law failed");
        law->commit();
        h.time.push_back(t);
        h.deformation.push_back(u);
        h.force.push_back(law->committedForce());
    }
    h.source = "synthetic Bouc-Wen specimen";
    h.deformationUnits = std::string("m");
    h.forceUnits = std::string("kN");
    return h;
}

/// The shared record's plain text: '#' lines, then index, deformation, force.
bool readGill(SpecimenHistory& h) {
    std::ifstream in(std::string(HSMU_SHARED_DATA_DIR) +
                     "/rc-column-gill1979/rc_column_force_disp.txt");
    if (!in)
        return false;
    std::string line;
    double t = 0.0;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#')
            continue;
        std::istringstream s(line);
        double a, u, f;
        if (!(s >> a >> u >> f))
            return false;
        h.time.push_back(t);
        t += 0.01;
        h.deformation.push_back(u);
        h.force.push_back(f);
    }
    h.source = "Gill 1979";
    return h.size() > 0;
}

/// The single-method run of `method` as `hsmu replay --method` runs it.
double singleRun(const SpecimenHistory& h, const IdentificationSettings& base,
                 const std::string& method) {
    IdentificationSettings s = method == "calibration" ? base : withMethod(base, method);
    s.online = method != "calibration";
    return identifyOffline(h, s).finalNrmse;
}

void checkRowsEqualSingleRuns(const SpecimenHistory& h, const IdentificationSettings& s,
                              const MethodComparison& c) {
    QCOMPARE(c.rows.size(), std::size_t(3));
    QCOMPARE(c.rows[0].method, std::string("calibration"));
    QCOMPARE(c.rows[1].method, std::string("ukf"));
    QCOMPARE(c.rows[2].method, std::string("nelder-mead"));
    for (const auto& row : c.rows) {
        QVERIFY2(row.ok, row.verdict.c_str());
        const double single = singleRun(h, s, row.method);
        qInfo("%s: %s NRMSE %.6f (single run %.6f), %.2f s CPU, %d on bounds, %d rejected: %s",
              h.source.c_str(), row.method.c_str(), row.nrmse, single, row.cpuSeconds,
              int(row.onBounds.size()), row.rejected, row.verdict.c_str());
        QCOMPARE(row.nrmse, single);
        QVERIFY(row.cpuSeconds >= 0.0);
    }
    QVERIFY(!c.recommended.empty());
}

} // namespace

class TestMethodComparison : public QObject {
    Q_OBJECT

private slots:
    void syntheticSpecimen() {
        const SpecimenHistory h = synthetic();
        IdentificationSettings s = defaultIdentificationSettings();
        s.dt = h.meanStep();
        const MethodComparison c = compareMethods(h, s);
        checkRowsEqualSingleRuns(h, s, c);
        // The answer is known: the law generated the data, so its calibration recovers it.
        QVERIFY2(c.rows[0].nrmse < 1e-3, QByteArray::number(c.rows[0].nrmse));
        double best = 1e300;
        for (const auto& row : c.rows)
            best = std::min(best, row.nrmse);
        int recommended = 0;
        for (const auto& row : c.rows) {
            if (row.verdict.rfind("recommended", 0) == 0) {
                ++recommended;
                QCOMPARE(row.method, c.recommended);
                QVERIFY(row.nrmse <= std::max(1.05 * best, best + 5e-3));
            } else if (row.nrmse > std::max(1.05 * best, best + 5e-3)) {
                QVERIFY2(row.verdict.find("x the best") != std::string::npos, row.verdict.c_str());
            }
        }
        QCOMPARE(recommended, 1);
        QVERIFY(c.lawVerdict.empty());
        // The files: comparison.csv's rows read back the table (numbers round-trip exactly).
        const std::filesystem::path dir =
            std::filesystem::temp_directory_path() / "hsmu-test-method-comparison";
        std::filesystem::remove_all(dir);
        std::filesystem::create_directories(dir);
        const std::vector<std::string> written = writeMethodComparison(dir.string(), h, c);
        QVERIFY(written.size() >= 2 + 3 * 2);
        std::ifstream csv(dir / "comparison.csv");
        std::string line;
        QVERIFY(std::getline(csv, line));
        QCOMPARE(line, std::string("method,nrmse [-],cpu [s],on_bounds,rejected [-],verdict"));
        for (const auto& row : c.rows) {
            QVERIFY(std::getline(csv, line));
            std::istringstream fields(line);
            std::string method, nrmse;
            std::getline(fields, method, ',');
            std::getline(fields, nrmse, ',');
            QCOMPARE(method, row.method);
            QCOMPARE(std::stod(nrmse), row.nrmse);
        }
        std::ifstream summary(dir / "summary.json");
        const nlohmann::json j = nlohmann::json::parse(summary);
        QCOMPARE(j.at("method").get<std::string>(), std::string("all"));
        QCOMPARE(j.at("comparison").size(), std::size_t(3));
        QCOMPARE(j.at("recommended").get<std::string>(), c.recommended);
        for (const char* m : {"calibration", "ukf", "nelder-mead"})
            QVERIFY(std::filesystem::exists(dir / m / "summary.json"));
        std::filesystem::remove_all(dir);
    }

    /// A model a method cannot use: its row says why, the others run.
    void aMethodThatCannotRunIsAFailedRow() {
        const SpecimenHistory h = synthetic();
        IdentificationSettings s = withOverride(
            defaultIdentificationSettings(),
            nlohmann::json{
                {"model", {{"law", "bilinear"}, {"k0", 1000.0}, {"fy", 10.0}, {"b", 0.05}}},
                {"updating", {{"method", "nelderMead"}}}},
            "test");
        s.dt = h.meanStep();
        const MethodComparison c = compareMethods(h, s);
        QVERIFY(c.rows[0].ok);
        QVERIFY(!c.rows[1].ok);
        QVERIFY2(c.rows[1].verdict.rfind("failed: ", 0) == 0, c.rows[1].verdict.c_str());
        QVERIFY(c.rows[2].ok);
        QVERIFY(c.recommended == "calibration" || c.recommended == "nelder-mead");
    }

    void gillColumn() {
        SpecimenHistory h;
        if (!readGill(h))
            QSKIP("shared record absent (a fresh machine has no ../shared/data)");
        const IdentificationSettings s = defaultIdentificationSettings();
        const MethodComparison c = compareMethods(h, s);
        checkRowsEqualSingleRuns(h, s, c);
        // docs/validation.md: calibration 0.1381, robust UKF 0.1453, Nelder-Mead 0.1381
        QVERIFY(std::abs(c.rows[0].nrmse - 0.1381) < 5e-4);
    }
};

QTEST_APPLESS_MAIN(TestMethodComparison)
#include "TestMethodComparison.moc"
