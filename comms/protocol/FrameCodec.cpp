#include "comms/protocol/FrameCodec.h"

#include <algorithm>
#include <bit>
#include <cstring>

namespace hsmu::comms {

namespace {

static_assert(sizeof(double) == 8 && std::numeric_limits<double>::is_iec559,
              "the protocol carries IEEE 754 binary64");

class Writer {
public:
    explicit Writer(std::vector<std::uint8_t>& out) : m_out(out) {}
    void u8(std::uint8_t v) { m_out.push_back(v); }
    void u16(std::uint16_t v) { le(v, 2); }
    void u32(std::uint32_t v) { le(v, 4); }
    void u64(std::uint64_t v) { le(v, 8); }
    void f64(double v) { u64(std::bit_cast<std::uint64_t>(v)); }
    void str(const std::string& s) {
        std::size_t n = std::min(s.size(), kMaxStringBytes);
        // Do not cut a UTF-8 sequence: back off over continuation bytes (10xxxxxx).
        if (n < s.size())
            while (n > 0 && (static_cast<unsigned char>(s[n]) & 0xC0u) == 0x80u)
                --n;
        u16(static_cast<std::uint16_t>(n));
        m_out.insert(m_out.end(), s.begin(), s.begin() + static_cast<std::ptrdiff_t>(n));
    }

private:
    void le(std::uint64_t v, int bytes) {
        for (int i = 0; i < bytes; ++i)
            m_out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
    }
    std::vector<std::uint8_t>& m_out;
};

class Reader {
public:
    Reader(const std::uint8_t* p, std::size_t n) : m_p(p), m_n(n) {}
    bool u8(std::uint8_t& v) { return take(1, v); }
    bool u16(std::uint16_t& v) { return take(2, v); }
    bool u32(std::uint32_t& v) { return take(4, v); }
    bool u64(std::uint64_t& v) { return take(8, v); }
    bool f64(double& v) {
        std::uint64_t bits = 0;
        if (!u64(bits))
            return false;
        v = std::bit_cast<double>(bits);
        return true;
    }
    bool boolean(bool& v) {
        std::uint8_t b = 0;
        if (!u8(b) || b > 1)
            return false;
        v = b == 1;
        return true;
    }
    bool str(std::string& s) {
        std::uint16_t n = 0;
        if (!u16(n) || n > kMaxStringBytes || n > m_n - m_pos)
            return false;
        s.assign(reinterpret_cast<const char*>(m_p + m_pos), n);
        m_pos += n;
        return true;
    }
    bool atEnd() const { return m_pos == m_n; }

private:
    template <typename T> bool take(std::size_t bytes, T& v) {
        if (bytes > m_n - m_pos)
            return false;
        std::uint64_t x = 0;
        for (std::size_t i = 0; i < bytes; ++i)
            x |= std::uint64_t(m_p[m_pos + i]) << (8 * i);
        m_pos += bytes;
        v = static_cast<T>(x);
        return true;
    }
    const std::uint8_t* m_p;
    std::size_t m_n;
    std::size_t m_pos = 0;
};

struct Bounds {
    std::size_t min, max;
};

constexpr std::size_t kStr = 2 + kMaxStringBytes; // largest string field

Bounds boundsOf(MessageType t) {
    switch (t) {
    case MessageType::Hello:
        return {14, 12 + 2 * kStr};
    case MessageType::HelloAck:
        return {25, 19 + 3 * kStr + 2 + 8 * kMaxChannels};
    case MessageType::Configure:
        return {32, 32};
    case MessageType::Target:
        return {16, 16};
    case MessageType::Measurement:
        return {40, 40};
    case MessageType::Commit:
        return {8, 8};
    case MessageType::Ack:
        return {10, 10};
    case MessageType::Hold:
        return {2, kStr};
    case MessageType::Resume:
    case MessageType::Reset:
        return {0, 0};
    case MessageType::Heartbeat:
        return {8, 8};
    case MessageType::Error:
        return {4, 2 + kStr};
    case MessageType::Bye:
        return {2, kStr};
    case MessageType::RthsStart:
        return {12, 12};
    case MessageType::EmergencyHold:
        return {2, kStr};
    case MessageType::Telemetry:
        return {75, 73 + kStr};
    case MessageType::RthsEnd:
        return {170, 168 + kStr};
    case MessageType::Targets:
        return {10 + 9 * 2, 10 + 9 * kMaxChannels};
    case MessageType::Measurements:
        return {14 + 24 * 2, 14 + 24 * kMaxChannels};
    case MessageType::RthsUpdate:
        return {12, kMaxPayload};
    case MessageType::RthsUpdateApplied:
        return {13, kMaxPayload};
    case MessageType::RthsProposal:
        return {25, kMaxPayload};
    case MessageType::RthsDecision:
        return {5, 5};
    }
    return {0, 0};
}

struct Encoder {
    Writer& w;
    void operator()(const HelloMsg& m) {
        w.u16(m.version);
        w.u64(m.sessionId);
        w.str(m.token);
        w.str(m.element);
    }
    void operator()(const HelloAckMsg& m) {
        w.u16(m.version);
        w.u64(m.committedSteps);
        w.f64(m.lastCommittedTarget);
        w.u8(m.holding ? 1 : 0);
        w.str(m.element);
        w.str(m.description);
        w.str(m.holdReason);
        if (!m.channelCommands.empty()) {
            w.u16(static_cast<std::uint16_t>(m.channelCommands.size()));
            for (double c : m.channelCommands)
                w.f64(c);
        }
    }
    void operator()(const ConfigureMsg& m) {
        w.f64(m.dt);
        w.f64(m.maxDeformation);
        w.f64(m.maxForce);
        w.f64(m.maxIncrement);
    }
    void operator()(const TargetMsg& m) {
        w.u64(m.step);
        w.f64(m.deformation);
    }
    void operator()(const MeasurementMsg& m) {
        w.u64(m.step);
        w.f64(m.deformation);
        w.f64(m.force);
        w.f64(m.commanded);
        w.u32(m.heldTicks);
        w.u32(m.flags);
    }
    void operator()(const CommitMsg& m) { w.u64(m.step); }
    void operator()(const AckMsg& m) {
        w.u16(static_cast<std::uint16_t>(m.acked));
        w.u64(m.step);
    }
    void operator()(const HoldMsg& m) { w.str(m.reason); }
    void operator()(const ResumeMsg&) {}
    void operator()(const ResetMsg&) {}
    void operator()(const HeartbeatMsg& m) { w.u64(m.nonce); }
    void operator()(const ErrorMsg& m) {
        w.u16(static_cast<std::uint16_t>(m.code));
        w.str(m.reason);
    }
    void operator()(const ByeMsg& m) { w.str(m.reason); }
    void operator()(const RthsStartMsg& m) {
        w.u32(m.decimation);
        w.f64(m.duration);
    }
    void operator()(const EmergencyHoldMsg& m) { w.str(m.reason); }
    void namedValues(const std::vector<std::string>& names, const std::vector<double>& values) {
        const std::size_t n = std::min({names.size(), values.size(), kMaxUpdateParameters});
        w.u16(static_cast<std::uint16_t>(n));
        for (std::size_t i = 0; i < n; ++i) {
            w.str(names[i]);
            w.f64(values[i]);
        }
    }
    void operator()(const RthsUpdateMsg& m) { namedValues(m.names, m.values); }
    void operator()(const RthsUpdateAppliedMsg& m) {
        w.u64(m.tick);
        w.u8(m.applied ? 1 : 0);
        w.str(m.message);
        namedValues(m.names, m.values);
    }
    void operator()(const RthsProposalMsg& m) {
        w.u32(m.id);
        w.u64(m.tick);
        w.u8(m.decision);
        w.f64(m.fitError);
        w.str(m.message);
        namedValues(m.names, m.values);
    }
    void operator()(const RthsDecisionMsg& m) {
        w.u32(m.id);
        w.u8(m.approve ? 1 : 0);
    }
    void operator()(const TelemetryMsg& m) {
        w.u64(m.tick);
        for (double v : {m.time, m.desired, m.command, m.measured, m.force})
            w.f64(v);
        w.u64(m.misses);
        w.f64(m.worstLateness);
        w.u64(m.dropped);
        w.u8(m.holding ? 1 : 0);
        w.str(m.holdReason);
    }
    void operator()(const RthsEndMsg& m) {
        w.u64(m.ticks);
        for (double v : m.j)
            w.f64(v);
        w.u64(m.misses);
        w.f64(m.worstLateness);
        w.u64(m.telemetrySent);
        w.u64(m.telemetryDropped);
        for (double v : {m.peakForce, m.peakStroke, m.peakVelocity, m.trackingIndicator,
                         m.frequencyAmplitude, m.frequencyDelay, m.frequency})
            w.f64(v);
        w.str(m.hold);
    }
    void operator()(const TargetsMsg& m) {
        w.u64(m.step);
        w.u16(static_cast<std::uint16_t>(m.channels.size()));
        for (const ChannelTarget& c : m.channels) {
            w.u8(c.mode);
            w.f64(c.command);
        }
    }
    void operator()(const MeasurementsMsg& m) {
        w.u64(m.step);
        w.u32(m.flags);
        w.u16(static_cast<std::uint16_t>(m.channels.size()));
        for (const ChannelMeasurement& c : m.channels)
            for (double v : {c.stroke, c.force, c.command})
                w.f64(v);
    }
};

/// A channel count field: 2..kMaxChannels.
bool channelCount(Reader& r, std::uint16_t& n) {
    return r.u16(n) && n >= 2 && n <= kMaxChannels;
}

/// u16 count (at most kMaxUpdateParameters), count x (str name, f64 value).
bool readNamedValues(Reader& r, std::vector<std::string>& names, std::vector<double>& values) {
    std::uint16_t n = 0;
    if (!r.u16(n) || n > kMaxUpdateParameters)
        return false;
    names.resize(n);
    values.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        if (!r.str(names[i]) || !r.f64(values[i]))
            return false;
    return true;
}

bool decodeInto(MessageType t, Reader& r, Message& out) {
    switch (t) {
    case MessageType::Hello: {
        HelloMsg m;
        if (!r.u16(m.version) || !r.u64(m.sessionId) || !r.str(m.token) || !r.str(m.element))
            return false;
        out = std::move(m);
        return true;
    }
    case MessageType::HelloAck: {
        HelloAckMsg m;
        if (!r.u16(m.version) || !r.u64(m.committedSteps) || !r.f64(m.lastCommittedTarget) ||
            !r.boolean(m.holding) || !r.str(m.element) || !r.str(m.description) ||
            !r.str(m.holdReason))
            return false;
        if (!r.atEnd()) { // an N-channel specimen's tail
            std::uint16_t n = 0;
            if (!channelCount(r, n))
                return false;
            m.channelCommands.resize(n);
            for (double& c : m.channelCommands)
                if (!r.f64(c))
                    return false;
        }
        out = std::move(m);
        return true;
    }
    case MessageType::Configure: {
        ConfigureMsg m;
        if (!r.f64(m.dt) || !r.f64(m.maxDeformation) || !r.f64(m.maxForce) ||
            !r.f64(m.maxIncrement))
            return false;
        out = m;
        return true;
    }
    case MessageType::Target: {
        TargetMsg m;
        if (!r.u64(m.step) || !r.f64(m.deformation))
            return false;
        out = m;
        return true;
    }
    case MessageType::Measurement: {
        MeasurementMsg m;
        if (!r.u64(m.step) || !r.f64(m.deformation) || !r.f64(m.force) || !r.f64(m.commanded) ||
            !r.u32(m.heldTicks) || !r.u32(m.flags))
            return false;
        out = m;
        return true;
    }
    case MessageType::Commit: {
        CommitMsg m;
        if (!r.u64(m.step))
            return false;
        out = m;
        return true;
    }
    case MessageType::Ack: {
        AckMsg m;
        std::uint16_t acked = 0;
        if (!r.u16(acked) || !isKnownMessageType(acked) || !r.u64(m.step))
            return false;
        m.acked = static_cast<MessageType>(acked);
        out = m;
        return true;
    }
    case MessageType::Hold: {
        HoldMsg m;
        if (!r.str(m.reason))
            return false;
        out = std::move(m);
        return true;
    }
    case MessageType::Resume:
        out = ResumeMsg{};
        return true;
    case MessageType::Reset:
        out = ResetMsg{};
        return true;
    case MessageType::Heartbeat: {
        HeartbeatMsg m;
        if (!r.u64(m.nonce))
            return false;
        out = m;
        return true;
    }
    case MessageType::Error: {
        ErrorMsg m;
        std::uint16_t code = 0;
        if (!r.u16(code) || !r.str(m.reason))
            return false;
        m.code = static_cast<ErrorCode>(code);
        out = std::move(m);
        return true;
    }
    case MessageType::Bye: {
        ByeMsg m;
        if (!r.str(m.reason))
            return false;
        out = std::move(m);
        return true;
    }
    case MessageType::RthsStart: {
        RthsStartMsg m;
        if (!r.u32(m.decimation) || !r.f64(m.duration))
            return false;
        out = m;
        return true;
    }
    case MessageType::EmergencyHold: {
        EmergencyHoldMsg m;
        if (!r.str(m.reason))
            return false;
        out = std::move(m);
        return true;
    }
    case MessageType::Telemetry: {
        TelemetryMsg m;
        if (!r.u64(m.tick) || !r.f64(m.time) || !r.f64(m.desired) || !r.f64(m.command) ||
            !r.f64(m.measured) || !r.f64(m.force) || !r.u64(m.misses) ||
            !r.f64(m.worstLateness) || !r.u64(m.dropped) || !r.boolean(m.holding) ||
            !r.str(m.holdReason))
            return false;
        out = std::move(m);
        return true;
    }
    case MessageType::RthsUpdate: {
        RthsUpdateMsg m;
        if (!readNamedValues(r, m.names, m.values) || m.names.empty())
            return false;
        out = std::move(m);
        return true;
    }
    case MessageType::RthsUpdateApplied: {
        RthsUpdateAppliedMsg m;
        if (!r.u64(m.tick) || !r.boolean(m.applied) || !r.str(m.message) ||
            !readNamedValues(r, m.names, m.values))
            return false;
        out = std::move(m);
        return true;
    }
    case MessageType::RthsProposal: {
        RthsProposalMsg m;
        if (!r.u32(m.id) || !r.u64(m.tick) || !r.u8(m.decision) || !r.f64(m.fitError) || !r.str(m.message) ||
            !readNamedValues(r, m.names, m.values))
            return false;
        out = std::move(m);
        return true;
    }
    case MessageType::RthsDecision: {
        RthsDecisionMsg m;
        if (!r.u32(m.id) || !r.boolean(m.approve))
            return false;
        out = std::move(m);
        return true;
    }
    case MessageType::RthsEnd: {
        RthsEndMsg m;
        if (!r.u64(m.ticks))
            return false;
        for (double& v : m.j)
            if (!r.f64(v))
                return false;
        if (!r.u64(m.misses) || !r.f64(m.worstLateness) || !r.u64(m.telemetrySent) ||
            !r.u64(m.telemetryDropped))
            return false;
        for (double* v : {&m.peakForce, &m.peakStroke, &m.peakVelocity, &m.trackingIndicator,
                          &m.frequencyAmplitude, &m.frequencyDelay, &m.frequency})
            if (!r.f64(*v))
                return false;
        if (!r.str(m.hold))
            return false;
        out = std::move(m);
        return true;
    }
    case MessageType::Targets: {
        TargetsMsg m;
        std::uint16_t n = 0;
        if (!r.u64(m.step) || !channelCount(r, n))
            return false;
        m.channels.resize(n);
        for (ChannelTarget& c : m.channels)
            if (!r.u8(c.mode) || c.mode > kChannelForce || !r.f64(c.command))
                return false;
        out = std::move(m);
        return true;
    }
    case MessageType::Measurements: {
        MeasurementsMsg m;
        std::uint16_t n = 0;
        if (!r.u64(m.step) || !r.u32(m.flags) || !channelCount(r, n))
            return false;
        m.channels.resize(n);
        for (ChannelMeasurement& c : m.channels)
            if (!r.f64(c.stroke) || !r.f64(c.force) || !r.f64(c.command))
                return false;
        out = std::move(m);
        return true;
    }
    }
    return false;
}

} // namespace

void encodeRawFrame(const FrameHeader& h, const std::vector<std::uint8_t>& payload,
                    std::vector<std::uint8_t>& out) {
    Writer w(out);
    w.u32(h.magic);
    w.u16(h.version);
    w.u16(h.type);
    w.u32(h.sequence);
    w.u32(h.length);
    out.insert(out.end(), payload.begin(), payload.end());
}

void encodeFrame(const Message& m, std::uint32_t sequence, std::vector<std::uint8_t>& out) {
    const std::size_t start = out.size();
    Writer w(out);
    w.u32(kFrameMagic);
    w.u16(kProtocolVersion);
    w.u16(static_cast<std::uint16_t>(messageTypeOf(m)));
    w.u32(sequence);
    w.u32(0); // length, patched below
    std::visit(Encoder{w}, m);
    const auto length = static_cast<std::uint32_t>(out.size() - start - kHeaderSize);
    for (int i = 0; i < 4; ++i)
        out[start + 12 + i] = static_cast<std::uint8_t>(length >> (8 * i));
}

FrameHeader readHeader(const std::uint8_t* p) {
    auto le = [p](int at, int bytes) {
        std::uint32_t v = 0;
        for (int i = 0; i < bytes; ++i)
            v |= std::uint32_t(p[at + i]) << (8 * i);
        return v;
    };
    FrameHeader h;
    h.magic = le(0, 4);
    h.version = static_cast<std::uint16_t>(le(4, 2));
    h.type = static_cast<std::uint16_t>(le(6, 2));
    h.sequence = le(8, 4);
    h.length = le(12, 4);
    return h;
}

CodecError checkHeader(const FrameHeader& h) {
    if (h.magic != kFrameMagic)
        return CodecError::fail(ErrorCode::Malformed, "bad magic (not an HSMU frame)");
    if (h.version != kProtocolVersion)
        return CodecError::fail(ErrorCode::UnsupportedVersion,
                                "protocol version " + std::to_string(h.version) +
                                    " is not supported (this side speaks version " +
                                    std::to_string(kProtocolVersion) + ")");
    if (!isKnownMessageType(h.type))
        return CodecError::fail(ErrorCode::Malformed,
                                "unknown message type " + std::to_string(h.type));
    const Bounds b = boundsOf(static_cast<MessageType>(h.type));
    if (h.length < b.min || h.length > b.max || h.length > kMaxPayload)
        return CodecError::fail(ErrorCode::Malformed,
                                std::string(messageTypeName(static_cast<MessageType>(h.type))) +
                                    " payload of " + std::to_string(h.length) +
                                    " bytes is outside " + std::to_string(b.min) + ".." +
                                    std::to_string(b.max));
    return CodecError::none();
}

CodecError decodePayload(MessageType type, const std::uint8_t* p, std::size_t size, Message& out) {
    Reader r(p, size);
    if (!decodeInto(type, r, out))
        return CodecError::fail(ErrorCode::Malformed,
                                std::string(messageTypeName(type)) +
                                    " payload does not parse (a field is missing or out of range)");
    if (!r.atEnd())
        return CodecError::fail(ErrorCode::Malformed,
                                std::string(messageTypeName(type)) + " payload has trailing bytes");
    return CodecError::none();
}

} // namespace hsmu::comms
