// The experimental link2d with the corotational geometry (core/experimental/ExperimentalLink2d.h,
// Link2dKinematics.h eq. L3-L5; docs/setups.md "Multi-DOF elements") through an exact setup
// on the in-process virtual lab equals the all-numerical run to 1e-9 of the peak, at drifts
// where the corotational and the linear geometry differ.
//
// The column (L = 3 m, base fixed, top DOFs x, y, theta with 20 t, 20 t, 1 t m^2) is a
// cantilever specimen simulated as a whole (CantileverColumn: Bouc-Wen base hinge, elastic
// column EI = 2e5 kN m^2, elastic axial 2e5 kN/m) behind OpenFresco's
// `expSetup ThreeActuators2d 1 1.6 1.1 1.3 0.7 0.5 -nlGeom -phiLocX 90` with three
// displacement-controlled actuators. Reference: the same column as a numerical element (the
// corotational kinematics, the same CantileverColumn on its basic DOFs, the specimen's K0), so
// the two runs differ only by the setup's and the lab's Newton tolerances. Units: kN, m, s, t.

#include "core/experiment/HybridTest.h"
#include "core/experimental/ExperimentalLink2d.h"
#include "core/experimental/VirtualActuatorLab.h"
#include "core/experimental/setup/PlanarSetups.h"
#include "core/hysteresis/BoucWen.h"
#include "core/hysteresis/LinearElastic.h"
#include "core/integration/AlphaOS.h"
#include "core/structure/Structure.h"

#include <QtTest>

#include <cmath>
#include <numbers>

using namespace hsmu;

namespace {

constexpr double kL = 3.0, kEI = 2e5, kAxial = 2e5;

std::unique_ptr<CantileverColumn> column()
{
    BoucWenParameters p;
    p.alpha = 0.05;
    p.uRef = 0.001875; // [rad]
    p.fRef = 60.0;     // [kN m]: initial 3.2e4 kN m/rad, lateral yield near 20 kN
    return std::make_unique<CantileverColumn>(std::make_unique<LinearElastic>(kAxial),
                                              std::make_unique<BoucWen>(p), kL, kEI);
}

std::unique_ptr<ExperimentalSetup> setup()
{
    std::string error;
    auto s = makeThreeActuators2d({1.6, 1.1, 1.3, 0.7, 0.5, SetupGeometry::Exact, false, 90.0},
                                  error);
    if (!s)
        qFatal("%s", error.c_str());
    return s;
}

Link2dGeometry geometry(Link2dTransformation t)
{
    return {{-1, -1, -1, 0, 1, 2}, kL, 90.0, t};
}

// The numerical twin: eq. L3 kinematics, the column's basic forces, K0 given.
class ColumnTwin final : public Element {
public:
    ColumnTwin(const Link2dGeometry& g, const Eigen::Matrix3d& kb0)
        : Element("Column", Link2dKinematics("Column", g).terms(1)), m_kin("Column", g),
          m_column(column()), m_kb0(kb0)
    {
    }
    std::string typeName() const override { return "columnTwin"; }
    ElementStatus setTrial(const Eigen::VectorXd& u) override
    {
        m_ue = m_kin.local(u);
        m_d = m_kin.basicAt(m_ue);
        if (const std::string why = m_column->setTrial(m_d); !why.empty())
            return ElementStatus::failure(why);
        m_q = m_column->trialForces();
        return ElementStatus::success();
    }
    double deformation() const override { return m_d[1]; }
    double force() const override { return m_q[1]; }
    double initialGeneralizedStiffness() const override { return m_kb0(1, 1); }
    ElementStatus commit() override
    {
        m_column->commit();
        m_cUe = m_ue;
        m_cd = m_d;
        m_cq = m_q;
        return ElementStatus::success();
    }
    void revert() override
    {
        m_column->revert();
        m_ue = m_cUe;
        m_d = m_cd;
        m_q = m_cq;
    }
    void addNodalForces(Eigen::VectorXd& r) const override { m_kin.addNodalForces(m_ue, m_q, r); }
    void addInitialStiffness(std::vector<Eigen::Triplet<double>>& k,
                             const std::vector<int>& freeOf) const override
    {
        m_kin.addMatrix(m_kin.tangent(Link2dVector6::Zero(), m_kb0, Eigen::Vector3d::Zero()), k,
                        freeOf);
    }

private:
    Link2dKinematics m_kin;
    std::unique_ptr<CantileverColumn> m_column;
    Eigen::Matrix3d m_kb0;
    Link2dVector6 m_ue = Link2dVector6::Zero(), m_cUe = Link2dVector6::Zero();
    Eigen::Vector3d m_d = Eigen::Vector3d::Zero(), m_cd = m_d, m_q = m_d, m_cq = m_d;
};

std::unique_ptr<ExperimentalLink2d> specimen(Link2dTransformation t)
{
    const std::vector<ActuatorMode> modes(3, ActuatorMode::Displacement);
    auto whole = std::make_unique<SpecimenBehindSetup>(setup(), column(), modes);
    std::vector<ActuatorChannelSpec> ch;
    std::vector<VirtualActuator> acts;
    for (int i = 0; i < 3; ++i) {
        const std::string name = "actuator " + std::to_string(i + 1);
        // K0 = A^T J0^T diag(k_c) J0 A above the specimen's stiffness at rest (alpha-OS stays
        // stable while the structure softens from K0; each channel alone sees far less)
        ch.push_back({name, ActuatorMode::Displacement, 0.0, {}, i == 0 ? 1e5 : 1e6});
        acts.push_back({name, ActuatorMode::Displacement, nullptr});
    }
    auto lab = std::make_unique<VirtualActuatorLab>(std::move(acts), std::move(whole));
    return std::make_unique<ExperimentalLink2d>("Column", geometry(t), setup(), std::move(ch),
                                                std::move(lab));
}

struct Recorder final : StepObserver {
    std::vector<StepRecord> records;
    void onStep(const StepRecord& r) override { records.push_back(r); }
};

std::vector<StepRecord> run(std::unique_ptr<Element> e)
{
    auto s = std::make_unique<Structure>();
    s->addDof("x", 20.0);
    s->addDof("y", 20.0, 0.0);
    s->addDof("theta", 1.0, 0.0);
    s->addElement(std::move(e));
    s->setModalDamping(0.02, 1, 2);
    GroundMotion gm;
    gm.name = "sine";
    gm.dt = 0.01;
    for (int i = 0; i <= 300; ++i)
        gm.acceleration.push_back(6.0 * std::sin(2.0 * std::numbers::pi * 1.0 * i * gm.dt));
    HybridTestOptions o;
    o.dt = 0.01;
    HybridTest t(std::move(s), std::make_unique<AlphaOS>(), gm, o);
    Recorder rec;
    t.addObserver(&rec);
    if (!t.prepare())
        qFatal("%s", t.lastError().c_str());
    while (t.step() == HybridTest::StepResult::Advanced) {
    }
    if (t.state() != HybridTest::State::Finished)
        qFatal("not finished at step %d (u = %g %g %g): %s", t.currentStep(),
               rec.records.empty() ? 0.0 : rec.records.back().u[0],
               rec.records.empty() ? 0.0 : rec.records.back().u[1],
               rec.records.empty() ? 0.0 : rec.records.back().u[2],
               t.alarms().empty() ? "" : t.alarms().back().message.c_str());
    t.removeObserver(&rec);
    return rec.records;
}

} // namespace

