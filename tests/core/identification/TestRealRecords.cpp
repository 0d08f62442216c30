// Identification on specimens measured by other labs (../shared/data; QSKIP where absent):
// the offline calibration (CalibrationDefaults.h) with no user scales, bounds or starts must
// reach within 5 % of an independent multi-start least-squares fit of the same law (OpenSees'
// BoucWen, 7 parameters; figures in docs/validation.md), and the default online identifier
// (the robust UKF, replayed sample by sample as online) must end within 25 % of the
// calibration's NRMSE, without a divergence and with no parameter on a bound that the
// calibration does not also put there.
// Nelder-Mead (nelderMead:<record>) must end within 25 % of the calibration's NRMSE in <= 60 s.
// One CTest test per record: the executable takes a data tag (e.g. `calibrates:gill`).

#include "core/hysteresis/HysteresisLaw.h"
#include "core/hysteresis/LawFactory.h"
#include "core/identification/CalibrationDefaults.h"
#include "core/offline/OfflineIdentification.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace hsmu;

namespace {

/// The plain-text conversions in ../shared/data: '#' lines, then index-or-time, deformation,
/// force, [more columns]. Units do not matter here (the NRMSE is scale-free), except that a
/// rate-dependent law needs the times: with `timeColumn` the first column (s), else 0.01 k.
bool readRecord(const std::string& path, SpecimenHistory& h, bool timeColumn = false) {
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
        h.time.push_back(timeColumn ? a : t);
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
        // The offsets (CalibrationDefaults.h; on by default offline, kept when the data ask
        // for them): never worse than the fit without them.
        const CalibrationResult::OffsetTest& o = r.calibration->offsetTest;
        qInfo("  offsets %s: NRMSE %.4f without, %.4f with, criterion %.1f over %d branches",
              o.used ? "kept" : "left off", o.nrmseWithout, o.nrmseWith, o.criterion, o.branches);
        QVERIFY(o.ran);
        QVERIFY(best <= o.nrmseWithout);
        QVERIFY(o.nrmseWith <= o.nrmseWithout); // from the plain optimum: never worse
        // A record at rest off centre when it begins (the MR damper, 12.6 mm): the offsets'
        // second start (its first sample) finds them there; from offsets 0 alone the fit
        // stayed in the plain optimum's basin (0.2277 against 0.2292; docs/validation.md).
        const auto [lo, hi] = std::minmax_element(h.deformation.begin(), h.deformation.end());
        const double range = *hi - *lo;
        if (std::abs(h.deformation.front()) > 0.01 * range) {
            QVERIFY(o.used);
            const double u0 = r.calibration->parameters.at("deformationOffset");
            qInfo("  at rest %.4g off centre: u0 %.4g", h.deformation.front(), u0);
            QVERIFY(std::abs(u0 - h.deformation.front()) <= 0.02 * range);
            QVERIFY(best <= 0.9 * o.nrmseWithout);
        }
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
        QVERIFY2(r.estimatorWarnings == 0,
                 qPrintable(QString("%1 rejected samples").arg(r.estimatorWarnings)));
        // No parameter on a bound unless the data put it there: a bound of the default box
        // (CalibrationDefaults.h; the deltas' upper bounds depend on the energy seen, their
        // lower bound 0 does not) is reached online only where the calibration sits on it
        // (the calibration without offsets when they are kept: the online UKF fits none).
        const CalibrationSpec box = defaultCalibrationSpec({}, HistoryScales{true, "", 1, 1, 1, 1});
        QStringList pinned;
        for (std::size_t i = 0; i < r.calibration->names.size(); ++i) {
            const std::string& name = r.calibration->names[i];
            const auto estimate = r.finalEstimate.find(name);
            if (estimate == r.finalEstimate.end())
                continue; // the calibration's offsets (the online UKF has none)
            const double v = estimate->second;
            for (const auto& b : box.fitted) {
                if (b.name != name)
                    continue;
                const double tol = 1e-6 * (b.upper - b.lower);
                const bool delta = name.rfind("delta", 0) == 0;
                const bool onBound = v <= b.lower + tol || (!delta && v >= b.upper - tol);
                const bool calibrationOnBound =
                    o.used ? std::count(o.onBoundWithout.begin(), o.onBoundWithout.end(), name) > 0
                           : bool(r.calibration->onBound[i]);
                if (onBound && !calibrationOnBound)
                    pinned << QString("%1 = %2").arg(QString::fromStdString(name)).arg(v);
            }
        }
        QVERIFY2(pinned.isEmpty(), qPrintable("on a bound online only: " + pinned.join(", ")));
    }

