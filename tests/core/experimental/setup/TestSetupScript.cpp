// Tests of parseSetupScript (core/experimental/setup/SetupScript.h): OpenFresco `expSetup`
// lines give the very setups the factories build from the same numbers (strokes and Jacobians
// equal bit for bit at basic displacements up to 0.3 rad), and every word that is not understood
// is refused with the line, the type and the word (OpenFresco ignores unknown options).

#include "SetupCatalog.h"
#include "core/experimental/setup/SetupScript.h"

#include <QtTest>

using namespace hsmu;

namespace {

bool sameSetup(const ExperimentalSetup& a, const ExperimentalSetup& b) {
    if (a.typeName() != b.typeName() || a.basicSize() != b.basicSize() ||
        a.actuatorCount() != b.actuatorCount())
        return false;
    for (double scale : {0.0, 0.3, -1.0}) {
        Eigen::VectorXd d(a.basicSize());
        for (int k = 0; k < d.size(); ++k)
            d(k) = scale * (0.1 + 0.05 * k) * (k % 2 ? -1.0 : 1.0);
        Eigen::VectorXd sa, sb;
        Eigen::MatrixXd Ja, Jb;
        if (!a.strokes(d, sa).ok || !b.strokes(d, sb).ok || sa != sb)
            return false;
        if (!a.jacobian(d, Ja).ok || !b.jacobian(d, Jb).ok || Ja != Jb)
            return false;
    }
    return true;
}

QString parseError(const std::string& script) {
    SetupsByTag s;
    std::string e;
    if (parseSetupScript(script, s, e))
        return {};
    return QString::fromStdString(e);
}

} // namespace

class TestSetupScript : public QObject {
    Q_OBJECT
private slots:
    void linesBuildTheFactoriesSetups();
    void aggregatorTakesItsParts();
    void everyUnknownWordIsRefused();
};

void TestSetupScript::linesBuildTheFactoriesSetups() {
    using G = SetupGeometry;
    const auto two = setupcatalog::two(G::Exact, true, 30.0);
    const auto three = setupcatalog::three(G::Linear, true);
    const auto jo = setupcatalog::jntOff(G::Exact, false);
    const auto four = setupcatalog::four(G::Exact, 25.0);
    const std::string script =
        "# a lab's setups\n"
        "expSetup TwoActuators2d 1 -control 1 1.5 1.2 0.6 -nlGeom -posAct right -phiLocX 30\n"
        "\n"
        "expSetup ThreeActuators2d 2 1.6 1.1 1.3 0.7 0.5 -posAct1 r\n"
        "expSetup ThreeActuatorsJntOff2d 3 -ctrl 4 1.6 1.1 1.3 0.2 0.7 0.5 0.25 0.3 0.35 -nlGeom\n"
        "expSetup InvertedVBrace2d 4 1.6 1.1 1.3 0.7 0.5 -posAct1 right\n"
        "expSetup ChevronBrace2d 5 1.6 1.1 1.3 0.7 0.5 -posAct1 right\n"
        "expSetup InvertedVBraceJntOff2d 6 1.6 1.1 1.3 0.2 0.7 0.5 0.25 0.3 0.35 -nlGeom\n"
        "expSetup FourActuators3d 7 1.2 1.3 1.1 1.4 0.3 0.35 0.25 0.4 0.8 0.45 0 0 0 1.6 1.9 0 "
        "-nlGeom "
        "-phiLocX 25\n"
        "expSetup OneActuator 8 -control 2 2 -sizeTrialOut 3 3\n"
        "expSetup NoTransformation 9 -dir 3 1 -sizeTrialOut 3 3\n";
    SetupsByTag s;
    std::string e;
    QVERIFY2(parseSetupScript(script, s, e), e.c_str());
    QCOMPARE(s.size(), std::size_t(9));
    QVERIFY(sameSetup(*s.at(1), *makeTwoActuators2d(two, e)));
    QVERIFY(sameSetup(*s.at(2), *makeThreeActuators2d(three, e)));
    QVERIFY(sameSetup(*s.at(3), *makeThreeActuatorsJntOff2d(jo, e)));
    QVERIFY(sameSetup(*s.at(4), *makeInvertedVBrace2d(three, e)));
    QVERIFY(sameSetup(*s.at(5), *makeChevronBrace2d(three, e)));
    QVERIFY(sameSetup(*s.at(6), *makeInvertedVBraceJntOff2d(jo, e)));
    QVERIFY(sameSetup(*s.at(7), *FourActuators3d::create(four, e)));
    QVERIFY(sameSetup(*s.at(8), *OneActuator::create(2, 3, e)));
    QVERIFY(sameSetup(*s.at(9), *NoTransformation::create({3, 1}, 3, e)));
    // and a setup built otherwise differs (the comparison can fail)
    QVERIFY(!sameSetup(*s.at(2), *makeThreeActuators2d(setupcatalog::three(G::Linear, false), e)));
    QVERIFY(!sameSetup(*s.at(3),
                       *makeThreeActuatorsJntOff2d(setupcatalog::jntOff(G::Linear, false), e)));
}

