// Issue 24 on hsmu-controller: the state-file journal of an N-channel specimen
// (comms/controller/StateJournal.h `commits` lines, SpecimenStation.h): a controller killed
// with SIGKILL at step 120 of the two-actuator column frame and restarted on the same port with
// its journal lets the console's link reconnect and continue, and the run ends equal to an
// uninterrupted one (ideal actuators: also to the all-numerical frame; lagging ones: to the
// uninterrupted controller run) to 1e-9; a station rebuilt from the journal holds every
// channel at its committed stroke, force and reached value, bit for bit, and a journal whose
// step does not replay is refused naming the step.
#include "comms/controller/SpecimenStation.h"
#include "comms/link/ControlFactory.h"

#include "../ControllerProcess.h"
#include "ChannelLoopsFixture.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

using namespace hsmu;
using namespace hsmu::comms;
using namespace linkfixture;
using namespace multiactuator;
using namespace channelloops;

namespace {

/// The frame for 3 s; lagging: lateral tau 5 ms, vertical force loop tau 3 ms at 1024 Hz.
nlohmann::json frame(bool lagging) {
    if (!lagging)
        return preset(3.0);
    nlohmann::json j = preset(3.0);
    nlohmann::json& a = j["structure"]["elements"][0]["actuators"];
    a[1]["actuator"] = {{"type", "lag"}, {"timeConstant", 0.005}};
    a[0]["actuator"] = {{"type", "lag"}, {"timeConstant", 0.003}};
    return j;
}

TargetsMsg targets(std::uint64_t n) {
    return TargetsMsg{n,
                      {{kChannelForce, -500.0 + 10.0 * std::sin(0.3 * double(n))},
                       {kChannelDisplacement, 0.004 * std::sin(0.2 * double(n))}}};
}

} // namespace

