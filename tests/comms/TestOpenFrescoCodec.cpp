// The OpenFresco wire layout (comms/openfresco, docs/openfresco.md) checked byte by byte
// against the documented layout: the 11-int32 sizes header, action codes in element 0,
// padding to dataSize, fixed 16385-byte init lines; and the configuration's link section.
#include "comms/LinkAddress.h"
#include "comms/openfresco/OfFrame.h"
#include "comms/openfresco/OfSizes.h"
#include "core/config/ConfigLoader.h"

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <cstring>
#include <fstream>

using namespace hsmu;
using namespace hsmu::comms;
using namespace hsmu::comms::of;

namespace {

std::int32_t int32At(const std::uint8_t* p, std::size_t index) {
    std::int32_t v;
    std::memcpy(&v, p + 4 * index, 4);
    return v;
}

double doubleAt(const std::vector<std::uint8_t>& b, std::size_t index) {
    double v;
    std::memcpy(&v, b.data() + 8 * index, 8);
    return v;
}

nlohmann::json minimalConfig() {
    return nlohmann::json::parse(R"({
      "structure": {"dofs": [{"mass": 1}],
                    "elements": [{"name": "s", "type": "lateralSpring", "dof": 0,
                                  "material": {"law": "elastic", "k": 10}}]},
      "analysis": {"dt": 0.01, "duration": 0.1}
    })");
}

} // namespace

class TestOpenFrescoCodec : public QObject {
    Q_OBJECT
private slots:
    void sizesHeaderIsElevenInt32InOrder() {
        OfSizes s;
        s.ctrl = {2, 3, 4, 5, 1};
        s.daq = {6, 7, 8, 9, 1};
        s.dataSize = 300;
        const auto bytes = encodeSizes(s);
        QCOMPARE(bytes.size(), std::size_t(44));
        const int expected[11] = {2, 3, 4, 5, 1, 6, 7, 8, 9, 1, 300};
        for (std::size_t i = 0; i < 11; ++i)
            QCOMPARE(int32At(bytes.data(), i), expected[i]);
        // little-endian: the low byte of dataSize 300 = 0x012C comes first
        QCOMPARE(int(bytes[40]), 0x2C);
        QCOMPARE(int(bytes[41]), 0x01);
        QVERIFY(decodeSizes(bytes.data()) == s);
    }

    void sizesLayoutAndValidation() {
        OfSizes s;
        s.ctrl = {2, 2, 2, 0, 1};
        s.daq = {2, 0, 0, 2, 1};
        s.dataSize = 8;
        QCOMPARE(s.ctrlIndex(Resp::Disp), 1); // after the action code
        QCOMPARE(s.ctrlIndex(Resp::Vel), 3);
        QCOMPARE(s.ctrlIndex(Resp::Time), 7);
        QCOMPARE(s.daqIndex(Resp::Disp), 0); // replies start at index 0
        QCOMPARE(s.daqIndex(Resp::Force), 2);
        QCOMPARE(s.daqIndex(Resp::Time), 4);
        QVERIFY(!s.problem()); // 1 + 7 = 8 doubles fit exactly
        s.dataSize = 7;
        QVERIFY(s.problem() && s.problem()->find("1 + 7") != std::string::npos);
        s.dataSize = 0;
        QVERIFY(s.problem() && s.problem()->find("dataSize 0") != std::string::npos);
        s.dataSize = 256;
        s.daq[1] = -1;
        QVERIFY(s.problem() && s.problem()->find("daq vel") != std::string::npos);
        const std::string d = OfSizes{}.describe();
        QVERIFY2(d.find("dataSize 256") != std::string::npos &&
                     d.find("force 1") != std::string::npos,
                 d.c_str());
    }

    void requestHasCodeAtZeroAndZeroPadding() {
        std::vector<std::uint8_t> b;
        std::string error;
        const double values[] = {0.0125, -3.5};
        QVERIFY(encodeRequest(Action::SetTrialResponse, values, 16, b, error));
        QCOMPARE(b.size(), std::size_t(16 * 8));
        // 3.0 as an IEEE-754 double, little-endian: 00 00 00 00 00 00 08 40
        const std::uint8_t three[8] = {0, 0, 0, 0, 0, 0, 0x08, 0x40};
        QVERIFY(std::memcmp(b.data(), three, 8) == 0);
        QCOMPARE(doubleAt(b, 1), 0.0125);
        QCOMPARE(doubleAt(b, 2), -3.5);
        for (std::size_t i = 3; i < 16; ++i)
            QCOMPARE(doubleAt(b, i), 0.0);
        std::vector<double> decoded;
        decodeFrame(b.data(), 16, decoded);
        QCOMPARE(decoded.size(), std::size_t(16));
        QCOMPARE(decoded[0], 3.0);

        // a reply: values from index 0
        QVERIFY(encodeFrame(values, 4, b, error));
        QCOMPARE(b.size(), std::size_t(32));
        QCOMPARE(doubleAt(b, 0), 0.0125);
        QCOMPARE(doubleAt(b, 3), 0.0);

        const std::vector<double> tooMany(17, 1.0);
        QVERIFY(!encodeFrame(tooMany, 16, b, error));
        QVERIFY2(error.find("dataSize 16") != std::string::npos, error.c_str());
        QVERIFY(!encodeRequest(Action::GetDaqResponse, std::vector<double>(16, 0.0), 16, b, error));
    }

