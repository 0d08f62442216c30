// The real El Centro 1940 N-S files in ../shared/data/elcentro (README.md there gives the
// reference values computed independently in Python). Skipped when the folder is absent.
#include "core/groundmotion/GroundMotionReader.h"

#include <QtTest>

#include <cmath>
#include <filesystem>
#include <string>

using namespace hsmu;

namespace {

const std::string kDir = std::string(HSMU_SHARED_DATA_DIR) + "/elcentro/";
const std::string kPeknoldAt2 = kDir + "elCentro_Peknold_NS_0.02s.AT2";
const std::string kPeknoldText = kDir + "elcentro_NS_0.02s_time_accel_g.txt";
const std::string kPeerAt2 = kDir + "IELC180_PEER_0.01s.AT2";
const std::string kPeerText = kDir + "elcentro_IELC180_PEER_0.01s_time_accel_g.txt";

bool dataPresent() {
    for (const std::string& path : {kPeknoldAt2, kPeknoldText, kPeerAt2, kPeerText}) {
        if (!std::filesystem::exists(path))
            return false;
    }
    return true;
}

double maxAbsDifference(const GroundMotion& a, const GroundMotion& b) {
    double worst = 0.0;
    for (std::size_t i = 0; i < a.acceleration.size(); ++i)
        worst = std::max(worst, std::abs(a.acceleration[i] - b.acceleration[i]));
    return worst;
}

} // namespace

#define REQUIRE_DATA()                                                                             \
    if (!dataPresent())                                                                            \
    QSKIP("El Centro files not found in HSMU_SHARED_DATA_DIR/elcentro (" HSMU_SHARED_DATA_DIR      \
          "): the real-record checks need the shared data folder next to the source tree")

class TestSharedRecords : public QObject {
    Q_OBJECT

private slots:
    void peknoldAt2() {
        REQUIRE_DATA();
        const GroundMotion g = readAt2(kPeknoldAt2);
        QCOMPARE(g.acceleration.size(), std::size_t(1559));
        QCOMPARE(g.dt, 0.02);
        QCOMPARE(g.name, std::string("elCentro_Peknold_NS_0.02s.AT2"));
        QVERIFY(std::abs(g.duration() - 31.16) < 1e-9);
        QVERIFY(std::abs(g.pga() / kStandardGravity - 0.31882) < 1e-4);
        QVERIFY(std::abs(g.pga() - 3.127) < 1e-3);
        QVERIFY(std::abs(g.pgaTime() - 2.02) < 1e-9); // index 101
        QVERIFY(g.acceleration[101] < 0.0);           // the peak is negative
        QCOMPARE(g.acceleration.back(), 0.0);         // the artificial ramp ends at 0.00000
        QVERIFY(std::abs(g.acceleration.front() - 0.00630 * kStandardGravity) < 1e-15);
    }

    void peerAt2() {
        REQUIRE_DATA();
        const GroundMotion g = readAt2(kPeerAt2);
        QCOMPARE(g.acceleration.size(), std::size_t(4000));
        QCOMPARE(g.dt, 0.01);
        QVERIFY(std::abs(g.duration() - 39.99) < 1e-9);
        QVERIFY(std::abs(g.pga() / kStandardGravity - 0.31288) < 1e-4);
        QVERIFY(std::abs(g.pgaTime() - 2.15) < 1e-9); // index 215
        QVERIFY(std::abs(g.acceleration.front() - (-0.6403182e-2) * kStandardGravity) < 1e-15);
        QVERIFY(std::abs(g.acceleration.back() - 0.9459335e-4 * kStandardGravity) < 1e-15);
    }

    void textConversionsMatchAt2() {
        REQUIRE_DATA();
        for (const auto& [at2, text] :
             {std::pair{kPeknoldAt2, kPeknoldText}, std::pair{kPeerAt2, kPeerText}}) {
            const GroundMotion a = readAt2(at2);
            const GroundMotion b = readTimeAcceleration(text, AccelerationUnit::G);
            QCOMPARE(b.acceleration.size(), a.acceleration.size());
            QVERIFY(std::abs(b.dt - a.dt) < 1e-12);
            // Same decimal values, so the same doubles (std::from_chars rounds correctly).
            QVERIFY2(maxAbsDifference(a, b) <= 1e-12, text.c_str());
        }
    }

    void unitOverrideScalesEverything() {
        REQUIRE_DATA();
        const GroundMotion g = readAt2(kPeknoldAt2);
        const GroundMotion cm = readAt2(kPeknoldAt2, AccelerationUnit::CentimetersPerSecond2);
        QCOMPARE(cm.acceleration.size(), g.acceleration.size());
        QVERIFY(std::abs(cm.pga() - 0.31882 * 0.01) < 1e-12);
        QVERIFY(std::abs(cm.pgaTime() - g.pgaTime()) < 1e-12);
    }

    void autoDetection() {
        REQUIRE_DATA();
        QCOMPARE(detectGroundMotionFormat(kPeknoldAt2), GroundMotionFormat::At2);
        QCOMPARE(detectGroundMotionFormat(kPeerAt2), GroundMotionFormat::At2);
        QCOMPARE(detectGroundMotionFormat(kPeknoldText), GroundMotionFormat::TimeAcceleration);
        QCOMPARE(detectGroundMotionFormat(kPeerText), GroundMotionFormat::TimeAcceleration);

        const GroundMotion at2 = readGroundMotion(kPeerAt2);
        const GroundMotion text = readGroundMotion(kPeerText); // text defaults to g
        QCOMPARE(at2.acceleration.size(), std::size_t(4000));
        QCOMPARE(text.acceleration.size(), std::size_t(4000));
        QVERIFY(maxAbsDifference(at2, text) <= 1e-12);
        QCOMPARE(at2.acceleration, readAt2(kPeerAt2).acceleration);

        // A dt that agrees with the file is accepted, a different one is an error.
        QCOMPARE(readGroundMotion(kPeknoldAt2, GroundMotionFormat::Auto, std::nullopt, 0.02)
                     .acceleration.size(),
                 std::size_t(1559));
        QVERIFY_THROWS_EXCEPTION(
            GroundMotionError,
            readGroundMotion(kPeknoldAt2, GroundMotionFormat::Auto, std::nullopt, 0.01));
    }
};

QTEST_APPLESS_MAIN(TestSharedRecords)
#include "TestSharedRecords.moc"
