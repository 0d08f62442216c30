// The native protocol's codec (comms/protocol): every message survives a round trip through
// the incremental decoder in any chunking, and malformed input (truncated, oversize, bad
// magic, wrong version, unknown type, bad fields, trailing bytes, sequence gaps) is refused
// with the right error code, without growing the buffer.
#include "comms/protocol/FrameDecoder.h"

#include <QtTest>

#include <cmath>
#include <limits>

using namespace hsmu::comms;

namespace {

RthsEndMsg rthsEnd();

std::vector<Message> samples() {
    const double inf = std::numeric_limits<double>::infinity();
    return {HelloMsg{1, 0x0123456789abcdefull, "s3cret", "Element 1"},
            HelloAckMsg{1, 42, -0.0125, true, "Element 1", "specimen 'Element 1' (boucWen)",
                        "interlock: force", {}},
            ConfigureMsg{0.01, 0.15, inf, 0.01},
            TargetMsg{7, 1.0e-3},
            MeasurementMsg{7, 1.0e-3, -12.5, 1.0e-3, 3, kFlagFractured | kFlagReplayed},
            CommitMsg{7},
            AckMsg{MessageType::Commit, 7},
            HoldMsg{"operator hold \xc3\xa9"},
            ResumeMsg{},
            ResetMsg{},
            HeartbeatMsg{99},
            ErrorMsg{ErrorCode::Interlock, "target deformation |d| = 0.2 exceeds the limit 0.15"},
            ByeMsg{"test finished"},
            RthsStartMsg{8, 2.5},
            EmergencyHoldMsg{"operator: emergency stop"},
            TelemetryMsg{1024, 1.0, 1e-3, 1.1e-3, 0.9e-3, -250.0, 3, 42e-6, 1, true,
                         "console hold at tick 1024"},
            rthsEnd(),
            TargetsMsg{8, {{kChannelDisplacement, 0.0125}, {kChannelForce, -1500.0}}},
            MeasurementsMsg{8, kFlagReplayed, {{0.0125, 310.5, 0.0125}, {-2.5e-4, -1500.0, -1500.0}}},
            RthsUpdateMsg{{"alpha", "c0"}, {80.0, 0.03}},
            RthsUpdateAppliedMsg{4097, true, "operator", {"alpha", "c0"}, {80.0, 0.03}},
            RthsProposalMsg{3, 2304, 5, 0.125, "identification", {"alpha"}, {81.5}},
            RthsDecisionMsg{3, true}};
}

RthsEndMsg rthsEnd() {
    RthsEndMsg m;
    m.ticks = 3073;
    for (int i = 0; i < 9; ++i)
        m.j[i] = 0.5 * (i + 1) + 1e-13;
    m.misses = 2;
    m.worstLateness = 1.5e-4;
    m.telemetrySent = 385;
    m.telemetryDropped = 1;
    m.peakForce = 812.5;
    m.peakStroke = 2e-3;
    m.peakVelocity = 0.03;
    m.trackingIndicator = -1e-9;
    m.frequencyAmplitude = 1.02;
    m.frequencyDelay = 0.4;
    m.frequency = 2.0;
    m.hold = "emergency hold at tick 3072 (t = 3 s): test held";
    return m;
}

std::vector<std::uint8_t> header(std::uint32_t magic, std::uint16_t version, std::uint16_t type,
                                 std::uint32_t seq, std::uint32_t length) {
    std::vector<std::uint8_t> out;
    encodeRawFrame({magic, version, type, seq, length}, {}, out);
    return out;
}

FrameDecoder::Status decodeAll(FrameDecoder& d, const std::vector<std::uint8_t>& bytes,
                               std::vector<Frame>* frames = nullptr) {
    d.append(bytes.data(), bytes.size());
    Frame f;
    FrameDecoder::Status st;
    while ((st = d.next(f)) == FrameDecoder::Status::Frame)
        if (frames)
            frames->push_back(f);
    return st;
}

} // namespace

