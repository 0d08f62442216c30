// Tests of the offline calibration (core/identification: LevenbergMarquardt, HistoryScales,
// Calibration, CalibrationDefaults): the bounded Levenberg-Marquardt against an analytic
// least-squares problem; the scales derived from a synthetic Bouc-Wen history against its
// known stiffness and peak force; the whole default calibration recovering a synthetic Bouc-Wen
// specimen (physical parameters) from no user input; admissibility by projection with wide
// beta, gamma boxes; the statistics (standard deviations, correlations) against a direct
// Gauss-Newton computation on a linear model.

#include "core/hysteresis/BoucWen.h"
#include "core/identification/Calibration.h"
#include "core/identification/CalibrationDefaults.h"
#include "core/identification/HistoryScales.h"
#include "core/identification/LevenbergMarquardt.h"
#include "core/identification/PinchingSearch.h"

#include "SyntheticHistory.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

using namespace hsmu;

using hsmu::testing::cyclic;
using hsmu::testing::forcesOf;

class TestCalibration : public QObject {
    Q_OBJECT

private slots:
    void levenbergMarquardtSolvesAnExponentialFit() {
        // y = a exp(-b t) + c sampled without noise: the minimum is exact (cost 0).
        const double a = 2.5, b = 1.3, c = -0.4;
        std::vector<double> t, y;
        for (int k = 0; k < 50; ++k) {
            t.push_back(0.1 * k);
            y.push_back(a * std::exp(-b * t.back()) + c);
        }
        const LevenbergMarquardt::Residual r = [&](const Eigen::VectorXd& x, Eigen::VectorXd& out) {
            out.resize(Eigen::Index(t.size()));
            for (std::size_t k = 0; k < t.size(); ++k)
                out[Eigen::Index(k)] = x[0] * std::exp(-x[1] * t[k]) + x[2] - y[k];
            return true;
        };
        Eigen::VectorXd x0(3), lo(3), hi(3), typ(3);
        x0 << 1.0, 0.5, 0.0;
        lo << -10, 0, -10;
        hi << 10, 10, 10;
        typ << 1, 1, 1;
        LevenbergMarquardtSettings s;
        s.maxIterations = 200;
        s.costTolerance = 1e-14;
        const LevenbergMarquardtResult res = LevenbergMarquardt(s).minimize(r, x0, lo, hi, typ);
        QVERIFY(res.converged);
        QVERIFY(std::abs(res.x[0] - a) < 1e-6);
        QVERIFY(std::abs(res.x[1] - b) < 1e-6);
        QVERIFY(std::abs(res.x[2] - c) < 1e-6);
        // With b held below its optimum by the box, the result sits on that bound.
        hi[1] = 1.0;
        const LevenbergMarquardtResult held = LevenbergMarquardt(s).minimize(r, x0, lo, hi, typ);
        QCOMPARE(held.x[1], 1.0);
        QVERIFY(held.cost > 0.0);
    }

    void scalesFollowTheSpecimen() {
        // A physical Bouc-Wen specimen: k0 = 2000 kN/m, yield near 0.01 m.
        BoucWenParameters p;
        p.k0 = 1.0;
        p.uRef = 0.01;
        p.fRef = 20.0;
        p.alpha = 0.05;
        p.beta = 0.6;
        p.gamma = 0.4;
        p.n = 2.0;
        BoucWen law(p);
        const std::vector<double> u = cyclic(0.05, 5, 400);
        const std::vector<double> f = forcesOf(law, u);
        const HistoryScales s = deriveHistoryScales(u, f);
        QVERIFY(s.ok);
        double peak = 0;
        for (double v : f)
            peak = std::max(peak, std::abs(v));
        QCOMPARE(s.fRef, peak);
        // Branches leave a reversal with the unloading tangent k0 (alpha + (1 - alpha)
        // (1 - z_u^n (gamma - beta))) = 1.19 k0 and soften within 10 % of the range: the
        // estimate lies between the post-yield stiffness and that tangent.
        QVERIFY2(s.stiffness > 0.3 * 2000.0 && s.stiffness <= 1.19 * 2000.0,
                 qPrintable(QString::number(s.stiffness)));
        QCOMPARE(s.reversals, 10); // 5 cycles: 10 extremes, each followed by a return
        QVERIFY(s.energy > 0.0);
        QVERIFY(!deriveHistoryScales({0, 0, 0}, {1, 2, 3}).ok);
    }

