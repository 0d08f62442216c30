// LinkAddress parsing: the forms `hsmu run --controller` accepts and the errors it gives.
#include "comms/LinkAddress.h"

#include <QtTest>

using hsmu::comms::LinkAddress;

class TestLinkAddress : public QObject {
    Q_OBJECT
private slots:
    void builtin()
    {
        const auto a = LinkAddress::parse("builtin");
        QVERIFY(a.has_value());
        QVERIFY(a->kind == LinkAddress::Kind::Builtin);
        QCOMPARE(a->toString(), std::string("builtin"));
    }
    void tcpHostPort()
    {
        const auto a = LinkAddress::parse("tcp://127.0.0.1:5555");
        QVERIFY(a.has_value());
        QVERIFY(a->kind == LinkAddress::Kind::Tcp);
        QCOMPARE(a->host, std::string("127.0.0.1"));
        QCOMPARE(int(a->port), 5555);
        QCOMPARE(a->toString(), std::string("tcp://127.0.0.1:5555"));
    }
    void ipv6RoundTrip()
    {
        const auto a = LinkAddress::parse("tcp://[::1]:80");
        QVERIFY(a.has_value());
        QCOMPARE(a->host, std::string("::1"));
        QCOMPARE(a->toString(), std::string("tcp://[::1]:80"));
    }
    void tlsAddressAndSecurity()
    {
        const auto a = LinkAddress::parse("tls://lab-d.example.org:5101");
        QVERIFY(a.has_value());
        QVERIFY(a->kind == LinkAddress::Kind::Tls);
        QCOMPARE(a->host, std::string("lab-d.example.org"));
        QCOMPARE(a->toString(), std::string("tls://lab-d.example.org:5101"));
        QCOMPARE(a->security(), std::string("tls"));
        // What the record says about each kind of link (docs/recording.md).
        const std::pair<const char*, const char*> cases[] = {
            {"builtin", "builtin"},
            {"tcp://127.0.0.1:1", "plaintext-loopback"},
            {"tcp://127.8.9.10:1", "plaintext-loopback"},
            {"tcp://[::1]:1", "plaintext-loopback"},
            {"tcp://localhost:1", "plaintext-loopback"},
            {"tcp://10.0.0.5:1", "insecure-plaintext"},
            {"tcp://lab-d.example.org:1", "insecure-plaintext"},
            {"simapp://192.168.1.2:1", "insecure-plaintext"},
            {"generictcp://127.0.0.1:1", "plaintext-loopback"},
            {"tls://[::1]:1", "tls"},
        };
        for (const auto& [text, security] : cases)
            QCOMPARE(LinkAddress::parse(text)->security(), std::string(security));
    }
    void errorsSayWhat()
    {
        const std::pair<const char*, const char*> cases[] = {
            {"udp://h:1", "unknown scheme"},       {"tcp://host", "missing port"},
            {"tcp://:80", "missing host"},         {"tcp://h:0", "1..65535"},
            {"tcp://h:70000", "1..65535"},         {"tcp://h:12x", "1..65535"},
            {"tcp://[::1]80", "malformed IPv6"},   {"tls://h", "missing port"},
        };
        for (const auto& [text, why] : cases) {
            std::string error;
            QVERIFY2(!LinkAddress::parse(text, &error).has_value(), text);
            QVERIFY2(error.find(why) != std::string::npos, error.c_str());
            QVERIFY2(error.find(text) != std::string::npos, error.c_str());
        }
    }
};

QTEST_APPLESS_MAIN(TestLinkAddress)
#include "TestLinkAddress.moc"