class TestFrameCodec : public QObject {
    Q_OBJECT
private slots:
    void roundTripEveryMessage() {
        const auto msgs = samples();
        QCOMPARE(msgs.size(), std::size_t(23)); // one of each type
        std::vector<std::uint8_t> stream;
        for (std::size_t i = 0; i < msgs.size(); ++i)
            encodeFrame(msgs[i], std::uint32_t(i + 1), stream);
        FrameDecoder d;
        std::vector<Frame> frames;
        QCOMPARE(decodeAll(d, stream, &frames), FrameDecoder::Status::NeedMore);
        QCOMPARE(frames.size(), msgs.size());
        for (std::size_t i = 0; i < msgs.size(); ++i) {
            QCOMPARE(frames[i].sequence, std::uint32_t(i + 1));
            QVERIFY2(frames[i].message.index() == msgs[i].index(),
                     messageTypeName(messageTypeOf(msgs[i])));
            std::vector<std::uint8_t> a, b; // equal re-encodings = equal fields, bit for bit
            encodeFrame(frames[i].message, 1, a);
            encodeFrame(msgs[i], 1, b);
            QVERIFY(a == b);
        }
        const auto& c = std::get<ConfigureMsg>(frames[2].message);
        QVERIFY(std::isinf(c.maxForce));
        QCOMPARE(std::get<HelloAckMsg>(frames[1].message).lastCommittedTarget, -0.0125);
        // The RTHS frames' documented sizes (docs/protocol.md): telemetry 75 bytes + its
        // reason, rths-end 170 + its hold, rths-start 12.
        const auto payload = [](const Message& m) {
            std::vector<std::uint8_t> b;
            encodeFrame(m, 1, b);
            return b.size() - kHeaderSize;
        };
        QCOMPARE(payload(RthsStartMsg{}), std::size_t(12));
        QCOMPARE(payload(TelemetryMsg{}), std::size_t(75));
        QCOMPARE(payload(RthsEndMsg{}), std::size_t(170));
        const auto& end = std::get<RthsEndMsg>(frames[16].message);
        QCOMPARE(end.j[8], 4.5 + 1e-13);
        QCOMPARE(std::get<TelemetryMsg>(frames[15].message).force, -250.0);
        // rths-update: u16 count + (str, f64) each; rths-update-applied 13 + the same.
        QCOMPARE(payload(RthsUpdateMsg{{"alpha"}, {1.0}}), std::size_t(2 + 2 + 5 + 8));
        QCOMPARE(payload(RthsUpdateAppliedMsg{}), std::size_t(13));
        const auto& u = std::get<RthsUpdateMsg>(frames[19].message);
        QVERIFY(u.names == (std::vector<std::string>{"alpha", "c0"}));
        QCOMPARE(u.values[1], 0.03);
        QCOMPARE(std::get<RthsUpdateAppliedMsg>(frames[20].message).tick, std::uint64_t(4097));
        // rths-proposal: 25 + the named values; rths-decision: u32 id, u8 approve.
        QCOMPARE(payload(RthsProposalMsg{}), std::size_t(25));
        QCOMPARE(payload(RthsDecisionMsg{}), std::size_t(5));
        const auto& p = std::get<RthsProposalMsg>(frames[21].message);
        QVERIFY(p.id == 3 && p.tick == 2304 && p.decision == 5 && p.fitError == 0.125 && p.values[0] == 81.5);
        QVERIFY(std::get<RthsDecisionMsg>(frames[22].message).approve);
        // N channels (docs/protocol.md, "Several actuator channels"): targets 10 + 9 N bytes,
        // measurements 14 + 24 N, the hello-ack's tail 2 + 8 N (none for one channel).
        QCOMPARE(payload(msgs[17]), std::size_t(10 + 9 * 2));
        QCOMPARE(payload(msgs[18]), std::size_t(14 + 24 * 2));
        const auto& ms = std::get<MeasurementsMsg>(frames[18].message);
        QCOMPARE(ms.channels[1].force, -1500.0);
        QCOMPARE(std::get<TargetsMsg>(frames[17].message).channels[1].mode, kChannelForce);
        HelloAckMsg one;
        HelloAckMsg three;
        three.channelCommands = {0.01, -0.02, -1500.0};
        QCOMPARE(payload(three), payload(one) + 2 + 8 * 3);
        std::vector<std::uint8_t> b;
        encodeFrame(three, 1, b);
        FrameDecoder d2;
        std::vector<Frame> f;
        QCOMPARE(decodeAll(d2, b, &f), FrameDecoder::Status::NeedMore);
        QCOMPARE(std::get<HelloAckMsg>(f.at(0).message).channelCommands,
                 three.channelCommands);
    }

