// Identification on specimens measured by other labs (../shared/data; QSKIP where absent):
// the offline calibration (CalibrationDefaults.h) with no user scales, bounds or starts must
// reach within 5 % of an independent multi-start least-squares fit of the same law (OpenSees'
// BoucWen, 7 parameters; figures in docs/validation.md), and the default online identifier
// (the robust UKF, replayed sample by sample as online) must end within 25 % of the
// calibration's NRMSE, without a divergence and with no parameter on a bound that the
// calibration does not also put there.
// One CTest test per record: the executable takes a data tag (e.g. `calibrates:gill`).

#include "core/identification/CalibrationDefaults.h"
#include "core/offline/OfflineIdentification.h"

#include <QtTest>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace hsmu;

namespace {

/// The plain-text conversions in ../shared/data: '#' lines, then index-or-time, deformation,
/// force, [more columns]. Units do not matter here (the NRMSE is scale-free).
bool readRecord(const std::string& path, SpecimenHistory& h) {
    std::ifstream in(path);
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
    h.source = path;
    return h.size() > 0;
}

const std::string kData = HSMU_SHARED_DATA_DIR;

} // namespace

class TestRealRecords : public QObject {
    Q_OBJECT

private slots:
    void calibrates_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<double>("reference"); // independent best fit, NRMSE
        QTest::newRow("gill") << QString::fromStdString(kData + "/rc-column-gill1979/rc_column_force_disp.txt") << 0.138;
        QTest::newRow("soesianawati") << QString::fromStdString(kData + "/hysteresis/rc-column-soesianawati-unit1/soesianawati_unit1.txt") << 0.170;
        QTest::newRow("hdrb") << QString::fromStdString(kData + "/hysteresis/isolator-hdrb-gallardo2023/hdrb_test.txt") << 0.144;
        QTest::newRow("mr-damper") << QString::fromStdString(kData + "/hysteresis/mr-damper-labcontrol-utfpr/mr_damper_4p1_0V.txt") << 0.222;
        QTest::newRow("clt") << QString::fromStdString(kData + "/hysteresis/clt-steel-plate-connection-tannert-spc1/spc1.txt") << 0.173;
    }

    void calibrates() {
        QFETCH(QString, file);
        QFETCH(double, reference);
        SpecimenHistory h;
        if (!readRecord(file.toStdString(), h))
            QSKIP(qPrintable("shared record absent (a fresh machine has no ../shared/data): " + file));
        IdentificationSettings s = defaultIdentificationSettings();
        const OfflineIdentificationResult r = identifyOffline(h, s);
        QVERIFY(r.calibration && r.calibration->ok);
        const double best = r.calibration->nrmse;
        qInfo("%s: calibration NRMSE %.4f (reference %.3f, %.3fx), %d replays, %.2f s; "
              "robust UKF final NRMSE %.4f (%.3fx the calibration), %d messages",
              qPrintable(QFileInfo(file).fileName()), best, reference, best / reference,
              r.calibration->residualEvaluations, r.calibration->computeSeconds, r.finalNrmse,
              r.finalNrmse / best, int(r.messages.size()));
        if (qEnvironmentVariableIsSet("HSMU_VERBOSE"))
            for (const std::string& m : r.messages)
                qInfo("  %s", m.c_str());
        QVERIFY2(best <= 1.05 * reference,
                 qPrintable(QString("calibration NRMSE %1 > 1.05 x %2").arg(best).arg(reference)));
        // The online robust UKF.
        QVERIFY2(r.finalNrmse <= 1.25 * best,
                 qPrintable(QString("online NRMSE %1 > 1.25 x %2").arg(r.finalNrmse).arg(best)));
        // No divergence (on HDRB the filter diverged 31-38 times while its scales stayed those
        // of a first anchor on 14 samples of sensor noise; they are re-derived now).
        int divergences = 0;
        for (const std::string& m : r.messages)
            if (m.find("UKF diverging") != std::string::npos &&
                m.find("identification step rejected") == std::string::npos)
                ++divergences;
        qInfo("  divergences detected and recovered: %d", divergences);
        QVERIFY2(divergences == 0, qPrintable(QString("%1 divergences").arg(divergences)));
        // No parameter on a bound unless the data put it there: a bound of the default box
        // (CalibrationDefaults.h; the deltas' upper bounds depend on the energy seen, their
        // lower bound 0 does not) is reached online only where the calibration sits on it.
        const CalibrationSpec box = defaultCalibrationSpec({}, HistoryScales{true, "", 1, 1, 1, 1});
        QStringList pinned;
        for (std::size_t i = 0; i < r.calibration->names.size(); ++i) {
            const std::string& name = r.calibration->names[i];
            const double v = r.finalEstimate.at(name);
            for (const auto& b : box.fitted) {
                if (b.name != name)
                    continue;
                const double tol = 1e-6 * (b.upper - b.lower);
                const bool delta = name.rfind("delta", 0) == 0;
                const bool onBound = v <= b.lower + tol || (!delta && v >= b.upper - tol);
                if (onBound && !r.calibration->onBound[i])
                    pinned << QString("%1 = %2").arg(QString::fromStdString(name)).arg(v);
            }
        }
        QVERIFY2(pinned.isEmpty(), qPrintable("on a bound online only: " + pinned.join(", ")));
    }

    /// The pinching law (boucWenPinching) with no user input: within 5 % of the independent
    /// Baber-Noori / Foliente fit on the three records that have one, and better than the
    /// plain law's own optimum by a margin no plain fit can reach (so the search did leave
    /// the Bouc-Wen basin).
    void calibratesPinching_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<double>("reference");
        QTest::addColumn<double>("plainReference");
        QTest::newRow("gill") << QString::fromStdString(kData + "/rc-column-gill1979/rc_column_force_disp.txt") << 0.105 << 0.138;
        QTest::newRow("soesianawati") << QString::fromStdString(kData + "/hysteresis/rc-column-soesianawati-unit1/soesianawati_unit1.txt") << 0.126 << 0.170;
        QTest::newRow("hdrb") << QString::fromStdString(kData + "/hysteresis/isolator-hdrb-gallardo2023/hdrb_test.txt") << 0.110 << 0.144;
    }

    void calibratesPinching() {
        QFETCH(QString, file);
        QFETCH(double, reference);
        QFETCH(double, plainReference);
        SpecimenHistory h;
        if (!readRecord(file.toStdString(), h))
            QSKIP(qPrintable("shared record absent (a fresh machine has no ../shared/data): " + file));
        CalibrationRequest request;
        request.law = "boucWenPinching";
        const CalibrationResult r = calibrateHistory(h.deformation, h.force, request);
        QVERIFY2(r.ok, r.reason.c_str());
        qInfo("%s: pinching calibration NRMSE %.4f (reference %.3f, %.3fx), %d starts, %d "
              "replays, %.2f s; zetaS %.3f q %.3f",
              qPrintable(QFileInfo(file).fileName()), r.nrmse, reference, r.nrmse / reference,
              r.startsTried, r.residualEvaluations, r.computeSeconds, r.parameters.at("zetaS"),
              r.parameters.at("q"));
        QVERIFY2(r.nrmse <= 1.05 * reference,
                 qPrintable(QString("pinching NRMSE %1 > 1.05 x %2").arg(r.nrmse).arg(reference)));
        QVERIFY(r.nrmse < 0.9 * plainReference);
        QVERIFY(r.parameters.at("zetaS") > 0.1); // the loops are pinched
    }

    /// The MR damper at 0.88 V is rate-dependent beyond what a Bouc-Wen law can follow: its
    /// best fit stays above the verdict's NRMSE of 0.25 and the verdict says so.
    void verdictOnASpecimenTheLawCannotFollow() {
        SpecimenHistory h;
        const std::string file =
            kData + "/hysteresis/mr-damper-labcontrol-utfpr/mr_damper_4p2_0p88V.txt";
        if (!readRecord(file, h))
            QSKIP(qPrintable(QString::fromStdString("shared record absent: " + file)));
        IdentificationSettings s = defaultIdentificationSettings();
        s.online = false;
        const OfflineIdentificationResult r = identifyOffline(h, s);
        QVERIFY(r.calibration && r.calibration->ok);
        qInfo("MR damper 0.88 V: best NRMSE %.3f; verdict: %s", r.calibration->nrmse,
              r.verdict.c_str());
        QVERIFY(r.calibration->nrmse > s.verdictNrmse);
        QVERIFY(r.verdict.find("cannot represent this specimen (best NRMSE") != std::string::npos);
        // ... and a specimen the law follows gets none.
        SpecimenHistory g;
        QVERIFY(readRecord(kData + "/rc-column-gill1979/rc_column_force_disp.txt", g));
        QVERIFY(identifyOffline(g, s).verdict.empty());
    }
};

QTEST_APPLESS_MAIN(TestRealRecords)
#include "TestRealRecords.moc"
