// RecordWriter + RecordReader: a full short run of the paper's condition 3 (3 s, UKF updating)
// read back equals the in-memory StepRecords exactly (bit for bit, NaN where NaN), with the
// metadata, layout and alarms; a reader opened while the writer is still open sees the
// flushed rows and, after refresh(), the rows flushed later.

#include "RecordFixture.h"

#include "core/Version.h"
#include "core/hysteresis/BoucWen.h"
#include "core/record/RecordError.h"
#include "core/record/RecordReader.h"
#include "core/record/RecordSchema.h"

#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <cstring>

using namespace hsmu;
using namespace hsmu::testsupport;

namespace {

bool same(double x, double y) {
    return std::memcmp(&x, &y, sizeof x) == 0;
}

} // namespace

class TestRecordRoundTrip : public QObject {
    Q_OBJECT
private slots:
    void fullRunRoundTrips();
    void concurrentReaderSeesGrowingData();
    void writerErrorsNameTheFile();
};

void TestRecordRoundTrip::fullRunRoundTrips() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const std::string path = dir.filePath("record.h5").toStdString();
    const TestConfig cfg = condition3(3.0);
    auto test = buildHybridTest(cfg);
    Collector collector;
    RecordWriter writer(path, RunLayout::of(*test), recordStart(cfg, "sample notes, ünïcode"));
    writer.trackAlarms(&test->alarms());
    test->addObserver(&collector);
    test->addObserver(&writer);
    QVERIFY(test->prepare());
    while (test->step() == HybridTest::StepResult::Advanced) {
        if (test->currentStep() == 100 || test->currentStep() == 250)
            writer.addNote(test->time(), test->currentStep(),
                           "note at step " + std::to_string(test->currentStep()) + ", ünïcode");
    }
    QCOMPARE(test->state(), HybridTest::State::Finished);
    QVERIFY2(writer.finish(), writer.error().c_str());
    writer.addNote(9.0, 999, "after finish: ignored");
    QCOMPARE(writer.rowsFlushed(), int(collector.records.size()));
    QCOMPARE(collector.records.size(), std::size_t(301));

    const RecordReader reader(path);
    const RecordData& d = reader.data();
    QCOMPARE(d.meta.schemaVersion, recordschema::kVersion);
    QCOMPARE(d.meta.program, std::string("HSMU Console"));
    QCOMPARE(d.meta.programVersion, std::string(versionString()));
    QCOMPARE(d.meta.configuration, cfg.raw.dump());
    QCOMPARE(nlohmann::json::parse(d.meta.configuration)["analysis"]["duration"].get<double>(),
             3.0);
    QCOMPARE(d.meta.configName, cfg.name);
    QCOMPARE(d.meta.operatorNotes, std::string("sample notes, ünïcode"));
    QCOMPARE(d.meta.dt, 0.01);
    QCOMPARE(d.meta.numerics, std::string("UKF sigma points: ") + BoucWen::fastBatchMathName());
    QVERIFY(QRegularExpression(R"(^\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ$)")
                .match(QString::fromStdString(d.meta.startTime))
                .hasMatch());

    const RunLayout layout = RunLayout::of(*test);
    QCOMPARE(d.layout.dofNames, layout.dofNames);
    QCOMPARE(d.layout.elements.size(), layout.elements.size());
    for (std::size_t j = 0; j < layout.elements.size(); ++j) {
        QCOMPARE(d.layout.elements[j].name, layout.elements[j].name);
        QCOMPARE(d.layout.elements[j].type, layout.elements[j].type);
        QCOMPARE(d.layout.elements[j].experimental, layout.elements[j].experimental);
        QCOMPARE(d.layout.elements[j].nonlinear, layout.elements[j].nonlinear);
        QCOMPARE(d.layout.elements[j].units.deformation, layout.elements[j].units.deformation);
        QCOMPARE(d.layout.elements[j].units.force, layout.elements[j].units.force);
    }
    QVERIFY(d.layout.updating.has_value());
    QCOMPARE(d.layout.updating->specimen, layout.updating->specimen);
    QCOMPARE(d.layout.updating->method, layout.updating->method);
    QCOMPARE(d.layout.updating->parameters, layout.updating->parameters);
    QCOMPARE(d.layout.updating->units.force, std::string("kN m"));

    QCOMPARE(d.rows(), int(collector.records.size()));
    const auto nDof = Eigen::Index(layout.dofNames.size());
    const auto nPar = Eigen::Index(layout.updating->parameters.size());
    int nanCommanded = 0;
    for (int i = 0; i < d.rows(); ++i) {
        const StepRecord& r = collector.records[std::size_t(i)];
        QCOMPARE(d.steps[std::size_t(i)], r.step);
        QVERIFY(same(d.time[i], r.time));
        QVERIFY(same(d.groundAcceleration[i], r.groundAcceleration));
        for (Eigen::Index k = 0; k < nDof; ++k) {
            QVERIFY(same(d.u(i, k), r.u[k]));
            QVERIFY(same(d.v(i, k), r.v[k]));
            QVERIFY(same(d.a(i, k), r.a[k]));
        }
        for (std::size_t j = 0; j < r.elements.size(); ++j) {
            const auto c = Eigen::Index(j);
            QVERIFY(same(d.deformation(i, c), r.elements[j].deformation));
            QVERIFY(same(d.force(i, c), r.elements[j].force));
            QVERIFY(same(d.commanded(i, c), r.elements[j].commanded));
            nanCommanded += std::isnan(d.commanded(i, c)) ? 1 : 0;
            // Actuator channels: as recorded, and for the in-process virtual specimen the
            // commanded position is the target and the measured one the measured deformation.
            const ActuatorChannels& ac = r.elements[j].actuator;
            QVERIFY(same(d.actuatorCommanded(i, c), ac.commanded));
            QVERIFY(same(d.actuatorMeasured(i, c), ac.measured));
            QCOMPARE(std::isnan(d.heldTicks(i, c)), ac.heldTicks < 0);
            QCOMPARE(std::isnan(d.actuatorFlags(i, c)), ac.flags < 0);
            if (ac.flags >= 0)
                QCOMPARE(d.actuatorFlags(i, c), double(ac.flags));
            if (layout.elements[j].experimental && i > 0) {
                QVERIFY(same(d.actuatorCommanded(i, c), r.elements[j].commanded));
                QVERIFY(same(d.actuatorMeasured(i, c), r.elements[j].deformation));
                QVERIFY(d.actuatorFlags(i, c) == 0.0 || d.actuatorFlags(i, c) == 1.0);
                QVERIFY(std::isnan(d.heldTicks(i, c)));
            } else {
                QVERIFY(std::isnan(d.actuatorCommanded(i, c)));
                QVERIFY(std::isnan(d.actuatorFlags(i, c)));
            }
        }
        QVERIFY(r.hasUpdating);
        for (Eigen::Index k = 0; k < nPar; ++k) {
            QVERIFY(same(d.parameters(i, k), r.updating.parameters[std::size_t(k)]));
            QVERIFY(same(d.stddev(i, k), r.updating.stddev[std::size_t(k)]));
        }
        QVERIFY(same(d.auxiliaryForce[i], r.updating.auxiliaryForce));
        QVERIFY(same(d.fitError[i], r.updating.fitError));
        QCOMPARE(d.appliedUpdates[std::size_t(i)], r.updating.appliedUpdates);
        QCOMPARE(d.updatesThisStep[std::size_t(i)], r.updating.updatesThisStep);
        QCOMPARE(d.pendingProposals[std::size_t(i)], r.updating.pendingProposals);
        QVERIFY(same(d.tracking(i, 0), r.updating.tracking.j1));
        QVERIFY(same(d.tracking(i, 1), r.updating.tracking.j2));
        QVERIFY(same(d.tracking(i, 2), r.updating.tracking.j3));
        QCOMPARE(d.updateRequested[std::size_t(i)], r.updating.updateRequested ? 1 : 0);
        // Sites: one (the built-in virtual lab as the default site), its round trip per step.
        QCOMPARE(r.siteRoundTrips.size(), std::size_t(1));
        QVERIFY(same(d.siteRoundTrip(i, 0), r.siteRoundTrips[0]));
        QVERIFY(i == 0 ? std::isnan(d.siteRoundTrip(i, 0)) : d.siteRoundTrip(i, 0) >= 0.0);
    }
    QCOMPARE(d.layout.sites, std::vector<std::string>{"controller"});
    QCOMPARE(nanCommanded, 2 * d.rows()); // Elements 2 and 3 are numerical
    QVERIFY(d.appliedUpdates.back() > 0);

    // Applied-update events: one per update in the StepRecords, with the values sent.
    std::vector<UpdateEvent> events;
    for (const StepRecord& r : collector.records)
        events.insert(events.end(), r.updating.applied.begin(), r.updating.applied.end());
    QCOMPARE(int(events.size()), d.appliedUpdates.back());
    QCOMPARE(d.updateEvents.size(), events.size());
    for (std::size_t k = 0; k < events.size(); ++k) {
        QCOMPARE(d.updateEvents[k].step, events[k].step);
        QVERIFY(same(d.updateEvents[k].time, events[k].time));
        QCOMPARE(d.updateEvents[k].element, events[k].element);
        QCOMPARE(d.updateEvents[k].decision, std::string("applied"));
        for (Eigen::Index j = 0; j < nPar; ++j) {
            const auto at = events[k].parameters.find(layout.updating->parameters[std::size_t(j)]);
            const double v = d.updateEvents[k].values[std::size_t(j)];
            QVERIFY(!at ? std::isnan(v) : same(v, events[k].applied[*at]));
        }
    }

    QCOMPARE(d.notes.size(), std::size_t(2));
    QCOMPARE(d.notes[0].step, 100);
    QVERIFY(same(d.notes[0].time, collector.records[100].time));
    QCOMPARE(d.notes[0].text, std::string("note at step 100, ünïcode"));
    QCOMPARE(d.notes[1].step, 250);

    const auto& alarms = test->alarms();
    QCOMPARE(d.alarms.size(), alarms.size());
    for (std::size_t k = 0; k < alarms.size(); ++k) {
        QVERIFY(same(d.alarms[k].time, alarms[k].time));
        QCOMPARE(d.alarms[k].step, alarms[k].step);
        QCOMPARE(d.alarms[k].severity, alarms[k].severity);
        QCOMPARE(d.alarms[k].kind, alarms[k].kind);
        QCOMPARE(d.alarms[k].message, alarms[k].message);
    }
}

