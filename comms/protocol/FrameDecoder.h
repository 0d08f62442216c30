#pragma once
// FrameDecoder: turns a TCP byte stream into frames, incrementally. Bytes arrive in any
// chunking; the header is checked as soon as its 16 bytes are in (so an oversize length is
// refused before its payload is waited for), the payload when it is complete.
//
// Memory: the buffer holds at most one unfinished frame (<= kHeaderSize + kMaxPayload bytes)
// plus the last chunk appended; callers drain next() after each append().
// After the first error the decoder stays failed (the connection is to be closed) and
// next() keeps returning Status::Error.
// Sequence numbers: when checkSequence is on, every frame must carry the previous one's
// number + 1 and the first must carry 1 (docs/protocol.md); a gap, another first number or a
// frame after 0xFFFFFFFF (no wrap to 0) is a ProtocolViolation.
// Thread rules: one thread at a time.

#include "comms/protocol/FrameCodec.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace hsmu::comms {

struct Frame {
    std::uint32_t sequence = 0;
    Message message;
};

class FrameDecoder {
public:
    enum class Status { Frame, NeedMore, Error };

    explicit FrameDecoder(bool checkSequence = true) : m_checkSequence(checkSequence) {}

    /// Append received bytes.
    void append(const std::uint8_t* data, std::size_t size);
    /// The next complete frame, NeedMore, or Error (then see error()).
    Status next(Frame& out);
    /// Why decoding failed (code and a sentence), valid after Status::Error.
    const CodecError& error() const { return m_error; }
    bool failed() const { return !m_error.ok; }
    std::size_t buffered() const { return m_buffer.size() - m_start; }

private:
    Status fail(CodecError e);
    std::vector<std::uint8_t> m_buffer;
    std::size_t m_start = 0;             // first unconsumed byte
    std::optional<FrameHeader> m_header; // checked header of the frame in progress
    bool m_checkSequence;
    std::optional<std::uint32_t> m_lastSequence;
    CodecError m_error;
};

} // namespace hsmu::comms
