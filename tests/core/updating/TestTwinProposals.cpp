// TwinProposals (core/updating/TwinProposals.h; docs/rths.md, "Proposals approved by the
// console"): the damper twin's offers wait for the operator, in the hybrid test's approval model.
//  - the queue: an offer becomes proposal #N at its tick (nothing applied); approve applies it
//    before the loop's next tick; reject records it, nothing applied; a newer offer supersedes
//    the pending one (an approval of the old one is refused naming its successor); a proposal
//    outside the box is refused at approval and never applied;
//  - in a run (benchmark case 1 at 1024 Hz, the 0.88 V record's damper, its twin on floor 2):
//    a proposal made at tick 1024 and approved before tick 1500 gives the ticks of the run with
//    the same values scheduled before tick 1500, bit for bit; a rejected one (and an
//    out-of-box one approved) gives the run without any update; the run's events say proposed,
//    approved (applied, with the proposal's id), rejected or refused, each at its tick.
#include "core/rths/RthsBenchmark.h"
#include "core/updating/TwinProposals.h"

#include <QtTest>

#include <cmath>
#include <functional>
#include <numbers>

using namespace hsmu;
using namespace hsmu::rths;

namespace {

constexpr double kRate = 1024.0;

RthsSettings damperSettings()
{
    RthsSettings s = benchmarkSampleController();
    s.rate = kRate;
    s.sensors.seed = 5;
    s.damper.enabled = true;
    MrDamperParameters p;
    p.c0 = 0.0236, p.c1 = 3.29, p.k0 = 0.016, p.k1 = 0.0083, p.f0 = -0.069;
    p.alpha = 72.1, p.beta = 2.41, p.gamma = 8.96, p.n = 0.521, p.uRef = 0.0054, p.fRef = 320.0;
    s.damper.specimen = p;
    MrDamperParameters twin; // the law's defaults, in the specimen's scales
    twin.uRef = p.uRef;
    twin.fRef = p.fRef;
    s.damper.twin = twin;
    s.damper.twinDof = 1;
    s.damper.box = {{"alpha", {0.0, 500.0}}, {"c1", {0.01, 100.0}}};
    return s;
}

GroundMotion sine(double seconds)
{
    GroundMotion g;
    g.dt = 0.01;
    g.name = "sine";
    for (int i = 0; i <= int(std::lround(seconds * 100)); ++i)
        g.acceleration.push_back(std::sin(2 * std::numbers::pi * 1.5 * 0.01 * i));
    return g;
}

/// A gate that calls `act` once before tick `at` (on the loop's thread, as the operator's
/// decision arrives between two ticks).
class DecideAt final : public TickGate {
public:
    DecideAt(long at, std::function<void()> act) : m_at(at), m_act(std::move(act)) {}
    bool admit(long k, std::string&) override
    {
        if (k == m_at)
            m_act();
        return true;
    }
    void done(long) override {}

private:
    long m_at;
    std::function<void()> m_act;
};

RthsRun run(TwinUpdateSource* updates, TickGate* gate = nullptr)
{
    const RthsSettings s = damperSettings();
    RthsSettings prepared = s;
    fitToNominalLoop(prepared);
    return runRths(benchmarkPartition(1, s.plant), sine(2.5), prepared, gate, 0.0, nullptr, updates);
}

void sameTicks(const RthsRun& a, const RthsRun& b)
{
    QCOMPARE(a.time.size(), b.time.size());
    for (std::size_t k = 0; k < a.time.size(); ++k) {
        QVERIFY(a.measured[k] == b.measured[k]);
        QVERIFY(a.force[k] == b.force[k]);
    }
    QVERIFY(a.hybrid == b.hybrid);
}

const UpdateEvent* find(const RthsRun& r, UpdateDecision d)
{
    for (const UpdateEvent& e : r.updates)
        if (e.decision == d)
            return &e;
    return nullptr;
}

} // namespace

