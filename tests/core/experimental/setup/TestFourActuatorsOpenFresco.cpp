// FourActuators3d against the real OpenFresco 2.8 (../shared/tools/opensees; QSKIP with the
// reason where it is absent). OpenFresco's SimUniaxialMaterials refuses this setup's sizes
// (four commands, six daq forces: docs/setups.md, "Differences from OpenFresco" item 7), so the
// virtual lab here is a GenericTCP server in this test (comms' OfSocket): OpenFresco's
// `expControl GenericTCP` sends the four strokes, the server answers the six daq forces, the
// rods' load cells (given per step) and four elastic actuators k_i s_i. OpenSees drives a
// zero-length 3-D `expElement twoNodeLink` (-dir 1..6) through a basic-displacement history
// (lateral to 0.12 m, rotations to 0.25 rad), one static step per row, and records the
// element's ctrlDisp and daqForce and the control's ctrlDisp and daqForce. Checked
// (docs/setups.md, "Checked against OpenFresco" and "Differences" items 8-9):
// - strokes: HSMU's exact strokes(d) against OpenFresco's commands to 1e-10 of the peak, with and
//   without -nlGeom (OpenFresco has no linear version);
// - the actuators' share of the basic forces (rods unloaded): the shears, axial and twist
//   entries to 1e-10 of the peak; OpenFresco's moments against its own form (moments about the
//   axes of actuators 3 and 4, arms shifted by the translation) computed here from the deformed
//   geometry, to 1e-10; HSMU's moments are J^T f (test_experimental_setups) and differ, measured;
// - the rods' share (a second run with the rods loaded, minus the first): OpenFresco reports no
//   axial force (exactly 0) and its lateral entries equal its small-angle forms to 1e-10;
//   HSMU's rods are checked against the exact statics in test_experimental_setup_rods.

#include "OpenFrescoSetupRun.h"
#include "SetupCatalog.h"
#include "comms/openfresco/OfSocket.h"
#include "core/experimental/setup/SetupScript.h"

#include <QTemporaryDir>
#include <QtTest>

#include <array>
#include <cmath>
#include <cstdint>
#include <thread>

using namespace hsmu;

