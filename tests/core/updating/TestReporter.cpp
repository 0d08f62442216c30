// Reporter policies (core/updating/Reporter.h): each fires exactly when it should, approval
// applies and rejection does not, a target's Bouc-Wen state stays continuous, nothing
// non-finite is ever applied.
#include "core/hysteresis/BoucWen.h"
#include "core/hysteresis/LinearElastic.h"
#include "core/structure/SpringElement.h"
#include "core/structure/Structure.h"
#include "core/updating/Reporter.h"

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

ParameterValues estimate(double k0) { return {{"k0", k0}, {"alpha", 0.04}, {"A0", 2.0}}; }

std::vector<ReporterTarget> oneTarget()
{
    return {{"Target", {"k0", "alpha"}, {}}};
}

} // namespace

class TestReporter : public QObject {
    Q_OBJECT
private slots:
    void offerValuesEqualsOffer_data()
    {
        QTest::addColumn<int>("policy");
        for (ReporterPolicy p : {ReporterPolicy::EveryStep, ReporterPolicy::ZeroCrossing,
                                 ReporterPolicy::EveryNSteps, ReporterPolicy::OnApproval})
            QTest::newRow(reporterPolicyName(p)) << int(p);
    }

    // The by-position offer (names resolved once by bind()) against the by-name one on a twin
    // rig: the same decisions, the same parameters and forces bit for bit, the same refusals.
    void offerValuesEqualsOffer()
    {
        QFETCH(int, policy);
        const std::vector<std::string> names{"A0", "alpha", "k0"}; // sorted, as in a map
        const std::vector<ReporterTarget> targets{{"Target", {"k0", "alpha", "gamma"}, {{"k0", 0.9}}}};
        Rig a, b;
        Reporter byName(targets, static_cast<ReporterPolicy>(policy), 3);
        Reporter byPosition(targets, static_cast<ReporterPolicy>(policy), 3);
        QVERIFY(byPosition.bind(b.s, names, nullptr));
        int appliedA = 0, appliedB = 0, refusedA = 0;
        std::string lastRefusal;
        std::vector<UpdateEvent> eventsB;
        for (int step = 1; step <= 40; ++step) {
            const double u = 0.05 * std::sin(0.4 * step);
            a.moveTo(u);
            b.moveTo(u);
            // Step 17: a NaN; step 23: alpha > 1, which the law refuses.
            const double alpha = step == 23 ? 1.5 : 0.04 + 0.001 * step;
            const double k0 = step == 17 ? NAN : 1.0 + 0.01 * step;
            const std::vector<UpdateEvent> eventsA =
                byName.offer(step, 0.01 * step, {{"A0", 2.0}, {"alpha", alpha}, {"k0", k0}}, a.s);
            for (const UpdateEvent& ev : eventsA) {
                appliedA += ev.ok;
                refusedA += !ev.ok;
            }
            const std::vector<double> values{2.0, alpha, k0};
            eventsB.clear();
            appliedB += byPosition.offerValues(step, 0.01 * step, values, b.s, eventsB);
            QCOMPARE(appliedB, appliedA);
            QCOMPARE(eventsB.size(), eventsA.size()); // the same events, applied or refused
            for (std::size_t e = 0; e < eventsA.size(); ++e) {
                QCOMPARE(eventsB[e].ok, eventsA[e].ok);
                QCOMPARE(eventsB[e].element, eventsA[e].element);
                QCOMPARE(eventsB[e].step, eventsA[e].step);
                QCOMPARE(eventsB[e].applied.size(), eventsA[e].applied.size());
                for (auto i = eventsA[e].applied.cbegin(), j = eventsB[e].applied.cbegin();
                     i != eventsA[e].applied.end(); ++i, ++j)
                    QVERIFY(i->first == j->first &&
                            (std::memcmp(&i->second, &j->second, sizeof(double)) == 0));
                if (!eventsA[e].ok)
                    lastRefusal = eventsB[e].message;
            }
            for (const auto& n : a.law().parameterNames()) {
                const double x = *a.law().parameter(n), y = *b.law().parameter(n);
                QVERIFY(std::memcmp(&x, &y, sizeof x) == 0);
            }
            const double fa = a.law().committedForce(), fb = b.law().committedForce();
            QVERIFY(std::memcmp(&fa, &fb, sizeof fa) == 0);
            QCOMPARE(byPosition.pending().size(), byName.pending().size());
            if (!byName.pending().empty()) { // bit for bit (step 17 proposes a NaN)
                const ParameterValues &x = byPosition.pending().back().proposed,
                                      &y = byName.pending().back().proposed;
                QCOMPARE(x.size(), y.size());
                for (auto i = x.begin(), j = y.begin(); i != x.end(); ++i, ++j)
                    QVERIFY(i->first == j->first &&
                            std::memcmp(&i->second, &j->second, sizeof(double)) == 0);
            }
        }
        QCOMPARE(byPosition.appliedCount(), byName.appliedCount());
        if (static_cast<ReporterPolicy>(policy) == ReporterPolicy::EveryStep) {
            QCOMPARE(appliedA, 38); // all but the NaN and the refused alpha
            QCOMPARE(refusedA, 2);
            QVERIFY(lastRefusal.find("refused alpha") != std::string::npos);
        }
    }

