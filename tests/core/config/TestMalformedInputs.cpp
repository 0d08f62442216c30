// A corpus of malformed inputs (issue 14): configurations, AT2 / time-acceleration / single
// column ground motions and measured-data CSV imports. Each must fail with the loader's own
// error (ConfigError, GroundMotionError, MeasuredDataError, or HybridTest::prepare() false)
// whose message names the file and the field or line; never std::bad_alloc, never a run of 0
// steps, never raw binary bytes in the message. Sizes and steps are checked against
// core/util/InputLimits.h before anything is allocated.

#include "core/config/ConfigLoader.h"
#include "core/config/TestFactory.h"
#include "core/groundmotion/GroundMotionReader.h"
#include "core/offline/MeasuredDataCsv.h"
#include "core/experiment/HybridTest.h"

#include <QTemporaryDir>
#include <QtTest>

#include <fstream>
#include <string>

using namespace hsmu;
using json = nlohmann::json;

namespace {

json preset() {
    std::ifstream in(std::string(HSMU_SOURCE_DIR) + "/resources/presets/paper-condition-3.json");
    return json::parse(in);
}

std::string write(const QTemporaryDir& dir, const QString& name, const std::string& text) {
    const std::string path = dir.filePath(name).toStdString();
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

/// The error of loading the configuration at path, building and preparing its test ("" if
/// it prepared). Any exception other than the loaders' own is reported as such.
std::string runError(const std::string& path) {
    try {
        const TestConfig cfg = loadConfigFile(path);
        auto test = buildHybridTest(cfg);
        if (!test->prepare())
            return "prepare: " + test->lastError();
        return {};
    } catch (const ConfigError& e) {
        return e.what();
    } catch (const GroundMotionError& e) {
        return e.what();
    } catch (const std::bad_alloc&) {
        return "UNEXPECTED std::bad_alloc";
    } catch (const std::exception& e) {
        return std::string("UNEXPECTED ") + e.what();
    }
}

bool printable(const std::string& s) {
    for (const char c : s)
        if ((static_cast<unsigned char>(c) < 0x20 && c != '\n') || c == 0x7f)
            return false;
    return true;
}

} // namespace

class TestMalformedInputs : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private slots:
    void configurations_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("expected"); // every comma-separated part must appear
        const auto edit = [](const std::function<void(json&)>& f) {
            json j = preset();
            f(j);
            return QString::fromStdString(j.dump(1));
        };
        QTest::newRow("1e999") << QString::fromStdString(
                                      preset().dump(1).replace(
                                          preset().dump(1).find("\"dt\": 0.01"), 10,
                                          "\"dt\": 1e999"))
                               << "bad.json line ,1e999";
        QTest::newRow("dof index 2^32 + 1")
            << edit([](json& j) { j["structure"]["elements"][0]["dof"] = 4294967297ull; })
            << "bad.json,structure.elements[0].dof,4294967297,out of range";
        QTest::newRow("damping modes 2^32 + 1") << edit([](json& j) {
            j["structure"]["damping"] = {{"ratio", 0.05}, {"modes", {4294967297ull, 2}}};
        }) << "bad.json,structure.damping.modes.[0],out of range";
        QTest::newRow("seed 2^32 + 1")
            << edit([](json& j) {
                   j["structure"]["elements"][0]["specimen"]["seed"] = 4294967297ull;
               })
            << "bad.json,specimen.seed,out of range";
        QTest::newRow("actuator delay 1e9") << edit([](json& j) {
            j["structure"]["elements"][0]["specimen"]["actuator"] = {{"type", "delay"},
                                                                     {"delay", 1e9}};
        }) << "bad.json,actuator.delay,[0, 1] s";
        QTest::newRow("lag 1e9") << edit([](json& j) {
            j["structure"]["elements"][0]["specimen"]["actuator"] = {{"type", "lag"},
                                                                     {"timeConstant", 1e9}};
        }) << "bad.json,actuator.timeConstant";
        QTest::newRow("analysis.dt 1e-12")
            << edit([](json& j) { j["analysis"]["dt"] = 1e-12; }) << "bad.json,analysis.dt";
        QTest::newRow("analysis.dt 1e300")
            << edit([](json& j) { j["analysis"]["dt"] = 1e300; }) << "bad.json,analysis.dt";
        QTest::newRow("duration 1e9") << edit([](json& j) { j["analysis"]["duration"] = 1e9; })
                                      << "bad.json,analysis.duration";
        QTest::newRow("duration / dt too many steps") << edit([](json& j) {
            j["analysis"]["dt"] = 1e-5;
            j["analysis"]["duration"] = 80000.0;
        }) << "bad.json,analysis.duration,steps";
        QTest::newRow("groundMotion.dt 1e-300") << edit([](json& j) {
            j["groundMotion"] = {{"file", "/dev/null"}, {"format", "single"}, {"dt", 1e-300}};
        }) << "bad.json,groundMotion.dt";
        QTest::newRow("ground motion /dev/zero") << edit([](json& j) {
            j["groundMotion"] = {{"file", "/dev/zero"}, {"format", "single"}, {"dt", 0.01}};
        }) << "zero,not a regular file";
        QTest::newRow("binary") << QString("{\"name\": \"\x01\x02\x7f\"") << "bad.json";
        // D1 (issue 26): nesting deep enough to overflow a recursive walk's stack.
        QTest::newRow("2,000,000 nested arrays")
            << QString::fromStdString("{\"nest\": " + std::string(2'000'000, '[') +
                                      std::string(2'000'000, ']') + "}")
            << "bad.json line 1,nested deeper than 64";
        {
            std::string objects;
            for (int i = 0; i < 200'000; ++i)
                objects += "{\"a\": ";
            objects += "1" + std::string(200'000, '}');
            QTest::newRow("200,000 nested objects")
                << QString::fromStdString(objects) << "bad.json line 1,nested deeper than 64";
        }
        QTest::newRow("integer as float") << edit([](json& j) {
            j["structure"]["elements"][0]["specimen"]["seed"] = 1.5;
        }) << "bad.json,specimen.seed,expected an integer";
    }
    void configurations() {
        QFETCH(QString, text);
        QFETCH(QString, expected);
        const std::string path = write(m_dir, "bad.json", text.toStdString());
        const QString error = QString::fromStdString(runError(path));
        QVERIFY2(!error.isEmpty(), "accepted");
        QVERIFY2(!error.contains("UNEXPECTED"), qPrintable(error));
        for (const QString& part : expected.split(','))
            QVERIFY2(error.contains(part), qPrintable(error + " lacks " + part));
        QVERIFY2(printable(error.toStdString()), qPrintable(error));
    }

