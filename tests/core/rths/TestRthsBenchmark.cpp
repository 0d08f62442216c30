// The RTHS benchmark (docs/rths.md, "The benchmark"): the published sample controller reproduced
// within +-0.5 (ms or % points) of the independent reproduction's means (RTHS-BENCHMARK.md, noise
// on), the product's default compensation meeting issue 23's figures on the nominal and on 20
// perturbed plants per case, and the holds. Needs the benchmark's El Centro record in
// HSMU_SHARED_DATA_DIR/rths-benchmark; skipped (with the reason) without it.
// CTest runs one case per test (tests/core/rths/CMakeLists.txt): data tags "case1".."case4".
#include "core/groundmotion/GroundMotionReader.h"
#include "core/rths/RthsBenchmark.h"
#include "core/rths/RthsReport.h"

#include <QtTest>

#include <filesystem>

using namespace hsmu;
using namespace hsmu::rths;

namespace {

const std::string kRecord = std::string(HSMU_SHARED_DATA_DIR) + "/rths-benchmark/elcentro_benchmark.txt";

GroundMotion benchmarkRecord()
{
    return readGroundMotion(kRecord, GroundMotionFormat::Auto, AccelerationUnit::MetersPerSecond2)
        .scaled(0.4);
}

// RTHS-BENCHMARK.md, "Measured here": the reproduction's means of J1..J9 per case.
const double kReproduction[4][9] = {
    {4.60, 10.39, 11.52, 36.07, 18.45, 32.25, 32.37, 14.81, 14.75},
    {4.60, 9.81, 11.12, 33.08, 17.31, 30.48, 30.57, 15.28, 15.23},
    {4.60, 9.04, 10.18, 49.84, 36.61, 49.78, 49.79, 35.50, 35.55},
    {4.60, 10.47, 11.29, 72.57, 35.21, 68.50, 68.66, 33.42, 33.29}};

QString criteriaText(const BenchmarkCriteria& c)
{
    QString s;
    for (int i = 0; i < 9; ++i)
        s += QString("J%1 %2  ").arg(i + 1).arg(c.j[i], 0, 'f', 2);
    return s;
}

} // namespace

#define REQUIRE_RECORD()                                                                           \
    if (!std::filesystem::exists(kRecord))                                                         \
    QSKIP("the RTHS benchmark's El Centro record is not in HSMU_SHARED_DATA_DIR/rths-benchmark "   \
          "(" HSMU_SHARED_DATA_DIR "): the benchmark checks need the shared data folder")

class TestRthsBenchmark : public QObject {
    Q_OBJECT

    void cases()
    {
        QTest::addColumn<int>("benchmarkCase");
        for (int c = 1; c <= 4; ++c)
            QTest::newRow(qPrintable(QString("case%1").arg(c))) << c;
    }

private slots:
    void sampleControllerReproducesTheBenchmark_data() { cases(); }
    void sampleControllerReproducesTheBenchmark()
    {
        REQUIRE_RECORD();
        QFETCH(int, benchmarkCase);
        const GroundMotion ag = benchmarkRecord();
        const PlantParameters nominal;
        double mean[9] = {};
        const int seeds = 4;
        for (int seed = 1; seed <= seeds; ++seed) {
            RthsSettings s = benchmarkSampleController();
            s.sensors.seed = std::uint64_t(seed);
            const RthsRun run = runRths(benchmarkPartition(benchmarkCase, nominal), ag, s);
            QVERIFY2(run.hold.empty(), run.hold.c_str());
            for (int i = 0; i < 9; ++i)
                mean[i] += run.criteria.j[i] / seeds;
        }
        BenchmarkCriteria m;
        std::copy(mean, mean + 9, m.j);
        qInfo("case %d, sample controller, mean of %d seeds: %s", benchmarkCase, seeds, qPrintable(criteriaText(m)));
        for (int i = 0; i < 9; ++i)
            QVERIFY2(std::abs(mean[i] - kReproduction[benchmarkCase - 1][i]) <= 0.5,
                     qPrintable(QString("J%1 = %2, reproduction %3").arg(i + 1).arg(mean[i]).arg(kReproduction[benchmarkCase - 1][i])));
    }

    void defaultCompensationOnTheNominalPlant_data() { cases(); }
    void defaultCompensationOnTheNominalPlant()
    {
        REQUIRE_RECORD();
        QFETCH(int, benchmarkCase);
        const PlantParameters nominal;
        const RthsRun run = runRths(benchmarkPartition(benchmarkCase, nominal), benchmarkRecord(),
                                    defaultCompensation(nominal));
        qInfo("case %d, default compensation: %s", benchmarkCase, qPrintable(criteriaText(run.criteria)));
        QVERIFY2(run.hold.empty(), run.hold.c_str());
        QVERIFY(run.criteria.j[0] <= 0.5);
        QVERIFY(run.criteria.j[1] <= 3.0);
        QVERIFY(run.criteria.j[3] <= 4.5);
    }

