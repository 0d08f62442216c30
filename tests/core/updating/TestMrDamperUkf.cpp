// The MR damper UKF (core/updating/MrDamperUkf.h, MrDamperUkfIdentifier.h): a synthetic MR
// damper with known parameters (Spencer et al.'s modified Bouc-Wen model, mrDamper) driven by
// sinusoids of several amplitudes and frequencies with 1 % force noise is identified online,
// sample by sample, from the law's default parameters; the published estimate replays the
// noise-free force to within the noise (closer to it than the noisy measurement is). And the identifier's contract: the layout, bounds,
// a model without a time step, the configuration that selects it.

#include "core/config/ConfigLoader.h"
#include "core/config/TestFactory.h"
#include "core/config/UpdatingConfig.h"
#include "core/hysteresis/MrDamper.h"
#include "core/updating/ModelUpdater.h"
#include "core/updating/MrDamperUkfIdentifier.h"
#include "tests/support/LawByName.h"

#include <QtTest>

#include <cmath>
#include <numbers>
#include <random>

using namespace hsmu;

namespace {

/// The 0.88 V record's calibrated damper (normalized; uRef, fRef in m and kN).
MrDamperParameters trueDamper() {
    MrDamperParameters p;
    p.c0 = 0.0236;
    p.c1 = 3.29;
    p.k0 = 0.016;
    p.k1 = 0.0083;
    p.f0 = -0.069;
    p.alpha = 72.1;
    p.beta = 2.41;
    p.gamma = 8.96;
    p.n = 0.521;
    p.uRef = 0.0054;
    p.fRef = 0.32;
    return p;
}

struct Synthetic {
    std::vector<double> u, f, clean;
    double dt = 0.01;
};

/// Sinusoids of 4 to 12 mm at 0.5 to 1.5 Hz, 2 cycles each, dt = 0.01 s, 1 % (of the peak)
/// Gaussian force noise with a fixed seed.
Synthetic makeHistory() {
    Synthetic h;
    MrDamper law(trueDamper());
    law.setTimeIncrement(h.dt);
    std::mt19937 rng(23);
    std::normal_distribution<double> noise(0.0, 1.0);
    double t = 0.0;
    for (const auto& [amplitude, hz] : {std::pair{0.004, 0.5}, std::pair{0.008, 1.0},
                                        std::pair{0.012, 1.5}, std::pair{0.006, 0.75},
                                        std::pair{0.010, 1.25}}) {
        const int steps = int(std::lround(2.0 / hz / h.dt));
        const double t0 = t;
        for (int k = 1; k <= steps; ++k) {
            t += h.dt;
            h.u.push_back(amplitude * std::sin(2.0 * std::numbers::pi * hz * (t - t0)));
        }
    }
    for (double u : h.u) {
        if (law.setTrialDeformation(u) != LawStatus::Ok)
            return {};
        law.commit();
        h.clean.push_back(law.committedForce());
    }
    double peak = 0.0;
    for (double f : h.clean)
        peak = std::max(peak, std::abs(f));
    for (double f : h.clean)
        h.f.push_back(f + 0.01 * peak * noise(rng));
    return h;
}

double rms(const std::vector<double>& v) {
    double s = 0.0;
    for (double x : v)
        s += x * x;
    return std::sqrt(s / double(v.size()));
}

/// NRMSE of p replayed over u (first sample quasi-static) against `against`.
double replayNrmse(const MrDamperParameters& p, const std::vector<double>& u,
                   const std::vector<double>& against, double dt) {
    MrDamper law(p);
    double sse = 0.0;
    for (std::size_t k = 0; k < u.size(); ++k) {
        law.setTimeIncrement(k == 0 ? std::numeric_limits<double>::infinity() : dt);
        if (law.setTrialDeformation(u[k]) != LawStatus::Ok)
            return std::nan("");
        law.commit();
        sse += (law.committedForce() - against[k]) * (law.committedForce() - against[k]);
    }
    return std::sqrt(sse / double(u.size())) / rms(against);
}

} // namespace

class TestMrDamperUkf : public QObject {
    Q_OBJECT

private slots:
    void identifiesASyntheticDamperOnline();
    void contract();
    void selectedByTheConfiguration();
};