    void defaultCalibrationRecoversASyntheticSpecimen() {
        // Physical units (no normalization known to the calibration).
        BoucWenParameters p;
        p.k0 = 1500.0;
        p.alpha = 0.08;
        p.n = 1.5;
        p.beta = 180.0;
        p.gamma = -60.0; // beta + gamma > 0: admissible although gamma < 0
        p.deltaNu = 0.002;
        p.deltaEta = 0.004;
        BoucWen truth(p);
        const std::vector<double> u = cyclic(0.04, 6, 300);
        const std::vector<double> f = forcesOf(truth, u);
        // Its progress (hsmu replay's calibration lines): one call per minimization, counted
        // up to the total of the starts and the polishes.
        std::vector<std::pair<int, int>> calls;
        CalibrationRequest request;
        request.progress = [&calls](int done, int total) { calls.emplace_back(done, total); };
        const CalibrationResult r = calibrateHistory(u, f, request);
        QVERIFY2(r.ok, r.reason.c_str());
        QVERIFY2(r.nrmse < 1e-5, qPrintable(QString::number(r.nrmse)));
        const CalibrationSpec spec = defaultCalibrationSpec(request, deriveHistoryScales(u, f));
        const int total = int(spec.starts.size()) + spec.polished;
        QVERIFY(!calls.empty() && int(calls.size()) % total == 0); // once, or twice (a re-run)
        for (std::size_t k = 0; k < calls.size(); ++k)
            QCOMPARE(calls[k], std::make_pair(int(k) % total + 1, total));
        QCOMPARE(r.startsTried, int(calls.size()) / total * int(spec.starts.size()));
        // Back to physical units: stiffness k0 fRef / uRef, alpha and n are scale-free.
        const auto& q = r.parameters;
        const double k0 = q.at("k0") * q.at("fRef") / q.at("uRef");
        QVERIFY2(std::abs(k0 / p.k0 - 1.0) < 1e-3, qPrintable(QString::number(k0)));
        QVERIFY(std::abs(q.at("alpha") - p.alpha) < 1e-3);
        QVERIFY(std::abs(q.at("n") - p.n) < 1e-2);
        // The replay of the result through the law itself gives the same NRMSE.
        BoucWenParameters fit;
        fit.k0 = q.at("k0");
        fit.alpha = q.at("alpha");
        fit.n = q.at("n");
        fit.beta = q.at("beta");
        fit.gamma = q.at("gamma");
        fit.deltaNu = q.at("deltaNu");
        fit.deltaEta = q.at("deltaEta");
        fit.uRef = q.at("uRef");
        fit.fRef = q.at("fRef");
        BoucWen model(fit);
        const std::vector<double> g = forcesOf(model, u);
        double e2 = 0, f2 = 0;
        for (std::size_t k = 0; k < u.size(); ++k) {
            e2 += (g[k] - f[k]) * (g[k] - f[k]);
            f2 += f[k] * f[k];
        }
        QVERIFY(std::abs(std::sqrt(e2 / f2) - r.nrmse) < 1e-9);
    }

    void screenedPointsJoinTheStarts() {
        // A start in the wrong place and no minimization at all (0 iterations): the result is
        // the best screened point, replayed once each on the reduced history.
        BoucWenParameters p;
        p.k0 = 1.2;
        p.alpha = 0.1;
        p.n = 2.0;
        p.beta = 0.9;
        p.gamma = 0.3;
        BoucWen truth(p);
        const std::vector<double> u = cyclic(3.0, 4, 200);
        const std::vector<double> f = forcesOf(truth, u);
        CalibrationSpec spec;
        spec.fixed = {{"A0", 1.0}, {"deltaA", 0.0}, {"uRef", 1.0}, {"fRef", 1.0},
                      {"n", 2.0}, {"deltaNu", 0.0}, {"deltaEta", 0.0}};
        spec.fitted = {{"k0", 0.1, 10.0, 1.0}, {"alpha", 0.0, 0.9, 0.05},
                       {"beta", -5.0, 5.0, 1.0}, {"gamma", -5.0, 5.0, 1.0}};
        spec.starts = {{5.0, 0.6, 3.0, -1.0}};
        spec.global.maxIterations = 0;
        spec.local.maxIterations = 0;
        const CalibrationResult far = calibrate(u, f, spec);
        QVERIFY2(far.ok && far.nrmse > 0.1, qPrintable(QString::number(far.nrmse)));
        spec.screened = {{3.0, 0.5, 1.0, 1.0}, {1.2, 0.1, 0.9, 0.3}, {0.5, 0.2, 2.0, -1.0}};
        spec.screenSamples = 100;
        spec.screenKept = 1;
        const CalibrationResult r = calibrate(u, f, spec);
        QVERIFY2(r.ok && r.nrmse < 1e-12, qPrintable(QString::number(r.nrmse)));
        QCOMPARE(r.parameters.at("beta"), 0.9);
        QVERIFY(r.residualEvaluations >= far.residualEvaluations + 1 + 3); // a start, 3 screened
    }

