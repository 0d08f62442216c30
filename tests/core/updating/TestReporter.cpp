// Reporter policies (core/updating/Reporter.h): each fires exactly when it should, approval
// applies and rejection does not, a target's Bouc-Wen state stays continuous, nothing
// non-finite is ever applied.
#include "core/hysteresis/BoucWen.h"
#include "core/hysteresis/LinearElastic.h"
#include "core/structure/SpringElement.h"
#include "core/structure/Structure.h"
#include "core/updating/Reporter.h"
#include "tests/support/LawByName.h"

#include <QtTest>

#include <cmath>
#include <cstring>

using namespace hsmu;

namespace {

/// One DOF with a Bouc-Wen lateral spring "Target" driven by hand.
struct Rig {
    Structure s;
    explicit Rig()
    {
        s.addDof("DOF 1", 1.0);
        BoucWenParameters p;
        p.k0 = 1.0;
        p.alpha = 0.05;
        p.beta = 3.0;
        p.gamma = 1.0;
        s.addElement(SpringElement::lateral("Target", 0, std::make_unique<BoucWen>(p)));
        s.finalize();
    }
    /// Move the DOF to u and commit.
    void moveTo(double u)
    {
        Eigen::VectorXd x(1);
        x << u;
        QVERIFY(s.setTrial(x).ok);
        QVERIFY(s.commit().ok);
    }
    HysteresisLaw& law() { return *s.element("Target")->law(); }
};

/// The identifier's layout these tests offer in, and an estimate in it.
const ParameterLayout kIdentified({"k0", "alpha", "A0"});
std::vector<double> estimate(double k0) { return {k0, 0.04, 2.0}; }

/// Offer `values` (kIdentified order) once bound to `s`; the events decided.
std::vector<UpdateEvent> offer(Reporter& r, int step, double time,
                               const std::vector<double>& values, Structure& s)
{
    std::vector<UpdateEvent> events;
    if (r.bind(s, kIdentified, nullptr))
        r.offer(step, time, values, s, events);
    return events;
}

/// The value of parameter `name` among `values` in `names` order.
double valueOf(const ParameterLayout& names, const std::vector<double>& values,
               const std::string& name)
{
    return values.at(names.indexOf(name, "test"));
}

std::vector<ReporterTarget> oneTarget()
{
    return {{"Target", {"k0", "alpha"}, {}}};
}

} // namespace

class TestReporter : public QObject {
    Q_OBJECT
private slots:
    // Values by position in the identifier's layout (any order) reach the target's parameters
    // of those names, scaled, bit for bit as setting them on the law directly; events carry
    // the target's names in name order; a NaN and a value the law refuses are refused by name.
    void offerRoutesValuesByPosition()
    {
        const ParameterLayout identified({"k0", "A0", "alpha"}); // not in name order
        const std::vector<ReporterTarget> targets{{"Target", {"k0", "alpha", "gamma"}, {{"k0", 0.9}}}};
        Rig rig, reference;
        Reporter r(targets, ReporterPolicy::EveryStep);
        QVERIFY(r.bind(rig.s, identified, nullptr));
        const int k0At = reference.law().parameterIndex("k0");
        const int alphaAt = reference.law().parameterIndex("alpha");
        int applied = 0, refused = 0;
        std::string lastRefusal;
        std::vector<UpdateEvent> events;
        for (int step = 1; step <= 40; ++step) {
            const double u = 0.05 * std::sin(0.4 * step);
            rig.moveTo(u);
            reference.moveTo(u);
            // Step 17: a NaN; step 23: alpha > 1, which the law refuses.
            const double alpha = step == 23 ? 1.5 : 0.04 + 0.001 * step;
            const double k0 = step == 17 ? NAN : 1.0 + 0.01 * step;
            const std::vector<double> values{k0, 2.0, alpha};
            events.clear();
            applied += r.offer(step, 0.01 * step, values, rig.s, events);
            QCOMPARE(events.size(), std::size_t(1));
            const UpdateEvent& ev = events.front();
            QCOMPARE(ev.parameters.names(), (std::vector<std::string>{"alpha", "k0"}));
            QCOMPARE(ev.applied.size(), std::size_t(2));
            QCOMPARE(ev.applied[0], alpha);
            if (step != 17)
                QCOMPARE(ev.applied[1], 0.9 * k0);
            if (ev.ok) {
                const int idx[] = {alphaAt, k0At};
                const double set[] = {alpha, 0.9 * k0};
                QCOMPARE(reference.law().setParameterValues(idx, set, true), -1);
            } else {
                ++refused;
                lastRefusal = ev.message;
            }
            for (int i = 0; i < int(rig.law().parameterNames().size()); ++i) {
                const double x = rig.law().parameterValue(i), y = reference.law().parameterValue(i);
                QVERIFY(std::memcmp(&x, &y, sizeof x) == 0);
            }
            const double fa = rig.law().committedForce(), fb = reference.law().committedForce();
            QVERIFY(std::memcmp(&fa, &fb, sizeof fa) == 0);
        }
        QCOMPARE(applied, 38); // all but the NaN and the refused alpha
        QCOMPARE(r.appliedCount(), 38);
        QCOMPARE(refused, 2);
        QVERIFY(lastRefusal.find("refused alpha") != std::string::npos);
    }

