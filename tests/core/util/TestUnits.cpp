// Units (core/util/Units.h): every factor against a value derived here independently from the
// definitions (NIST SP 811 / the 1959 yard-pound agreement / CGPM 1901), moments as products,
// round trips and the refusals.

#include "core/util/Units.h"

#include <QtTest>

#include <cmath>

using namespace hsmu;
using namespace hsmu::units;

namespace {

// Relative agreement to a few ulps: the factors are exact decimal constants or one product.
bool close(double a, double b) {
    return std::abs(a - b) <= 1e-15 * std::abs(b);
}

} // namespace

class TestUnits : public QObject {
    Q_OBJECT
private slots:
    void lengthFactors();
    void forceFactors();
    void rotationAndTimeFactors();
    void momentsAreProducts();
    void roundTrips();
    void refusalsAndMessages();
};

void TestUnits::lengthFactors() {
    // 1 in = 2.54 cm exactly; 1 ft = 12 in = 30.48 cm.
    const struct { const char* s; double m; } cases[] = {
        {"m", 1.0}, {"cm", 1.0 / 100.0}, {"mm", 1.0 / 1000.0}, {"in", 2.54 / 100.0},
        {"ft", 12.0 * 2.54 / 100.0}};
    for (const auto& c : cases) {
        const auto u = parse(c.s, Dimension::Length);
        QVERIFY2(u.has_value(), c.s);
        QVERIFY2(close(u->factor, c.m), c.s);
        QCOMPARE(u->dimension, Dimension::Length);
    }
    QCOMPARE(parse("in", Dimension::Length)->factor, 0.0254);
    QCOMPARE(parse("ft", Dimension::Length)->factor, 0.3048);
}

void TestUnits::forceFactors() {
    // lbf: the avoirdupois pound 0.45359237 kg under standard gravity 9.80665 m/s^2, in kN;
    // NIST SP 811 lists 4.448222 N. kgf = 9.80665 N; metric tonf = 1000 kgf.
    const double lbfN = 0.45359237 * 9.80665;
    QVERIFY(std::abs(lbfN - 4.448222) < 5e-7);
    const struct { const char* s; double kN; } cases[] = {
        {"N", 1.0 / 1000.0},      {"kN", 1.0},         {"MN", 1000.0},
        {"lbf", lbfN / 1000.0},   {"kip", lbfN},       {"kgf", 9.80665 / 1000.0},
        {"tonf", 9.80665}};
    for (const auto& c : cases) {
        const auto u = parse(c.s, Dimension::Force);
        QVERIFY2(u.has_value(), c.s);
        QVERIFY2(close(u->factor, c.kN), c.s);
    }
    QCOMPARE(parse("lbf", Dimension::Force)->factor * 1000.0, 4.4482216152605);
    // Letter case is free except that mN is not MN.
    QCOMPARE(parse("KN", Dimension::Force)->factor, 1.0);
    QCOMPARE(parse(" kip ", Dimension::Force)->factor, parse("KIP", Dimension::Force)->factor);
    // The US plural (issue 29: `--units s,in,kips` was refused), also in a moment.
    QCOMPARE(parse("kips", Dimension::Force)->factor, parse("kip", Dimension::Force)->factor);
    QCOMPARE(parse("kips", Dimension::Force)->symbol, std::string("kip"));
    QCOMPARE(parse("kips*in", Dimension::Moment)->factor, parse("kip in", Dimension::Moment)->factor);
    QVERIFY(!parse("mN", Dimension::Force).has_value());
    QCOMPARE(parse("MN", Dimension::Force)->factor, 1000.0);
}

void TestUnits::rotationAndTimeFactors() {
    QCOMPARE(parse("rad", Dimension::Rotation)->factor, 1.0);
    QCOMPARE(parse("mrad", Dimension::Rotation)->factor, 1e-3);
    // 180 deg = pi rad: 90 deg against 2 atan(1) = pi / 2.
    QVERIFY(close(90.0 * parse("deg", Dimension::Rotation)->factor, 2.0 * std::atan(1.0)));
    QCOMPARE(parse("s", Dimension::Time)->factor, 1.0);
    QCOMPARE(parse("ms", Dimension::Time)->factor, 1e-3);
    QVERIFY(!parse("m", Dimension::Time).has_value()); // not minutes
}