    void groundMotions_data() {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QByteArray>("content");
        QTest::addColumn<QString>("expected");
        const QByteArray head = "PEER\nrecord\nUNITS OF G\n";
        QTest::newRow("at2 DT 1e300") << "big.AT2" << head + "NPTS= 3, DT= 1e300 SEC\n0 0.1 0\n"
                                      << "big.AT2 line 4,DT";
        QTest::newRow("at2 DT 1e-300") << "tiny.AT2" << head + "NPTS= 3, DT= 1e-300 SEC\n0 1 0\n"
                                       << "tiny.AT2 line 4,DT";
        QTest::newRow("at2 binary") << "bin.AT2"
                                    << QByteArray("PEER\n\x00\xff\xfe\x01garbage\n", 17)
                                    << "bin.AT2,not a text file";
        QTest::newRow("at2 NPTS huge") << "npts.AT2" << head + "NPTS= 1e12, DT= 0.01 SEC\n0\n"
                                       << "npts.AT2 line 4,NPTS";
        QTest::newRow("at2 control bytes") << "ctl.AT2" << head + "NPTS= \x1b[31m, DT\n"
                                           << "ctl.AT2 line 4,?[31m";
        QTest::newRow("time-acc dt 1e-300")
            << "ta.csv" << QByteArray("0 0\n1e-300 1\n2e-300 0\n") << "ta.csv,time step";
        QTest::newRow("time-acc text") << "tt.csv" << QByteArray("0 0\n0.01 abc\n")
                                       << "tt.csv line 2";
        QTest::newRow("empty") << "empty.AT2" << QByteArray() << "empty.AT2";
    }
    void groundMotions() {
        QFETCH(QString, name);
        QFETCH(QByteArray, content);
        QFETCH(QString, expected);
        const std::string path = write(m_dir, name, content.toStdString());
        json j = preset();
        j["groundMotion"] = {{"file", path}};
        const std::string cfg = write(m_dir, "gm.json", j.dump());
        const QString error = QString::fromStdString(runError(cfg));
        QVERIFY2(!error.isEmpty(), "accepted");
        QVERIFY2(!error.contains("UNEXPECTED"), qPrintable(error));
        for (const QString& part : expected.split(','))
            QVERIFY2(error.contains(part), qPrintable(error + " lacks " + part));
        QVERIFY2(printable(error.toStdString()), qPrintable(error));
    }

    void zeroStepRunIsAnError() {
        // A 1-sample-step record shorter than dt: 0 steps is an error, not a finished run.
        const std::string gm = write(m_dir, "short.AT2",
                                     "PEER\nrecord\nUNITS OF G\nNPTS= 2, DT= 0.001 SEC\n0 0.1\n");
        json j = preset();
        j["groundMotion"] = {{"file", gm}};
        j["analysis"]["dt"] = 0.01;
        const std::string error = runError(write(m_dir, "zero.json", j.dump()));
        QVERIFY2(error.find("0 steps") != std::string::npos, error.c_str());
    }

    void measuredDataImports_data() {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QByteArray>("content");
        QTest::addColumn<QString>("expected");
        QTest::newRow("device") << "/dev/zero" << QByteArray() << "/dev/zero,not a regular file";
        QTest::newRow("text in numbers")
            << "m1.csv" << QByteArray("time,deformation,force\n0,0,x\n") << "m1.csv";
        QTest::newRow("no header") << "m2.csv" << QByteArray("1,2\n") << "m2.csv";
        QTest::newRow("binary") << "m3.csv" << QByteArray("\x00\x01\x02\xff", 4) << "m3.csv";
    }
    void measuredDataImports() {
        QFETCH(QString, name);
        QFETCH(QByteArray, content);
        QFETCH(QString, expected);
        const std::string path = name.startsWith('/') ? name.toStdString()
                                                      : write(m_dir, name, content.toStdString());
        QString error;
        try {
            readMeasuredDataCsv(path, std::nullopt);
        } catch (const MeasuredDataError& e) {
            error = QString::fromUtf8(e.what());
        } catch (const std::exception& e) {
            error = QString("UNEXPECTED ") + e.what();
        }
        QVERIFY2(!error.isEmpty(), "accepted");
        QVERIFY2(!error.contains("UNEXPECTED"), qPrintable(error));
        for (const QString& part : expected.split(','))
            QVERIFY2(error.contains(part), qPrintable(error + " lacks " + part));
    }
};

QTEST_GUILESS_MAIN(TestMalformedInputs)
#include "TestMalformedInputs.moc"
