// The preset cantilever-column-lab (resources/presets, docs/presets.md; issue 24): the frame of
// two-actuator-column-frame whose left column the virtual lab simulates as a whole specimen
// ("specimen": {"type": "cantileverColumn"}, docs/setups.md "The specimen as a whole"): a
// Bouc-Wen base hinge (tangent at rest k_h = k0 fRef / uRef = 1.6e5 kN m/rad), EI 2e5 kN m^2,
// L = 3 m, elastic axial 2e5 kN/m, a vertical actuator holding P = 500 kN of compression and a
// lateral actuator lagging 5 ms. Checked against the closed form of W1-W3 (docs/setups.md):
// a free top under compression P has the lateral stiffness k - P/L, k = 1 / (L^2/k_h +
// L^3/(3 EI)) = 9876.5 kN/m:
//  - the shipped preset runs its whole record with no alarm; the vertical actuator holds
//    -500 kN (1e-9 kN) and the top carries no moment (1e-9 kN m) at every step; the lab's
//    default K0 share of the lateral actuator is k (1e-12 relative); at the first steps (shear
//    deformation below 2 % of the hinge's yield drift) the measured secant stiffness V / D is
//    k - P/L to 1e-3 (the Bouc-Wen tangent at rest is k0 and drops by O((D/D_y)^n), n = 2);
//    the column yields (peak shear past 40 kN, M_y / L = 50 kN) and the lagged stroke trails
//    its command;
//  - with the hinge elastic at that tangent and the lateral actuator ideal, the preset equals
//    the frame whose left column is numerical with shear stiffness k - P/L, the axial load held
//    and a free rotation, to 1e-9 of the peak.
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

#include "Link2dFrameFixture.h"

using namespace hsmu;
using namespace link2dframe;

namespace {

const std::string kLabPreset = HSMU_SOURCE_DIR "/resources/presets/cantilever-column-lab.json";
constexpr double kL = 3.0, kEI = 2e5, kHinge = 1.6e5, kP = 500.0;

nlohmann::json labPreset()
{
    std::ifstream in(kLabPreset);
    return nlohmann::json::parse(in);
}

double freeTopStiffness() { return 1.0 / (kL * kL / kHinge + kL * kL * kL / (3.0 * kEI)); }

/// Index of the channel `name` of element `element` in the run's channels.
int channel(const RunLayout& layout, const std::string& element, const std::string& name)
{
    for (std::size_t i = 0; i < layout.channels.size(); ++i)
        if (layout.channels[i].element == element && layout.channels[i].name == name)
            return static_cast<int>(i);
    qFatal("no channel %s of %s", name.c_str(), element.c_str());
    return -1;
}

} // namespace

class TestCantileverColumnLabPreset : public QObject {
    Q_OBJECT

private slots:
    void presetRunsAgainstTheClosedForm()
    {
        const nlohmann::json doc = labPreset();
        const TestConfig cfg = parseConfig(doc, "cantilever-column-lab.json");
        const double k = freeTopStiffness();
        QVERIFY(std::abs(cfg.elements[0].link2d->actuators[1].channel.initialStiffness - k) <=
                1e-12 * k);
        std::unique_ptr<HybridTest> test;
        const auto recs = run(doc, 0.0, &test); // the whole record
        QVERIFY(recs.size() > 500);
        QVERIFY(test->alarms().empty());
        const RunLayout layout = RunLayout::of(*test);
        const int vForce = channel(layout, "Column L", "vertical force");
        const int mForce = channel(layout, "Column L", "rotation force");
        const int dShear = channel(layout, "Column L", "shear deformation");
        const int qShear = channel(layout, "Column L", "shear force");
        const int lCommand = channel(layout, "Column L", "lateral command");
        const int lStroke = channel(layout, "Column L", "lateral stroke");
        const double dYield = 150.0 / kHinge * kL; // the hinge's yield drift [m]
        double worstAxial = 0.0, worstMoment = 0.0, worstSecant = 0.0, peakShear = 0.0,
               lagged = 0.0;
        int secants = 0;
        for (std::size_t s = 1; s < recs.size(); ++s) {
            const std::vector<double>& c = recs[s].channels;
            worstAxial = std::max(worstAxial, std::abs(c[vForce] + kP));
            worstMoment = std::max(worstMoment, std::abs(c[mForce]));
            peakShear = std::max(peakShear, std::abs(c[qShear]));
            lagged = std::max(lagged, std::abs(c[lStroke] - c[lCommand]));
            const double d = c[dShear];
            if (secants < 20 && std::abs(d) > 1e-7 && std::abs(d) < 0.02 * dYield) {
                // the shear deformation's history never left this range before: still virgin
                worstSecant = std::max(worstSecant,
                                       std::abs(c[qShear] / d - (k - kP / kL)) / (k - kP / kL));
                ++secants;
            }
        }
        qInfo("steps %d, peak shear %.6g kN, axial %.3g kN, moment %.3g kN m, secant %.3g over "
              "%d steps, stroke - command up to %.3g m",
              int(recs.size()), peakShear, worstAxial, worstMoment, worstSecant, secants,
              lagged);
        QVERIFY(secants >= 5);
        QVERIFY(worstSecant <= 1e-3);
        QVERIFY(worstAxial <= 1e-9);
        QVERIFY(worstMoment <= 1e-9);
        QVERIFY(peakShear > 40.0 && peakShear < 80.0);
        QVERIFY(lagged > 0.0);
    }

    // The hinge elastic at the Bouc-Wen's tangent at rest, the lateral actuator ideal: the
    // frame equals its closed-form twin (left column numerical, k - P/L) to 1e-9 of the peak.
    void elasticHingeEqualsTheClosedFormTwin()
    {
        const double k = freeTopStiffness();
        nlohmann::json lab = labPreset();
        nlohmann::json& col = lab["structure"]["elements"][0];
        col["specimen"]["hinge"] = {{"law", "elastic"}, {"k", kHinge}};
        col["actuators"][1].erase("actuator");
        col["actuators"][1]["initialStiffness"] = k - kP / kL;
        nlohmann::json twin = labPreset();
        nlohmann::json& num = twin["structure"]["elements"][0];
        for (const char* key : {"experimental", "setup", "specimen", "actuators"})
            num.erase(key);
        num["basic"] = nlohmann::json::array({{{"heldForce", -kP}},
                                              {{"material", {{"law", "elastic"}, {"k", k - kP / kL}}}},
                                              nlohmann::json::object()});
        const auto a = run(twin, 4.0);
        const auto b = run(lab, 4.0);
        QCOMPARE(a.size(), b.size());
        const RunDifference d = compareRuns(a, b);
        QVERIFY(d.peak > 0.005);
        QVERIFY(d.du <= 1e-9 * d.peak);
        QVERIFY(d.dF <= 1e-9 * d.peakF);
    }
};

QTEST_APPLESS_MAIN(TestCantileverColumnLabPreset)
#include "TestCantileverColumnLabPreset.moc"
