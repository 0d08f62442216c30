// The one by-position parameter path (docs/method.md, "Parameters by position"): a layout
// resolves names once and refuses an unknown one with the name; each identifier's estimate,
// standard deviations and bounds are in its layout's order; a bound is changed by position and
// only there; a law takes values by position, judged together or one by one.
#include "core/hysteresis/Bilinear.h"
#include "core/hysteresis/BoucWen.h"
#include "core/identification/ParameterLayout.h"
#include "core/updating/NelderMeadIdentifier.h"
#include "core/updating/RobustUkfIdentifier.h"
#include "core/updating/UkfIdentifier.h"

#include <QtTest>

#include <cmath>
#include <stdexcept>

using namespace hsmu;

namespace {

/// The message of the std::invalid_argument that f throws ("" if none).
template <class F> std::string refusal(F f)
{
    try {
        f();
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return {};
}

const std::vector<std::string> kBoucWenUkf{"k0", "alpha", "beta", "gamma", "n", "deltaNu",
                                           "deltaEta"};

} // namespace

class TestParameterLayout : public QObject {
    Q_OBJECT
private slots:
    void namesResolveOnceAndUnknownOnesAreRefusedByName()
    {
        const ParameterLayout layout({"k0", "alpha", "beta"});
        QCOMPARE(layout.size(), std::size_t(3));
        QCOMPARE(layout.name(2), std::string("beta"));
        QCOMPARE(*layout.find("alpha"), std::size_t(1));
        QVERIFY(!layout.find("Alpha")); // names are exact
        QCOMPARE(layout.indexOf("beta", "updating.bounds"), std::size_t(2));
        QCOMPARE(refusal([&] { layout.indexOf("gama", "updating.bounds"); }),
                 std::string("updating.bounds: unknown parameter 'gama' (expected k0, alpha, beta)"));
        const ParameterLayout copy = layout; // shares the names
        QVERIFY(&copy.names() == &layout.names());
        QVERIFY(copy == layout);
        QVERIFY(!(ParameterLayout({"alpha", "k0", "beta"}) == layout)); // order matters
        QVERIFY(ParameterLayout().empty());
    }

    void ukfIdentifierValuesAndBoundsAreInItsLayoutOrder()
    {
        BoucWenParameters p;
        p.k0 = 1.1;
        p.alpha = 0.03;
        p.beta = 2.7;
        p.gamma = 0.4;
        p.n = 1.6;
        p.deltaNu = 0.02;
        p.deltaEta = 0.05;
        UkfIdentifier id(p, {}, {{"n", {1.5, 2.5}}});
        QCOMPARE(id.layout().names(), kBoucWenUkf);
        const std::vector<double> expected{1.1, 0.03, 2.7, 0.4, 1.6, 0.02, 0.05};
        QCOMPARE(std::vector<double>(id.estimate().begin(), id.estimate().end()), expected);
        QCOMPARE(id.standardDeviation().size(), expected.size());
        // The configured bound at n's position, Table III at the others (k0: [0.7, 1.4]).
        QCOMPARE(id.bounds()[4].lower, 1.5);
        QCOMPARE(id.bounds()[4].upper, 2.5);
        QCOMPARE(id.bounds()[0].lower, 0.7);
        QCOMPARE(id.bounds()[0].upper, 1.4);
        // By position: only that bound changes; a position past the layout is refused.
        QVERIFY(id.setBounds(1, {0.01, 0.04}));
        QCOMPARE(id.bounds()[1].upper, 0.04);
        QCOMPARE(id.bounds()[0].upper, 1.4);
        QCOMPARE(id.bounds()[2].upper, 5.0);
        QVERIFY(!id.setBounds(7, {0.0, 1.0}));
        QVERIFY(id.setLocked(2, true));
        QVERIFY(id.locked(2) && !id.locked(3));
        QVERIFY(!id.setLocked(9, true));
        // A configured bound for a name the UKF does not identify: refused with the name.
        QVERIFY(refusal([&] { UkfIdentifier(p, {}, {{"A0", {0.5, 1.5}}}); }).find("'A0'") !=
                std::string::npos);
    }

