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
    void errorsSayWhat()
    {
        const std::pair<const char*, const char*> cases[] = {
            {"udp://h:1", "unknown scheme"},       {"tcp://host", "missing port"},
            {"tcp://:80", "missing host"},         {"tcp://h:0", "1..65535"},
            {"tcp://h:70000", "1..65535"},         {"tcp://h:12x", "1..65535"},
            {"tcp://[::1]80", "malformed IPv6"},
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
