// A force-controlled actuator following a schedule of (t, F) points (core/experimental/
// ActuatorChannel.h, eq. F1; docs/setups.md "Scheduled forces"), on the preset
// two-actuator-column-frame whose vertical actuator (elastic, 2e5 kN/m, on the column's axial
// DOF through NoTransformation) ramps the axial load up, holds it and lets it down:
//  - commandedForce against the closed form (piecewise linear, constant outside);
//  - the run: at every step k the vertical actuator's recorded command equals F(k dt) of the
//    closed form to 1e-12 kN, its measured force F to 1e-12 max(1, |F|) (the lab's Newton
//    tolerance), its stroke F / 2e5 to 1e-12 relative, the element's axial basic force F;
//  - the limits are still checked on F(t): a schedule that crosses the force limit is refused
//    at configuration time naming the actuator and the time; built past that check, the test
//    holds at the first step whose F(t) exceeds the limit, before that command leaves, every
//    actuator holding at its committed stroke and force.
// Units: kN, m, s.

#include "core/config/ConfigLoader.h"
#include "core/config/TestFactory.h"
#include "core/experiment/HybridTest.h"
#include "core/experimental/ActuatorChannel.h"
#include "core/experimental/ExperimentalLink2d.h"
#include "core/experimental/VirtualActuatorLab.h"
#include "core/output/RunLayout.h"
#include "core/structure/Structure.h"

#include <QtTest>

#include <cmath>
#include <fstream>

using namespace hsmu;
using nlohmann::json;

namespace {

const std::string kPreset = HSMU_SOURCE_DIR "/resources/presets/two-actuator-column-frame.json";
constexpr double kVerticalK = 2e5; // [kN/m]

// The schedule of the run: 0 -> -500 kN over 1 s, held to 2 s, -300 kN at 3 s, then held.
const json kSchedule = json::array({{0.0, 0.0}, {1.0, -500.0}, {2.0, -500.0}, {3.0, -300.0}});

// F(t) by hand (eq. F1 for this schedule).
double closedForm(double t) {
    if (t <= 0.0)
        return 0.0;
    if (t <= 1.0)
        return -500.0 * t;
    if (t <= 2.0)
        return -500.0;
    if (t <= 3.0)
        return -500.0 + 200.0 * (t - 2.0);
    return -300.0;
}

json presetWith(const json& schedule) {
    std::ifstream in(kPreset);
    json doc = json::parse(in);
    json& vertical = doc["structure"]["elements"][0]["actuators"][0];
    vertical.erase("force");
    vertical["forceSchedule"] = schedule;
    return doc;
}

struct Recorder final : StepObserver {
    std::vector<StepRecord> records;
    void onStep(const StepRecord& r) override { records.push_back(r); }
};

int channel(const RunLayout& layout, const std::string& name) {
    for (std::size_t j = 0; j < layout.channels.size(); ++j)
        if (layout.channels[j].element == "Column L" && layout.channels[j].name == name)
            return int(j);
    return -1;
}

} // namespace

class TestScheduledForce : public QObject {
    Q_OBJECT

private slots:
    void scheduleClosedForm() {
        ActuatorChannelSpec c;
        c.mode = ActuatorMode::Force;
        c.heldForce = -7.0;
        QCOMPARE(commandedForce(c, 12.0), -7.0); // no schedule: the constant force
        for (const auto& p : kSchedule)
            c.forceSchedule.push_back({p[0].get<double>(), p[1].get<double>()});
        for (double t : {-1.0, 0.0, 0.25, 0.5, 1.0, 1.3, 2.0, 2.5, 2.9, 3.0, 7.0})
            QVERIFY2(std::abs(commandedForce(c, t) - closedForm(t)) <= 1e-12,
                     qPrintable(QString::number(t)));
        QVERIFY(forceScheduleProblem(c.forceSchedule).empty());
        QVERIFY(!forceScheduleProblem({{0.0, 1.0}, {0.0, 2.0}}).empty());
        QVERIFY(!forceScheduleProblem({{0.0, 1.0}, {std::nan(""), 2.0}}).empty());
    }

