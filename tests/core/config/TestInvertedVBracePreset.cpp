// The preset inverted-v-brace-frame (resources/presets, docs/presets.md; issue 24 item 6): a
// one-storey frame whose braced bay is a link2d specimen behind OpenFresco's InvertedVBrace2d
// setup (given as JSON type + parameters, exact geometry, -phiLocX 90) with three
// displacement-controlled actuators on the built-in virtual lab. Checked end to end:
//  - the shipped preset runs its 30 s to the end with no alarm; at every step the recorded
//    actuator commands equal the setup's strokes S1 of the recorded commanded basic
//    deformations (1e-15 m) and the recorded basic forces J(d_m)^T f_m (eq. S3) of the recorded
//    measured deformations and actuator forces (1e-9 of the peak); the brace yields (the
//    horizontal stroke past 0.005 m);
//  - with linear geometry (nlGeom false) it equals its numerical twin to 1e-9 of the peak:
//    the same frame with the brace a numerical link2d whose shear DOF carries the horizontal
//    actuator's Bouc-Wen law (stroke -shear; the law is odd, so q_shear = f(shear)) and whose
//    rotation carries k2 L1^2 + k3 L2^2 = 1e4 kN m/rad (S1L, S3 at rest).
// Units: kN, m, rad, s, t.

#include "core/config/ConfigLoader.h"
#include "core/config/TestFactory.h"
#include "core/experiment/HybridTest.h"
#include "core/experimental/ExperimentalLink2d.h"
#include "core/output/RunLayout.h"
#include "core/structure/Structure.h"

#include <QtTest>

#include <cmath>
#include <fstream>

using namespace hsmu;
using nlohmann::json;

namespace {

const std::string kPreset = HSMU_SOURCE_DIR "/resources/presets/inverted-v-brace-frame.json";

struct Recorder final : StepObserver {
    std::vector<StepRecord> records;
    void onStep(const StepRecord& r) override { records.push_back(r); }
};

json preset() {
    std::ifstream in(kPreset);
    return json::parse(in);
}

std::vector<StepRecord> run(const json& doc, std::unique_ptr<HybridTest>* keep = nullptr) {
    TestConfig cfg = parseConfig(doc, "brace.json");
    auto test = buildHybridTest(cfg);
    Recorder rec;
    test->addObserver(&rec);
    if (!test->prepare())
        qFatal("%s", test->lastError().c_str());
    while (test->step() == HybridTest::StepResult::Advanced) {
    }
    if (test->state() != HybridTest::State::Finished)
        qFatal("not finished: %s",
               test->alarms().empty() ? "" : test->alarms().back().message.c_str());
    test->removeObserver(&rec);
    if (keep)
        *keep = std::move(test);
    return rec.records;
}

} // namespace

class TestInvertedVBracePreset : public QObject {
    Q_OBJECT

private slots:
    void presetRunsEndToEnd() {
        std::unique_ptr<HybridTest> test;
        const auto recs = run(preset(), &test);
        QCOMPARE(recs.size(), std::size_t(3001)); // the 30 s synthetic record
        QVERIFY(test->alarms().empty());
        const auto& x = static_cast<const ExperimentalLink2d&>(*test->structure().element("Brace"));
        QCOMPARE(x.setup().typeName(), std::string("InvertedVBrace2d"));
        const RunLayout layout = RunLayout::of(*test);
        // Brace channels: 3 x (commanded, deformation, force), then 3 x (command, stroke, force).
        QCOMPARE(layout.channels[0].element, std::string("Brace"));
        QCOMPARE(layout.channels[9].name, std::string("horizontal command"));
        double peakQ = 0.0, peakStroke = 0.0, worstS = 0.0, worstQ = 0.0;
        for (const auto& r : recs)
            for (int k = 0; k < 3; ++k)
                peakQ = std::max(peakQ, std::abs(r.channels[std::size_t(3 * k + 2)]));
        for (std::size_t i = 1; i < recs.size(); ++i) {
            const auto& c = recs[i].channels;
            const Eigen::Vector3d dCmd(c[0], c[3], c[6]), dMeas(c[1], c[4], c[7]),
                q(c[2], c[5], c[8]);
            const Eigen::Vector3d cmd(c[9], c[12], c[15]), f(c[11], c[14], c[17]);
            Eigen::VectorXd s, qs;
            QVERIFY(x.setup().strokes(dCmd, s).ok);
            QVERIFY(x.setup().basicForces(dMeas, f, qs).ok);
            worstS = std::max(worstS, (s - cmd).cwiseAbs().maxCoeff());
            worstQ = std::max(worstQ, (qs - q).cwiseAbs().maxCoeff());
            peakStroke = std::max(peakStroke, std::abs(c[10]));
            QVERIFY(recs[i].u.allFinite());
        }
        qInfo("peak horizontal stroke %.6g m, peak basic force %.6g; max |s - S1(d)| %.3g m, "
              "max |q - J^T f| %.3g",
              peakStroke, peakQ, worstS, worstQ);
        QVERIFY(worstS <= 1e-15);
        QVERIFY(worstQ <= 1e-9 * peakQ);
        QVERIFY(peakStroke > 0.005);
    }

    void linearEqualsNumericalTwin() {
        json hybrid = preset();
        hybrid["structure"]["elements"][0]["setup"]["nlGeom"] = false;
        json twin = hybrid;
        json& b = twin["structure"]["elements"][0];
        const json shear = b["actuators"][0]["material"];
        for (const char* k : {"experimental", "setup", "actuators"})
            b.erase(k);
        b["basic"] = json::array({{{"material", {{"law", "elastic"}, {"k", 40000.0}}}},
                                  {{"material", shear}},
                                  {{"material", {{"law", "elastic"}, {"k", 10000.0}}}}});
        const auto a = run(twin);
        const auto h = run(hybrid);
        QCOMPARE(a.size(), h.size());
        double peak = 0, du = 0;
        for (std::size_t i = 0; i < a.size(); ++i) {
            peak = std::max(peak, a[i].u.cwiseAbs().maxCoeff());
            du = std::max(du, (a[i].u - h[i].u).cwiseAbs().maxCoeff());
        }
        qInfo("peak |u| %.6g, max |du| %.3g", peak, du);
        QVERIFY(peak > 0.005);
        QVERIFY(du <= 1e-9 * peak);
    }
};

QTEST_GUILESS_MAIN(TestInvertedVBracePreset)
#include "TestInvertedVBracePreset.moc"
