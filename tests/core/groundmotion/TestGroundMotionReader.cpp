// Ground-motion readers on small files written here: the three AT2 header layouts, Fortran
// fixed-width fields, units, the text formats, and every malformed case with its message.
#include "GroundMotionTestFiles.h"

#include "core/groundmotion/GroundMotionReader.h"

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <limits>

using namespace hsmu;
using hsmu::test::containsAll;
using hsmu::test::errorOf;

namespace {

const double g = kStandardGravity;

bool near(double a, double b, double tol = 1e-12) {
    return std::abs(a - b) <= tol;
}

} // namespace

class TestGroundMotionReader : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    std::string write(const char* name, const std::string& content) {
        return hsmu::test::writeFile(m_dir.path(), QString::fromUtf8(name), content);
    }

private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    void ngaWest2Layout() {
        const std::string path =
            write("RSN_TEST.AT2", "PEER NGA STRONG MOTION DATABASE RECORD\n"
                                  "Test event, 1/1/2000, Test station, 090\n"
                                  "ACCELERATION TIME SERIES IN UNITS OF G\n"
                                  "NPTS=    7, DT=   .0050 SEC\n"
                                  "  .1000000E-01 -.2000000E-01  .3000000E+00\n"
                                  " -.4000000E-02  .5000000E-02\n"
                                  "  .6000000E-03 -.7000000E-01\n");
        const GroundMotion m = readAt2(path);
        QCOMPARE(m.acceleration.size(), std::size_t(7));
        QCOMPARE(m.dt, 0.005);
        const double expected[] = {0.01, -0.02, 0.3, -0.004, 0.005, 0.0006, -0.07};
        for (std::size_t i = 0; i < 7; ++i)
            QVERIFY(near(m.acceleration[i], expected[i] * g, 1e-15));
        QCOMPARE(detectGroundMotionFormat(path), GroundMotionFormat::At2);
    }

    void oldNgaLayout() {
        const std::string path = write("OLDNGA.txt", "PEER NGA STRONG MOTION DATABASE RECORD\n"
                                                     "IMPERIAL VALLEY 05/19/40, EL CENTRO, 180\n"
                                                     "ACCELERATION TIME HISTORY IN UNITS OF G\n"
                                                     "    6    0.0100    NPTS, DT\n"
                                                     "  0.1 0.2 0.3 0.4\n"
                                                     "  -0.5 -0.6\n\n");
        QCOMPARE(detectGroundMotionFormat(path), GroundMotionFormat::At2); // by content
        const GroundMotion m = readGroundMotion(path);
        QCOMPARE(m.acceleration.size(), std::size_t(6));
        QCOMPARE(m.dt, 0.01);
        QVERIFY(near(m.acceleration[5], -0.6 * g, 1e-15));
        QVERIFY(near(m.duration(), 0.05));
    }

    void crlfAndFortranExponent() {
        const std::string path = write("crlf.at2", "a\r\nb\r\nUNITS OF G\r\n"
                                                   "NPTS=3, DT=0.02 SEC\r\n"
                                                   "1.0D-02 +2.0E-02 3\r\n");
        const GroundMotion m = readAt2(path);
        QCOMPARE(m.acceleration.size(), std::size_t(3));
        QVERIFY(near(m.acceleration[0], 0.01 * g, 1e-15));
        QVERIFY(near(m.acceleration[1], 0.02 * g, 1e-15));
        QVERIFY(near(m.acceleration[2], 3.0 * g, 1e-15));
    }

    void gluedFixedWidthFields() {
        // 4F10.5 in cm/s/s: 10-character fields run together once a value needs all 10.
        const std::string path = write("glued.AT2", "glued fields, cm/s/s\n"
                                                    "format 4F10.5\n"
                                                    "UNITS ARE CM/S/S\n"
                                                    "NPTS=  8, DT= .01000 SEC\n"
                                                    "1234.567891234.56789-123.45678   0.50000\n"
                                                    "   1.00000-999.99999   2.00000   3.00000\n");
        const GroundMotion m = readAt2(path);
        const double expected[] = {1234.56789, 1234.56789, -123.45678, 0.5,
                                   1.0,        -999.99999, 2.0,        3.0};
        QCOMPARE(m.acceleration.size(), std::size_t(8));
        for (std::size_t i = 0; i < 8; ++i)
            QVERIFY(near(m.acceleration[i], expected[i] * 0.01, 1e-13));

        // No format in the header: the width is taken from the first clean data line.
        const std::string inferred = write("inferred.AT2", "no format stated\nx\nUNITS OF G\n"
                                                           "NPTS=  6, DT= .01000 SEC\n"
                                                           "   0.00100   0.00200   0.00300\n"
                                                           "1000.000002000.00000-300.00000\n");
        const GroundMotion n = readAt2(inferred);
        QCOMPARE(n.acceleration.size(), std::size_t(6));
        QVERIFY(near(n.acceleration[3], 1000.0 * g, 1e-9));
        QVERIFY(near(n.acceleration[4], 2000.0 * g, 1e-9));
        QVERIFY(near(n.acceleration[5], -300.0 * g, 1e-9));
    }

    void unitsFromHeader() {
        const auto header = [](const char* unitsLine) {
            return std::string("title\nstation\n") + unitsLine +
                   "\nNPTS=  2, DT= .01 SEC\n1.0 -2.0\n";
        };
        struct Case {
            const char* file;
            const char* line;
            double factor;
        };
        const Case cases[] = {{"u1.AT2", "ACCELERATION IN UNITS OF G", g},
                              {"u2.AT2", "The units are (g)", g},
                              {"u3.AT2", "ACCELERATION IN CM/SEC/SEC", 0.01},
                              {"u4.AT2", "acceleration, cm/s/s", 0.01},
                              {"u5.AT2", "UNITS: GAL", 0.01},
                              {"u6.AT2", "acceleration in m/s^2", 1.0},
                              {"u7.AT2", "no unit stated", g}};
        for (const Case& c : cases) {
            const GroundMotion m = readAt2(write(c.file, header(c.line)));
            QVERIFY2(near(m.acceleration[1], -2.0 * c.factor, 1e-15), c.line);
        }
        // An explicit unit overrides the header.
        const GroundMotion over =
            readAt2(write("u8.AT2", header("UNITS OF G")), AccelerationUnit::MetersPerSecond2);
        QCOMPARE(over.acceleration[1], -2.0);
    }

    void textFormatsAndUnits() {
        const std::string twoCol = write("two.csv", "# time, accel\n"
                                                    "1.00, 10\n1.02; -20\n1.04\t30  # comment\n\n");
        const GroundMotion m =
            readTimeAcceleration(twoCol, AccelerationUnit::CentimetersPerSecond2);
        QCOMPARE(m.acceleration.size(), std::size_t(3));
        QVERIFY(near(m.dt, 0.02));
        QVERIFY(near(m.acceleration[1], -0.2, 1e-15)); // cm/s^2 -> m/s^2
        QCOMPARE(detectGroundMotionFormat(twoCol), GroundMotionFormat::TimeAcceleration);
        QCOMPARE(readGroundMotion(twoCol).acceleration[2], 30.0 * g); // text defaults to g

        const std::string oneCol = write("one.txt", "# one value per line\n0.1\n-0.2\n0.3\n");
        const GroundMotion s = readSingleColumn(oneCol, 0.005, AccelerationUnit::MetersPerSecond2);
        QCOMPARE(s.acceleration, (std::vector<double>{0.1, -0.2, 0.3}));
        QCOMPARE(s.dt, 0.005);
        QCOMPARE(detectGroundMotionFormat(oneCol), GroundMotionFormat::SingleColumn);
        const GroundMotion viaAuto =
            readGroundMotion(oneCol, GroundMotionFormat::Auto, AccelerationUnit::G, 0.01);
        QVERIFY(near(viaAuto.acceleration[2], 0.3 * g, 1e-15));
        QCOMPARE(viaAuto.name, std::string("one.txt"));
        QCOMPARE(viaAuto.source, oneCol);
    }

    // ---- malformed files: each message names the file and the specific problem ----

    void badHeader() {
        const std::string path = write("bad_header.AT2", "a\nb\nc\nthis is not a header\n0.1\n");
        const std::string msg = errorOf([&] { readAt2(path); });
        QVERIFY2(containsAll(msg, {"bad_header.AT2 line 4", "expected 'NPTS=..., DT=...'",
                                   "this is not a header"}),
                 msg.c_str());
        const std::string shortFile = write("short.AT2", "a\nb\n");
        const std::string msg2 = errorOf([&] { readAt2(shortFile); });
        QVERIFY2(containsAll(msg2, {"short.AT2", "4 header lines", "only 2"}), msg2.c_str());
    }

    void nptsMismatch() {
        const std::string fewer =
            write("fewer.AT2", "a\nb\nc\nNPTS=  10, DT= .01 SEC\n0.1 0.2 0.3\n0.4\n");
        const std::string msg = errorOf([&] { readAt2(fewer); });
        QVERIFY2(containsAll(msg, {"fewer.AT2", "NPTS = 10", "only 4 values"}), msg.c_str());

        const std::string more = write("more.AT2", "a\nb\nc\nNPTS=  3, DT= .01 SEC\n0.1 0.2\n"
                                                   "0.3 0.4\n");
        const std::string msg2 = errorOf([&] { readAt2(more); });
        QVERIFY2(containsAll(msg2, {"more.AT2 line 6", "more values than NPTS = 3"}), msg2.c_str());

        const std::string trailing =
            write("trailing.AT2", "a\nb\nc\nNPTS=  3, DT= .01 SEC\n0.1 0.2\n0.3\n   \n\n");
        QCOMPARE(readAt2(trailing).acceleration.size(), std::size_t(3)); // blanks are fine
    }

    void nonNumericToken() {
        const std::string at2 = write("token.AT2", "a\nb\nc\nNPTS= 6, DT= .01 SEC\n0.1 0.2 0.3\n"
                                                   "0.4 abc 0.6\n");
        const std::string msg = errorOf([&] { readAt2(at2); });
        QVERIFY2(containsAll(msg, {"token.AT2 line 6", "expected a number", "'abc'"}), msg.c_str());

        const std::string text = write("token.txt", "# t a\n0.0 0.1\n0.01 x0.2\n");
        const std::string msg2 = errorOf([&] { readTimeAcceleration(text); });
        QVERIFY2(containsAll(msg2, {"token.txt line 3", "expected a number", "'x0.2'"}),
                 msg2.c_str());

        const std::string three = write("three.txt", "0.0 0.1\n0.01 0.2 0.3\n");
        const std::string msg3 = errorOf([&] { readTimeAcceleration(three); });
        QVERIFY2(containsAll(msg3, {"three.txt line 2", "two columns", "found 3"}), msg3.c_str());

        const std::string nan = write("nan.txt", "0.1\nnan\n");
        const std::string msg4 = errorOf([&] { readSingleColumn(nan, 0.01); });
        QVERIFY2(containsAll(msg4, {"nan.txt line 2", "non-finite"}), msg4.c_str());
        const std::string inf = write("inf.AT2", "a\nb\nc\nNPTS= 2, DT= .01 SEC\n0.1 inf\n");
        const std::string msg5 = errorOf([&] { readAt2(inf); });
        QVERIFY2(containsAll(msg5, {"inf.AT2 line 5", "non-finite"}), msg5.c_str());
    }

    void nonUniformTime() {
        const std::string path =
            write("jitter.txt", "# t a\n0.00 1\n0.02 2\n0.04 3\n0.07 4\n0.09 5\n0.11 6\n");
        const std::string msg = errorOf([&] { readTimeAcceleration(path); });
        QVERIFY2(containsAll(msg, {"jitter.txt line 5", "non-uniform time step", "0.07"}),
                 msg.c_str());

        const std::string back = write("back.txt", "0.00 1\n0.02 2\n0.01 3\n");
        const std::string msg2 = errorOf([&] { readTimeAcceleration(back); });
        QVERIFY2(containsAll(msg2, {"back.txt line 3", "time must increase"}), msg2.c_str());

        const std::string single = write("single.txt", "0.0 1.0\n");
        const std::string msg3 = errorOf([&] { readTimeAcceleration(single); });
        QVERIFY2(containsAll(msg3, {"single.txt", "only one sample"}), msg3.c_str());
    }

    void emptyAndMissingFiles() {
        const std::string empty = write("empty.AT2", "");
        for (const std::string& msg :
             {errorOf([&] { readAt2(empty); }), errorOf([&] { readTimeAcceleration(empty); }),
              errorOf([&] { readSingleColumn(empty, 0.01); }),
              errorOf([&] { readGroundMotion(empty); })})
            QVERIFY2(containsAll(msg, {"empty.AT2", "file is empty"}), msg.c_str());

        const std::string comments = write("comments.txt", "# nothing here\n\n");
        const std::string msg = errorOf([&] { readTimeAcceleration(comments); });
        QVERIFY2(containsAll(msg, {"comments.txt", "no data lines"}), msg.c_str());

        const std::string missing = QDir(m_dir.path()).filePath("missing.AT2").toStdString();
        for (const std::string& msg2 :
             {errorOf([&] { readAt2(missing); }), errorOf([&] { readGroundMotion(missing); })})
            QVERIFY2(containsAll(msg2, {"missing.AT2", "does not exist"}), msg2.c_str());
    }

    void badTimeStep() {
        const std::string values = write("values.txt", "0.1\n0.2\n");
        for (double dt : {0.0, -0.01, std::numeric_limits<double>::quiet_NaN()}) {
            const std::string msg = errorOf([&] { readSingleColumn(values, dt); });
            QVERIFY2(containsAll(msg, {"values.txt", "dt must be > 0"}), msg.c_str());
        }
        const std::string msg = errorOf([&] { readGroundMotion(values); });
        QVERIFY2(containsAll(msg, {"values.txt", "needs the time step dt"}), msg.c_str());

        const std::string zero = write("zero_dt.AT2", "a\nb\nc\nNPTS= 2, DT= .0000 SEC\n0.1 0.2\n");
        const std::string msg2 = errorOf([&] { readAt2(zero); });
        QVERIFY2(containsAll(msg2, {"zero_dt.AT2 line 4", "DT must be", "'.0000'"}), msg2.c_str());
        const std::string negative = write("neg_dt.AT2", "a\nb\nc\nNPTS= 2, DT= -.01 SEC\n1 2\n");
        const std::string msg3 = errorOf([&] { readAt2(negative); });
        QVERIFY2(containsAll(msg3, {"neg_dt.AT2 line 4", "DT must be"}), msg3.c_str());
        const std::string npts = write("npts.AT2", "a\nb\nc\nNPTS= 2.5, DT= .01 SEC\n1 2\n");
        const std::string msg4 = errorOf([&] { readAt2(npts); });
        QVERIFY2(containsAll(msg4, {"npts.AT2 line 4", "NPTS must be"}), msg4.c_str());
    }

    void errorCarriesFileAndLine() {
        const std::string path = write("where.AT2", "a\nb\nc\nNPTS= 2, DT= .01 SEC\n0.1 ?\n");
        try {
            readAt2(path);
            QFAIL("no error thrown");
        } catch (const GroundMotionError& e) {
            QCOMPARE(e.file(), std::string("where.AT2"));
            QCOMPARE(e.line(), 5);
            const std::runtime_error& base = e; // usable as a plain runtime_error
            QVERIFY(std::string(base.what()).find("where.AT2 line 5") == 0);
        }
    }
};

QTEST_APPLESS_MAIN(TestGroundMotionReader)
#include "TestGroundMotionReader.moc"
