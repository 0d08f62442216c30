// Issue 24 with the real OpenSees 3.8 + OpenFresco 2.8 kit (../shared/tools/opensees; skipped
// where absent): OpenFresco's `expControl GenericTCP` drives the two actuator channels of
// hsmu-controller's GenericTCP server (`expSetup NoTransformation -dir 1 2`, ctrl disp 2, daq
// disp 2 and force 2), each channel with its actuator model at the controller's loop rate:
// the vertical actuator (elastic 2e5 kN/m, displacement-controlled here) delayed by 3 ms,
// the lateral one (Bouc-Wen) lagging with tau 5 ms, 1024 Hz, 10 ticks per 10 ms step. The
// strokes and forces OpenSees records equal those HSMU's own GenericTCP client
// (comms/openfresco/GenericTcpControl) measures from a second controller with the same
// settings and the same stroke history, to 1e-12 of each column's peak (both go through the
// same doubles: the recorder's 16 digits are the only rounding).
#include "comms/openfresco/GenericTcpControl.h"

#include "../ControllerProcess.h"
#include "../OpenSeesRunner.h"
#include "ChannelLoopsFixture.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace hsmu;
using namespace hsmu::comms;
using namespace linkfixture;
using namespace channelloops;

namespace {

// The stroke history [m] of step k = 1..12: vertical (dir 1), lateral (dir 2).
double verticalAt(int k) {
    return -0.0025 + 0.0005 * std::sin(0.7 * k);
}
double lateralAt(int k) {
    return 0.006 * std::sin(0.5 * k);
}
constexpr int kSteps = 12;

// The Path series' points at t = 0 .. kSteps + 1: OpenSees's Path gives 0 at its last point.
QString pathValues(double (*f)(int)) {
    QString v = "0.0";
    for (int k = 1; k <= kSteps + 1; ++k)
        v += " " + QString::number(f(k), 'g', 17);
    return v;
}

// OpenSees + OpenFresco: a twoNodeLink on 2 DOFs, both imposed by sp constraints following
// Path series (one step each), behind NoTransformation -dir 1 2 and GenericTCP with
// displacement control (ctrl disp 2) and daq disp + force (2 + 2). A truss to node 3 leaves
// the model one free equation (node 3's x), without which the solver has nothing to solve.
QString kitScript(quint16 port) {
    return QString(R"(model BasicBuilder -ndm 2 -ndf 2
loadPackage OpenFrescoTcl
node 1 0.0 0.0
node 2 0.0 0.0
node 3 1.0 0.0
fix 1 1 1
fix 3 0 1
uniaxialMaterial Elastic 1 1.0
element truss 2 2 3 1.0 1
expControl GenericTCP 1 127.0.0.1 %1 -ctrlModes 1 0 0 0 0 -daqModes 1 0 0 1 0
expSetup NoTransformation 1 -control 1 -dir 1 2 -sizeTrialOut 2 2
expSite LocalSite 1 1
expElement twoNodeLink 1 1 2 -dir 1 2 -site 1 -initStif 200000.0 0.0 0.0 1000.0
timeSeries Path 1 -dt 1.0 -values {%2}
timeSeries Path 2 -dt 1.0 -values {%3}
pattern Plain 1 1 { sp 2 1 1.0 }
pattern Plain 2 2 { sp 2 2 1.0 }
recorder Element -precision 16 -file force.out -time -ele 1 daqForce
recorder Element -precision 16 -file daqDisp.out -time -ele 1 daqDisp
constraints Transformation
numberer Plain
system FullGeneral
test NormDispIncr 1e-12 10
algorithm Newton
integrator LoadControl 1.0
analysis Static
analyze %4
wipeExp
wipe
exit
)")
        .arg(port)
        .arg(pathValues(verticalAt), pathValues(lateralAt))
        .arg(kSteps);
}

/// The preset's column with both actuators displacement-controlled: vertical elastic 2e5
/// kN/m delayed 3 ms (3 ticks of a 10-tick step: only the loop rate can show it), lateral
/// Bouc-Wen lagging 5 ms. (A delay as long as the step's 5 corrected ticks or longer leaves the
/// first strokes and forces exactly 0, and OpenFresco's element replaces a measured force of
/// exactly 0 by its initial stiffness times the trial displacement: seen in the kit's
/// daqForce, 200000 x the vertical trial, while the controller measured 0.)
nlohmann::json delayAndLag() {
    nlohmann::json j = multiactuator::preset(1.0);
    nlohmann::json& a = j["structure"]["elements"][0]["actuators"];
    a[0].erase("force");
    a[0]["control"] = "displacement";
    a[0]["actuator"] = {{"type", "delay"}, {"delay", 0.003}};
    a[1]["actuator"] = {{"type", "lag"}, {"timeConstant", 0.005}};
    return j;
}

double relativeGap(const std::vector<std::vector<double>>& kit,
                   const std::vector<std::vector<double>>& own, std::size_t col) {
    double peak = 0.0, gap = 0.0;
    for (std::size_t i = 0; i < kit.size(); ++i) {
        peak = std::max(peak, std::abs(own[i][col]));
        gap = std::max(gap, std::abs(kit[i][col + 1] - own[i][col])); // kit col 0: time
    }
    return peak > 0.0 ? gap / peak : gap;
}

} // namespace

