// Tests of HistoryFit (core/identification/HistoryFit.h): Nelder-Mead recovers the bilinear
// parameters of synthetic data (the law of the paper's Figures 1-2) to 1e-3 relative, reduces
// the RMS force error of a Bouc-Wen model from a wrong start by more than 5x, honours the
// window, and reports bad requests.
// NelderMeadStop is compared with QVERIFY(a == b): QCOMPARE would look for a toString by ADL.

#include "core/hysteresis/Bilinear.h"
#include "core/hysteresis/BoucWen.h"
#include "core/identification/HistoryFit.h"

#include "SyntheticHistory.h"

#include <QtTest>

#include <cmath>
#include <vector>

using namespace hsmu;

using hsmu::testing::cyclic;
using hsmu::testing::forcesOf;

class TestHistoryFit : public QObject {
    Q_OBJECT

private slots:
    void recoversBilinearParameters();
    void reducesBoucWenError();
    void windowRestrictsTheError();
    void badRequestsAreReported();
};

void TestHistoryFit::recoversBilinearParameters() {
    // The paper's first example: k0 1.015 kN/mm, fy 2.8 kN, b 0.1; deformation to 5 yield.
    Bilinear truth({1.015, 2.8, 0.1});
    const std::vector<double> u = cyclic(5.0 * 2.8 / 1.015, 4, 250);
    const std::vector<double> f = forcesOf(truth, u);

    HistoryFitSpec spec;
    spec.law = "bilinear";
    spec.initial = {{"k0", 0.7}, {"fy", 2.0}, {"b", 0.2}};
    spec.fitted = {{"k0", 0.3, 3.0}, {"fy", 0.5, 6.0}, {"b", 0.0, 0.5}};
    spec.optimizer.maxEvaluations = 2000;
    const HistoryFitResult r = HistoryFit(spec).fit(u, f);
    qInfo("bilinear: k0 %.6f fy %.6f b %.6f; RMS %.3g -> %.3g kN, %d replays, %.1f ms (%s)",
          r.parameters.at("k0"), r.parameters.at("fy"), r.parameters.at("b"), r.rmsBefore,
          r.rmsAfter, r.evaluations, 1e3 * r.computeSeconds, r.reason.c_str());
    QVERIFY2(r.ok, r.reason.c_str());
    QVERIFY(std::abs(r.parameters.at("k0") / 1.015 - 1.0) <= 1e-3);
    QVERIFY(std::abs(r.parameters.at("fy") / 2.8 - 1.0) <= 1e-3);
    QVERIFY(std::abs(r.parameters.at("b") / 0.1 - 1.0) <= 1e-3);
    QVERIFY(r.rmsAfter < 1e-3 * r.rmsBefore);
    QVERIFY(r.computeSeconds > 0.0);
    QVERIFY(r.evaluations <= spec.optimizer.maxEvaluations + 1);
}