    void everyStepAppliesEveryOffer()
    {
        Rig rig;
        Reporter r(oneTarget(), ReporterPolicy::EveryStep);
        for (int step = 1; step <= 5; ++step) {
            rig.moveTo(0.01 * step);
            const auto ev = r.offer(step, 0.01 * step, estimate(1.0 + 0.01 * step), rig.s);
            QCOMPARE(int(ev.size()), 1);
            QVERIFY(ev[0].ok);
            QCOMPARE(*rig.law().parameter("k0"), 1.0 + 0.01 * step);
        }
        QCOMPARE(r.appliedCount(), 5);
        // Only the named parameters go: A0 was offered but is not in the target's list.
        QCOMPARE(*rig.law().parameter("A0"), 1.0);
        QCOMPARE(*rig.law().parameter("alpha"), 0.04);
    }

    void everyNStepsFiresOnMultiplesOfN()
    {
        Rig rig;
        Reporter r(oneTarget(), ReporterPolicy::EveryNSteps, 4);
        std::vector<int> fired;
        for (int step = 1; step <= 12; ++step)
            if (!r.offer(step, 0.0, estimate(1.1), rig.s).empty())
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
            if (!r.offer(step, 0.0, estimate(1.1), rig.s).empty())
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
        QVERIFY(r.offer(1, 0.01, estimate(1.2), rig.s).empty());
        QCOMPARE(int(r.pending().size()), 1);
        const UpdateProposal p = r.pending().front();
        QCOMPARE(p.proposed.at("k0"), 1.2);
        QCOMPARE(p.current.at("k0"), 1.0);
        QVERIFY(r.reject(p.id));
        QCOMPARE(*rig.law().parameter("k0"), 1.0); // rejected: unchanged
        QVERIFY(!r.reject(p.id));                   // gone

        r.setProposalFitError(0.25);
        r.offer(2, 0.02, estimate(1.3), rig.s);
        r.offer(3, 0.03, estimate(1.35), rig.s); // queued after the older one, not replacing it
        QCOMPARE(int(r.pending().size()), 2);
        QCOMPARE(r.pending().front().proposed.at("k0"), 1.3);
        QCOMPARE(r.pending().back().proposed.at("k0"), 1.35);
        QCOMPARE(r.pending().back().fitError, 0.25);
        const auto ev = r.approve(r.pending().back().id, rig.s, 3, 0.03);
        QVERIFY(ev && ev->ok);
        QCOMPARE(ev->decision, UpdateDecision::Applied);
        QCOMPARE(*rig.law().parameter("k0"), 1.35);
        QCOMPARE(r.appliedCount(), 1);
        // The older one is still pending; rejecting it is an event with its values.
        const int older = r.pending().front().id;
        const auto no = r.rejectProposal(older, 4, 0.04);
        QVERIFY(no && !no->ok);
        QCOMPARE(no->decision, UpdateDecision::Rejected);
        QCOMPARE(no->proposal, older);
        QCOMPARE(no->applied.at("k0"), 1.3);
        QCOMPARE(no->step, 4);
        QCOMPARE(*rig.law().parameter("k0"), 1.35);
        QVERIFY(r.pending().empty());
    }

