// Tests of SafetyLimits (core/experimental/SafetyLimits.h): each limit stops exactly what it
// names, disabled limits (<= 0 or infinite) never stop anything, and every message names the
// quantity, its value and the limit.

#include "core/experimental/SafetyLimits.h"

#include <QtTest>

#include <cmath>
#include <limits>

using namespace hsmu;

namespace {
QString text(const std::optional<std::string>& s) {
    return s ? QString::fromStdString(*s) : QString();
}
} // namespace

class TestSafetyLimits : public QObject {
    Q_OBJECT
private slots:
    void defaultsAllowEverythingFinite();
    void deformationLimit();
    void incrementLimit();
    void forceLimit();
    void disabledLimits();
    void nonFiniteValuesAreRefused();
};

void TestSafetyLimits::defaultsAllowEverythingFinite() {
    const SafetyLimits l;
    QVERIFY(!l.violationOfTarget(1e6, -1e6));
    QVERIFY(!l.violationOfForce(-1e9));
}

void TestSafetyLimits::deformationLimit() {
    SafetyLimits l;
    l.maxDeformation = 0.05;
    QVERIFY(!l.violationOfTarget(0.05, 0.0)); // at the limit: allowed (|d| > limit stops)
    QVERIFY(!l.violationOfTarget(-0.049, 0.0));
    for (double d : {0.0501, -0.07}) {
        const QString msg = text(l.violationOfTarget(d, 0.0));
        QVERIFY2(!msg.isEmpty(), "a target past the deformation limit was allowed");
        QVERIFY2(msg.contains("deformation"), qPrintable(msg));
        QVERIFY2(msg.contains("0.05"), qPrintable(msg));                       // the limit
        QVERIFY2(msg.contains(QString::number(std::abs(d))), qPrintable(msg)); // the value
        QVERIFY2(msg.contains("limit"), qPrintable(msg));
    }
    QVERIFY(!l.violationOfForce(1e6)); // only deformation is limited
}

void TestSafetyLimits::incrementLimit() {
    SafetyLimits l;
    l.maxIncrement = 0.01;
    QVERIFY(!l.violationOfTarget(0.50, 0.495));
    QVERIFY(!l.violationOfTarget(-0.3, -0.305));
    const QString msg = text(l.violationOfTarget(0.52, 0.5)); // |dd| = 0.02 > 0.01
    QVERIFY2(!msg.isEmpty(), "an increment past the limit was allowed");
    QVERIFY2(msg.contains("increment"), qPrintable(msg));
    QVERIFY2(msg.contains("0.01"), qPrintable(msg));
    QVERIFY2(msg.contains("0.02"), qPrintable(msg));
    QVERIFY(l.violationOfTarget(-0.52, -0.5)); // both directions
}

void TestSafetyLimits::forceLimit() {
    SafetyLimits l;
    l.maxForce = 40.0;
    QVERIFY(!l.violationOfForce(40.0));
    QVERIFY(!l.violationOfForce(-39.9));
    const QString msg = text(l.violationOfForce(-45.5));
    QVERIFY2(!msg.isEmpty(), "a force past the limit was allowed");
    QVERIFY2(msg.contains("force"), qPrintable(msg));
    QVERIFY2(msg.contains("40"), qPrintable(msg));
    QVERIFY2(msg.contains("45.5"), qPrintable(msg));
    QVERIFY(!l.violationOfTarget(10.0, -10.0)); // only force is limited
}

void TestSafetyLimits::disabledLimits() {
    SafetyLimits l;
    l.maxDeformation = 0.0;
    l.maxIncrement = -1.0;
    l.maxForce = std::numeric_limits<double>::infinity();
    QVERIFY(!l.violationOfTarget(3.0, -3.0));
    QVERIFY(!l.violationOfForce(1e12));
}

void TestSafetyLimits::nonFiniteValuesAreRefused() {
    const SafetyLimits l; // even with every limit disabled
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    QVERIFY(text(l.violationOfTarget(nan, 0.0)).contains("finite"));
    QVERIFY(text(l.violationOfTarget(inf, 0.0)).contains("finite"));
    QVERIFY(text(l.violationOfForce(nan)).contains("finite"));
    QVERIFY(text(l.violationOfForce(-inf)).contains("finite"));
}

QTEST_APPLESS_MAIN(TestSafetyLimits)
#include "TestSafetyLimits.moc"