void TestSetupScript::aggregatorTakesItsParts() {
    SetupsByTag s;
    std::string e;
    QVERIFY2(parseSetupScript("expSetup OneActuator 11 1 -sizeTrialOut 1 1\n"
                              "expSetup NoTransformation 12 -dir 2 1 -sizeTrialOut 2 2\n"
                              "expSetup Aggregator 1 -control 1 -setup 11 12 -sizeTrialOut 3 3\n",
                              s, e),
             e.c_str());
    QCOMPARE(s.size(), std::size_t(1)); // the parts live in the aggregator
    const ExperimentalSetup& agg = *s.at(1);
    QCOMPARE(agg.typeName(), std::string("Aggregator"));
    Eigen::VectorXd sk;
    QVERIFY(agg.strokes(Eigen::Vector3d(0.1, 0.2, 0.3), sk).ok);
    QCOMPARE(sk, Eigen::VectorXd(Eigen::Vector3d(0.1, 0.3, 0.2)));
}

void TestSetupScript::everyUnknownWordIsRefused() {
    const std::string three = "expSetup ThreeActuators2d 1 1.6 1.1 1.3 0.7 0.5";
    auto refused = [](const QString& e, const char* a, const char* b) {
        return e.contains(a) && e.contains(b);
    };
    QString e = parseError(three + " -nlgeom\n");
    QVERIFY2(refused(e, "line 1: ThreeActuators2d", "unknown option '-nlgeom'"), qPrintable(e));
    e = parseError("\n" + three + " -posAct1 middle\n");
    QVERIFY2(refused(e, "line 2: ThreeActuators2d", "-posAct1 wants left, right"), qPrintable(e));
    e = parseError("expSetup ThreeActuators2d 1 1.6 1.1 1.3 0.7\n");
    QVERIFY2(refused(e, "ThreeActuators2d", "L2 missing"), qPrintable(e));
    e = parseError("expSetup TwoActuators2d 1 1.5 abc 0.6\n");
    QVERIFY2(refused(e, "TwoActuators2d", "La2: 'abc' is not a number"), qPrintable(e));
    e = parseError("expSetup TwoActuators2d 1 1.5 1.2 0\n");
    QVERIFY2(refused(e, "TwoActuators2d", "L = 0"), qPrintable(e));
    // FourActuators3d's axial-load rods: a rod of zero length is refused naming it
    e = parseError("expSetup FourActuators3d 3 1.2 1.3 1.1 1.4 0.3 0.35 0.25 0.4 0.8 0.45 0 0 0 "
                   "1.6 0 0 -nlGeom\n");
    QVERIFY2(refused(e, "line 1: FourActuators3d",
                     "LrodS = 0 must be a positive finite length "
                     "(an axial-load rod's pin-to-pin length)"),
             qPrintable(e));
    e = parseError("expSetup FourActuators3d 3 1.2 1.3 1.1 1.4 0.3 0.35 0.25 0.4 0.8 0.45 0 0 0 "
                   "1.6\n");
    QVERIFY2(refused(e, "FourActuators3d", "LrodS missing"), qPrintable(e));
    e = parseError("expSetup FiveActuators 1 1 2 3\n");
    QVERIFY2(refused(e, "FiveActuators", "unknown experimental setup type"), qPrintable(e));
    e = parseError(three + "\n" + three + "\n");
    QVERIFY2(refused(e, "line 2", "tag 1 already defined"), qPrintable(e));
    e = parseError("expSetup Aggregator 1 -setup 7 -sizeTrialOut 1 1\n");
    QVERIFY2(refused(e, "Aggregator", "-setup 7: no such setup above"), qPrintable(e));
    e = parseError("expSetup OneActuator 2 1 -sizeTrialOut 1 1\n"
                   "expSetup Aggregator 1 -setup 2 -sizeTrialOut 2 2\n");
    QVERIFY2(refused(e, "line 2: Aggregator", "the sum of the setups' basic sizes"), qPrintable(e));
    e = parseError("expSetup NoTransformation 1 -dir 1 -sizeTrialOut 3 3 -trialDispFact 2\n");
    QVERIFY2(refused(e, "NoTransformation", "unknown option '-trialDispFact'"), qPrintable(e));
    e = parseError("expSetup OneActuator 1 1 -sizeTrialOut 3 2\n");
    QVERIFY2(refused(e, "OneActuator", "sizeOut 2 != sizeTrial 3"), qPrintable(e));
    e = parseError("expControl SimUniaxialMaterials 1 1\n");
    QVERIFY2(refused(e, "line 1", "'expSetup $type $tag ...' wanted"), qPrintable(e));
    // nothing is handed out from a script with an error
    SetupsByTag s;
    std::string err;
    QVERIFY(!parseSetupScript(three + "\nexpSetup TwoActuators2d 2 1.5 1.2 0.6 -nlgeom\n", s, err));
    QVERIFY(s.empty());
}

QTEST_APPLESS_MAIN(TestSetupScript)
#include "TestSetupScript.moc"