class TestExperimentalLink2dCorotational : public QObject {
    Q_OBJECT

private slots:
    void equalsNumericalThroughExactSetup()
    {
        auto x = specimen(Link2dTransformation::Corotational);
        const Eigen::Matrix3d kb0 = x->basicInitialStiffness();
        const auto hyb = run(std::move(x));
        const auto ref =
            run(std::make_unique<ColumnTwin>(geometry(Link2dTransformation::Corotational), kb0));
        const auto lin = run(specimen(Link2dTransformation::Linear));
        QCOMPARE(hyb.size(), ref.size());
        double peak = 0, du = 0, peakF = 0, dF = 0, dLinear = 0, peakY = 0;
        for (std::size_t i = 0; i < ref.size(); ++i) {
            peak = std::max(peak, std::abs(ref[i].u[0]));
            peakY = std::max(peakY, std::abs(ref[i].u[1]));
            du = std::max(du, (hyb[i].u - ref[i].u).cwiseAbs().maxCoeff());
            peakF = std::max(peakF, std::abs(ref[i].elements[0].force));
            dF = std::max(dF, std::abs(hyb[i].elements[0].force - ref[i].elements[0].force));
            dLinear = std::max(dLinear, std::abs(lin[i].u[0] - ref[i].u[0]));
        }
        qInfo("peak drift %.6g m (%.4g rad), peak |y| %.3g m, max |du| %.3g m; peak shear %.6g "
              "kN, max |dF| %.3g kN; linear geometry departs by %.3g m",
              peak, peak / kL, peakY, du, peakF, dF, dLinear);
        QVERIFY(peak / kL > 0.05);          // large drifts: beyond 0.05 rad
        QVERIFY(dLinear > 1e-3 * peak);     // where the geometry matters
        QVERIFY(du <= 1e-9 * peak);
        QVERIFY(dF <= 1e-9 * peakF);
    }
};

QTEST_APPLESS_MAIN(TestExperimentalLink2dCorotational)
#include "TestExperimentalLink2dCorotational.moc"