    // A channel count of 0, 1 or past kMaxChannels, a mode byte other than 0/1, and a hello-ack
    // tail that is cut short are refused as malformed.
    void badChannelFields() {
        const auto refused = [](const Message& m, std::size_t at, std::uint8_t value) {
            std::vector<std::uint8_t> b;
            encodeFrame(m, 1, b);
            b[kHeaderSize + at] = value;
            FrameDecoder d;
            return decodeAll(d, b) == FrameDecoder::Status::Error &&
                   d.error().code == ErrorCode::Malformed;
        };
        const TargetsMsg t{1, {{kChannelDisplacement, 0.1}, {kChannelForce, 2.0}}};
        QVERIFY(refused(t, 8, 1));  // N = 1 (the length no longer matches either)
        QVERIFY(refused(t, 10, 2)); // first channel's mode byte
        const MeasurementsMsg m{1, 0, {{0.1, 1.0, 0.1}, {0.2, 2.0, 0.2}}};
        QVERIFY(refused(m, 12, 0)); // N = 0
        std::vector<std::uint8_t> b; // 17 channels: past kMaxChannels, refused at the header
        TargetsMsg big{1, std::vector<ChannelTarget>(kMaxChannels + 1)};
        encodeFrame(big, 1, b);
        FrameDecoder d;
        QCOMPARE(decodeAll(d, b), FrameDecoder::Status::Error);
        QVERIFY(d.error().reason.find("outside") != std::string::npos);
        HelloAckMsg a;
        a.channelCommands = {1.0, 2.0};
        b.clear();
        encodeFrame(a, 1, b);
        b.resize(b.size() - 8); // the second command cut off (length fixed below)
        const auto len = static_cast<std::uint32_t>(b.size() - kHeaderSize);
        for (int i = 0; i < 4; ++i)
            b[12 + i] = static_cast<std::uint8_t>(len >> (8 * i));
        FrameDecoder d2;
        QCOMPARE(decodeAll(d2, b), FrameDecoder::Status::Error);
    }

    void byteByByteChunking() {
        std::vector<std::uint8_t> stream;
        encodeFrame(TargetMsg{3, 0.5}, 1, stream);
        encodeFrame(MeasurementMsg{3, 0.5, 2.0, 0.5, 0, 0}, 2, stream);
        FrameDecoder d;
        int frames = 0;
        Frame f;
        for (std::uint8_t b : stream) {
            d.append(&b, 1);
            while (d.next(f) == FrameDecoder::Status::Frame)
                ++frames;
            QVERIFY(d.buffered() <= kHeaderSize + kMaxPayload);
        }
        QCOMPARE(frames, 2);
        QCOMPARE(std::get<MeasurementMsg>(f.message).force, 2.0);
    }

    void littleEndianLayout() {
        std::vector<std::uint8_t> b;
        encodeFrame(TargetMsg{0x0102, 1.0}, 0x0A0B0C0D, b);
        QCOMPARE(b.size(), std::size_t(16 + 16));
        const std::vector<std::uint8_t> head{'H',  'S',  'M',  'U',  1,  0, 4, 0,
                                             0x0D, 0x0C, 0x0B, 0x0A, 16, 0, 0, 0};
        QVERIFY(std::equal(head.begin(), head.end(), b.begin()));
        QCOMPARE(int(b[16]), 0x02); // step, u64 LE
        QCOMPARE(int(b[17]), 0x01);
        QCOMPARE(int(b[31]), 0x3F); // 1.0 = 0x3FF0000000000000, LE: last byte 0x3F
        QCOMPARE(int(b[30]), 0xF0);
    }

