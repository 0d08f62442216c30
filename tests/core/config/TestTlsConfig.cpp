// The configuration's "tls" block (core/config/TlsConfig.h, docs/configuration.md "TLS"): paths
// resolved against the configuration's folder, a site's own block, fingerprints normalized,
// and every missing or unsafe piece refused naming the field (a key file others can read is
// refused like a token file). The files' contents are comms' business (tests/comms/TestTls*).
#include "core/config/ConfigLoader.h"
#include "core/config/TlsConfig.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <fstream>

using namespace hsmu;

namespace {
const std::string kPin = "3F:1C:" + std::string(60, 'a'); // 64 hex digits with colons

nlohmann::json preset() {
    std::ifstream in(std::string(HSMU_SOURCE_DIR) + "/resources/presets/paper-condition-3.json");
    return nlohmann::json::parse(in);
}
} // namespace

class TestTlsConfig : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

    std::string file(const QString& name, QFile::Permissions mode) {
        const QString p = m_dir.filePath(name);
        std::ofstream(p.toStdString()) << "PEM\n";
        QFile::setPermissions(p, mode);
        return p.toStdString();
    }

    /// Load j written as tls.json in the temporary folder; the error text if it is refused.
    std::string load(const nlohmann::json& j, TestConfig* out = nullptr) {
        const std::string path = m_dir.filePath("tls.json").toStdString();
        std::ofstream(path) << j.dump();
        try {
            const TestConfig cfg = loadConfigFile(path);
            if (out)
                *out = cfg;
            return {};
        } catch (const std::exception& e) {
            return e.what();
        }
    }

private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        const auto owner = QFile::ReadOwner | QFile::WriteOwner;
        file("ca.pem", owner | QFile::ReadOther);
        file("console.pem", owner | QFile::ReadOther);
        file("console.key", owner);
        file("open.key", owner | QFile::ReadGroup | QFile::ReadOther);
    }

    void fingerprints() {
        QCOMPARE(normalizeFingerprint(kPin).value(), "3f1c" + std::string(60, 'a'));
        QCOMPARE(normalizeFingerprint("sha256:" + std::string(64, 'B')).value(),
                 std::string(64, 'b'));
        QVERIFY(!normalizeFingerprint(std::string(63, 'a')));
        QVERIFY(!normalizeFingerprint(std::string(65, 'a')));
        QVERIFY(!normalizeFingerprint(std::string(63, 'a') + "g"));
        const std::string list = m_dir.filePath("pins.txt").toStdString();
        std::ofstream(list) << "# lab D\n"
                            << kPin << "  # its controller\n\n"
                            << std::string(64, 'c') << "\n";
        std::vector<std::string> pins;
        std::string error;
        QVERIFY2(readFingerprintFile(list, pins, error), error.c_str());
        QCOMPARE(pins.size(), std::size_t(2));
        QCOMPARE(pins[1], std::string(64, 'c'));
        std::ofstream(list, std::ios::app) << "not-a-fingerprint\n";
        QVERIFY(!readFingerprintFile(list, pins, error));
        QVERIFY2(error.find("pins.txt:5") != std::string::npos, error.c_str());
    }

    void blockResolvedAgainstTheConfigurationFolder() {
        nlohmann::json j = preset();
        j["tls"] = {{"ca", "ca.pem"},
                    {"certificate", "console.pem"},
                    {"key", "console.key"},
                    {"pins", {kPin}}};
        TestConfig cfg;
        QCOMPARE(load(j, &cfg), std::string());
        QVERIFY(cfg.link.tls.has_value());
        QCOMPARE(cfg.link.tls->ca, m_dir.filePath("ca.pem").toStdString());
        QCOMPARE(cfg.link.tls->key, m_dir.filePath("console.key").toStdString());
        QCOMPARE(cfg.link.tls->pins, std::vector<std::string>{"3f1c" + std::string(60, 'a')});
        // Without the block: no TLS settings at all.
        QCOMPARE(load(preset(), &cfg), std::string());
        QVERIFY(!cfg.link.tls.has_value());
    }

    void refusalsNameTheField() {
        const std::pair<nlohmann::json, const char*> cases[] = {
            {{{"ca", "ca.pem"}, {"key", "console.key"}}, "tls.certificate"},
            {{{"ca", "ca.pem"}, {"certificate", "console.pem"}}, "tls.key"},
            {{{"certificate", "console.pem"}, {"key", "console.key"}}, "a CA or pinned"},
            {{{"ca", "ca.pem"}, {"certificate", "console.pem"}, {"key", "open.key"}}, "chmod 600"},
            {{{"ca", "missing.pem"}, {"certificate", "console.pem"}, {"key", "console.key"}},
             "cannot read"},
            {{{"ca", "ca.pem"},
              {"certificate", "console.pem"},
              {"key", "console.key"},
              {"pins", {"12:34"}}},
             "tls.pins"},
            {{{"ca", "ca.pem"},
              {"certificate", "console.pem"},
              {"key", "console.key"},
              {"password", "x"}},
             "password"},
        };
        for (const auto& [block, why] : cases) {
            nlohmann::json j = preset();
            j["tls"] = block;
            const std::string error = load(j);
            QVERIFY2(error.find(why) != std::string::npos, (why + (": " + error)).c_str());
        }
    }
};

QTEST_APPLESS_MAIN(TestTlsConfig)
#include "TestTlsConfig.moc"