class TestChannelJournal : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    void killedControllerContinuesFromItsJournal_data() {
        QTest::addColumn<bool>("lagging");
        QTest::newRow("ideal") << false;
        QTest::newRow("lag") << true;
    }

    void killedControllerContinuesFromItsJournal() {
        QFETCH(bool, lagging);
        const QString name = lagging ? "lag" : "ideal";
        const std::string path = writeConfig(m_dir.path(), name + ".json", frame(lagging));
        const TestConfig cfg = loadConfigFile(path);
        Run reference;
        {
            ControllerProcess ctl(
                {"--config", QString::fromStdString(path), "--pace", "fast", "--quiet"});
            QVERIFY2(ctl.start(), qPrintable(ctl.log()));
            reference = runTest(cfg, nativeAt(ctl.port()));
            QVERIFY2(reference.state == HybridTest::State::Finished, reference.error.c_str());
        }
        const QString state = m_dir.filePath(name + ".state");
        ControllerProcess ctl(
            {"--config", QString::fromStdString(path), "--pace", "fast", "--state-file", state});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        const quint16 port = ctl.port();
        bool restarted = false;
        const Run run = runTest(
            cfg, nativeAt(port),
            [&](int step) {
                if (step == 120)
                    ctl.kill(); // SIGKILL between steps 120 and 121
            },
            [&] { restarted = ctl.start(port); }, 1);
        QVERIFY2(restarted, qPrintable(ctl.log()));
        QCOMPARE(run.holds, 1);
        QVERIFY2(run.state == HybridTest::State::Finished, run.error.c_str());
        QCOMPARE(run.records.size(), std::size_t(301));
        QVERIFY(everyStepOnce(run));
        QVERIFY2(ctl.waitForLog("specimen 'Column L' continues after step 120"),
                 qPrintable(ctl.log()));
        const double diff = maxDifference(reference, run);
        qInfo("%s actuators: killed at step 120 and restarted with the journal, max |diff| to "
              "the uninterrupted controller run %.3g",
              qPrintable(name), diff);
        QVERIFY2(diff <= 1e-9, qPrintable(QString::number(diff)));
        if (!lagging) {
            const Run numerical = runTest(parseConfig(numericalTwin(preset(3.0)), "twin.json"), {});
            const double vsNumerical = relativeDifference(numerical, run);
            QVERIFY2(vsNumerical <= 1e-9, qPrintable(QString::number(vsNumerical)));
        }
        ctl.stop();
    }

    void restartedStationHoldsEveryChannelAtItsCommittedState() {
        const ElementSpec spec = parseConfig(frame(true), "memory.json").elements[0];
        const std::string file = m_dir.filePath("station.state").toStdString();
        const std::vector<JournalElement> ids{{"Column L", 24}};
        const ControllerSettings cs;
        const auto fast = SpecimenStation::Pace::Fast;
        StateJournal journal;
        std::vector<JournalRecord> records;
        std::string error;
        QVERIFY2(journal.open(file, ids, records, error), error.c_str());
        SpecimenStation first(0, spec, cs, fast, &journal);
        QVERIFY(std::holds_alternative<AckMsg>(first.configure(ConfigureMsg{0.01})));
        for (std::uint64_t n = 1; n <= 40; ++n) {
            const auto m = first.targets(targets(n));
            QVERIFY(m && std::holds_alternative<MeasurementsMsg>(*m));
            QVERIFY(std::holds_alternative<AckMsg>(first.commit(CommitMsg{n})));
        }
        QVERIFY(first.targets(targets(41))); // measured, not committed: not journaled

        StateJournal again;
        QVERIFY2(again.open(file, ids, records, error), error.c_str());
        QCOMPARE(records.size(), std::size_t(41)); // configure + 40 commits
        SpecimenStation second(0, spec, cs, fast, &again);
        for (const JournalRecord& r : records)
            QVERIFY2(second.replay(r, error), error.c_str());
        QCOMPARE(second.committedSteps(), std::uint64_t(40));
        QCOMPARE(second.status().channelCommands, first.status().channelCommands);
        for (int i = 0; i < 2; ++i) {
            QCOMPARE(second.rig()->lab().committedStroke(i), first.rig()->lab().committedStroke(i));
            QCOMPARE(second.rig()->lab().committedForce(i), first.rig()->lab().committedForce(i));
            QCOMPARE(second.rig()->committedAchieved()[std::size_t(i)],
                     first.rig()->committedAchieved()[std::size_t(i)]);
            QCOMPARE(second.loop(i).achieved(), second.rig()->committedAchieved()[std::size_t(i)]);
        }
        // The next step from the restarted station equals the first station's, bit for bit.
        QVERIFY(std::holds_alternative<AckMsg>(second.configure(ConfigureMsg{0.01})));
        const auto a = first.targets(targets(41)), b = second.targets(targets(41));
        QVERIFY(a && b && std::holds_alternative<MeasurementsMsg>(*b));
        const auto& ma = std::get<MeasurementsMsg>(*a);
        const auto& mb = std::get<MeasurementsMsg>(*b);
        for (std::size_t i = 0; i < 2; ++i) {
            QCOMPARE(mb.channels[i].stroke, ma.channels[i].stroke);
            QCOMPARE(mb.channels[i].force, ma.channels[i].force);
        }
    }

    void journalThatDoesNotReplayIsRefused() {
        const ElementSpec spec = parseConfig(frame(false), "memory.json").elements[0];
        const QString file = m_dir.filePath("edited.state");
        {
            QFile f(file);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("hsmu-controller-state 1\nelement 0 0000000000000018 Column L\n"
                    "configure 0 0.01\ncommits 0 1 2 -500 -500 -0.0025 -500 0.001 0.001 "
                    "0.001 99\n");
        }
        StateJournal journal;
        std::vector<JournalRecord> records;
        std::string error;
        QVERIFY2(journal.open(file.toStdString(), {{"Column L", 24}}, records, error),
                 error.c_str());
        QCOMPARE(records.size(), std::size_t(2));
        QCOMPARE(records[1].channels.size(), std::size_t(2));
        SpecimenStation st(0, spec, ControllerSettings{}, SpecimenStation::Pace::Fast, &journal);
        QVERIFY(st.replay(records[0], error));
        QVERIFY(!st.replay(records[1], error));
        QVERIFY2(error.find("specimen 'Column L': replaying step 1 does not give the recorded "
                            "measurement") != std::string::npos,
                 error.c_str());
    }
};

QTEST_GUILESS_MAIN(TestChannelJournal)
#include "TestChannelJournal.moc"