    /// Nelder-Mead (`hsmu replay --import FILE --method nelder-mead`, no user input): its
    /// scales and box from the data as the calibration's, its refits bounded in cost on the
    /// long records; the final model within 1.25 x the calibration's NRMSE, in <= 60 s, and
    /// never worse than the initial model.
    void nelderMead_data() { calibrates_data(); }

    void nelderMead() {
        QFETCH(QString, file);
        SpecimenHistory h;
        if (!readRecord(file.toStdString(), h))
            QSKIP(qPrintable("shared record absent (a fresh machine has no ../shared/data): " + file));
        const IdentificationSettings s0 = withMethod(defaultIdentificationSettings(), "nelder-mead");
        IdentificationSettings s = s0;
        s.calibrate = false;
        // Timed in process CPU (Nelder-Mead runs on this thread alone): the machine's other
        // work (ctest -j, builds) does not count against its budget.
        QElapsedTimer timer;
        timer.start();
        const std::clock_t cpu0 = std::clock();
        const OfflineIdentificationResult r = identifyOffline(h, s);
        const double seconds = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
        const double wall = 1e-3 * double(timer.elapsed());
        CalibrationRequest request;
        const CalibrationResult c = calibrateHistory(h.deformation, h.force, request);
        QVERIFY2(c.ok, c.reason.c_str());
        qInfo("%s: Nelder-Mead final NRMSE %.4f (%.3fx the calibration's %.4f), initial %.4f, "
              "online prediction %.4f, %d fits accepted, %.1f s CPU (%.1f s wall)",
              qPrintable(QFileInfo(file).fileName()), r.finalNrmse, r.finalNrmse / c.nrmse,
              c.nrmse, r.initialNrmse, r.auxiliaryNrmse, r.refits, seconds, wall);
        if (qEnvironmentVariableIsSet("HSMU_VERBOSE"))
            for (const std::string& m : r.messages)
                qInfo("  %s", m.c_str());
        QVERIFY2(r.finalNrmse <= 1.25 * c.nrmse,
                 qPrintable(QString("Nelder-Mead NRMSE %1 > 1.25 x %2").arg(r.finalNrmse).arg(c.nrmse)));
#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__) // the Release budget
        QVERIFY2(seconds <= 60.0, qPrintable(QString("%1 s > 60 s").arg(seconds)));
#endif
        QVERIFY(r.worseThanInitial.empty());
        QVERIFY(r.finalNrmse <= r.initialNrmse);
    }

    /// The default online UKF on a record that starts with 5 s of sub-millimetre noise (a
    /// specimen at rest before the test: the first anchor's scales come from sensor noise)
    /// and then cycles to 5 yield deformations: no rejected sample (the law's integration
    /// holds at every sigma point, BoucWen.cpp's bracketed fallback), no divergence, and the
    /// final model within 1.25 x the calibration.
    void noRejectionAfterANoisyStart() {
        SpecimenHistory h;
        std::mt19937 rng(29u);
        const auto uniform = [&rng] { return double(rng()) / 4294967296.0 * 2.0 - 1.0; };
        const auto gauss = [&] { // sum of 12 uniforms: mean 0, std 1 (Irwin-Hall)
            double sum = 0.0;
            for (int i = 0; i < 12; ++i)
                sum += 0.5 * (uniform() + 1.0);
            return sum - 6.0;
        };
        // Bouc-Wen, units mm and kN: k0 20 kN/mm, alpha 0.05, n 2, z ultimate 5 mm.
        const double k0 = 20.0, alpha = 0.05, n = 2.0, beta = 0.02, gamma = 0.02;
        double z = 0.0, uPrevious = 0.0;
        for (int k = 0; k < 4500; ++k) {
            const double t = 0.01 * k;
            double u = 0.0;
            if (k < 500) {
                u = 0.3 * uniform(); // sub-millimetre noise
            } else {
                const double tt = 0.01 * (k - 500);
                u = std::min(1.0, tt / 30.0) * 25.0 * std::sin(2.0 * M_PI * 0.25 * tt);
            }
            const double du = (u - uPrevious) / 50.0;
            for (int i = 0; i < 50; ++i)
                z += (1.0 - std::pow(std::abs(z), n) * (du * z > 0 ? beta + gamma : gamma - beta)) * du;
            uPrevious = u;
            h.time.push_back(t);
            h.deformation.push_back(1e-3 * u); // m
            h.force.push_back(k0 * (alpha * u + (1.0 - alpha) * z) + 0.5 * gauss()); // kN
        }
        h.source = "synthetic record with a noisy start";
        const OfflineIdentificationResult r = identifyOffline(h, defaultIdentificationSettings());
        QVERIFY(r.calibration && r.calibration->ok);
        int rejected = 0, divergences = 0;
        for (const std::string& m : r.messages) {
            rejected += m.find("identification step rejected") != std::string::npos;
            divergences += m.find("UKF diverging") != std::string::npos;
        }
        qInfo("noisy start: %d rejected samples, %d divergences; UKF final NRMSE %.4f, "
              "calibration %.4f", rejected, divergences, r.finalNrmse, r.calibration->nrmse);
        if (rejected > 0 || qEnvironmentVariableIsSet("HSMU_VERBOSE"))
            for (const std::string& m : r.messages)
                qInfo("  %s", m.c_str());
        QVERIFY(r.finalNrmse <= 1.25 * r.calibration->nrmse);
        // 35 rejected samples and 2 divergences before the law's return to the unloading
        // bound (BoucWen.h): the first anchor's scales come from 6 samples of noise, and sigma
        // points with beta < 0 or a deltaNu at its bound put z beyond the bound z1(e) from
        // which the unloading branch runs away (no step existed: NoConvergence).
        QCOMPARE(rejected + divergences, 0);
    }