namespace {

using ofsetup::Table;

constexpr std::array<double, 4> kStiffness = {2.0e7, 2.5e7, 3.0e7, 2.2e7}; // [N/m]
// the setup's line: SetupCatalog's four() with OpenFresco's spreader-beam numbers
const char* kLine = "expSetup FourActuators3d 1 -control 1 1.2 1.3 1.1 1.4 0.3 0.35 0.25 0.4 0.8 "
                    "0.45 0.3 0.2 0.2 1.6 1.9 0.4";

// Node 2's six global DOFs per step; with -orient 0 0 1 1 0 0 the element's basic d is
// (uz, ux, uy, rz, rx, ry) of node 2 (read back from the element's ctrlDisp).
std::vector<std::array<double, 6>> history() {
    std::vector<std::array<double, 6>> h;
    for (int k = 1; k <= 24; ++k) {
        const double t = k / 24.0;
        // d = (uz, ux, uy, rz, rx, ry): axial, lateral 1, rotation 1, lateral 2, rotation 2, twist
        h.push_back({0.12 * std::sin(5.0 * t), -0.2 * std::sin(6.0 * t + 1.0),
                     0.004 * std::sin(2.0 * t), 0.25 * std::sin(4.0 * t + 0.3), 0.003 * t,
                     -0.09 * std::sin(3.0 * t + 0.5)});
    }
    return h;
}

// the load cells' forces the lab reports [N]: rods in tension (negative), varying with the
// strokes so that every step differs; zero when the rods are unloaded
std::array<double, 2> rodForces(const std::array<double, 4>& s, bool loaded) {
    if (!loaded)
        return {0.0, 0.0};
    return {-4.0e5 * (1.0 + 2.0 * s[0]), -3.5e5 * (1.0 - 3.0 * s[1])};
}

// The virtual lab: one GenericTCP session (OpenFresco sends 3 then 6 per step, 99 at the end).
struct Lab {
    std::string error;
    int trials = 0;
};

void serve(comms::of::OfListener& listener, bool rodsLoaded, Lab& lab) {
    comms::of::OfSocket sock;
    std::string e;
    if (!listener.accept(sock, 60.0, e)) {
        lab.error = "no connection: " + e;
        return;
    }
    std::int32_t hdr[11];
    if (!sock.read(hdr, sizeof hdr, 30.0, e)) {
        lab.error = "no header: " + e;
        return;
    }
    if (hdr[0] != 4 || hdr[8] != 6) {
        lab.error =
            "sizes: ctrl disp " + std::to_string(hdr[0]) + ", daq force " + std::to_string(hdr[8]);
        return;
    }
    const int n = hdr[10];
    const int force = hdr[5] + hdr[6] + hdr[7]; // daq disp, vel, accel come first
    std::vector<double> frame(static_cast<std::size_t>(n));
    std::array<double, 4> s{};
    for (;;) {
        if (!sock.read(frame.data(), frame.size() * sizeof(double), 30.0, e)) {
            lab.error = "read: " + e;
            return;
        }
        const int code = static_cast<int>(frame[0]);
        if (code == 3) {
            for (int i = 0; i < 4; ++i)
                s[i] = frame[1 + i];
            ++lab.trials;
        } else if (code == 6) {
            std::vector<double> out(frame.size(), 0.0);
            const auto rods = rodForces(s, rodsLoaded);
            out[force] = rods[0];
            out[force + 1] = rods[1];
            for (int i = 0; i < 4; ++i)
                out[force + 2 + i] = kStiffness[i] * s[i];
            if (!sock.write(out.data(), out.size() * sizeof(double), 30.0, e)) {
                lab.error = "write: " + e;
                return;
            }
        } else if (code == 99) {
            return;
        }
    }
}

struct Run {
    bool ran = false;
    QString output;
    std::string labError;
    Table trial, daqDisp, daqForce, strokes, forces;
};

Run runOpenFresco(const QString& dir, bool nlGeom, bool rodsLoaded) {
    Run out;
    comms::of::OfListener listener;
    std::string e;
    if (!listener.listen("127.0.0.1", 0, e)) {
        out.labError = e;
        return out;
    }
    Lab lab;
    std::thread server([&] { serve(listener, rodsLoaded, lab); });
    const auto h = history();
    const int n = static_cast<int>(h.size());
    QStringList tcl;
    tcl << "model BasicBuilder -ndm 3 -ndf 6"
        << "loadPackage OpenFrescoTcl"
        << "node 1 0 0 0"
        << "node 2 0 0 0"
        << "node 3 0 0 0"
        << "fix 1 1 1 1 1 1 1"
        << QString("expControl GenericTCP 1 127.0.0.1 %1 -ctrlModes 1 0 0 0 0 -daqModes 0 0 0 1 0")
               .arg(listener.port())
        << QString(kLine) + (nlGeom ? " -nlGeom" : "") << "expSite LocalSite 1 1"
        << "expRecorder Control -file act_cmd.out -precision 17 -control 1 ctrlDisp"
        << "expRecorder Control -file act_force.out -precision 17 -control 1 daqForce"
        << "expElement twoNodeLink 1 1 2 -dir 1 2 3 4 5 6 -site 1 -initStif 1e6 0 0 0 0 0 0 1e6 "
           "0 0 0 0 0 0 1e6 0 0 0 0 0 0 1e6 0 0 0 0 0 0 1e6 0 0 0 0 0 0 1e6 -orient 0 0 1 1 0 0"
        << "uniaxialMaterial Elastic 99 1.0"
        << "element zeroLength 2 1 3 -mat 99 99 99 99 99 99 -dir 1 2 3 4 5 6";
    tcl << ofsetup::imposeHistory(h) << ofsetup::stepAndRecord(n, "FOUR_RUN_DONE", true);
    // ECGenericTCP waits for two Enter presses before it starts
    const opensees::Result r =
        opensees::run(dir, "four.tcl", tcl.join('\n') + '\n', 60000, QByteArray("\n\n"));
    listener.close();
    server.join();
    out.output = r.output;
    out.labError = lab.error;
    out.trial = ofsetup::recorded(dir, "ele_trial.out", n);
    out.daqDisp = ofsetup::recorded(dir, "ele_disp.out", n);
    out.daqForce = ofsetup::recorded(dir, "ele_force.out", n);
    out.strokes = ofsetup::recorded(dir, "act_cmd.out", n, true);
    out.forces = ofsetup::recorded(dir, "act_force.out", n, true);
    out.ran = r.finished && r.output.contains("FOUR_RUN_DONE") && lab.error.empty();
    for (const Table* t : {&out.trial, &out.daqDisp, &out.daqForce, &out.strokes, &out.forces})
        out.ran = out.ran && static_cast<int>(t->size()) == n;
    return out;
}

Eigen::VectorXd row(const Table& t, int k) {
    const auto& r = t.at(static_cast<std::size_t>(k));
    return Eigen::Map<const Eigen::VectorXd>(r.data(), static_cast<Eigen::Index>(r.size()));
}

// OpenFresco's setup forces: the element's daqForce. Measured here: in DOFs 1-4 it carries the
// setup's forces as they are (HSMU's shears equal them to 1e-16), in DOFs 0 and 5 (the setup
// reports 0) the element's initial-stiffness term K0 d alone (checked below).
Eigen::VectorXd openFrescoSetupForces(const Run& r, int k) {
    Eigen::VectorXd q = row(r.daqForce, k);
    q(0) = q(5) = 0.0;
    return q;
}

// The deformed geometry, independent of HSMU's code (Eigen's AngleAxis for the rotation vector).
struct Pose {
    double ux, uy, phix, phiy;
    Eigen::Matrix3d R;
};
Pose poseOf(const Eigen::VectorXd& d) {
    Pose p{-d(1), -d(3), -d(4), -d(2), Eigen::Matrix3d::Identity()};
    const Eigen::Vector3d w(p.phix, p.phiy, 0.0);
    if (w.norm() > 0)
        p.R = Eigen::AngleAxisd(w.norm(), w.normalized()).toRotationMatrix();
    return p;
}

// OpenFresco's moments of the actuators (item 9d): about the x and y axes through the control
// point, of actuators 3 and 4 only, their arms shifted by the control point's translation:
// My = sum_{3,4} (Ra x F)_y + ux Fz, Mx = sum_{3,4} (Ra x F)_x - uy Fz; q(2) = -My, q(4) = -Mx.
Eigen::Vector2d openFrescoActuatorMoments(const Eigen::VectorXd& d, const Eigen::VectorXd& f6) {
    const Pose p = poseOf(d);
    const double a3 = 0.25, a4 = 0.4, h = 0.8, L3 = 1.1, L4 = 1.4;
    const Eigen::Vector3d att[2] = {{-a3, 0, h}, {0, -a4, h}};
    const Eigen::Vector3d base[2] = {{-a3 - L3, 0, h}, {0, -a4 - L4, h}};
    Eigen::Vector3d M = Eigen::Vector3d::Zero();
    double Fz = 0;
    for (int i = 0; i < 2; ++i) {
        const Eigen::Vector3d Ra = p.R * att[i];
        const Eigen::Vector3d F =
            f6(4 + i) * (Eigen::Vector3d(p.ux, p.uy, 0) + Ra - base[i]).normalized();
        M += Ra.cross(F);
        Fz += F.z();
    }
    return {-(M.y() + p.ux * Fz), -(M.x() - p.uy * Fz)};
}

// HSMU's moments by exact statics: all four actuators' moment M about the control point at the
// deformed position, made conjugate to the rotation vector: q_w = J_r(w)^T R(w)^T M, with
// J_r's columns from central differences of R (vee of R^T dR), independent of HSMU's code.
Eigen::Vector2d exactMoments(const Eigen::VectorXd& d, const Eigen::VectorXd& f6) {
    const Pose p = poseOf(d);
    const double a[4] = {0.3, 0.35, 0.25, 0.4}, L[4] = {1.2, 1.3, 1.1, 1.4}, h = 0.8;
    Eigen::Vector3d M = Eigen::Vector3d::Zero();
    for (int i = 0; i < 4; ++i) {
        const bool x = i % 2 == 0;
        const Eigen::Vector3d att(x ? -a[i] : 0, x ? 0 : -a[i], i < 2 ? 0 : h);
        const Eigen::Vector3d base =
            att - L[i] * (x ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY());
        const Eigen::Vector3d Ra = p.R * att;
        M += Ra.cross(f6(2 + i) * (Eigen::Vector3d(p.ux, p.uy, 0) + Ra - base).normalized());
    }
    auto rot = [](const Eigen::Vector3d& w) -> Eigen::Matrix3d {
        return w.norm() > 0 ? Eigen::AngleAxisd(w.norm(), w.normalized()).toRotationMatrix()
                            : Eigen::Matrix3d::Identity();
    };
    const Eigen::Vector3d w(p.phix, p.phiy, 0.0);
    Eigen::Matrix<double, 3, 2> Jr;
    for (int k = 0; k < 2; ++k) {
        const double e = 1e-6;
        const Eigen::Matrix3d dR =
            p.R.transpose() *
            (rot(w + e * Eigen::Vector3d::Unit(k)) - rot(w - e * Eigen::Vector3d::Unit(k))) /
            (2 * e);
        Jr.col(k) << dR(2, 1), dR(0, 2), dR(1, 0);
    }
    const Eigen::Vector2d qw = Jr.transpose() * p.R.transpose() * M; // (phix, phiy)
    return {-qw(1), -qw(0)};                                         // q(2), q(4)
}

} // namespace