void TestHistoryFit::reducesBoucWenError() {
    BoucWenParameters p;
    p.k0 = 1.0;
    p.alpha = 0.03;
    p.n = 2.0;
    p.beta = 2.5;
    p.gamma = 0.5;
    p.deltaNu = 0.03;
    p.deltaEta = 0.03;
    p.uRef = 0.02;
    p.fRef = 20.0;
    BoucWen truth(p);
    const std::vector<double> u = cyclic(4.0 * p.uRef, 4, 250);
    const std::vector<double> f = forcesOf(truth, u);

    HistoryFitSpec spec;
    spec.law = "boucWen";
    spec.initial = {{"k0", 1.3},        {"alpha", 0.01}, {"n", 1.3},
                    {"beta", 4.0},      {"gamma", 2.0},  {"deltaNu", 0.08},
                    {"deltaEta", 0.08}, {"uRef", 0.02},  {"fRef", 20.0}};
    // Table III bounds (normalized).
    spec.fitted = {{"k0", 0.7, 1.4},        {"alpha", 0.001, 0.05}, {"n", 1.0, 3.0},
                   {"beta", 2.5, 5.0},      {"gamma", 0.0, 2.5},    {"deltaNu", 0.001, 0.1},
                   {"deltaEta", 0.001, 0.1}};
    spec.optimizer.maxEvaluations = 400;
    const HistoryFitResult r = HistoryFit(spec).fit(u, f);
    qInfo("Bouc-Wen: RMS %.4g -> %.4g kN m (%.1fx) in %d replays of %zu points, %.1f ms (%s)",
          r.rmsBefore, r.rmsAfter, r.rmsBefore / r.rmsAfter, r.evaluations, u.size(),
          1e3 * r.computeSeconds, r.reason.c_str());
    QVERIFY2(r.ok, r.reason.c_str());
    QVERIFY(r.rmsAfter * 5.0 < r.rmsBefore);
    QVERIFY(r.evaluations <= 401);
    // The reported RMS is that of the reported parameters.
    QVERIFY(std::abs(HistoryFit::rmsError("boucWen", r.parameters, u, f, 0) - r.rmsAfter) <=
            1e-12 * r.rmsBefore);
    for (const auto& b : spec.fitted) {
        const double v = r.parameters.at(b.name);
        QVERIFY(v >= b.lower && v <= b.upper);
    }
}

void TestHistoryFit::windowRestrictsTheError() {
    // The specimen changes (fy 2.8 -> 2.0) halfway; fitting the last 300 points finds the new
    // fy, fitting all of them a compromise.
    std::vector<double> u = cyclic(14.0, 4, 250);
    Bilinear before({1.0, 2.8, 0.1}), after({1.0, 2.0, 0.1});
    std::vector<double> f = forcesOf(before, u);
    const std::vector<double> f2 = forcesOf(after, u);
    for (std::size_t k = 500; k < u.size(); ++k) {
        f[k] = f2[k];
    }
    HistoryFitSpec spec;
    spec.law = "bilinear";
    spec.initial = {{"k0", 1.0}, {"fy", 2.5}, {"b", 0.1}};
    spec.fitted = {{"fy", 0.5, 6.0}};
    spec.window = 300;
    // Replayed from the start with one fy, the last 300 points are those of the new law.
    const HistoryFitResult windowed = HistoryFit(spec).fit(u, f);
    spec.window = 0;
    const HistoryFitResult whole = HistoryFit(spec).fit(u, f);
    QVERIFY(windowed.ok && whole.ok);
    QVERIFY2(std::abs(windowed.parameters.at("fy") - 2.0) <= 1e-3,
             qPrintable(QString::number(windowed.parameters.at("fy"))));
    QVERIFY(windowed.rmsAfter <= 1e-6);
    QVERIFY(whole.parameters.at("fy") > 2.05 && whole.rmsAfter > 1e-2);
}

void TestHistoryFit::badRequestsAreReported() {
    const std::vector<double> u{0.1, 0.2}, f{0.1, 0.2};
    HistoryFitSpec spec;
    spec.law = "bilinear";
    spec.fitted = {{"fyy", 0.0, 1.0}};
    HistoryFitResult r = HistoryFit(spec).fit(u, f);
    QVERIFY(!r.ok && r.reason.find("fyy") != std::string::npos);
    spec.law = "nonsense";
    QVERIFY(!HistoryFit(spec).fit(u, f).ok);
    spec.law = "bilinear";
    spec.fitted = {{"fy", 2.0, 1.0}};
    QVERIFY(!HistoryFit(spec).fit(u, f).ok);
    spec.fitted = {{"fy", 2.0, 3.0}}; // default fy 1 is outside
    QVERIFY(!HistoryFit(spec).fit(u, f).ok);
    spec.fitted = {{"fy", 0.5, 3.0}};
    QVERIFY(!HistoryFit(spec).fit(u, {0.1}).ok);
    QVERIFY(!HistoryFit(spec).fit({0.1, std::nan("")}, f).ok);
    QVERIFY(HistoryFit(spec).fit(u, f).ok);
}

QTEST_APPLESS_MAIN(TestHistoryFit)
#include "TestHistoryFit.moc"