void TestMrDamperUkf::identifiesASyntheticDamperOnline() {
    const Synthetic h = makeHistory();
    QVERIFY(!h.u.empty());
    // The initial model: the law's defaults in the configured scales (far from the truth).
    MrDamperParameters start;
    start.uRef = trueDamper().uRef;
    start.fRef = trueDamper().fRef;
    MrDamper model(start);
    model.setTimeIncrement(h.dt);
    MrDamperUkfIdentifier id(model, start.uRef, start.fRef, {});
    QCOMPARE(id.layout().size(), std::size_t(11));
    QCOMPARE(id.layout().name(0), std::string("c0"));
    QCOMPARE(id.layout().name(10), std::string("fRef"));
    int rejected = 0, notReportable = 0;
    std::vector<double> predicted;
    for (std::size_t k = 0; k < h.u.size(); ++k) {
        const IdentificationStatus st = id.observe(h.u[k], h.f[k], false);
        rejected += !st.ok;
        notReportable += !st.reportable;
        predicted.push_back(id.predictedForce());
        for (double v : id.estimate())
            QVERIFY(std::isfinite(v));
    }
    const MrDamperParameters& e = id.published();
    const double initial = replayNrmse(start, h.u, h.clean, h.dt);
    const double final = replayNrmse(e, h.u, h.clean, h.dt);
    const double truth = replayNrmse(trueDamper(), h.u, h.f, h.dt); // the noise itself
    // The last cycle's one-step predictions against the clean force.
    double sse = 0.0, sff = 0.0;
    for (std::size_t k = h.u.size() - 160; k < h.u.size(); ++k) {
        sse += (predicted[k] - h.clean[k]) * (predicted[k] - h.clean[k]);
        sff += h.clean[k] * h.clean[k];
    }
    qInfo("synthetic MR damper, %zu samples: %d anchors (%d global), %d divergences, %d "
          "rejected, %d not reportable; NRMSE against the clean force: initial model %.3f, "
          "final estimate %.4f (noise %.4f); last cycle's predictions %.4f",
          h.u.size(), id.anchors(), id.globalAnchors(), id.divergences(), rejected,
          notReportable, initial, final, truth, std::sqrt(sse / sff));
    QVERIFY(initial > 0.3);
    QVERIFY(id.anchors() >= 2);
    QCOMPARE(id.divergences(), 0);
    // within the noise: closer to the clean force than the noisy measurement is
    QVERIFY2(final < truth && final < 0.03, qPrintable(QString::number(final)));
    QVERIFY(std::sqrt(sse / sff) < 0.03);
    // The published estimate carries the scales it is in.
    QCOMPARE(id.estimate()[9], start.uRef);
    QCOMPARE(id.estimate()[10], start.fRef);
}

void TestMrDamperUkf::contract() {
    MrDamper model;
    // No time step: refused.
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             MrDamperUkfIdentifier(model, std::nullopt, std::nullopt, {}));
    model.setTimeIncrement(0.01);
    // A bound on a parameter it does not identify: refused with the names.
    try {
        MrDamperUkfIdentifier(model, std::nullopt, std::nullopt, {{"A", {0.5, 2.0}}});
        QFAIL("a bound on A was accepted");
    } catch (const std::invalid_argument& e) {
        QVERIFY(std::string(e.what()).find("'A'") != std::string::npos);
    }
    MrDamperUkfIdentifier id(model, std::nullopt, std::nullopt, {{"c1", {0.5, 20.0}}});
    QCOMPARE(id.methodName(), std::string("UKF (MR damper)"));
    QCOMPARE(id.bounds()[1].lower, 0.5);
    QCOMPARE(id.bounds()[1].upper, 20.0);
    QVERIFY(std::isnan(id.bounds()[9].lower)); // uRef: no bounds
    QVERIFY(id.setBounds(0, {0.0, 1.0}));
    QVERIFY(!id.setBounds(9, {0.0, 1.0}));
    QVERIFY(!id.setBounds(0, {1.0, 0.0}));
    // Before the warm-up: the initial model, not reportable, no prediction.
    const IdentificationStatus st = id.observe(0.001, 0.1, false);
    QVERIFY(st.ok && !st.reportable);
    QVERIFY(std::isnan(id.predictedForce()));
    QCOMPARE(id.estimate()[0], model.parameters().c0);
}

void TestMrDamperUkf::selectedByTheConfiguration() {
    // An mrDamper specimen model takes the UKF (robust formulation, the default); the paper's
    // formulation is refused with a reason.
    const std::string json = R"({
      "structure": {
        "dofs": [{"name": "DOF 1", "mass": 0.1}],
        "elements": [{"name": "Damper", "type": "lateralSpring", "dof": "DOF 1",
                      "experimental": true,
                      "material": {"law": "mr-damper", "uRef": 0.0054, "fRef": 0.32},
                      "specimen": {"material": {"law": "mrDamper"}}}]
      },
      "analysis": {"dt": 0.002},
      "updating": {"specimen": "Damper", "method": "ukf"}
    })";
    const TestConfig cfg = parseConfig(nlohmann::json::parse(json), "mr.json");
    QCOMPARE(cfg.elements[0].material.law, std::string("mrDamper")); // the canonical name
    auto updater = buildModelUpdater(cfg);
    QVERIFY(updater);
    QCOMPARE(updater->identifier().methodName(), std::string("UKF (MR damper)"));
    nlohmann::json paper = nlohmann::json::parse(json);
    paper["updating"]["ukf"] = {{"formulation", "paper"}};
    QVERIFY_THROWS_EXCEPTION(ConfigError, buildModelUpdater(parseConfig(paper, "mr.json")));
}

QTEST_APPLESS_MAIN(TestMrDamperUkf)
#include "TestMrDamperUkf.moc"