    void scrambledHaltonIsStratified() {
        // The first b^k points of a base-b coordinate fall one in each interval of 1 / b^k.
        const auto x = scrambledHalton(3, 125, 7u);
        QCOMPARE(int(x.size()), 125);
        for (const auto& [dim, base, count] : {std::tuple{0, 2, 64}, std::tuple{1, 3, 81},
                                               std::tuple{2, 5, 125}}) {
            std::vector<int> hits(std::size_t(count), 0);
            for (int i = 0; i < count; ++i) {
                const double v = x[std::size_t(i)][std::size_t(dim)];
                QVERIFY(v >= 0.0 && v < 1.0);
                ++hits[std::size_t(v * count + 1e-9)]; // (1/3 and 1/5 are not exact)
            }
            QVERIFY2(std::all_of(hits.begin(), hits.end(), [](int h) { return h == 1; }),
                     qPrintable(QString("base %1").arg(base)));
        }
        QCOMPARE(scrambledHalton(3, 125, 7u), x); // deterministic
        QVERIFY(scrambledHalton(3, 125, 8u) != x);
    }

    void wideBetaGammaBoxesAreProjected() {
        Eigen::VectorXd x(3);
        x << -3.0, 2.0, 5.0; // beta, gamma, other
        projectBetaGamma(x, 0, 1, 0, 0);
        QVERIFY(std::abs(x[0] + x[1] - 1e-3) < 1e-12);
        QCOMPARE(x[0] - x[1], -5.0); // moved along (1, 1)
        QCOMPARE(x[2], 5.0);
        Eigen::VectorXd ok(2);
        ok << 3.0, -1.0;
        projectBetaGamma(ok, 0, 1, 0, 0);
        QCOMPARE(ok[0], 3.0);
        // The default box is not admissible as a whole, and the calibration accepts it.
        const CalibrationSpec spec = defaultCalibrationSpec({}, HistoryScales{true, "", 1, 1, 1, 10});
        double betaLow = 0, gammaLow = 0;
        for (const auto& b : spec.fitted) {
            if (b.name == "beta")
                betaLow = b.lower;
            if (b.name == "gamma")
                gammaLow = b.lower;
        }
        QVERIFY(betaLow + gammaLow < 0);
    }

    void statisticsMatchLinearLeastSquares() {
        // An elastic law F = k u is linear in k: the calibration's standard deviation must be
        // the textbook s / sqrt(sum u^2), s^2 = SSR / (N - 1).
        std::vector<double> u, f;
        for (int k = 0; k < 200; ++k) {
            u.push_back(std::sin(0.1 * k));
            f.push_back(3.0 * u.back() + 0.05 * std::cos(1.7 * k)); // a deterministic "noise"
        }
        CalibrationSpec spec;
        spec.law = "elastic";
        spec.fitted = {{"k", 0.1, 10.0, 1.0}};
        spec.starts = {{1.0}};
        const CalibrationResult r = calibrate(u, f, spec);
        QVERIFY(r.ok);
        double suu = 0, suf = 0;
        for (std::size_t k = 0; k < u.size(); ++k) {
            suu += u[k] * u[k];
            suf += u[k] * f[k];
        }
        const double kHat = suf / suu;
        double ssr = 0;
        for (std::size_t k = 0; k < u.size(); ++k)
            ssr += (f[k] - kHat * u[k]) * (f[k] - kHat * u[k]);
        QVERIFY(std::abs(r.estimate[0] - kHat) < 1e-7);
        const double sd = std::sqrt(ssr / double(u.size() - 1) / suu);
        QVERIFY2(std::abs(r.standardDeviation[0] / sd - 1.0) < 1e-4,
                 qPrintable(QString::number(r.standardDeviation[0] / sd)));
        QCOMPARE(r.correlation(0, 0), 1.0);
    }

    void reducedHistoryKeepsTurningPoints() {
        const std::vector<double> u = cyclic(1.0, 10, 1000);
        const std::vector<std::size_t> keep = reducedHistory(u, 400);
        QVERIFY(keep.size() > 300 && keep.size() < 600);
        QCOMPARE(keep.front(), std::size_t(0));
        QCOMPARE(keep.back(), u.size() - 1);
        for (std::size_t tp : turningPoints(u, 0.01 * 2.0))
            QVERIFY(std::binary_search(keep.begin(), keep.end(), tp));
    }

    void badInputIsReported() {
        CalibrationSpec spec;
        QVERIFY(!calibrate({0, 1}, {0, 1}, spec).ok);
        spec.fitted = {{"nonsense", 0, 1, 1}};
        spec.starts = {{0.5}};
        const CalibrationResult r = calibrate({0, 1, 2}, {0, 1, 2}, spec);
        QVERIFY(!r.ok);
        QVERIFY(r.reason.find("nonsense") != std::string::npos);
        QVERIFY(!calibrate({0, NAN, 2}, {0, 1, 2}, spec).ok);
    }
};

QTEST_APPLESS_MAIN(TestCalibration)
#include "TestCalibration.moc"