class TestChannelLoopsOpenSees : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    void kitEqualsHsmusOwnClientWithLagAndDelay() {
        if (!opensees::available())
            QSKIP(qPrintable(opensees::reason()));
        const std::string path = writeConfig(m_dir.path(), "kit.json", delayAndLag());
        const QStringList args{
            "--config", QString::fromStdString(path), "--protocol", "generictcp", "--pace", "fast"};
        // OpenSees + OpenFresco against one controller.
        ControllerProcess kitCtl(args);
        QVERIFY2(kitCtl.start(), qPrintable(kitCtl.log()));
        const auto r = opensees::run(m_dir.path(), "kit.tcl", kitScript(kitCtl.port()), 60000,
                                     "\n\n"); // ECGenericTCP::setup waits for two <Enter>
        QVERIFY2(r.finished, qPrintable(r.output));
        QVERIFY2(kitCtl.waitForLog("terminated by the client (99)"), qPrintable(kitCtl.log()));
        const auto force = opensees::table(m_dir.path() + "/force.out");
        const auto disp = opensees::table(m_dir.path() + "/daqDisp.out");
        QVERIFY2(force.size() == std::size_t(kSteps) && disp.size() == std::size_t(kSteps),
                 qPrintable(QString("%1 rows, %2 rows\n").arg(force.size()).arg(disp.size()) +
                            r.output + kitCtl.log()));

        // HSMU's own GenericTCP client against a second controller with the same settings.
        ControllerProcess ownCtl(args);
        QVERIFY2(ownCtl.start(), qPrintable(ownCtl.log()));
        of::OfControlOptions o;
        o.sizes.ctrl = {2, 0, 0, 0, 0};
        o.sizes.daq = {2, 0, 0, 2, 0};
        o.channelModes = {ActuatorMode::Displacement, ActuatorMode::Displacement};
        o.stepDeadline = 30.0;
        o.logConnect = false;
        o.warnNoCommit = false;
        of::GenericTcpControl own("127.0.0.1", ownCtl.port(), "Column L", o);
        QVERIFY2(own.prepare(0.01).ok, "HSMU's GenericTCP client connects");
        std::vector<std::vector<double>> ownDisp, ownForce;
        // OpenFresco's GenericTCP sends a trial of zeros at its setup (the "initial values of
        // DAQ" it prints): the controller's step 1. HSMU's client sends it too, so both
        // controllers see the same command history.
        for (int k = 0; k <= kSteps; ++k) {
            Eigen::Vector2d c(k == 0 ? 0.0 : verticalAt(k), k == 0 ? 0.0 : lateralAt(k));
            QVERIFY(own.setTargets(c).ok);
            Eigen::VectorXd s, f;
            QVERIFY(own.measureChannels(s, f).ok);
            QVERIFY(own.commit().ok);
            if (k == 0)
                continue;
            ownDisp.push_back({s[0], s[1]});
            ownForce.push_back({f[0], f[1]});
        }
        own.hold("end of the comparison");
        double worst = 0.0;
        for (std::size_t col = 0; col < 2; ++col)
            worst = std::max(
                {worst, relativeGap(disp, ownDisp, col), relativeGap(force, ownForce, col)});
        qInfo("OpenSees/OpenFresco vs HSMU's client, delay and lag channels: largest gap %.3g "
              "of the peak (lateral stroke at step 12: kit %.17g, HSMU %.17g, commanded %.17g)",
              worst, disp.back()[2], ownDisp.back()[1], lateralAt(kSteps));
        QVERIFY2(worst <= 1e-12, qPrintable(QString::number(worst)));
        // The models act: each stroke differs from its step's command.
        for (int k = 1; k <= kSteps; ++k) {
            QVERIFY(std::abs(ownDisp[std::size_t(k - 1)][0] - verticalAt(k)) > 1e-8);
            QVERIFY(std::abs(ownDisp[std::size_t(k - 1)][1] - lateralAt(k)) > 1e-8);
        }
    }
};

QTEST_GUILESS_MAIN(TestChannelLoopsOpenSees)
#include "TestChannelLoopsOpenSees.moc"