    void everyStepAppliesEveryOffer()
    {
        Rig rig;
        Reporter r(oneTarget(), ReporterPolicy::EveryStep);
        for (int step = 1; step <= 5; ++step) {
            rig.moveTo(0.01 * step);
            const auto ev = offer(r, step, 0.01 * step, estimate(1.0 + 0.01 * step), rig.s);
            QCOMPARE(int(ev.size()), 1);
            QVERIFY(ev[0].ok);
            QCOMPARE(*test::parameterNamed(rig.law(), "k0"), 1.0 + 0.01 * step);
        }
        QCOMPARE(r.appliedCount(), 5);
        // Only the named parameters go: A0 was offered but is not in the target's list.
        QCOMPARE(*test::parameterNamed(rig.law(), "A0"), 1.0);
        QCOMPARE(*test::parameterNamed(rig.law(), "alpha"), 0.04);
    }

    void everyNStepsFiresOnMultiplesOfN()
    {
        Rig rig;
        Reporter r(oneTarget(), ReporterPolicy::EveryNSteps, 4);
        std::vector<int> fired;
        for (int step = 1; step <= 12; ++step)
            if (!offer(r, step, 0.0, estimate(1.1), rig.s).empty())
                fired.push_back(step);
        QCOMPARE(fired, (std::vector<int>{4, 8, 12}));
    }

    void zeroCrossingFiresOnlyWhenTheTargetForceChangesSign()
    {
        Rig rig;
        Reporter r(oneTarget(), ReporterPolicy::ZeroCrossing);
        // A history whose force is + for steps 1-3, - for 4-6, + from 7 on.
        const double u[] = {0.0, 0.02, 0.03, 0.01, -0.05, -0.06, -0.02, 0.06, 0.07};
        std::vector<int> fired;
        double previous = 0.0;
        std::vector<int> expected;
        for (int step = 1; step < 9; ++step) {
            rig.moveTo(u[step]);
            const double f = rig.law().committedForce();
            if ((previous < 0 && f >= 0) || (previous > 0 && f <= 0))
                expected.push_back(step);
            previous = f;
            if (!offer(r, step, 0.0, estimate(1.1), rig.s).empty())
                fired.push_back(step);
        }
        QVERIFY(!expected.empty());
        QCOMPARE(fired, expected);
    }