    void defaultCompensationOnPerturbedPlants_data() { cases(); }
    void defaultCompensationOnPerturbedPlants()
    {
        // 20 plants drawn from the benchmark's distributions; the feedforward stays fitted to the
        // nominal plant (a lab knows only its nominal model), the partition takes the drawn
        // specimen (Kn = Kr - Ke).
        REQUIRE_RECORD();
        QFETCH(int, benchmarkCase);
        const GroundMotion ag = benchmarkRecord();
        const PlantParameters nominal;
        const RthsSettings compensated = defaultCompensation(nominal);
        PortableRandom random(std::uint64_t(1000 + benchmarkCase));
        double worstJ2 = 0.0, worstJ4 = 0.0;
        for (int i = 0; i < 20; ++i) {
            RthsSettings s = compensated;
            s.plant = perturbedPlant(nominal, random);
            s.sensors.seed = std::uint64_t(i + 1);
            const RthsRun run = runRths(benchmarkPartition(benchmarkCase, s.plant), ag, s);
            QVERIFY2(run.hold.empty(), run.hold.c_str());
            QVERIFY(run.peakStroke < s.limits.stroke && run.peakForce < s.limits.force &&
                    run.peakVelocity < s.limits.velocity);
            worstJ2 = std::max(worstJ2, run.criteria.j[1]);
            worstJ4 = std::max(worstJ4, run.criteria.j[3]);
        }
        qInfo("case %d, 20 perturbed plants: worst J2 %.2f %%, worst J4 %.2f %%", benchmarkCase, worstJ2, worstJ4);
        QVERIFY(worstJ2 <= 3.5);
        QVERIFY(worstJ4 <= 7.0);
    }

    void aStrokeLimitHoldsTheTestNamingTheChannel()
    {
        // Floor 1 peaks near 3.9 mm: a 2 mm stroke is reached. Every tick before the hold is kept.
        REQUIRE_RECORD();
        RthsSettings s = benchmarkSampleController();
        s.limits.stroke = 2e-3;
        const RthsRun run = runRths(benchmarkPartition(1, s.plant), benchmarkRecord(), s);
        QVERIFY(!run.hold.empty());
        QVERIFY2(run.hold.find("stroke limit") != std::string::npos, run.hold.c_str());
        QVERIFY(run.hold.find("at tick") != std::string::npos);
        QVERIFY(run.time.size() > 1000);
        QCOMPARE(run.reference.rows(), Eigen::Index(run.time.size()));
    }

    void theLoopDelayOfTheSampleController()
    {
        // The closed loop's phase delay (the design model behind the feedforward fit): about
        // 4.6 ms with the lead, about 10.4 ms with the PI alone (RTHS-BENCHMARK.md).
        RthsSettings s = benchmarkSampleController();
        QVERIFY(std::abs(loopDelay(s, 1.0) - 4.6e-3) < 0.1e-3);
        s.compensation.lead.enabled = false;
        QVERIFY2(std::abs(loopDelay(s, 1.0) - 10.4e-3) < 0.3e-3, qPrintable(QString::number(loopDelay(s, 1.0) * 1e3)));
    }

    void preflightRefusesALoopSlowerThanTheCriticalDelay()
    {
        // The PI alone leaves ~10.6 ms (with the force's tick) against case 4's 8.7 ms: refused
        // with both delays; the sample controller (4.8 ms) passes case 1 (14.6 ms) unflagged
        // but is flagged on case 4; the default compensation leaves well under 1 ms.
        RthsSettings pi = benchmarkSampleController();
        pi.compensation.lead.enabled = false;
        const Preflight refused = preflight(benchmarkPartition(4, pi.plant), pi);
        QVERIFY(refused.refused);
        QVERIFY(std::abs(refused.criticalDelay - 8.7e-3) < 0.1e-3);
        QVERIFY2(refused.message.find("8.7") != std::string::npos && refused.message.find("10.") != std::string::npos,
                 refused.message.c_str());
        const RthsSettings sample = benchmarkSampleController();
        const Preflight ok = preflight(benchmarkPartition(1, sample.plant), sample);
        QVERIFY(!ok.refused && !ok.flagged);
        QVERIFY(std::abs(ok.loopDelay - (4.6e-3 + 1.0 / 4096.0)) < 0.15e-3);
        QVERIFY(preflight(benchmarkPartition(4, sample.plant), sample).flagged);
        const RthsSettings def = defaultCompensation();
        QVERIFY(preflight(benchmarkPartition(4, def.plant), def).loopDelay < 0.5e-3);
    }

    void badPlantIsRefusedWithItsName()
    {
        RthsSettings s = benchmarkSampleController();
        s.plant.b2 = -1.0;
        GroundMotion ag;
        ag.dt = 0.01;
        ag.acceleration = {0.0, 0.0};
        try {
            RthsLoop loop(benchmarkPartition(1, PlantParameters{}), ag, s);
            QFAIL("a negative b2 was accepted");
        } catch (const std::invalid_argument& e) {
            QVERIFY(std::string(e.what()).find("b2") != std::string::npos);
        }
    }
};

QTEST_APPLESS_MAIN(TestRthsBenchmark)
#include "TestRthsBenchmark.moc"