    void aFullApprovalQueueReportsEveryOfferNotQueued()
    {
        Rig rig;
        Reporter r(oneTarget(), ReporterPolicy::OnApproval);
        r.setMaxPending(3);
        int notQueued = 0;
        for (int step = 1; step <= 5; ++step) {
            const auto events = r.offer(step, 0.01 * step, estimate(1.0 + 0.01 * step), rig.s);
            for (const UpdateEvent& e : events) {
                QCOMPARE(e.decision, UpdateDecision::NotQueued);
                QCOMPARE(e.step, step);
                QCOMPARE(e.applied.at("k0"), 1.0 + 0.01 * step); // what was offered
                ++notQueued;
            }
        }
        QCOMPARE(notQueued, 2);
        QCOMPARE(r.notQueuedCount(), 2);
        QCOMPARE(int(r.pending().size()), 3);
        QCOMPARE(r.pending().front().step, 1); // the oldest kept: nothing moves under the operator
        // A decision makes room for the next offer.
        QVERIFY(r.reject(r.pending().front().id));
        QVERIFY(r.offer(6, 0.06, estimate(1.06), rig.s).empty());
        QCOMPARE(r.pending().back().step, 6);
        // The headless flag decides every one, rejections included.
        const auto all = r.resolveAll(false, rig.s, 7, 0.07);
        QCOMPARE(int(all.size()), 3);
        for (const UpdateEvent& e : all)
            QCOMPARE(e.decision, UpdateDecision::Rejected);
        QCOMPARE(*rig.law().parameter("k0"), 1.0);
    }

    void applyingKeepsTheTargetStateContinuous()
    {
        Rig rig;
        rig.moveTo(0.5);
        auto* bw = dynamic_cast<BoucWen*>(&rig.law());
        const BoucWenState before = bw->committedState();
        Reporter r(oneTarget(), ReporterPolicy::EveryStep);
        r.offer(1, 0.0, estimate(1.3), rig.s);
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
        r.offer(1, 0.0, estimate(1.2), rig.s);
        QCOMPARE(*rig.law().parameter("k0"), 0.6);
    }

    void nothingNonFiniteOrRefusedIsApplied()
    {
        Rig rig;
        Reporter r(oneTarget(), ReporterPolicy::EveryStep);
        auto ev = r.offer(1, 0.0, {{"k0", NAN}, {"alpha", 0.04}}, rig.s);
        QVERIFY(!ev[0].ok);
        QVERIFY(ev[0].message.find("not finite") != std::string::npos);
        QCOMPARE(*rig.law().parameter("k0"), 1.0);
        QCOMPARE(*rig.law().parameter("alpha"), 0.05);
        // n = -1 is refused by the law after k0 was set: all or nothing, k0 is restored.
        Reporter r2({{"Target", {"k0", "n"}, {}}}, ReporterPolicy::EveryStep);
        ev = r2.offer(2, 0.0, {{"k0", 1.2}, {"n", -1.0}}, rig.s);
        QVERIFY(!ev[0].ok);
        QVERIFY(ev[0].message.find("refused n") != std::string::npos);
        QCOMPARE(*rig.law().parameter("k0"), 1.0);
        QCOMPARE(*rig.law().parameter("n"), 2.0);
        QCOMPARE(r.appliedCount() + r2.appliedCount(), 0);
    }

    void policyChangeTakesEffectOnTheNextOffer()
    {
        Rig rig;
        Reporter r(oneTarget(), ReporterPolicy::OnApproval);
        QVERIFY(r.offer(1, 0.0, estimate(1.1), rig.s).empty());
        r.setPolicy(ReporterPolicy::EveryStep, 1);
        QCOMPARE(int(r.offer(2, 0.0, estimate(1.2), rig.s).size()), 1);
        QCOMPARE(*rig.law().parameter("k0"), 1.2);
    }
};

QTEST_APPLESS_MAIN(TestReporter)
#include "TestReporter.moc"