    void runFollowsTheSchedule() {
        TestConfig cfg = parseConfig(presetWith(kSchedule), "frame.json");
        cfg.analysis.duration = 4.0;
        auto test = buildHybridTest(cfg);
        const RunLayout layout = RunLayout::of(*test);
        const int vc = channel(layout, "vertical command"), vs = channel(layout, "vertical stroke"),
                  vf = channel(layout, "vertical force"), af = channel(layout, "axial force");
        QVERIFY(vc >= 0 && vs >= 0 && vf >= 0 && af >= 0);
        Recorder rec;
        test->addObserver(&rec);
        QVERIFY(test->prepare());
        while (test->step() == HybridTest::StepResult::Advanced) {
        }
        QCOMPARE(test->state(), HybridTest::State::Finished);
        QCOMPARE(rec.records.size(), std::size_t(401));
        double worstF = 0.0;
        for (std::size_t k = 1; k < rec.records.size(); ++k) {
            const auto& c = rec.records[k].channels;
            const double f = closedForm(rec.records[k].time);
            QVERIFY(std::abs(c[std::size_t(vc)] - f) <= 1e-12);
            QVERIFY(std::abs(c[std::size_t(vf)] - f) <= 1e-12 * std::max(1.0, std::abs(f)));
            QVERIFY(std::abs(c[std::size_t(vs)] - f / kVerticalK) <=
                    1e-12 * std::max(1e-9, std::abs(f / kVerticalK)));
            QCOMPARE(c[std::size_t(af)], c[std::size_t(vf)]);
            worstF = std::max(worstF, std::abs(c[std::size_t(vf)] - f));
        }
        qInfo("max |F - F(t)| %.3g kN over 400 steps", worstF);
        QCOMPARE(rec.records[100].channels[std::size_t(vc)], -500.0); // t = 1 s
    }

    void limitsCheckedOnTheSchedule() {
        // -500 - 1000 t kN crosses the 1005 kN limit at t = 0.505 s.
        const json crossing = json::array({{0.0, -500.0}, {1.0, -1500.0}});
        json doc = presetWith(crossing);
        doc["structure"]["elements"][0]["actuators"][0]["limits"]["force"] = 1005.0;
        QString e;
        try {
            parseConfig(doc, "frame.json");
        } catch (const std::exception& x) {
            e = x.what();
        }
        QVERIFY2(e.contains("forceSchedule") && e.contains("actuator 'vertical'") &&
                     e.contains("t = 1"),
                 qPrintable(e));

        // Past the configuration check (the schedule set on the parsed configuration): the run
        // holds at step 51 (t = 0.51 s, F = -1010 kN) before that command leaves.
        TestConfig cfg = parseConfig(presetWith(kSchedule), "frame.json");
        ActuatorChannelSpec& v = cfg.elements[0].link2d->actuators[0].channel;
        v.forceSchedule = {{0.0, -500.0}, {1.0, -1500.0}};
        v.limits.maxForce = 1005.0;
        cfg.analysis.duration = 2.0;
        auto test = buildHybridTest(cfg);
        QVERIFY(test->prepare());
        HybridTest::StepResult r = HybridTest::StepResult::Advanced;
        while (r == HybridTest::StepResult::Advanced)
            r = test->step();
        QCOMPARE(r, HybridTest::StepResult::Held);
        QCOMPARE(test->currentStep(), 50);
        const QString why = QString::fromStdString(test->alarms().back().message);
        QVERIFY2(why.contains("actuator 'vertical'") && why.contains("1005"), qPrintable(why));
        auto& x = static_cast<ExperimentalLink2d&>(*test->structure().elements()[0]);
        const auto& lab = static_cast<const VirtualActuatorLab&>(x.control());
        QVERIFY(lab.holding());
        QVERIFY(std::abs(lab.committedForce(0) - (-1000.0)) <= 1e-9); // F(0.50 s)
        QVERIFY(std::abs(lab.committedStroke(0) - (-1000.0 / kVerticalK)) <= 1e-15);
    }
};

QTEST_GUILESS_MAIN(TestScheduledForce)
#include "TestScheduledForce.moc"