void TestUnits::momentsAreProducts() {
    const struct { const char* s; const char* symbol; double kNm; } cases[] = {
        {"kN m", "kN m", 1.0},
        {"kNm", "kN m", 1.0},
        {"kN*m", "kN m", 1.0},
        {"kN.m", "kN m", 1.0},
        {"kN-m", "kN m", 1.0},
        {"kN\xC2\xB7m", "kN m", 1.0},
        {"N mm", "N mm", 1e-6},
        {"Nmm", "N mm", 1e-6},
        {"MNm", "MN m", 1000.0},
        {"kip in", "kip in", 0.45359237 * 9.80665 * 0.0254},
        {"kipin", "kip in", 0.45359237 * 9.80665 * 0.0254},
        {"kip-ft", "kip ft", 0.45359237 * 9.80665 * 0.3048},
        {"lbf ft", "lbf ft", 0.45359237 * 9.80665 * 0.3048 / 1000.0},
        {"lbf*in", "lbf in", 0.45359237 * 9.80665 * 0.0254 / 1000.0},
        {"tonf m", "tonf m", 9.80665},
        {"kgf cm", "kgf cm", 9.80665e-5}};
    for (const auto& c : cases) {
        const auto u = parse(c.s, Dimension::Moment);
        QVERIFY2(u.has_value(), c.s);
        QCOMPARE(u->symbol, std::string(c.symbol));
        QVERIFY2(close(u->factor, c.kNm), c.s);
        QCOMPARE(parseForce(c.s)->dimension, Dimension::Moment);
    }
    QVERIFY(!parse("kN", Dimension::Moment).has_value());
    QVERIFY(!parse("kN s", Dimension::Moment).has_value());
    QCOMPARE(parseForce("kN")->dimension, Dimension::Force);
    QCOMPARE(parseDeformation("deg")->dimension, Dimension::Rotation);
    QCOMPARE(parseDeformation("in")->dimension, Dimension::Length);
}

void TestUnits::roundTrips() {
    // value -> console unit -> value, for every unit: exact to an ulp or two.
    const char* all[][2] = {{"m", "L"},   {"cm", "L"},   {"mm", "L"},  {"in", "L"},
                            {"ft", "L"},  {"N", "F"},    {"kN", "F"},  {"MN", "F"},
                            {"lbf", "F"}, {"kip", "F"},  {"kgf", "F"}, {"tonf", "F"},
                            {"rad", "R"}, {"mrad", "R"}, {"deg", "R"}, {"s", "T"},
                            {"ms", "T"}};
    for (const auto& a : all) {
        const Dimension d = a[1][0] == 'L'   ? Dimension::Length
                            : a[1][0] == 'F' ? Dimension::Force
                            : a[1][0] == 'R' ? Dimension::Rotation
                                             : Dimension::Time;
        const Unit u = *parse(a[0], d);
        for (const double v : {1.0, -23.0222, 3.0e5, 1e-9}) {
            QVERIFY2(close(fromBase(toBase(v, u), u), v), a[0]);
        }
    }
    // kip in -> kN m -> lbf ft: 1 kip in = 1000 / 12 lbf ft.
    const Unit kipIn = *parse("kip in", Dimension::Moment);
    const Unit lbfFt = *parse("lbf ft", Dimension::Moment);
    QVERIFY(std::abs(fromBase(toBase(1.0, kipIn), lbfFt) - 1000.0 / 12.0) < 1e-12);
}

void TestUnits::refusalsAndMessages() {
    QVERIFY(!parse("yd", Dimension::Length).has_value());
    QVERIFY(!parse("", Dimension::Force).has_value());
    QVERIFY(!parse("kN", Dimension::Length).has_value());
    QCOMPARE(accepted(Dimension::Length), std::string("m, cm, mm, in, ft"));
    QCOMPARE(accepted(Dimension::Force), std::string("N, kN, MN, lbf, kip, kgf, tonf"));
    QCOMPARE(accepted(Dimension::Rotation), std::string("rad, mrad, deg"));
    QCOMPARE(accepted(Dimension::Time), std::string("s, ms"));
    QCOMPARE(std::string(baseSymbol(Dimension::Moment)), std::string("kN m"));
}

QTEST_APPLESS_MAIN(TestUnits)
#include "TestUnits.moc"