    void approvalAppliesAndRejectionDoesNot()
    {
        Rig rig;
        Reporter r(oneTarget(), ReporterPolicy::OnApproval);
        rig.moveTo(0.02);
        QVERIFY(offer(r, 1, 0.01, estimate(1.2), rig.s).empty());
        QCOMPARE(int(r.pending().size()), 1);
        const UpdateProposal p = r.pending().front();
        QCOMPARE(valueOf(p.parameters, p.proposed, "k0"), 1.2);
        QCOMPARE(valueOf(p.parameters, p.current, "k0"), 1.0);
        QVERIFY(r.reject(p.id));
        QCOMPARE(*test::parameterNamed(rig.law(), "k0"), 1.0); // rejected: unchanged
        QVERIFY(!r.reject(p.id));                   // gone

        r.setProposalFitError(0.25);
        offer(r, 2, 0.02, estimate(1.3), rig.s);
        offer(r, 3, 0.03, estimate(1.35), rig.s); // queued after the older one, not replacing it
        QCOMPARE(int(r.pending().size()), 2);
        QCOMPARE(valueOf(r.pending().front().parameters, r.pending().front().proposed, "k0"), 1.3);
        QCOMPARE(valueOf(r.pending().back().parameters, r.pending().back().proposed, "k0"), 1.35);
        QCOMPARE(r.pending().back().fitError, 0.25);
        const auto ev = r.approve(r.pending().back().id, rig.s, 3, 0.03);
        QVERIFY(ev && ev->ok);
        QCOMPARE(ev->decision, UpdateDecision::Applied);
        QCOMPARE(*test::parameterNamed(rig.law(), "k0"), 1.35);
        QCOMPARE(r.appliedCount(), 1);
        // The older one is still pending; rejecting it is an event with its values.
        const int older = r.pending().front().id;
        const auto no = r.rejectProposal(older, 4, 0.04);
        QVERIFY(no && !no->ok);
        QCOMPARE(no->decision, UpdateDecision::Rejected);
        QCOMPARE(no->proposal, older);
        QCOMPARE(valueOf(no->parameters, no->applied, "k0"), 1.3);
        QCOMPARE(no->step, 4);
        QCOMPARE(*test::parameterNamed(rig.law(), "k0"), 1.35);
        QVERIFY(r.pending().empty());
    }

    void aFullApprovalQueueReportsEveryOfferNotQueued()
    {
        Rig rig;
        Reporter r(oneTarget(), ReporterPolicy::OnApproval);
        r.setMaxPending(3);
        int notQueued = 0;
        for (int step = 1; step <= 5; ++step) {
            const auto events = offer(r, step, 0.01 * step, estimate(1.0 + 0.01 * step), rig.s);
            for (const UpdateEvent& e : events) {
                QCOMPARE(e.decision, UpdateDecision::NotQueued);
                QCOMPARE(e.step, step);
                QCOMPARE(valueOf(e.parameters, e.applied, "k0"), 1.0 + 0.01 * step); // what was offered
                ++notQueued;
            }
        }
        QCOMPARE(notQueued, 2);
        QCOMPARE(r.notQueuedCount(), 2);
        QCOMPARE(int(r.pending().size()), 3);
        QCOMPARE(r.pending().front().step, 1); // the oldest kept: nothing moves under the operator
        // A decision makes room for the next offer.
        QVERIFY(r.reject(r.pending().front().id));
        QVERIFY(offer(r, 6, 0.06, estimate(1.06), rig.s).empty());
        QCOMPARE(r.pending().back().step, 6);
        // The headless flag decides every one, rejections included.
        const auto all = r.resolveAll(false, rig.s, 7, 0.07);
        QCOMPARE(int(all.size()), 3);
        for (const UpdateEvent& e : all)
            QCOMPARE(e.decision, UpdateDecision::Rejected);
        QCOMPARE(*test::parameterNamed(rig.law(), "k0"), 1.0);
    }

    void applyingKeepsTheTargetStateContinuous()
    {
        Rig rig;
        rig.moveTo(0.5);
        auto* bw = dynamic_cast<BoucWen*>(&rig.law());
        const BoucWenState before = bw->committedState();
        Reporter r(oneTarget(), ReporterPolicy::EveryStep);
        offer(r, 1, 0.0, estimate(1.3), rig.s);
        const BoucWenState after = bw->committedState();
        QCOMPARE(after.z, before.z);
        QCOMPARE(after.e, before.e);
        // Force changes only through k0 and alpha at the same (u, z): closed form.
        const double expected = 0.04 * 1.3 * 0.5 + (1 - 0.04) * 1.3 * before.z;
        QVERIFY(std::abs(bw->committedForce() - expected) < 1e-12);
    }

