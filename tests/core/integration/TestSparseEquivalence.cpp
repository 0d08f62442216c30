// Issue 17: the sparse structure and integrators give today's results. Every shipped preset
// (resources/presets/*.json) runs through HybridTest twice, once as built (sparse K0, C; the
// left-hand side diagonal or a sparse LDL^T) and once with the dense reference of
// DenseReference.h (the code before issue 17), with explicit Newmark and with alpha-OS;
// displacements, velocities, accelerations and element forces agree to 1e-12 relative (of
// the history's peak) at every step. Also: the Rayleigh coefficients and omega_max equal the
// dense eigen-solve's, and a 40-storey shear building (sparse LDL^T path) matches likewise.

#include "DenseReference.h"

#include "core/config/ConfigLoader.h"
#include "core/config/ShearBuilding.h"
#include "core/config/TestFactory.h"
#include "core/config/UpdatingConfig.h"
#include "core/integration/StabilityCheck.h"
#include "core/experiment/HybridTest.h"
#include "core/updating/ModelUpdater.h"

#include <QDir>
#include <QtTest>

using namespace hsmu;
using namespace hsmu::testing;

namespace {

const QString kPresetDir = QStringLiteral(HSMU_SOURCE_DIR "/resources/presets");
constexpr double kTol = 1e-12;
constexpr int kMaxSteps = 1500; // a few seconds of every preset: the test stays short

struct Recorder final : StepObserver {
    std::vector<StepRecord> records;
    void onStep(const StepRecord& r) override { records.push_back(r); }
};

std::unique_ptr<Integrator> referenceIntegrator(const TestConfig& cfg) {
    if (cfg.analysis.integrator == "alphaOS")
        return std::make_unique<DenseAlphaOS>(cfg.damping, cfg.analysis.alpha);
    return std::make_unique<DenseExplicitNewmark>(cfg.damping);
}

/// Runs at most kMaxSteps; the reference replaces the integrator only.
std::vector<StepRecord> run(const TestConfig& cfg, bool reference) {
    HybridTestOptions o;
    o.dt = cfg.analysis.dt;
    o.duration = std::min(cfg.analysis.duration > 0.0 ? cfg.analysis.duration : 1e9,
                          kMaxSteps * cfg.analysis.dt);
    o.allowUnstable = cfg.analysis.allowUnstable;
    auto test = std::make_unique<HybridTest>(
        buildStructure(cfg), reference ? referenceIntegrator(cfg) : buildIntegrator(cfg.analysis),
        buildGroundMotion(cfg.groundMotion, cfg.sourcePath), o);
    test->setUpdater(buildModelUpdater(cfg));
    Recorder rec;
    test->addObserver(&rec);
    if (!test->prepare())
        return {};
    while (test->step() == HybridTest::StepResult::Advanced) {
    }
    return rec.records;
}

/// Largest |x - y| over the histories relative to the peak |y|; "" if sizes agree.
struct Deviation {
    double worst = 0.0;
    QString where;
};

void compare(const std::vector<StepRecord>& a, const std::vector<StepRecord>& b, Deviation& d) {
    auto peakOf = [&](auto get) {
        double p = 0.0;
        for (const auto& r : b)
            p = std::max(p, get(r));
        return p > 0.0 ? p : 1.0;
    };
    const double pu = peakOf([](const StepRecord& r) { return r.u.cwiseAbs().maxCoeff(); });
    const double pv = peakOf([](const StepRecord& r) { return r.v.cwiseAbs().maxCoeff(); });
    const double pa = peakOf([](const StepRecord& r) { return r.a.cwiseAbs().maxCoeff(); });
    const double pf = peakOf([](const StepRecord& r) {
        double m = 0.0;
        for (const auto& e : r.elements)
            m = std::max(m, std::abs(e.force));
        return m;
    });
    for (std::size_t i = 0; i < a.size(); ++i) {
        auto note = [&](double dev, const char* what) {
            if (dev > d.worst) {
                d.worst = dev;
                d.where = QString("%1 at step %2").arg(what).arg(i);
            }
        };
        note((a[i].u - b[i].u).cwiseAbs().maxCoeff() / pu, "u");
        note((a[i].v - b[i].v).cwiseAbs().maxCoeff() / pv, "v");
        note((a[i].a - b[i].a).cwiseAbs().maxCoeff() / pa, "a");
        for (std::size_t e = 0; e < a[i].elements.size(); ++e)
            note(std::abs(a[i].elements[e].force - b[i].elements[e].force) / pf, "force");
    }
}

} // namespace

