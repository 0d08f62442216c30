// The generated shear-building preset family (core/config/ShearBuilding.h, issue 17): names,
// the document's schema (it parses), and its physics against the closed form of a uniform
// fixed-free chain: omega_j = 2 sqrt(k/m) sin((2j - 1) pi / (2 (2N + 1))).

#include "core/config/ConfigLoader.h"
#include "core/config/ShearBuilding.h"
#include "core/config/TestFactory.h"
#include "core/structure/Structure.h"

#include <QtTest>

#include <cmath>

using namespace hsmu;

class TestShearBuilding : public QObject {
    Q_OBJECT
private slots:
    void names();
    void documentParsesAndMatchesClosedForm();
};

void TestShearBuilding::names() {
    const auto a = parseShearBuildingName("shear-building-10000");
    QVERIFY(a && a->storeys == 10000 && a->boucWen && !a->massDamped);
    const auto b = parseShearBuildingName("shear-building-7-elastic-mass-damped");
    QVERIFY(b && b->storeys == 7 && !b->boucWen && b->massDamped);
    const auto c = parseShearBuildingName("shear-building-7-mass-damped-elastic");
    QVERIFY(c && c->storeys == 7 && !c->boucWen && c->massDamped);
    for (const char* bad : {"shear-building-", "shear-building-0", "shear-building-x",
                            "shear-building-10-plastic", "shear-building-1e3",
                            "shear-building-999999999", "paper-condition-3", "shear-building--5"})
        QVERIFY2(!parseShearBuildingName(bad), bad);
}

void TestShearBuilding::documentParsesAndMatchesClosedForm() {
    ShearBuildingSpec spec;
    spec.storeys = 12;
    spec.boucWen = false;
    const TestConfig cfg = parseConfig(shearBuildingConfig(spec), "shear-building-12-elastic");
    QCOMPARE(int(cfg.dofs.size()), 12);
    QCOMPARE(int(cfg.elements.size()), 12);
    QCOMPARE(cfg.analysis.dt, 0.001);
    auto s = buildStructure(cfg);
    s->finalize();
    const double k = 4000.0, m = 10.0;
    for (int j = 1; j <= 3; ++j) {
        const double w = 2.0 * std::sqrt(k / m) * std::sin((2 * j - 1) * M_PI / (2.0 * 25.0));
        // Dense generalized eigen-solve of a 12 x 12 chain: 1e-12 relative.
        QVERIFY2(std::abs(s->frequencies()[j - 1] - w) <= 1e-12 * w,
                 qPrintable(QString("mode %1: %2 vs %3").arg(j).arg(s->frequencies()[j - 1]).arg(w)));
    }
    QVERIFY(s->maxFrequency() < 2.0 * std::sqrt(k / m)); // omega_max dt < 0.04 at any N
    QVERIFY(!s->dampingIsDiagonal()); // Rayleigh at modes 1 and 2
    spec.massDamped = true;
    auto md = buildStructure(parseConfig(shearBuildingConfig(spec), "md"));
    md->finalize();
    QVERIFY(md->dampingIsDiagonal()); // C = a0 M: the explicit step needs no solve
}

QTEST_GUILESS_MAIN(TestShearBuilding)
#include "TestShearBuilding.moc"
