// RunStatistics and the summary JSON: peaks equal the maxima over the records, counts and
// times match the test, a held test reports its reason and alarm.

#include "OutputFixture.h"

#include "core/output/RunLayout.h"
#include "core/output/RunStatistics.h"
#include "core/output/RunSummary.h"

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <fstream>

using namespace hsmu;
using namespace hsmu::testsupport;

namespace {

struct Run {
    std::unique_ptr<HybridTest> test;
    std::unique_ptr<RunStatistics> stats;
    Collector collector;
};

void runToEnd(Run& run) {
    run.stats = std::make_unique<RunStatistics>(RunLayout::of(*run.test));
    run.test->addObserver(run.stats.get());
    run.test->addObserver(&run.collector);
    QVERIFY2(run.test->prepare(), run.test->lastError().c_str());
    while (run.test->step() == HybridTest::StepResult::Advanced) {
    }
}

} // namespace

class TestRunSummary : public QObject {
    Q_OBJECT
private slots:
    void peaksAreMaximaOverRecords() {
        Run run{smallFrame(2.0), nullptr, {}};
        runToEnd(run);
        QCOMPARE(run.test->state(), HybridTest::State::Finished);
        const auto& recs = run.collector.records;
        QCOMPARE(run.stats->recordCount(), int(recs.size()));
        QCOMPARE(run.stats->last().step, 200);
        for (std::size_t i = 0; i < 2; ++i) {
            double peak = 0.0;
            for (const auto& r : recs)
                peak = std::max(peak, std::abs(r.u[Eigen::Index(i)]));
            QVERIFY(peak > 1e-4); // the record really moves the frame
            QCOMPARE(run.stats->peakDisplacement()[i], peak);
        }
        for (std::size_t e = 0; e < 3; ++e) {
            double pf = 0.0, pd = 0.0;
            for (const auto& r : recs) {
                pf = std::max(pf, std::abs(r.elements[e].force));
                pd = std::max(pd, std::abs(r.elements[e].deformation));
            }
            QVERIFY(pf > 0.0);
            QCOMPARE(run.stats->peakForce()[e], pf);
            QCOMPARE(run.stats->peakDeformation()[e], pd);
        }
    }

    void summaryJsonMatchesTheRun() {
        Run run{smallFrame(2.0), nullptr, {}};
        runToEnd(run);
        QTemporaryDir dir;
        const std::string path = dir.filePath(QStringLiteral("summary.json")).toStdString();
        RunInfo info{"small frame", "inline.json", 0.25};
        writeSummaryJson(path, *run.test, *run.stats, info);
        std::ifstream in(path);
        const nlohmann::json j = nlohmann::json::parse(in);
        QCOMPARE(j.at("config").at("name").get<std::string>(), std::string("small frame"));
        QCOMPARE(j.at("config").at("file").get<std::string>(), std::string("inline.json"));
        QCOMPARE(j.at("steps").get<int>(), 200);
        QCOMPARE(j.at("test_time_s").get<double>(), 2.0);
        QCOMPARE(j.at("wall_time_s").get<double>(), 0.25);
        QCOMPARE(j.at("dt_s").get<double>(), 0.01);
        QCOMPARE(j.at("state").get<std::string>(), std::string("finished"));
        QCOMPARE(j.at("integrator").get<std::string>(), std::string("explicitNewmark"));
        QVERIFY(j.at("stability").at("omega_max_rad_s").get<double>() > 0.0);
        QCOMPARE(j.at("stability").at("limit").get<double>(), 2.0);
        QCOMPARE(j.at("peak_displacement_m").at("D1").get<double>(),
                 run.stats->peakDisplacement()[0]);
        QCOMPARE(j.at("peak_force").at("E1").at("value").get<double>(), run.stats->peakForce()[0]);
        QCOMPARE(j.at("peak_force").at("E1").at("unit").get<std::string>(), std::string("kN m"));
        QCOMPARE(j.at("peak_force").at("E3").at("unit").get<std::string>(), std::string("kN"));
        QCOMPARE(j.at("peak_deformation").at("E2").at("unit").get<std::string>(),
                 std::string("rad"));
        QCOMPARE(j.at("final").at("displacement_m").at("D2").get<double>(),
                 run.collector.records.back().u[1]);
        QVERIFY(j.at("alarms").is_array() && j.at("alarms").empty());
        QVERIFY(j.at("hold_reason").is_null());
        QVERIFY(!j.contains("updating")); // no updater
    }

    void summaryFileIsTheSummaryDumped() {
        // writeSummaryJson streams the per-DOF / per-element objects (core/output/PrettyJson):
        // the file holds the bytes of makeRunSummary(...).dump(2), for a run with a specimen,
        // with updating (condition 3) and a held one (null peaks, alarms).
        Run frame{smallFrame(2.0), nullptr, {}}, updating{buildHybridTest(condition3(0.5)), nullptr, {}},
            held{smallFrame(2.0, 1e-4), nullptr, {}};
        for (Run* run : {&frame, &updating, &held}) {
            runToEnd(*run);
            QTemporaryDir dir;
            const std::string path = dir.filePath(QStringLiteral("summary.json")).toStdString();
            const RunInfo info{"frame \"ü\"", "inline.json", 0.25, {{"controller", "builtin"}}};
            writeSummaryJson(path, *run->test, *run->stats, info);
            std::ifstream in(path, std::ios::binary);
            const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
            const nlohmann::json dom = makeRunSummary(*run->test, *run->stats, info);
            QVERIFY(dom.at("peak_force").size() == run->stats->layout().elements.size());
            QCOMPARE(QString::fromStdString(text), QString::fromStdString(dom.dump(2) + "\n"));
        }
    }