    /// The pinching law (boucWenPinching) with no user input: within 5 % of the independent
    /// Baber-Noori / Foliente fit on the five shared records (issue 29), and better than the
    /// plain law's own optimum by a margin no plain fit can reach (so the search did leave
    /// the Bouc-Wen basin). The MR damper's record starts at rest 12.6 mm off centre under
    /// -51 N: its row runs the offsets as `hsmu replay` does by default (auto) and they are
    /// kept; the others are the plain law's fit (offsets off). docs/validation.md.
    void calibratesPinching_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<double>("reference");
        QTest::addColumn<double>("plainReference");
        QTest::addColumn<bool>("offsets"); // auto, and asserted kept; else off
        QTest::newRow("gill") << QString::fromStdString(kData + "/rc-column-gill1979/rc_column_force_disp.txt") << 0.105 << 0.138 << false;
        QTest::newRow("soesianawati") << QString::fromStdString(kData + "/hysteresis/rc-column-soesianawati-unit1/soesianawati_unit1.txt") << 0.126 << 0.170 << false;
        QTest::newRow("hdrb") << QString::fromStdString(kData + "/hysteresis/isolator-hdrb-gallardo2023/hdrb_test.txt") << 0.110 << 0.144 << false;
        QTest::newRow("mr-damper") << QString::fromStdString(kData + "/hysteresis/mr-damper-labcontrol-utfpr/mr_damper_4p1_0V.txt") << 0.184 << 0.222 << true;
        QTest::newRow("clt") << QString::fromStdString(kData + "/hysteresis/clt-steel-plate-connection-tannert-spc1/spc1.txt") << 0.141 << 0.173 << false;
    }

    void calibratesPinching() {
        QFETCH(QString, file);
        QFETCH(double, reference);
        QFETCH(double, plainReference);
        QFETCH(bool, offsets);
        SpecimenHistory h;
        if (!readRecord(file.toStdString(), h))
            QSKIP(qPrintable("shared record absent (a fresh machine has no ../shared/data): " + file));
        CalibrationRequest request;
        request.law = "boucWenPinching";
        if (offsets)
            request.offsets = CalibrationOffsets::Auto;
        const std::clock_t cpu0 = std::clock();
        const CalibrationResult r = calibrateHistory(h.deformation, h.force, request);
        const double cpu = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
        QVERIFY2(r.ok, r.reason.c_str());
        qInfo("%s: pinching calibration NRMSE %.4f (reference %.3f, %.3fx), %d starts, %d "
              "replays, %.2f s wall, %.2f s CPU; zetaS %.3f p %.4g q %.3f psi %.4g deltaPsi "
              "%.4g lambda %.4g n %.3f k0 %.4g uRef %.4g",
              qPrintable(QFileInfo(file).fileName()), r.nrmse, reference, r.nrmse / reference,
              r.startsTried, r.residualEvaluations, r.computeSeconds, cpu,
              r.parameters.at("zetaS"), r.parameters.at("p"), r.parameters.at("q"),
              r.parameters.at("psi"), r.parameters.at("deltaPsi"), r.parameters.at("lambda"),
              r.parameters.at("n"), r.parameters.at("k0"), r.parameters.at("uRef"));
        if (offsets) {
            qInfo("  offsets kept %d: u0 %.4g, F0 %.4g; NRMSE %.4f without, %.4f with, criterion %.1f over %d "
                  "branches", int(r.offsetTest.used), r.parameters.count("deformationOffset") ? r.parameters.at("deformationOffset") : 0.0,
                  r.parameters.count("forceOffset") ? r.parameters.at("forceOffset") : 0.0, r.offsetTest.nrmseWithout,
                  r.offsetTest.nrmseWith, r.offsetTest.criterion, r.offsetTest.branches);
            QVERIFY(r.offsetTest.used);
        }
        QVERIFY2(r.nrmse <= 1.05 * reference,
                 qPrintable(QString("pinching NRMSE %1 > 1.05 x %2").arg(r.nrmse).arg(reference)));
        QVERIFY(r.nrmse < 0.9 * plainReference);
        QVERIFY(r.parameters.at("zetaS") > 0.1); // the loops are pinched
    }

    /// The MR damper law (mrDamper: Spencer et al.'s modified Bouc-Wen model, rate-dependent)
    /// on both MR damper records, through the offline identification as `hsmu replay --import
    /// FILE --method calibration --config {"model": {"law": "mrDamper"}}` runs it: the
    /// calibration with no user input reaches NRMSE <= 0.15 where the Bouc-Wen optimum is
    /// 0.222 (0 V) and 0.280 (0.88 V), and the verdict "cannot represent" does not fire.
    void calibratesMrDamperLaw_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<double>("boucWen"); // the Bouc-Wen law's optimum (NRMSE)
        const std::string dir = kData + "/hysteresis/mr-damper-labcontrol-utfpr/";
        QTest::newRow("0V") << QString::fromStdString(dir + "mr_damper_4p1_0V.txt") << 0.222;
        QTest::newRow("0.88V") << QString::fromStdString(dir + "mr_damper_4p2_0p88V.txt") << 0.280;
    }

    void calibratesMrDamperLaw() {
        QFETCH(QString, file);
        QFETCH(double, boucWen);
        SpecimenHistory h;
        if (!readRecord(file.toStdString(), h, true))
            QSKIP(qPrintable("shared record absent (a fresh machine has no ../shared/data): " + file));
        const IdentificationSettings s =
            withOverride(defaultIdentificationSettings(),
                         nlohmann::json::parse(R"({"model": {"law": "mrDamper"}})"), "test",
                         "calibration");
        QCOMPARE(s.model.law, std::string("mrDamper"));
        IdentificationSettings settings = s;
        settings.online = false;
        settings.dt = h.meanStep();
        const OfflineIdentificationResult r = identifyOffline(h, settings);
        QVERIFY(r.calibration && r.calibration->ok);
        const CalibrationResult& c = *r.calibration;
        QString parameters;
        for (const auto& [name, v] : c.parameters)
            parameters += QString(" %1 %2").arg(QString::fromStdString(name)).arg(v, 0, 'g', 4);
        qInfo("%s: mrDamper calibration NRMSE %.4f (Bouc-Wen optimum %.3f), %d starts, %d "
              "replays, %.2f s; verdict '%s';%s",
              qPrintable(QFileInfo(file).fileName()), c.nrmse, boucWen, c.startsTried,
              c.residualEvaluations, c.computeSeconds, r.verdict.c_str(), qPrintable(parameters));
        QVERIFY2(c.nrmse <= 0.15, qPrintable(QString("mrDamper NRMSE %1 > 0.15").arg(c.nrmse)));
        QVERIFY(c.nrmse < 0.7 * boucWen);
        QVERIFY2(r.verdict.empty(), r.verdict.c_str());
        // The fit is the law's, not its integration's: the same parameters with every sample
        // split into 8 steps (a finer integration of the same motion) score within 2 %.
        auto law = makeLaw("mrDamper", c.parameters);
        double sse = 0.0, sff = 0.0;
        for (int k = 0; k < h.size(); ++k) {
            const int parts = k == 0 ? 1 : 8;
            for (int j = 1; j <= parts; ++j) {
                law->setTimeIncrement(k == 0 ? std::numeric_limits<double>::infinity()
                                             : (h.time[k] - h.time[k - 1]) / parts);
                const double u = k == 0 ? h.deformation[0]
                                        : h.deformation[k - 1] +
                                              (h.deformation[k] - h.deformation[k - 1]) * j / parts;
                QVERIFY(law->setTrialDeformation(u) == LawStatus::Ok);
                law->commit();
            }
            const double e = law->committedForce() - h.force[k];
            sse += e * e;
            sff += h.force[k] * h.force[k];
        }
        const double refined = std::sqrt(sse / sff);
        qInfo("  the same parameters integrated 8 times finer: NRMSE %.4f", refined);
        QVERIFY(std::abs(refined / c.nrmse - 1.0) < 0.02);
    }

    /// The MR damper UKF (mrDamper model, "method": "ukf") replayed sample by sample over
    /// the 0.88 V record as online, the samples 0.01 s apart: its final estimate replays the
    /// record within 1.1 x the calibration's NRMSE, with no divergence.
    void mrDamperUkfOnline() {
        SpecimenHistory h;
        const std::string file =
            kData + "/hysteresis/mr-damper-labcontrol-utfpr/mr_damper_4p2_0p88V.txt";
        if (!readRecord(file, h, true))
            QSKIP(qPrintable(QString::fromStdString("shared record absent: " + file)));
        IdentificationSettings s =
            withOverride(defaultIdentificationSettings(),
                         nlohmann::json::parse(R"({"model": {"law": "mrDamper"}})"), "test", "");
        QCOMPARE(s.updating.method, std::string("ukf"));
        s.dt = h.meanStep();
        const OfflineIdentificationResult r = identifyOffline(h, s);
        QCOMPARE(r.method, std::string("UKF (MR damper)"));
        QVERIFY(r.calibration && r.calibration->ok);
        int divergences = 0, anchors = 0;
        for (const std::string& m : r.messages) {
            divergences += m.find("diverging") != std::string::npos;
            anchors += m.find("MR damper UKF anchor") != std::string::npos;
        }
        qInfo("MR damper 0.88 V, online MR damper UKF: final NRMSE %.4f (calibration %.4f, "
              "%.3fx), %d anchors, %d divergences",
              r.finalNrmse, r.calibration->nrmse, r.finalNrmse / r.calibration->nrmse, anchors,
              divergences);
        QVERIFY(anchors >= 2);
        QCOMPARE(divergences, 0);
        QVERIFY2(r.finalNrmse <= 1.1 * r.calibration->nrmse,
                 qPrintable(QString("online %1 > 1.1 x %2").arg(r.finalNrmse).arg(r.calibration->nrmse)));
        QVERIFY(r.verdict.empty());
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
        s.offsets = CalibrationOffsets::Off; // the plain law (`hsmu replay --offsets off`)
        const OfflineIdentificationResult r = identifyOffline(h, s);
        QVERIFY(r.calibration && r.calibration->ok);
        qInfo("MR damper 0.88 V: best NRMSE %.3f; verdict: %s", r.calibration->nrmse,
              r.verdict.c_str());
        QVERIFY(r.calibration->nrmse > s.verdictNrmse);
        QVERIFY(r.verdict.find("cannot represent this specimen (best NRMSE") != std::string::npos);
        // With the default offsets (the record starts at rest 20 mm off centre, and its force
        // is biased) the plain law follows it well enough for no verdict (docs/validation.md).
        IdentificationSettings withOffsets = s;
        withOffsets.offsets = CalibrationOffsets::Auto;
        const OfflineIdentificationResult o = identifyOffline(h, withOffsets);
        QVERIFY(o.calibration && o.calibration->ok);
        const CalibrationResult& c = *o.calibration;
        qInfo("  with offsets (auto): NRMSE %.3f, criterion %.1f over %d branches, u0 %.4g, F0 "
              "%.4g; verdict: %s",
              c.nrmse, c.offsetTest.criterion, c.offsetTest.branches,
              c.parameters.count("deformationOffset") ? c.parameters.at("deformationOffset") : 0.0,
              c.parameters.count("forceOffset") ? c.parameters.at("forceOffset") : 0.0,
              o.verdict.c_str());
        QVERIFY(c.offsetTest.used);
        QVERIFY(c.nrmse < r.calibration->nrmse);
        QVERIFY(o.verdict.empty());
        // ... and a specimen the law follows gets none.
        SpecimenHistory g;
        QVERIFY(readRecord(kData + "/rc-column-gill1979/rc_column_force_disp.txt", g));
        QVERIFY(identifyOffline(g, s).verdict.empty());
    }
};

QTEST_APPLESS_MAIN(TestRealRecords)
#include "TestRealRecords.moc"