class TestFourActuatorsOpenFresco : public QObject {
    Q_OBJECT
private slots:
    void againstOpenFresco();
};

void TestFourActuatorsOpenFresco::againstOpenFresco() {
    if (!opensees::available())
        QSKIP(qPrintable(opensees::reason()));
    std::string e;
    SetupsByTag parsed; // HSMU reads the very line OpenFresco runs
    QVERIFY2(parseSetupScript(std::string(kLine) + " -nlGeom\n", parsed, e), e.c_str());
    const ExperimentalSetup& setup = *parsed.at(1);
    QCOMPARE(setup.loadCellCount(), 2);

    QTemporaryDir dirA, dirB, dirL;
    const Run a = runOpenFresco(dirA.path(), true, false);
    QVERIFY2(a.ran, qPrintable(QString::fromStdString(a.labError) + "\n" + a.output.right(2000)));
    const Run b = runOpenFresco(dirB.path(), true, true);
    QVERIFY2(b.ran, qPrintable(QString::fromStdString(b.labError) + "\n" + b.output.right(2000)));
    const Run lin = runOpenFresco(dirL.path(), false, true);
    QVERIFY2(lin.ran,
             qPrintable(QString::fromStdString(lin.labError) + "\n" + lin.output.right(2000)));
    const int n = static_cast<int>(a.trial.size());

    // strokes: exact geometry on both sides; OpenFresco's "linear" is its nonlinear one
    double sPeak = 0, sErr = 0, linErr = 0;
    Eigen::VectorXd qPeak = Eigen::VectorXd::Zero(6), actErr = Eigen::VectorXd::Zero(6);
    Eigen::VectorXd rodPeak = Eigen::VectorXd::Zero(6), rodErr = Eigen::VectorXd::Zero(6);
    double momentModelErr = 0, rodModelErr = 0, exactMomentErr = 0;
    for (int k = 0; k < n; ++k) {
        const Eigen::VectorXd d = row(a.trial, k);
        QVERIFY((row(b.trial, k) - d).cwiseAbs().maxCoeff() == 0.0);
        Eigen::VectorXd s;
        QVERIFY(setup.strokes(d, s).ok);
        sPeak = std::max(sPeak, s.cwiseAbs().maxCoeff());
        sErr = std::max(sErr, (s - row(a.strokes, k)).cwiseAbs().maxCoeff());
        linErr = std::max(linErr, (s - row(lin.strokes, k)).cwiseAbs().maxCoeff());
        // the lab's forces as OpenFresco received them
        const Eigen::VectorXd fA = row(a.forces, k), fB = row(b.forces, k);
        for (int i = 0; i < 4; ++i)
            QVERIFY(std::abs(fA(2 + i) - kStiffness[i] * s(i)) <= 1e-9 * kStiffness[i] * sPeak);
        // the element's K0 term where OpenFresco's setup reports 0
        QCOMPARE(row(a.daqForce, k)(0), 1e6 * d(0));
        QCOMPARE(row(a.daqForce, k)(5), 1e6 * d(5));
        // the actuators' share (rods unloaded)
        Eigen::VectorXd qh;
        QVERIFY(setup.basicForces(d, fA, qh).ok);
        const Eigen::VectorXd qo = openFrescoSetupForces(a, k);
        qPeak = qPeak.cwiseMax(qh.cwiseAbs());
        actErr = actErr.cwiseMax((qh - qo).cwiseAbs());
        const Eigen::Vector2d mo = openFrescoActuatorMoments(d, fA);
        const Eigen::Vector2d me = exactMoments(d, fA);
        exactMomentErr =
            std::max(exactMomentErr, std::max(std::abs(me(0) - qh(2)), std::abs(me(1) - qh(4))));
        momentModelErr =
            std::max(momentModelErr, std::max(std::abs(mo(0) - qo(2)), std::abs(mo(1) - qo(4))));
        // the rods' share: run B minus run A on each side (the same strokes and actuator forces)
        QVERIFY((fB.tail<4>() - fA.tail<4>()).cwiseAbs().maxCoeff() == 0.0);
        Eigen::VectorXd qhB;
        QVERIFY(setup.basicForces(d, fB, qhB).ok);
        const Eigen::VectorXd rodH = qhB - qh;
        const Eigen::VectorXd rodO = openFrescoSetupForces(b, k) - qo;
        rodPeak = rodPeak.cwiseMax(rodH.cwiseAbs());
        rodErr = rodErr.cwiseMax((rodH - rodO).cwiseAbs());
        QCOMPARE(rodO(0), 0.0); // item 9a: OpenFresco reports no axial force
        // item 9b/9c: OpenFresco's small-angle rod forces, lateral entries
        const Pose p = poseOf(d);
        const double uxPin = p.ux + (p.R * Eigen::Vector3d(0, 0, 0.45)).x();
        const double rodX = (fB(0) / 1.6 + fB(1) / 1.9) * uxPin * std::cos(p.phix);
        const double rodY = (fB(0) + fB(1)) * std::sin(p.phix);
        rodModelErr =
            std::max(rodModelErr, std::max(std::abs(rodO(1) - (-rodX)), std::abs(rodO(3) - rodY)));
    }
    qInfo("strokes: worst %.3g m of a %.3g m peak; without -nlGeom %.3g m", sErr, sPeak, linErr);
    QVERIFY2(sErr <= 1e-10 * sPeak, "strokes differ from OpenFresco's");
    QVERIFY2(linErr <= 1e-10 * sPeak, "OpenFresco's linear FourActuators3d is its nonlinear one");
    for (int j = 0; j < 6; ++j)
        qInfo("basic force %d: actuators' share differs by %.4g of a %.4g peak; rods' share by "
              "%.4g of a %.4g peak",
              j, actErr(j), qPeak(j), rodErr(j), rodPeak(j));
    qInfo("OpenFresco against its departures: actuators' moments %.3g, rods' lateral forces %.3g",
          momentModelErr, rodModelErr);
    // shears, axial and twist: equal to 1e-10 of the peak (OpenFresco's 0 in DOFs 0 and 5 is
    // the actuators' share there too)
    for (int j : {0, 1, 3, 5})
        QVERIFY2(actErr(j) <= 1e-10 * qPeak.maxCoeff(),
                 qPrintable(QString("actuators' share, DOF %1: %2").arg(j).arg(actErr(j))));
    qInfo("HSMU's moments against the exact statics (J_r^T R^T M): %.3g", exactMomentErr);
    QVERIFY2(exactMomentErr <= 1e-8 * qPeak.maxCoeff(), "HSMU's moments: not the exact statics");
    // moments: OpenFresco's equal its departure (item 9d) to 1e-10 of the peak
    QVERIFY2(momentModelErr <= 1e-10 * qPeak.maxCoeff(), "OpenFresco's moments: another form");
    // rods: OpenFresco's lateral forces equal its small-angle forms (items 9b, 9c)
    QVERIFY2(rodModelErr <= 1e-10 * rodPeak.maxCoeff(), "OpenFresco's rod forces: another form");
}

QTEST_GUILESS_MAIN(TestFourActuatorsOpenFresco)
#include "TestFourActuatorsOpenFresco.moc"
