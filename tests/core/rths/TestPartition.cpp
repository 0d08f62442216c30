// The RTHS benchmark's reference structures and partitions (docs/rths.md, "The partition"):
// natural frequencies and critical delays against RTHS-BENCHMARK's table, modal damping against
// its definition, the partition's matrices against M - Me etc.
#include "core/rths/Partition.h"
#include "core/rths/ServoHydraulicPlant.h"

#include <Eigen/Dense>
#include <QtTest>

using namespace hsmu::rths;

class TestPartition : public QObject {
    Q_OBJECT

private slots:
    void frequenciesOfTheFourCases()
    {
        const double f[4][3] = {{3.612, 15.997, 38.086}, {3.444, 15.252, 36.314},
                                {3.168, 14.030, 33.404}, {3.612, 15.997, 38.086}};
        for (int c = 1; c <= 4; ++c) {
            const LinearStructure r = benchmarkReference(c);
            const Eigen::VectorXd got = naturalFrequencies(r.m, r.k);
            for (int i = 0; i < 3; ++i)
                QVERIFY2(std::abs(got(i) - f[c - 1][i]) < 1e-3, qPrintable(QString("case %1 mode %2: %3 Hz").arg(c).arg(i + 1).arg(got(i))));
        }
    }

    void modalDampingGivesTheRatioInEveryMode()
    {
        // Phi^T C Phi is diagonal with 2 zeta w_i M_i (w_i rounded to 0.01 rad/s).
        const LinearStructure r = benchmarkReference(2);
        Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(r.k, r.m);
        const Eigen::MatrixXd phi = es.eigenvectors();
        const Eigen::MatrixXd d = phi.transpose() * r.c * phi;
        for (int i = 0; i < 3; ++i) {
            const double w = std::round(std::sqrt(es.eigenvalues()(i)) / 0.01) * 0.01;
            const double mi = phi.col(i).dot(r.m * phi.col(i));
            QVERIFY(std::abs(d(i, i) / (2.0 * w * mi) - 0.04) < 1e-9);
            for (int j = 0; j < 3; ++j)
                if (j != i)
                    QVERIFY(std::abs(d(i, j)) < 1e-9 * std::abs(d(i, i)));
        }
    }

    void partitionSubtractsTheSpecimen()
    {
        const PlantParameters p;
        const LinearStructure r = benchmarkReference(1);
        const Partition part = partition(r, Specimen{0, p.me, p.ce, p.ke});
        QCOMPARE(part.numerical.m(0, 0), 1000.0 - p.me);
        QCOMPARE(part.numerical.k(0, 0), r.k(0, 0) - p.ke);
        QCOMPARE(part.numerical.c(0, 0), r.c(0, 0) - p.ce);
        QCOMPARE(part.numerical.k(1, 2), r.k(1, 2));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, partition(r, Specimen{0, 2000.0, 0.0, 0.0}));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, partition(r, Specimen{3, 1.0, 0.0, 0.0}));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, benchmarkReference(5));
    }

    void criticalDelaysOfTheFourCases()
    {
        // RTHS-BENCHMARK: 14.6, 12.2, 9.9, 8.7 ms.
        const double expected[] = {14.6e-3, 12.2e-3, 9.9e-3, 8.7e-3};
        const PlantParameters p;
        for (int c = 1; c <= 4; ++c) {
            const double tau = criticalDelay(partition(benchmarkReference(c), Specimen{0, p.me, p.ce, p.ke}));
            QVERIFY2(std::abs(tau - expected[c - 1]) < 0.06e-3, qPrintable(QString("case %1: %2 ms").arg(c).arg(tau * 1e3)));
        }
    }

    void criticalDelayOfAnSdofClosedForm()
    {
        // SDOF, closed form: |L| > 1 below one crossing w_c and < 1 above it, so tau is
        // mod(arg L(j w_c) - pi, 2 pi) / w_c.
        LinearStructure r;
        r.m = Eigen::MatrixXd::Constant(1, 1, 10.0);
        r.k = Eigen::MatrixXd::Constant(1, 1, 3000.0);
        r.c = Eigen::MatrixXd::Constant(1, 1, 20.0);
        r.iota = Eigen::VectorXd::Ones(1);
        const Partition p = partition(r, Specimen{0, 0.0, 0.0, 2000.0});
        // numerical: m = 10, c = 20, k = 1000; L = 2000 / (1000 - 10 w^2 + 20 j w).
        // |L| = 1: (1000 - 10 w^2)^2 + 400 w^2 = 4e6 -> w^2 solves 100 w^4 - 19600 w^2 - 3e6 = 0.
        const double w2 = (19600.0 + std::sqrt(19600.0 * 19600.0 + 4 * 100.0 * 3e6)) / 200.0;
        const double w = std::sqrt(w2);
        const std::complex<double> l = 2000.0 / std::complex<double>(1000.0 - 10.0 * w2, 20.0 * w);
        double phase = std::fmod(std::arg(l) - M_PI, 2 * M_PI);
        if (phase < 0.0)
            phase += 2 * M_PI;
        const double expected = phase / w;
        QVERIFY2(std::abs(criticalDelay(p) - expected) < 1e-9, qPrintable(QString("%1 vs %2").arg(criticalDelay(p)).arg(expected)));
    }
};

QTEST_APPLESS_MAIN(TestPartition)
#include "TestPartition.moc"
