// writeTenDigits: the same characters as printf("%.10g") (glibc's, an independent
// implementation) and std::to_chars(general, 10) for every kind of double: random bit
// patterns, log-uniform magnitudes over 1e-40..1e40, values within a few ulps of the ties of
// the tenth digit (where the fast path must hand over), decade edges and the special values.

#include "core/output/TenDigits.h"

#include <QtTest>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <string>

using namespace hsmu;

namespace {

std::string fast(double x) {
    char buf[kTenDigitsMaxChars];
    return std::string(buf, writeTenDigits(buf, x));
}

std::string printfG(double x) {
    char buf[64];
    const int n = std::snprintf(buf, sizeof buf, "%.10g", x);
    return std::string(buf, std::size_t(n));
}

std::string toChars(double x) {
    char buf[64];
    return std::string(buf, std::to_chars(buf, buf + sizeof buf, x, std::chars_format::general, 10).ptr);
}

} // namespace

class TestTenDigits : public QObject {
    Q_OBJECT

    int m_checked = 0;
    int m_wrong = 0;
    QString m_first;

    void check(double x) {
        const std::string got = fast(x);
        ++m_checked;
        if (got != printfG(x) || got != toChars(x)) {
            if (m_wrong++ == 0)
                m_first = QString::asprintf("%.17g: %s, printf %s, to_chars %s", x, got.c_str(),
                                            printfG(x).c_str(), toChars(x).c_str());
        }
    }
    void verdict(int atLeast) {
        QVERIFY2(m_wrong == 0, qPrintable(QString::number(m_wrong) + " differ, first " + m_first));
        QVERIFY(m_checked >= atLeast);
    }

private slots:
    void init() {
        m_checked = m_wrong = 0;
        m_first.clear();
    }

    void knownTexts() {
        QCOMPARE(fast(0.0), std::string("0"));
        QCOMPARE(fast(-0.0), std::string("-0"));
        QCOMPARE(fast(0.1), std::string("0.1"));
        QCOMPARE(fast(-2.5), std::string("-2.5"));
        QCOMPARE(fast(1e-5), std::string("1e-05"));
        QCOMPARE(fast(0.0001), std::string("0.0001"));
        QCOMPARE(fast(1234567890.0), std::string("1234567890"));
        QCOMPARE(fast(12345678901.0), std::string("1.23456789e+10"));
        QCOMPARE(fast(1.0 / 3.0), std::string("0.3333333333"));
        QCOMPARE(fast(2.0 / 3.0 * 1e-7), std::string("6.666666667e-08"));
        QCOMPARE(fast(9999999999.6), std::string("1e+10"));
        QCOMPARE(fast(0.00099999999996), std::string("0.001"));
        QCOMPARE(fast(1e300), std::string("1e+300"));
        QCOMPARE(fast(std::numeric_limits<double>::infinity()), std::string("inf"));
        QCOMPARE(fast(-std::numeric_limits<double>::infinity()), std::string("-inf"));
        QCOMPARE(fast(std::nan("")), std::string("nan"));
    }

    void randomBitPatterns() {
        std::mt19937_64 rng(27);
        for (int i = 0; i < 1000000; ++i)
            check(std::bit_cast<double>(std::uint64_t(rng())));
        verdict(1000000);
    }

    void logUniformMagnitudes() {
        std::mt19937_64 rng(2027);
        std::uniform_real_distribution<double> exponent(-40.0, 40.0);
        for (int i = 0; i < 500000; ++i) {
            const double x = std::pow(10.0, exponent(rng)) * (rng() & 1 ? 1.0 : -1.0);
            check(x);
            check(std::nextafter(x, 0.0));
        }
        verdict(1000000);
    }

    // d.ddddddddd5 x 10^e: the exact tie of the tenth digit when representable, else the
    // double nearest it, and the doubles on either side.
    void nearTies() {
        std::mt19937_64 rng(1027);
        for (int i = 0; i < 200000; ++i) {
            const std::uint64_t m = 1000000000ULL + rng() % 9000000000ULL;
            const int e = int(rng() % 50) - 25;
            const double tie = double(m * 10 + 5) * std::pow(10.0, e - 10);
            check(tie);
            check(std::nextafter(tie, 1e308));
            check(std::nextafter(tie, -1e308));
            check(double(m) * std::pow(10.0, e)); // ten exact digits
        }
        for (int e = -30; e <= 30; ++e) { // decade edges
            const double p = std::pow(10.0, e);
            for (double x : {p, std::nextafter(p, 0.0), std::nextafter(p, 1e308), 0.99999999995 * p,
                             0.999999999949 * p, 9.9999999995 * p})
                check(x);
        }
        verdict(800000);
    }

    void subnormalsAndExtremes() {
        for (double x : {std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::min(),
                         std::numeric_limits<double>::max(), 1e-13, std::nextafter(1e-13, 0.0), 1e31,
                         std::nextafter(1e31, 0.0), 5e-320, -1.5e-310})
            check(x);
        verdict(9);
    }
};

QTEST_APPLESS_MAIN(TestTenDigits)
#include "TestTenDigits.moc"
