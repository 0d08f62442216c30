// ModalAnalysis (issue 17): the sparse Lanczos paths against the dense generalized
// eigen-solve on small models, and against the closed form of a uniform chain.
//   uniform chain of n storeys (mass m, storey stiffness k, fixed base, free top):
//   omega_j = 2 sqrt(k/m) sin((2j - 1) pi / (2 (2n + 1))),  j = 1..n.

#include "core/hysteresis/LinearElastic.h"
#include "core/structure/Lanczos.h"
#include "core/structure/ModalAnalysis.h"
#include "core/structure/SpringElement.h"
#include "core/structure/Structure.h"

#include <Eigen/QR>

#include <QtTest>

#include <cmath>
#include <vector>

using namespace hsmu;

namespace {

using SpMat = Eigen::SparseMatrix<double>;

/// Chain stiffness: storey i (0-based) of stiffness k[i] between floor i-1 (ground) and i;
/// `links` adds extra springs (i, j, k) to make the pattern less regular.
SpMat chainStiffness(const std::vector<double>& k,
                     const std::vector<std::tuple<int, int, double>>& links = {}) {
    const int n = int(k.size());
    std::vector<Eigen::Triplet<double>> t;
    for (int i = 0; i < n; ++i) {
        t.emplace_back(i, i, k[i]);
        if (i > 0) {
            t.emplace_back(i - 1, i - 1, k[i]);
            t.emplace_back(i - 1, i, -k[i]);
            t.emplace_back(i, i - 1, -k[i]);
        }
    }
    for (auto [a, b, kk] : links) {
        t.emplace_back(a, a, kk);
        t.emplace_back(b, b, kk);
        t.emplace_back(a, b, -kk);
        t.emplace_back(b, a, -kk);
    }
    SpMat m(n, n);
    m.setFromTriplets(t.begin(), t.end());
    return m;
}

/// Deterministic values in [lo, hi).
std::vector<double> spread(int n, double lo, double hi, int seed) {
    std::vector<double> v(n);
    for (int i = 0; i < n; ++i)
        v[i] = lo + (hi - lo) * std::fmod(0.6180339887 * (i + 1) * (seed + 1), 1.0);
    return v;
}

} // namespace

class TestModalAnalysis : public QObject {
    Q_OBJECT
private slots:
    void lanczosFullSpaceGivesEveryEigenvalue();
    void lowestModesMatchDense_data();
    void lowestModesMatchDense();
    void largestFrequencyBoundsDense();
    void uniformChainClosedForm();
    void stiffnessFreeDofGivesZero();
    void largeStructureUsesSparseModes();
};

void TestModalAnalysis::lanczosFullSpaceGivesEveryEigenvalue() {
    // m = n with full re-orthogonalization: T_n is similar to A, Ritz values are eigenvalues.
    const int n = 12;
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
    for (int i = 0; i < n; ++i)
        a(i, i) = i < 4 ? 2.0 : 1.0 + i; // a repeated eigenvalue forces a breakdown restart
    const Eigen::MatrixXd q = Eigen::HouseholderQR<Eigen::MatrixXd>(
                                  Eigen::MatrixXd::Random(n, n)).householderQ();
    const Eigen::MatrixXd b = q * a * q.transpose();
    const LanczosResult r = lanczos(
        n, [&](const Eigen::VectorXd& x, Eigen::VectorXd& y) { y = b * x; }, n);
    Eigen::VectorXd expected = a.diagonal();
    std::sort(expected.data(), expected.data() + n);
    // Orthogonal similarity of O(1) entries: 1e-12 absolute.
    QVERIFY2((r.ritz - expected).cwiseAbs().maxCoeff() < 1e-12,
             qPrintable(QString::number((r.ritz - expected).cwiseAbs().maxCoeff())));
}

void TestModalAnalysis::lowestModesMatchDense_data() {
    QTest::addColumn<int>("n");
    QTest::addColumn<bool>("links");
    QTest::newRow("chain 5") << 5 << false;
    QTest::newRow("chain 60") << 60 << false;
    QTest::newRow("chain 150 with braces") << 150 << true;
}

void TestModalAnalysis::lowestModesMatchDense() {
    QFETCH(int, n);
    QFETCH(bool, links);
    std::vector<std::tuple<int, int, double>> extra;
    if (links)
        for (int i = 0; i + 7 < n; i += 11)
            extra.emplace_back(i, i + 7, 300.0 + i);
    const SpMat k = chainStiffness(spread(n, 1000.0, 5000.0, 1), extra);
    const std::vector<double> mv = spread(n, 5.0, 20.0, 2);
    const Eigen::VectorXd m = Eigen::Map<const Eigen::VectorXd>(mv.data(), n);
    const Eigen::VectorXd dense = denseFrequencies(k, m);
    const int count = std::min(n, 4);
    const Eigen::VectorXd low = lowestFrequencies(k, m, count);
    QCOMPARE(low.size(), Eigen::Index(count));
    for (int i = 0; i < count; ++i) // converged Ritz values: 1e-10 relative to the dense solve
        QVERIFY2(std::abs(low[i] - dense[i]) <= 1e-10 * dense[i],
                 qPrintable(QString("mode %1: %2 vs %3").arg(i + 1).arg(low[i], 0, 'g', 17)
                                .arg(dense[i], 0, 'g', 17)));
    const double top = largestFrequency(k, m);
    // An estimate from above, within 1e-6 relative for these sizes.
    QVERIFY2(top >= dense.maxCoeff() * (1.0 - 1e-12) && top <= dense.maxCoeff() * (1.0 + 1e-6),
             qPrintable(QString("%1 vs %2").arg(top, 0, 'g', 17).arg(dense.maxCoeff(), 0, 'g', 17)));
}

