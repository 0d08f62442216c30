// ReasonText: core's fixed English texts under stable codes. Every template goes out and
// back (reasonText -> parseReason gives the same code and arguments), and the texts core's
// producers really write (SafetyLimits, the hold reasons) parse to the expected code, so a
// producer that drifts from the table fails here (the console could no longer translate it).
#include <QTest>

#include "core/experimental/SafetyLimits.h"
#include "core/groundmotion/SyntheticGroundMotion.h"
#include "core/util/ReasonText.h"

#include <cmath>
#include <set>

using namespace hsmu;

namespace {
std::string codeOf(const std::optional<std::string>& text)
{
    if (!text)
        return "(none)";
    const auto c = parseReason(*text);
    return c ? c->code : "(unparsed: " + *text + ")";
}
} // namespace

class TestReasonText : public QObject {
    Q_OBJECT
private slots:
    void everyTemplateGoesOutAndBack()
    {
        const std::vector<std::string> codes = reasonCodes();
        QVERIFY(codes.size() >= 20);
        QCOMPARE(std::set<std::string>(codes.begin(), codes.end()).size(), codes.size());
        for (const std::string& code : codes) {
            // Arguments unlike any literal of the tables (so a match cannot be accidental).
            const std::vector<std::string> args = {"A1x", "B2y", "C3z", "D4w", "E5v", "F6u", "G7t", "H8s", "I9r"};
            const std::string text = reasonText(code.c_str(), args);
            QVERIFY2(!text.empty(), code.c_str());
            const auto back = parseReason(text);
            QVERIFY2(back.has_value(), text.c_str());
            QCOMPARE(back->code, code);
            for (std::size_t i = 0; i < back->args.size(); ++i)
                QCOMPARE(back->args[i], args[i]);
        }
        QCOMPARE(reasonText("no-such-code", {"x"}), std::string());
        QVERIFY(!parseReason("an English text no template makes").has_value());
    }

    void argumentsAreTheShortestThatMatch()
    {
        // An emergency hold caused by a fault whose own text has parentheses.
        const auto c = parseReason(
            "emergency hold: operator at the console (Bearing D: measured deformation |d| = "
            "0.07 exceeds the limit 0.05 (+5% tolerance))");
        QVERIFY(c.has_value());
        QCOMPARE(c->code, std::string("emergency-hold-fault"));
        QCOMPARE(c->args.at(0), std::string("operator at the console"));
        QCOMPARE(c->args.at(1), std::string("Bearing D: measured deformation |d| = 0.07 "
                                            "exceeds the limit 0.05 (+5% tolerance)"));
        QCOMPARE(parseReason(c->args.at(0))->code, std::string("operator-console"));
        const auto plain = parseReason("emergency hold: operator");
        QCOMPARE(plain->code, std::string("emergency-hold"));
        QCOMPARE(parseReason(plain->args.at(0))->code, std::string("operator"));
    }

    void safetyLimitsWriteTheirTemplates()
    {
        SafetyLimits l;
        l.maxDeformation = 0.05;
        l.maxIncrement = 0.01;
        l.maxForce = 40.0;
        QCOMPARE(codeOf(l.violationOfTarget(0.06, 0.055)), std::string("limit-target"));
        QCOMPARE(codeOf(l.violationOfTarget(0.03, 0.0)), std::string("limit-increment"));
        QCOMPARE(codeOf(l.violationOfTarget(std::nan(""), 0.0)),
                 std::string("limit-target-not-finite"));
        QCOMPARE(codeOf(l.violationOfForce(-45.5)), std::string("limit-force"));
        QCOMPARE(codeOf(l.violationOfForce(INFINITY)), std::string("limit-force-not-finite"));
        QCOMPARE(codeOf(l.violationOfMeasuredDeformation(0.06)), std::string("limit-measured"));
        QCOMPARE(codeOf(l.violationOfMeasuredDeformation(NAN)),
                 std::string("limit-measured-not-finite"));
        // The built-in record's name (shown in the pre-flight check).
        const auto motion = parseReason(makeSyntheticGroundMotion(1940, 1.0).name);
        QVERIFY(motion.has_value());
        QCOMPARE(motion->code, std::string("synthetic-motion"));
        QCOMPARE(motion->args.at(0), std::string("1940"));
        const auto force = parseReason(*l.violationOfForce(-45.5));
        QCOMPARE(force->args.at(0), std::string("45.5"));
        QCOMPARE(force->args.at(1), std::string("40"));
    }
};

QTEST_APPLESS_MAIN(TestReasonText)
#include "TestReasonText.moc"
