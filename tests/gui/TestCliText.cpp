// CliText (gui/cli/CliText.h), the Qt-free text of `hsmu run`, against Qt itself: the same
// characters as QString::number and QString::arg on the forms RunFlow and RunReport use, so the
// Qt-free `hsmu` and hsmu-cli print the same bytes.
#include "gui/cli/CliText.h"

#include <QString>
#include <QTest>

#include <cmath>
#include <limits>
#include <random>

using hsmu::gui::number;
using hsmu::gui::Text;

class TestCliText : public QObject {
    Q_OBJECT
private slots:
    void numbersAsQString() {
        std::vector<double> values{
            0.0, -0.0, 1.0, -1.0, 0.5, 1e-5, 1.5e-7, 123456.0, 1234567.0, 99999.95, 0.000123449,
            31.16, 2.675, 1e300, -4.2e-310,
            // ties of the last printed digit: Qt rounds them away from 0
            0.5, 1.5, 2.5, -0.5, -2.5, 0.125, 0.375, -0.625, 12345.5, 1.25, 0.0625, 100.5,
            1e-3 * 0.5, -0.3, -0.004, 0.005, std::numeric_limits<double>::quiet_NaN(),
            -std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
            -std::numeric_limits<double>::infinity()};
        std::mt19937_64 rng(27);
        std::uniform_real_distribution<double> mantissa(-10.0, 10.0);
        std::uniform_int_distribution<int> exponent(-12, 12);
        for (int i = 0; i < 20000; ++i)
            values.push_back(mantissa(rng) * std::pow(10.0, exponent(rng)));
        for (const double x : values) {
            for (const int digits : {2, 3, 4, 5, 6})
                QCOMPARE(QString::fromStdString(number(x, 'g', digits)),
                         QString::number(x, 'g', digits));
            for (const int decimals : {0, 2})
                QCOMPARE(QString::fromStdString(number(x, 'f', decimals)),
                         QString::number(x, 'f', decimals));
        }
    }

    void placeholdersAsQStringArg() {
        const QString pattern = QStringLiteral("a %2 b %1 c %1 d %10 e %");
        QCOMPARE(QString::fromStdString(Text(pattern.toStdString()).arg("x").str()),
                 pattern.arg(QStringLiteral("x")));
        QCOMPARE(QString::fromStdString(Text(pattern.toStdString()).arg("x").arg("y").str()),
                 pattern.arg(QStringLiteral("x")).arg(QStringLiteral("y")));
        // one pass: a value's own "%2" stays; a chain would replace it
        QCOMPARE(QString::fromStdString(Text(pattern.toStdString()).args({"%2", "y", "z"}).str()),
                 pattern.arg(QStringLiteral("%2"), QStringLiteral("y"), QStringLiteral("z")));
        QCOMPARE(QString::fromStdString(Text("%1 %  t = %2 s").arg(7, 3).arg("0.50").str()),
                 QStringLiteral("%1 %  t = %2 s").arg(7, 3).arg(QStringLiteral("0.50")));
        QCOMPARE(QString::fromStdString(Text("%1 %").arg(100, 3).str()),
                 QStringLiteral("%1 %").arg(100, 3));
        QCOMPARE(QString::fromStdString(Text("no placeholder").arg("x").str()),
                 QStringLiteral("no placeholder"));
        QCOMPARE(QString::fromStdString(Text("%1 more").arg(std::size_t(123)).str()),
                 QStringLiteral("%1 more").arg(qulonglong(123)));
    }

    void translatorApplies() {
        QCOMPARE(hsmu::gui::translate("RunReport", "  alarms: none"),
                 std::string("  alarms: none"));
        hsmu::gui::setTranslator([](const char*, const char* s) { return std::string("<") + s; });
        QCOMPARE(hsmu::gui::translate("RunReport", "x"), std::string("<x"));
        hsmu::gui::setTranslator(nullptr);
        QCOMPARE(hsmu::gui::translate("RunReport", "x"), std::string("x"));
    }
};

QTEST_APPLESS_MAIN(TestCliText)
#include "TestCliText.moc"
