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
#include <optional>

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

    // Issue 25 item 2: one proposal per target, renewed every proposal interval with the
    // latest estimate (superseding the pending one, whose fate is an event); an approval of a
    // superseded or stale proposal is refused, so nothing older than one interval is applied.
    void approvalSupersedesPerTargetAndRefusesStaleProposals()
    {
        Rig rig;
        Reporter r(oneTarget(), ReporterPolicy::OnApproval);
        r.setProposalInterval(0.05);
        rig.moveTo(0.02);
        QVERIFY(offer(r, 1, 0.01, estimate(1.2), rig.s).empty()); // the first one at once
        QCOMPARE(int(r.pending().size()), 1);
        const UpdateProposal p = r.pending().front();
        QCOMPARE(valueOf(p.parameters, p.proposed, "k0"), 1.2);
        QCOMPARE(valueOf(p.parameters, p.current, "k0"), 1.0);
        QVERIFY(r.reject(p.id));
        QCOMPARE(*test::parameterNamed(rig.law(), "k0"), 1.0); // rejected: unchanged
        QVERIFY(!r.reject(p.id));                                // gone
        // The next one comes one interval after the last proposal, not at once.
        QVERIFY(offer(r, 2, 0.02, estimate(1.25), rig.s).empty());
        QVERIFY(r.pending().empty());

        r.setProposalFitError(0.25);
        QVERIFY(offer(r, 6, 0.06, estimate(1.3), rig.s).empty());
        QCOMPARE(int(r.pending().size()), 1);
        const int first = r.pending().front().id;
        QCOMPARE(r.pending().front().fitError, 0.25);
        // Within the interval the proposal stays as it is; the latest offer is known.
        QVERIFY(offer(r, 7, 0.07, estimate(1.31), rig.s).empty());
        QCOMPARE(r.pending().front().id, first);
        QCOMPARE(valueOf(r.pending().front().parameters, r.pending().front().proposed, "k0"), 1.3);
        QCOMPARE(r.latestOffer("Target").size(), std::size_t(2));
        QCOMPARE(valueOf(r.pending().front().parameters,
                         std::vector<double>(r.latestOffer("Target").begin(),
                                             r.latestOffer("Target").end()),
                         "k0"),
                 1.31);
        QVERIFY(r.latestOffer("Nowhere").empty());
        // One interval later a new proposal takes its place; the old one's fate is an event.
        const auto events = offer(r, 11, 0.11, estimate(1.35), rig.s);
        QCOMPARE(int(events.size()), 1);
        QCOMPARE(events[0].decision, UpdateDecision::Superseded);
        QCOMPARE(events[0].proposal, first);
        QCOMPARE(events[0].step, 11);
        QCOMPARE(valueOf(events[0].parameters, events[0].applied, "k0"), 1.3);
        QVERIFY(!events[0].ok);
        QCOMPARE(int(r.pending().size()), 1);
        const int newer = r.pending().front().id;
        QVERIFY(newer != first);
        QCOMPARE(r.pending().front().step, 11);
        QCOMPARE(r.supersededBy(first), std::optional<int>(newer));
        QVERIFY(!r.supersededBy(newer));
        // The superseded one cannot be approved; the one shown can.
        QVERIFY(!r.approve(first, rig.s, 11, 0.11));
        const auto ev = r.approve(newer, rig.s, 12, 0.12);
        QVERIFY(ev && ev->ok);
        QCOMPARE(ev->decision, UpdateDecision::Applied);
        QCOMPARE(ev->proposal, newer);
        QCOMPARE(*test::parameterNamed(rig.law(), "k0"), 1.35);
        QCOMPARE(r.appliedCount(), 1);
        // A proposal that no offer renewed for one interval is stale: refused, still pending.
        QVERIFY(offer(r, 16, 0.16, estimate(1.4), rig.s).empty());
        const UpdateProposal last = r.pending().front();
        QVERIFY(!r.stale(last, 0.20));
        QVERIFY(r.stale(last, 0.21));
        QVERIFY(!r.approve(last.id, rig.s, 21, 0.21));
        QCOMPARE(int(r.pending().size()), 1);
        QCOMPARE(*test::parameterNamed(rig.law(), "k0"), 1.35);
        // Rejecting is an event with its values.
        const auto no = r.rejectProposal(last.id, 21, 0.21);
        QVERIFY(no && !no->ok);
        QCOMPARE(no->decision, UpdateDecision::Rejected);
        QCOMPARE(no->proposal, last.id);
        QCOMPARE(valueOf(no->parameters, no->applied, "k0"), 1.4);
        QVERIFY(r.pending().empty());
        QCOMPARE(std::string(updateDecisionName(UpdateDecision::Superseded)), std::string("superseded"));
    }

    // With more targets than the pending list holds, an offer that finds it full is not
    // queued and is reported (never dropped silently); a decision makes room.
    void aFullApprovalQueueReportsEveryOfferNotQueued()
    {
        Structure s;
        s.addDof("DOF 1", 1.0);
        for (const char* name : {"Target", "Twin"}) {
            BoucWenParameters p;
            p.beta = 3.0;
            p.gamma = 1.0;
            s.addElement(SpringElement::lateral(name, 0, std::make_unique<BoucWen>(p)));
        }
        s.finalize();
        Reporter r({{"Target", {"k0"}, {}}, {"Twin", {"k0"}, {}}}, ReporterPolicy::OnApproval);
        r.setProposalInterval(0.0); // every offer renews
        r.setMaxPending(1);
        int notQueued = 0;
        for (int step = 1; step <= 3; ++step) {
            const auto events = offer(r, step, 0.01 * step, estimate(1.0 + 0.01 * step), s);
            for (const UpdateEvent& e : events) {
                if (e.decision == UpdateDecision::Superseded)
                    continue; // Target's own, renewed
                QCOMPARE(e.decision, UpdateDecision::NotQueued);
                QCOMPARE(e.element, std::string("Twin"));
                QCOMPARE(valueOf(e.parameters, e.applied, "k0"), 1.0 + 0.01 * step);
                ++notQueued;
            }
        }
        QCOMPARE(notQueued, 3);
        QCOMPARE(r.notQueuedCount(), 3);
        QCOMPARE(int(r.pending().size()), 1);
        QCOMPARE(r.pending().front().element, std::string("Target"));
        QCOMPARE(r.pending().front().step, 3); // renewed in place
        // The headless flag decides what is pending, rejections included.
        const auto all = r.resolveAll(false, s, 4, 0.04);
        QCOMPARE(int(all.size()), 1);
        QCOMPARE(all[0].decision, UpdateDecision::Rejected);
        // Room again: Target's next offer is queued, Twin's still not (the cap is 1).
        QVERIFY(offer(r, 5, 0.05, estimate(1.05), s).size() == 1);
        QCOMPARE(int(r.pending().size()), 1);
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