    void actionCodes() {
        QVERIFY(actionOf(3.0) == Action::SetTrialResponse);
        QVERIFY(actionOf(6.0) == Action::GetDaqResponse);
        QVERIFY(actionOf(12.0) == Action::GetInitialStiff);
        QVERIFY(actionOf(15.0) == Action::GetMass);
        QVERIFY(actionOf(99.0) == Action::Terminate);
        QVERIFY(!actionOf(0.0));
        QVERIFY(!actionOf(16.0));
        QVERIFY(!actionOf(3.5));
        QVERIFY(!actionOf(NAN));
        QVERIFY(!actionOf(-3.0));
        QCOMPARE(std::string(actionName(Action::CommitState)), std::string("commitState"));
    }

    void initLinesAreFixedSize() {
        std::vector<std::uint8_t> b;
        std::string error;
        QVERIFY(encodeInitLine("loadLVDT 1 2", b, error));
        QCOMPARE(b.size(), std::size_t(16385));
        QVERIFY(std::memcmp(b.data(), "loadLVDT 1 2", 12) == 0);
        for (std::size_t i = 12; i < b.size(); ++i)
            QCOMPARE(int(b[i]), 0);
        QCOMPARE(decodeInitLine(b.data()), std::string("loadLVDT 1 2"));
        QVERIFY(!startsWithAction(b.data()));
        QVERIFY(encodeInitLine("", b, error));
        QVERIFY(!startsWithAction(b.data())); // 0.0 is not an action
        QVERIFY(!encodeInitLine(std::string(16385, 'x'), b, error));
        QVERIFY2(error.find("16384") != std::string::npos, error.c_str());
        QVERIFY(encodeInitLine(std::string(16384, 'x'), b, error));
        QVERIFY(!encodeInitLine(std::string("a\0b", 3), b, error));
        std::vector<std::uint8_t> f;
        const double v[] = {1.0};
        QVERIFY(encodeRequest(Action::SetTrialResponse, v, 4, f, error));
        QVERIFY(startsWithAction(f.data()));
    }

    void addressSchemes() {
        std::string error;
        auto a = LinkAddress::parse("simapp://127.0.0.1:8090", &error);
        QVERIFY(a && a->kind == LinkAddress::Kind::SimApp && a->port == 8090);
        QCOMPARE(a->toString(), std::string("simapp://127.0.0.1:8090"));
        a = LinkAddress::parse("generictcp://[::1]:44000", &error);
        QVERIFY(a && a->kind == LinkAddress::Kind::GenericTcp && a->host == "::1");
        QCOMPARE(a->toString(), std::string("generictcp://[::1]:44000"));
        QVERIFY(!LinkAddress::parse("simapp://host", &error));
        QVERIFY2(error.find("simapp://HOST:PORT") != std::string::npos, error.c_str());
    }

    void configLinkSection() {
        QTemporaryDir dir;
        const QString init = dir.filePath(QStringLiteral("lab.init"));
        std::ofstream(init.toStdString()) << "first line\r\nsecond line\n";
        nlohmann::json j = minimalConfig();
        j["controller"] = {{"protocol", "generictcp"},
                           {"dataSize", 64},
                           {"ctrlSizes", {{"disp", 1}, {"time", 1}}},
                           {"initFile", "lab.init"},
                           {"rate", 2048}};
        const TestConfig cfg = parseConfig(j, dir.filePath(QStringLiteral("c.json")).toStdString());
        QCOMPARE(cfg.link.protocol, std::string("generictcp"));
        QCOMPARE(cfg.link.dataSize, 64);
        QCOMPARE(cfg.link.ctrlSizes[0], 1);
        QCOMPARE(cfg.link.ctrlSizes[4], 1);
        QCOMPARE(cfg.link.ctrlSizes[1], 0);
        QCOMPARE(cfg.link.daqSizes[3], 1); // default daq: disp and force
        QCOMPARE(cfg.link.initLines.size(), std::size_t(2));
        QCOMPARE(cfg.link.initLines[0], std::string("first line"));

        QCOMPARE(parseConfig(minimalConfig(), "m.json").link.protocol, std::string("native"));

        auto refused = [](nlohmann::json controller, const char* expected) {
            nlohmann::json k = minimalConfig();
            k["controller"] = std::move(controller);
            try {
                parseConfig(k, "bad.json");
            } catch (const ConfigError& e) {
                return std::string(e.what()).find(expected) != std::string::npos;
            }
            return false;
        };
        QVERIFY(refused({{"protocol", "modbus"}}, "controller.protocol"));
        QVERIFY(refused({{"dataSize", 0}}, "controller.dataSize"));
        QVERIFY(refused({{"dataSize", 2}, {"daqSizes", {{"disp", 2}, {"force", 2}}}},
                        "controller.dataSize"));
        QVERIFY(refused({{"daqSizes", {{"disp", 1}}}}, "daqSizes.force"));
        QVERIFY(refused({{"protocol", "simapp"}, {"initFile", "x"}}, "controller.initFile"));
        QVERIFY(refused({{"protocol", "generictcp"}, {"initFile", "/nonexistent/x.init"}},
                        "cannot open"));
    }
};

QTEST_APPLESS_MAIN(TestOpenFrescoCodec)
#include "TestOpenFrescoCodec.moc"