    void linkSecurityFollowsTheSites() {
        // Order of the sites, the last entry naming a site wins, a site not named: "" / null.
        const SiteSecurity given{{"Lab B", "tls"}, {"controller", "builtin"}, {"Lab B", "insecure-plaintext"}};
        const std::vector<std::string> sites{"controller", "Lab B", "Lab C"};
        QCOMPARE(securityOfSites(sites, given),
                 (std::vector<std::string>{"builtin", "insecure-plaintext", ""}));
        const nlohmann::json j = linkSecurityJson(sites, given);
        QCOMPARE(j.size(), std::size_t(3));
        QCOMPARE(j.at("controller").get<std::string>(), std::string("builtin"));
        QCOMPARE(j.at("Lab B").get<std::string>(), std::string("insecure-plaintext"));
        QVERIFY(j.at("Lab C").is_null());
        QCOMPARE(builtinSiteSecurity(RunLayout{{}, {}, {}, {"controller", "Lab C"}, {}}),
                 (SiteSecurity{{"controller", "builtin"}, {"Lab C", "builtin"}}));

        // summary.json: the run's sites (the small frame's specimen: the default site).
        Run run{smallFrame(0.2), nullptr, {}};
        runToEnd(run);
        QCOMPARE(run.stats->layout().sites, std::vector<std::string>{"controller"});
        RunInfo info{"small frame", "inline.json", 0.25, {{"controller", "tls"}}};
        QCOMPARE(makeRunSummary(*run.test, *run.stats, info).at("link_security"),
                 (nlohmann::json{{"controller", "tls"}}));
        info.siteSecurity.clear(); // not said: null, never a guess
        QVERIFY(makeRunSummary(*run.test, *run.stats, info).at("link_security").at("controller").is_null());
    }

    void updatingBlockHoldsTheFinalEstimate() {
        Run run{buildHybridTest(condition3(2.0)), nullptr, {}};
        runToEnd(run);
        QCOMPARE(run.test->state(), HybridTest::State::Finished);
        const nlohmann::json j = makeRunSummary(*run.test, *run.stats, RunInfo{});
        QVERIFY(j.contains("updating"));
        const nlohmann::json& u = j.at("updating");
        QCOMPARE(u.at("specimen").get<std::string>(), std::string("Element 1"));
        QCOMPARE(u.at("method").get<std::string>(), std::string("UKF"));
        const UpdatingSample& last = run.collector.records.back().updating;
        const std::vector<std::string> names = run.test->updater()->parameterNames();
        QCOMPARE(u.at("parameters").size(), std::size_t(7));
        QCOMPARE(u.at("standard_deviations").size(), std::size_t(7));
        for (std::size_t i = 0; i < names.size(); ++i) {
            QCOMPARE(u.at("parameters").at(names[i]).get<double>(), last.parameters[i]);
            QCOMPARE(u.at("standard_deviations").at(names[i]).get<double>(), last.stddev[i]);
        }
        QCOMPARE(u.at("applied_updates").get<int>(), last.appliedUpdates);
        QVERIFY(u.at("applied_updates").get<int>() > 0);
        QCOMPARE(u.at("pending_proposals").get<int>(), 0);
        QCOMPARE(u.at("final_fit_error").get<double>(), last.fitError);
        // The updater's alarms are the test's alarms, all listed.
        QCOMPARE(j.at("alarms").size(), run.test->alarms().size());
    }

    void heldRunReportsReasonAndAlarm() {
        Run run{smallFrame(2.0, 1e-4), nullptr, {}};
        runToEnd(run);
        QCOMPARE(run.test->state(), HybridTest::State::Holding);
        const nlohmann::json j = makeRunSummary(*run.test, *run.stats, RunInfo{});
        QCOMPARE(j.at("state").get<std::string>(), std::string("holding"));
        QVERIFY(j.at("steps").get<int>() < 200);
        QCOMPARE(j.at("steps").get<int>() + 1, int(run.collector.records.size()));
        const std::string reason = j.at("hold_reason").get<std::string>();
        QVERIFY2(reason.find("E1") != std::string::npos, reason.c_str());
        QVERIFY2(reason.find("deformation") != std::string::npos, reason.c_str());
        const auto& alarms = j.at("alarms");
        QVERIFY(!alarms.empty());
        QCOMPARE(alarms.back().at("severity").get<std::string>(), std::string("critical"));
        QCOMPARE(alarms.back().at("kind").get<std::string>(), std::string("limit exceeded"));
        QCOMPARE(alarms.back().at("step").get<int>(), j.at("steps").get<int>());
    }
};

QTEST_APPLESS_MAIN(TestRunSummary)
#include "TestRunSummary.moc"
