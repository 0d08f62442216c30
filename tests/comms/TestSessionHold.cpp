// Holds and console sessions on a real hsmu-controller process (issue 16): a hold is per
// console session. The hold a console asked for (Hold, also at Quit) ends when a new console
// session is admitted: that session arms through its own pre-flight and starts un-held
// (before: it started held, its first target was refused, and the console's reconnect policy
// then resumed the specimen by itself). The same session reconnecting still finds its own
// hold. A trip of the controller's interlock stays across sessions: the hello-ack reports it
// and the console refuses to arm ("held from the previous console session: interlock: ...")
// until it is cleared at the controller (docs/protocol.md, "Holds and sessions").
#include "comms/link/TcpControl.h"
#include "core/experimental/SafetyLimits.h"
#include "core/util/ReasonText.h"

#include "ControllerProcess.h"
#include "LinkFixture.h"
#include "RawClient.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace hsmu;
using namespace hsmu::comms;
using namespace linkfixture;

namespace {

constexpr double kDt = 0.01; // [s]

// One step: target, measurement, commit, ack.
bool step(RawClient& c, std::uint64_t n, double d) {
    return c.send(TargetMsg{n, d}) && c.expect<MeasurementMsg>().has_value() &&
           c.send(CommitMsg{n}) && c.expect<AckMsg>().has_value();
}

std::optional<HelloAckMsg> hello(RawClient& c, std::uint64_t session) {
    if (!c.send(HelloMsg{kProtocolVersion, session, "", ""}))
        return std::nullopt;
    return c.expect<HelloAckMsg>();
}

TcpControlOptions consoleOptions(std::uint64_t session) {
    TcpControlOptions o;
    o.connectTimeout = 20.0;
    o.stepDeadline = 30.0;
    o.silenceTimeout = 30.0;
    o.reconnectAttempts = 1;
    o.sessionId = session;
    return o;
}

} // namespace

class TestSessionHold : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString m_config;

private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        m_config = QString::fromStdString(writeConfig(m_dir.path(), "c3.json", condition3(1.0)));
    }

    void aConsoleHoldEndsWithItsSession() {
        ControllerProcess ctl({"--config", m_config, "--pace", "fast"});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        {
            RawClient first; // a console that steps twice, holds and quits
            QVERIFY(first.connect(ctl.port()));
            QVERIFY(hello(first, 11));
            QVERIFY(first.send(ConfigureMsg{kDt}));
            QVERIFY(first.expect<AckMsg>());
            QVERIFY(step(first, 1, 1e-4));
            QVERIFY(step(first, 2, 2e-4));
            QVERIFY(first.send(HoldMsg{"operator hold"}));
            const auto held = first.expect<AckMsg>();
            QVERIFY(held && held->acked == MessageType::Hold);
            QVERIFY(first.send(ByeMsg{"quit"}));
            first.close();
        }
        {
            RawClient again; // the same session reconnecting: its own hold is still there
            QVERIFY(again.connect(ctl.port()));
            const auto ack = hello(again, 11);
            QVERIFY(ack);
            QVERIFY(ack->holding);
            QCOMPARE(ack->holdReason, std::string("operator hold"));
            QVERIFY(again.send(ByeMsg{"quit"}));
            again.close();
        }
        RawClient next; // the next console session
        QVERIFY(next.connect(ctl.port()));
        const auto ack = hello(next, 22);
        QVERIFY(ack);
        QVERIFY2(!ack->holding, ack->holdReason.c_str());
        QCOMPARE(ack->committedSteps, std::uint64_t(2)); // the specimen's history is kept
        QVERIFY(next.send(ConfigureMsg{kDt}));
        QVERIFY(next.expect<AckMsg>());
        QVERIFY2(step(next, 3, 3e-4), qPrintable(ctl.log())); // not refused as holding
        ctl.stop(); // its log is complete once it has ended
        const QString log = ctl.log();
        QVERIFY2(log.contains(QStringLiteral("the previous session's hold ends")), qPrintable(log));
    }

    void aTripOutlivesTheSessionAndTheConsoleDoesNotArm() {
        ControllerProcess ctl({"--config", m_config, "--pace", "fast"});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        {
            RawClient first; // its first target is past the deformation limit it configured
            QVERIFY(first.connect(ctl.port()));
            QVERIFY(hello(first, 31));
            QVERIFY(first.send(ConfigureMsg{kDt, 0.01}));
            QVERIFY(first.expect<AckMsg>());
            QVERIFY(first.send(TargetMsg{1, 0.05}));
            const auto e = first.expect<ErrorMsg>();
            QVERIFY(e && e->code == ErrorCode::Interlock);
            first.close();
        }
        // The console's own link, as a new test prepares it: refused, with the trip's reason.
        TcpControl console("127.0.0.1", ctl.port(), "", SafetyLimits{}, consoleOptions(32));
        const ControlResult r = console.prepare(kDt);
        QVERIFY(!r.ok);
        const auto coded = parseReason(r.reason);
        QVERIFY2(coded && coded->code == "controller-refused" && coded->args.size() == 2,
                 r.reason.c_str());
        const auto held = parseReason(coded->args[1]);
        QVERIFY2(held && held->code == "held-from-previous-session", r.reason.c_str());
        QVERIFY2(held->args.at(0).rfind("interlock: ", 0) == 0, r.reason.c_str());
        QVERIFY(!console.linkUp());
    }
};

QTEST_MAIN(TestSessionHold)
#include "TestSessionHold.moc"