    void robustUkfLayoutEndsWithTheScalesAndHasNoBoundsForThem()
    {
        BoucWenParameters p;
        RobustUkfIdentifier id(p, 0.02, 20.0, {{"gamma", {-1.0, 1.0}}});
        std::vector<std::string> names = kBoucWenUkf;
        names.push_back("uRef");
        names.push_back("fRef");
        QCOMPARE(id.layout().names(), names);
        QCOMPARE(id.estimate()[7], 0.02);
        QCOMPARE(id.estimate()[8], 20.0);
        QCOMPARE(id.estimate()[3], p.gamma);
        QCOMPARE(id.bounds()[3].lower, -1.0); // gamma's, as configured
        QVERIFY(std::isnan(id.bounds()[0].lower)); // none until the first anchor
        QVERIFY(std::isnan(id.bounds()[7].lower) && std::isnan(id.bounds()[8].upper));
        QVERIFY(!id.setBounds(7, {0.01, 0.03})); // the scales are not bounded
        QVERIFY(id.setBounds(0, {0.5, 2.0}));
        QCOMPARE(id.bounds()[0].upper, 2.0);
        QVERIFY(refusal([&] { RobustUkfIdentifier(p, 0.02, 20.0, {{"kappa", {0.0, 1.0}}}); })
                    .find("'kappa'") != std::string::npos);
    }

    void nelderMeadLayoutIsTheConfiguredOrder()
    {
        const Bilinear model({2.0, 1.0, 0.1});
        NelderMeadIdentifierSettings s;
        s.parameters = {"fy", "k0"};
        s.bounds = {{"k0", {1.0, 3.0}}, {"fy", {0.5, 0.8}}};
        NelderMeadIdentifier id(model, s);
        QCOMPARE(id.layout().names(), s.parameters);
        QCOMPARE(id.estimate()[0], 0.8); // fy = 1.0 clamped into its bounds
        QCOMPARE(id.estimate()[1], 2.0);
        QCOMPARE(id.bounds()[0].upper, 0.8);
        QCOMPARE(id.bounds()[1].upper, 3.0);
        QVERIFY(id.setBounds(1, {1.0, 1.5})); // k0's, and the estimate clamped into it
        QCOMPARE(id.estimate()[1], 1.5);
        QCOMPARE(id.estimate()[0], 0.8);
        QVERIFY(!id.setBounds(1, {2.0, 1.0}));
        QVERIFY(!id.setBounds(2, {0.0, 1.0}));
        s.parameters = {"fy", "E"};
        QVERIFY(refusal([&] { NelderMeadIdentifier(model, s); }).find("'E'") != std::string::npos);
    }

    void lawsTakeValuesByPosition()
    {
        Bilinear law({2.0, 1.0, 0.1});
        QCOMPARE(law.parameterNames(), (std::vector<std::string>{"k0", "fy", "b"}));
        QCOMPARE(law.parameterIndex("b"), 2);
        QCOMPARE(law.parameterIndex("E"), -1);
        QVERIFY(std::isnan(law.parameterValue(3)));
        const int idx[] = {2, 0};
        const double ok[] = {0.2, 3.0};
        QCOMPARE(law.setParameterValues(idx, ok, true), -1);
        QCOMPARE(law.parameterValue(0), 3.0);
        QCOMPARE(law.parameterValue(2), 0.2);
        // All or nothing: b = 1 is refused on its own; nothing changes, its position returned.
        const double bad[] = {1.0, 4.0};
        QCOMPARE(law.setParameterValues(idx, bad, true), 0);
        QCOMPARE(law.parameterValue(0), 3.0);
        // One by one: the refused value is skipped, the others set.
        QCOMPARE(law.setParameterValues(idx, bad, false), 0);
        QCOMPARE(law.parameterValue(0), 4.0);
        QCOMPARE(law.parameterValue(2), 0.2);
        const int unknown[] = {0, 5};
        const double two[] = {5.0, 1.0};
        QCOMPARE(law.setParameterValues(unknown, two, true), 1);
        QCOMPARE(law.parameterValue(0), 4.0);

        // Bouc-Wen: beta and gamma changing sign together pass as one set, not one by one.
        BoucWenParameters p;
        p.beta = 3.0;
        p.gamma = -1.0;
        BoucWen bw(p);
        const int bg[] = {bw.parameterIndex("beta"), bw.parameterIndex("gamma")};
        const double flipped[] = {-1.0, 3.0}; // beta alone at -1 would give beta + gamma < 0
        BoucWen oneByOne = bw;
        QCOMPARE(oneByOne.setParameterValues(bg, flipped, false), 0);
        QCOMPARE(bw.setParameterValues(bg, flipped, true), -1);
        QCOMPARE(bw.parameterValue(bg[0]), -1.0);
        QCOMPARE(bw.parameterValue(bg[1]), 3.0);
        QVERIFY(bw.setParameterValue(bw.parameterIndex("k0"), 1.5));
        QVERIFY(!bw.setParameterValue(bw.parameterIndex("alpha"), 1.5));
    }
};

QTEST_APPLESS_MAIN(TestParameterLayout)
#include "TestParameterLayout.moc"