void TestModalAnalysis::largestFrequencyBoundsDense() {
    // A chain of 250 with a stiff top storey: an isolated top eigenvalue.
    std::vector<double> kv = spread(250, 1000.0, 2000.0, 3);
    kv.back() = 1e6;
    const SpMat k = chainStiffness(kv);
    const Eigen::VectorXd m = Eigen::VectorXd::Constant(250, 10.0);
    const double dense = denseFrequencies(k, m).maxCoeff();
    const double top = largestFrequency(k, m);
    QVERIFY2(std::abs(top - dense) <= 1e-10 * dense,
             qPrintable(QString("%1 vs %2").arg(top, 0, 'g', 17).arg(dense, 0, 'g', 17)));
}

void TestModalAnalysis::uniformChainClosedForm() {
    const int n = 3000;
    const double kk = 4000.0, mm = 10.0;
    const SpMat k = chainStiffness(std::vector<double>(n, kk));
    const Eigen::VectorXd m = Eigen::VectorXd::Constant(n, mm);
    const Eigen::VectorXd low = lowestFrequencies(k, m, 3);
    for (int j = 1; j <= 3; ++j) {
        const double w = 2.0 * std::sqrt(kk / mm) * std::sin((2 * j - 1) * M_PI / (2.0 * (2 * n + 1)));
        // Conditioning of the factor (kappa ~ 1e7): 1e-8 relative.
        QVERIFY2(std::abs(low[j - 1] - w) <= 1e-8 * w,
                 qPrintable(QString("mode %1: %2 vs %3").arg(j).arg(low[j - 1], 0, 'g', 17)
                                .arg(w, 0, 'g', 17)));
    }
    const double wMax = 2.0 * std::sqrt(kk / mm) * std::sin((2 * n - 1) * M_PI / (2.0 * (2 * n + 1)));
    const double top = largestFrequency(k, m);
    // Clustered top spectrum: the Gershgorin cap 2 sqrt(k/m) is within 1e-6 of omega_max.
    QVERIFY2(top >= wMax * (1.0 - 1e-12) && top <= 2.0 * std::sqrt(kk / mm) * (1.0 + 1e-12),
             qPrintable(QString("%1 vs %2").arg(top, 0, 'g', 17).arg(wMax, 0, 'g', 17)));
}

void TestModalAnalysis::stiffnessFreeDofGivesZero() {
    // DOF 2 of 3 has no spring at all: omega_1 = 0 (a rigid-body mode), no failed factor.
    std::vector<Eigen::Triplet<double>> t{{0, 0, 100.0}, {2, 2, 400.0}};
    SpMat k(3, 3);
    k.setFromTriplets(t.begin(), t.end());
    const Eigen::VectorXd m = Eigen::Vector3d(1.0, 1.0, 1.0);
    const Eigen::VectorXd low = lowestFrequencies(k, m, 3);
    QVERIFY2(low[0] < 1e-4, qPrintable(QString::number(low[0])));
    // The zero mode's Ritz value 1/|sigma| (~1e7 x the others) costs the others digits:
    // ~1e-7 relative (documented in ModalAnalysis.h); 1e-6 here.
    QVERIFY2(std::abs(low[1] - 10.0) < 1e-5 && std::abs(low[2] - 20.0) < 2e-5,
             qPrintable(QString("%1 %2 %3").arg(low[0]).arg(low[1], 0, 'g', 17).arg(low[2], 0, 'g', 17)));
    QVERIFY(std::abs(largestFrequency(k, m) - 20.0) < 1e-9);
}

void TestModalAnalysis::largeStructureUsesSparseModes() {
    // 400 storeys (> Structure::kDenseModalLimit): only the modes damping needs are computed;
    // Rayleigh coefficients and omega_max agree with the dense solve of the same K0, M.
    const int n = 400;
    const std::vector<double> kv = spread(n, 2000.0, 6000.0, 4);
    Structure s;
    for (int i = 0; i < n; ++i) {
        s.addDof("S" + std::to_string(i + 1), 5.0 + i % 7);
        auto law = std::make_unique<LinearElastic>(kv[std::size_t(i)]);
        if (i == 0)
            s.addElement(SpringElement::lateral("k1", 0, std::move(law)));
        else
            s.addElement(SpringElement::truss("k" + std::to_string(i + 1), i - 1, i, std::move(law)));
    }
    s.setModalDamping(0.05, 1, 3);
    s.finalize();
    QVERIFY(s.freeDofCount() > Structure::kDenseModalLimit);
    QCOMPARE(s.frequencies().size(), Eigen::Index(3));
    const Eigen::VectorXd dense = denseFrequencies(s.initialStiffness(), s.massDiagonal());
    for (int i = 0; i < 3; ++i)
        QVERIFY2(std::abs(s.frequencies()[i] - dense[i]) <= 1e-10 * dense[i],
                 qPrintable(QString("mode %1").arg(i + 1)));
    const RayleighDamping r = RayleighDamping::fromRatio(0.05, dense[0], dense[2]);
    QVERIFY(std::abs(s.rayleigh().a0 - r.a0) <= 1e-10 * r.a0);
    QVERIFY(std::abs(s.rayleigh().a1 - r.a1) <= 1e-10 * r.a1);
    const double wMax = dense.maxCoeff();
    QVERIFY2(s.maxFrequency() >= wMax * (1.0 - 1e-12) && s.maxFrequency() <= wMax * (1.0 + 1e-6),
             qPrintable(QString("%1 vs %2").arg(s.maxFrequency(), 0, 'g', 17).arg(wMax, 0, 'g', 17)));
    QVERIFY(!s.dampingIsDiagonal()); // a1 K0 couples the storeys
}

QTEST_GUILESS_MAIN(TestModalAnalysis)
#include "TestModalAnalysis.moc"