    void scaleConvertsForCategoryTwoTwins()
    {
        Rig rig;
        Reporter r({{"Target", {"k0"}, {{"k0", 0.5}}}}, ReporterPolicy::EveryStep);
        offer(r, 1, 0.0, estimate(1.2), rig.s);
        QCOMPARE(*test::parameterNamed(rig.law(), "k0"), 0.6);
    }

    void nothingNonFiniteOrRefusedIsApplied()
    {
        Rig rig;
        Reporter r(oneTarget(), ReporterPolicy::EveryStep);
        auto ev = offer(r, 1, 0.0, {NAN, 0.04, 2.0}, rig.s);
        QVERIFY(!ev[0].ok);
        QVERIFY(ev[0].message.find("not finite") != std::string::npos);
        QCOMPARE(*test::parameterNamed(rig.law(), "k0"), 1.0);
        QCOMPARE(*test::parameterNamed(rig.law(), "alpha"), 0.05);
        // n = -1 is refused by the law after k0 was set: all or nothing, k0 is restored.
        Reporter r2({{"Target", {"k0", "n"}, {}}}, ReporterPolicy::EveryStep);
        std::vector<UpdateEvent> events;
        QVERIFY(r2.bind(rig.s, ParameterLayout({"k0", "n"}), nullptr));
        r2.offer(2, 0.0, std::vector<double>{1.2, -1.0}, rig.s, events);
        ev = events;
        QVERIFY(!ev[0].ok);
        QVERIFY(ev[0].message.find("refused n") != std::string::npos);
        QCOMPARE(*test::parameterNamed(rig.law(), "k0"), 1.0);
        QCOMPARE(*test::parameterNamed(rig.law(), "n"), 2.0);
        QCOMPARE(r.appliedCount() + r2.appliedCount(), 0);
    }

    // A target naming a parameter its law does not have is refused when bound, with the
    // target and the name; a target that is not a numerical element too.
    void bindRefusesUnknownNamesWithTheName()
    {
        Rig rig;
        std::string error;
        Reporter bad({{"Target", {"k0", "kappa"}, {}}}, ReporterPolicy::EveryStep);
        QVERIFY(!bad.bind(rig.s, kIdentified, &error));
        QVERIFY2(error.find("target 'Target'") != std::string::npos &&
                     error.find("unknown parameter 'kappa'") != std::string::npos,
                 error.c_str());
        Reporter badScale({{"Target", {"k0"}, {{"k00", 2.0}}}}, ReporterPolicy::EveryStep);
        QVERIFY(!badScale.bind(rig.s, kIdentified, &error));
        QVERIFY2(error.find("unknown parameter 'k00'") != std::string::npos, error.c_str());
        Reporter missing({{"Nowhere", {"k0"}, {}}}, ReporterPolicy::EveryStep);
        QVERIFY(!missing.bind(rig.s, kIdentified, &error));
        QVERIFY2(error.find("'Nowhere' is not a numerical element") != std::string::npos,
                 error.c_str());
        Reporter good(oneTarget(), ReporterPolicy::EveryStep);
        QVERIFY(good.bind(rig.s, kIdentified, &error));
    }

    void policyChangeTakesEffectOnTheNextOffer()
    {
        Rig rig;
        Reporter r(oneTarget(), ReporterPolicy::OnApproval);
        QVERIFY(offer(r, 1, 0.0, estimate(1.1), rig.s).empty());
        r.setPolicy(ReporterPolicy::EveryStep, 1);
        QCOMPARE(int(offer(r, 2, 0.0, estimate(1.2), rig.s).size()), 1);
        QCOMPARE(*test::parameterNamed(rig.law(), "k0"), 1.2);
    }
};

QTEST_APPLESS_MAIN(TestReporter)
#include "TestReporter.moc"