class TestSparseEquivalence : public QObject {
    Q_OBJECT
private slots:
    void presetsMatchDensePath_data();
    void presetsMatchDensePath();
    void shearBuildingMatchesDensePath_data();
    void shearBuildingMatchesDensePath();
};

void TestSparseEquivalence::presetsMatchDensePath_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("integrator");
    const QStringList files = QDir(kPresetDir).entryList({"*.json"}, QDir::Files, QDir::Name);
    QVERIFY2(files.size() >= 6, qPrintable(kPresetDir));
    for (const QString& f : files)
        for (const char* in : {"explicitNewmark", "alphaOS"})
            QTest::newRow(qPrintable(f + " " + in)) << f << QString(in);
}

void TestSparseEquivalence::presetsMatchDensePath() {
    QFETCH(QString, file);
    QFETCH(QString, integrator);
    TestConfig cfg = loadConfigFile((kPresetDir + "/" + file).toStdString());
    cfg.analysis.integrator = integrator.toStdString();
    for (ElementSpec& e : cfg.elements) // an OpenSees twin: its model, in process
        e.numericalSite.clear();

    // The model: Rayleigh coefficients and omega_max as the dense eigen-solve gives them.
    auto s = buildStructure(cfg);
    s->finalize();
    const DenseModel d = denseModel(*s, cfg.damping);
    const double omegaMax = d.omega.maxCoeff();
    QVERIFY2(std::abs(s->maxFrequency() - omegaMax) <= kTol * omegaMax,
             qPrintable(QString("omega_max %1 vs %2").arg(s->maxFrequency(), 0, 'g', 17)
                            .arg(omegaMax, 0, 'g', 17)));
    QVERIFY(std::abs(s->rayleigh().a0 - d.rayleigh.a0) <= kTol * std::abs(d.rayleigh.a0));
    QVERIFY(std::abs(s->rayleigh().a1 - d.rayleigh.a1) <= kTol * std::abs(d.rayleigh.a1));
    const Eigen::MatrixXd k0(s->initialStiffness());
    QVERIFY((k0 - d.k0).cwiseAbs().maxCoeff() <= kTol * d.k0.cwiseAbs().maxCoeff());

    const auto sparse = run(cfg, false);
    const auto dense = run(cfg, true);
    QVERIFY2(sparse.size() > 100, "the preset did not run");
    QCOMPARE(sparse.size(), dense.size());
    Deviation dev;
    compare(sparse, dense, dev);
    QVERIFY2(dev.worst <= kTol,
             qPrintable(QString("%1 relative at %2").arg(dev.worst, 0, 'g', 3).arg(dev.where)));
}

void TestSparseEquivalence::shearBuildingMatchesDensePath_data() {
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("integrator");
    for (const char* n : {"shear-building-40", "shear-building-40-elastic-mass-damped"})
        for (const char* in : {"explicitNewmark", "alphaOS"})
            QTest::newRow(qPrintable(QString("%1 %2").arg(n, in))) << QString(n) << QString(in);
}

void TestSparseEquivalence::shearBuildingMatchesDensePath() {
    QFETCH(QString, name);
    QFETCH(QString, integrator);
    const auto spec = parseShearBuildingName(name.toStdString());
    QVERIFY(spec.has_value());
    TestConfig cfg = parseConfig(shearBuildingConfig(*spec), name.toStdString());
    cfg.analysis.integrator = integrator.toStdString();
    cfg.analysis.duration = 1.0;
    cfg.groundMotion.scale = 3.0; // Bouc-Wen storeys yield
    const auto sparse = run(cfg, false);
    const auto dense = run(cfg, true);
    QCOMPARE(int(sparse.size()), 1001);
    QCOMPARE(sparse.size(), dense.size());
    Deviation dev;
    compare(sparse, dense, dev);
    QVERIFY2(dev.worst <= kTol,
             qPrintable(QString("%1 relative at %2").arg(dev.worst, 0, 'g', 3).arg(dev.where)));
}

QTEST_GUILESS_MAIN(TestSparseEquivalence)
#include "TestSparseEquivalence.moc"