void TestRecordRoundTrip::concurrentReaderSeesGrowingData() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("live.h5").toStdString();
    const TestConfig cfg = condition3(3.0);
    auto test = buildHybridTest(cfg);
    RecordWriter writer(path, RunLayout::of(*test), recordStart(cfg));
    writer.trackAlarms(&test->alarms());
    test->addObserver(&writer);
    QVERIFY(test->prepare());
    for (int i = 0; i < 100; ++i)
        QCOMPARE(test->step(), HybridTest::StepResult::Advanced);
    QVERIFY(writer.flush());
    QCOMPARE(writer.rowsFlushed(), 101);

    RecordReader reader(path);
    QCOMPARE(reader.rows(), 101);
    QCOMPARE(reader.refresh(), 0);
    for (int i = 0; i < 50; ++i)
        QCOMPARE(test->step(), HybridTest::StepResult::Advanced);
    QVERIFY(writer.flush());
    QCOMPARE(reader.refresh(), 50);
    QCOMPARE(reader.rows(), 151);
    QCOMPARE(reader.data().steps.back(), 150);
    QCOMPARE(reader.data().time[150], test->time());
    QVERIFY(writer.finish());
    reader.refresh();
    QCOMPARE(reader.rows(), 151);
}

void TestRecordRoundTrip::writerErrorsNameTheFile() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("no/such/folder/record.h5").toStdString();
    const TestConfig cfg = condition3(1.0);
    auto test = buildHybridTest(cfg);
    try {
        RecordWriter writer(path, RunLayout::of(*test), recordStart(cfg));
        QFAIL("no error for a missing folder");
    } catch (const RecordError& e) {
        QVERIFY2(std::string(e.what()).rfind(path + ": cannot be created", 0) == 0, e.what());
    }
}

QTEST_APPLESS_MAIN(TestRecordRoundTrip)
#include "TestRecordRoundTrip.moc"