class TestTwinProposals : public QObject {
    Q_OBJECT
private slots:
    void theQueueFollowsTheApprovalModel()
    {
        ScheduledTwinUpdates offers({{{"alpha"}, {80.0}, "identification", 10},
                                     {{"alpha"}, {90.0}, "identification", 20},
                                     {{"c1"}, {-1.0}, "identification", 30},
                                     {{"alpha"}, {60.0}, "identification", 40},
                                     {{"alpha"}, {70.0}, "identification", 50}});
        TwinProposals q(offers, damperSettings().damper, kRate, true);
        TwinUpdate u;
        UpdateEvent e;
        QVERIFY(!q.next(5, u));
        QVERIFY(!q.next(10, u)); // a proposal, not an update
        QCOMPARE(q.pending().size(), std::size_t(1));
        QCOMPARE(q.pending()[0].id, 1);
        QCOMPARE(q.pending()[0].step, 10);
        QVERIFY(q.nextEvent(10, e));
        QCOMPARE(e.decision, UpdateDecision::Proposed);
        QCOMPARE(e.proposal, 1);
        QCOMPARE(e.step, 10);
        QCOMPARE(e.applied, std::vector<double>{80.0});
        QVERIFY(!q.nextEvent(10, e));
        QCOMPARE(q.approve(1), std::string());
        QVERIFY(q.pending().empty());
        QVERIFY(q.next(11, u));
        QCOMPARE(u.values, std::vector<double>{80.0});
        QCOMPARE(u.proposal, 1);
        QCOMPARE(q.approve(1), std::string("no pending proposal #1"));
        // Rejected: recorded at the next tick, nothing applied.
        QVERIFY(!q.next(20, u));
        QVERIFY(q.nextEvent(20, e) && e.decision == UpdateDecision::Proposed && e.proposal == 2);
        QCOMPARE(q.reject(2), std::string());
        QVERIFY(!q.next(21, u));
        QVERIFY(q.nextEvent(21, e));
        QCOMPARE(e.decision, UpdateDecision::Rejected);
        QCOMPARE(e.step, 21);
        // Outside the box: refused at approval, never applied.
        QVERIFY(!q.next(30, u));
        QVERIFY(q.nextEvent(30, e) && e.proposal == 3);
        const std::string why = q.approve(3);
        QVERIFY2(why.find("c1 = -1 is outside the parameter box [0.01, 100]") != std::string::npos, why.c_str());
        QVERIFY(!q.next(31, u));
        QVERIFY(q.nextEvent(31, e));
        QCOMPARE(e.decision, UpdateDecision::Refused);
        QCOMPARE(e.proposal, 3);
        QVERIFY(q.pending().empty());
        // A newer offer supersedes the pending one.
        QVERIFY(!q.next(40, u));
        QVERIFY(!q.next(50, u));
        QCOMPARE(q.pending().size(), std::size_t(1));
        QCOMPARE(q.pending()[0].id, 5);
        QCOMPARE(q.approve(4), std::string("proposal #4 was superseded by proposal #5"));
        QVERIFY(q.nextEvent(50, e) && e.decision == UpdateDecision::Proposed && e.proposal == 4);
        QVERIFY(q.nextEvent(50, e) && e.decision == UpdateDecision::Superseded && e.proposal == 4);
        QVERIFY(q.nextEvent(50, e) && e.decision == UpdateDecision::Proposed && e.proposal == 5);
    }

    void anApprovedProposalEqualsTheUpdateScheduledAtItsTick()
    {
        const TwinUpdate offer{{"alpha", "c0"}, {80.0, 0.03}, "identification", 1024};
        // Approved before tick 1500.
        ScheduledTwinUpdates offers({offer});
        TwinProposals q(offers, damperSettings().damper, kRate, true);
        DecideAt approve(1500, [&q] { QCOMPARE(q.approve(1), std::string()); });
        const RthsRun approved = run(&q, &approve);
        ScheduledTwinUpdates same({{offer.names, offer.values, "replay", 1500}});
        sameTicks(approved, run(&same));
        const UpdateEvent* made = find(approved, UpdateDecision::Proposed);
        QVERIFY(made && made->step == 1024 && made->proposal == 1);
        const UpdateEvent* applied = find(approved, UpdateDecision::Applied);
        QVERIFY(applied && applied->step == 1500 && applied->proposal == 1);
        QCOMPARE(applied->message, std::string("approved proposal #1"));
        QVERIFY(approved.twin && approved.twin->alpha == 80.0);
        // Rejected: the run without any update, the rejection at its tick.
        ScheduledTwinUpdates offers2({offer});
        TwinProposals q2(offers2, damperSettings().damper, kRate, true);
        DecideAt reject(1500, [&q2] { QCOMPARE(q2.reject(1), std::string()); });
        const RthsRun rejected = run(&q2, &reject);
        const RthsRun plain = run(nullptr);
        sameTicks(rejected, plain);
        const UpdateEvent* no = find(rejected, UpdateDecision::Rejected);
        QVERIFY(no && no->step == 1500 && no->proposal == 1);
        QVERIFY(!find(rejected, UpdateDecision::Applied));
        // Outside the box, approved: refused, never applied.
        ScheduledTwinUpdates offers3({{{"alpha"}, {900.0}, "identification", 1024}});
        TwinProposals q3(offers3, damperSettings().damper, kRate, true);
        DecideAt approve3(1500, [&q3] { QVERIFY(!q3.approve(1).empty()); });
        const RthsRun refused = run(&q3, &approve3);
        sameTicks(refused, plain);
        const UpdateEvent* r = find(refused, UpdateDecision::Refused);
        QVERIFY(r && r->step == 1500);
        QVERIFY(describeTwinUpdate(*r).find("alpha = 900 is outside the parameter box [0, 500]") != std::string::npos);
        QVERIFY(!find(refused, UpdateDecision::Applied));
    }
};

QTEST_APPLESS_MAIN(TestTwinProposals)
#include "TestTwinProposals.moc"