    void truncatedFrameWaits() {
        std::vector<std::uint8_t> b;
        encodeFrame(TargetMsg{1, 0.1}, 1, b);
        b.resize(b.size() - 3);
        FrameDecoder d;
        QCOMPARE(decodeAll(d, b), FrameDecoder::Status::NeedMore);
        QVERIFY(!d.failed());
    }

    void lengthTooShortForTheType() {
        std::vector<std::uint8_t> b =
            header(kFrameMagic, 1, std::uint16_t(MessageType::Target), 1, 8);
        b.resize(b.size() + 8, 0);
        FrameDecoder d;
        QCOMPARE(decodeAll(d, b), FrameDecoder::Status::Error);
        QCOMPARE(d.error().code, ErrorCode::Malformed);
    }

    void oversizeLengthRefusedAtTheHeader() {
        FrameDecoder d;
        QCOMPARE(
            decodeAll(d, header(kFrameMagic, 1, std::uint16_t(MessageType::Hold), 1, 0xFFFFFFFFu)),
            FrameDecoder::Status::Error);
        QCOMPARE(d.error().code, ErrorCode::Malformed);
        QVERIFY(d.error().reason.find("outside") != std::string::npos);
        QCOMPARE(d.buffered(), std::size_t(0)); // nothing kept, nothing allocated for it
        FrameDecoder d2;                        // just over the limit for a string message
        QCOMPARE(decodeAll(d2, header(kFrameMagic, 1, std::uint16_t(MessageType::Bye), 1,
                                      std::uint32_t(kMaxPayload + 1))),
                 FrameDecoder::Status::Error);
    }

    void badMagic() {
        FrameDecoder d;
        QCOMPARE(decodeAll(d, header(0x48545450u /* "PTTH" */, 1, 4, 1, 16)),
                 FrameDecoder::Status::Error);
        QCOMPARE(d.error().code, ErrorCode::Malformed);
        QVERIFY(d.error().reason.find("magic") != std::string::npos);
    }

    void wrongVersion() {
        FrameDecoder d;
        QCOMPARE(decodeAll(d, header(kFrameMagic, 2, 4, 1, 16)), FrameDecoder::Status::Error);
        QCOMPARE(d.error().code, ErrorCode::UnsupportedVersion);
    }

    void unknownType() {
        for (std::uint16_t t : {std::uint16_t(0), std::uint16_t(24), std::uint16_t(0xFFFF)}) {
            FrameDecoder d;
            QCOMPARE(decodeAll(d, header(kFrameMagic, 1, t, 1, 0)), FrameDecoder::Status::Error);
            QCOMPARE(d.error().code, ErrorCode::Malformed);
            QVERIFY(d.error().reason.find("unknown message type") != std::string::npos);
        }
    }

    void badFields() {
        // Hold whose string claims more bytes than the payload has.
        std::vector<std::uint8_t> b;
        encodeRawFrame({kFrameMagic, 1, std::uint16_t(MessageType::Hold), 1, 4}, {200, 0, 'a', 'b'},
                       b);
        FrameDecoder d;
        QCOMPARE(decodeAll(d, b), FrameDecoder::Status::Error);
        // Trailing bytes after the string.
        b.clear();
        encodeRawFrame({kFrameMagic, 1, std::uint16_t(MessageType::Hold), 1, 5},
                       {2, 0, 'a', 'b', 'c'}, b);
        FrameDecoder d2;
        QCOMPARE(decodeAll(d2, b), FrameDecoder::Status::Error);
        QVERIFY(d2.error().reason.find("trailing") != std::string::npos);
        // HelloAck 'holding' byte must be 0 or 1.
        b.clear();
        encodeFrame(HelloAckMsg{}, 1, b);
        b[16 + 2 + 8 + 8] = 7;
        FrameDecoder d3;
        QCOMPARE(decodeAll(d3, b), FrameDecoder::Status::Error);
        // Ack of an unknown type.
        b.clear();
        encodeRawFrame({kFrameMagic, 1, std::uint16_t(MessageType::Ack), 1, 10},
                       {99, 0, 0, 0, 0, 0, 0, 0, 0, 0}, b);
        FrameDecoder d4;
        QCOMPARE(decodeAll(d4, b), FrameDecoder::Status::Error);
    }

    void malformedUpdatesAreRefused() {
        // rths-update without a parameter, with more than kMaxUpdateParameters, with a name
        // running past the payload, or with trailing bytes: malformed, nothing decoded.
        const auto refused = [](std::vector<std::uint8_t> payload, const char* what) {
            std::vector<std::uint8_t> b;
            encodeRawFrame({kFrameMagic, 1, std::uint16_t(MessageType::RthsUpdate), 1,
                            std::uint32_t(payload.size())}, payload, b);
            FrameDecoder d;
            QVERIFY2(decodeAll(d, b) == FrameDecoder::Status::Error, what);
            QCOMPARE(d.error().code, ErrorCode::Malformed);
        };
        std::vector<std::uint8_t> none(12, 0); // count 0, padded to the minimum length
        refused(none, "count 0");
        std::vector<std::uint8_t> many(12, 0);
        many[0] = 33;
        refused(many, "33 parameters");
        std::vector<std::uint8_t> longName = {1, 0, 200, 0, 'a', 0, 0, 0, 0, 0, 0, 0};
        refused(longName, "a name past the payload");
        std::vector<std::uint8_t> b;
        encodeFrame(RthsUpdateMsg{{"a"}, {1.0}}, 1, b);
        std::vector<std::uint8_t> trailing(b.begin() + 16, b.end());
        trailing.push_back(0);
        refused(trailing, "trailing bytes");
    }

    void sequenceGapIsAViolation() {
        std::vector<std::uint8_t> b;
        encodeFrame(HeartbeatMsg{1}, 5, b);
        encodeFrame(HeartbeatMsg{2}, 7, b);
        FrameDecoder d;
        QCOMPARE(decodeAll(d, b), FrameDecoder::Status::Error);
        QCOMPARE(d.error().code, ErrorCode::ProtocolViolation);
    }

    // D6 (issue 26): a connection's first frame carries sequence 1 (docs/protocol.md), and
    // the sequence never wraps from 0xFFFFFFFF to 0.
    void firstSequenceMustBeOne() {
        for (const std::uint32_t first : {0u, 2u, 5u, 0xFFFFFFFFu}) {
            std::vector<std::uint8_t> b;
            encodeFrame(HeartbeatMsg{1}, first, b);
            FrameDecoder d;
            QCOMPARE(decodeAll(d, b), FrameDecoder::Status::Error);
            QCOMPARE(d.error().code, ErrorCode::ProtocolViolation);
            QVERIFY2(d.error().reason.find("first frame") != std::string::npos,
                     d.error().reason.c_str());
        }
        std::vector<std::uint8_t> ok;
        encodeFrame(HeartbeatMsg{1}, 1, ok);
        encodeFrame(HeartbeatMsg{2}, 2, ok);
        FrameDecoder d;
        QCOMPARE(decodeAll(d, ok), FrameDecoder::Status::NeedMore);
    }

    void errorIsSticky() {
        FrameDecoder d;
        QCOMPARE(decodeAll(d, header(0, 1, 4, 1, 16)), FrameDecoder::Status::Error);
        std::vector<std::uint8_t> good;
        encodeFrame(HeartbeatMsg{1}, 1, good);
        QCOMPARE(decodeAll(d, good), FrameDecoder::Status::Error);
    }

    void longStringsAreCutOnACharacterBoundary() {
        std::string s = "x"; // so that byte 1024 falls inside a character
        for (int i = 0; i < 600; ++i)
            s += "\xc3\xa9"; // 1200 bytes of two-byte characters
        std::vector<std::uint8_t> b;
        encodeFrame(ByeMsg{s}, 1, b);
        FrameDecoder d;
        std::vector<Frame> frames;
        decodeAll(d, b, &frames);
        QCOMPARE(frames.size(), std::size_t(1));
        const std::string& r = std::get<ByeMsg>(frames[0].message).reason;
        QVERIFY(r.size() <= kMaxStringBytes);
        QCOMPARE(r.size(), std::size_t(1023));
        QVERIFY(s.compare(0, r.size(), r) == 0);
    }
};

QTEST_APPLESS_MAIN(TestFrameCodec)
#include "TestFrameCodec.moc"
