#include "comms/protocol/FrameDecoder.h"

namespace hsmu::comms {

void FrameDecoder::append(const std::uint8_t* data, std::size_t size) {
    if (failed() || size == 0)
        return;
    // Compact first, so the buffer never holds more than one frame in progress + this chunk.
    if (m_start > 0) {
        m_buffer.erase(m_buffer.begin(), m_buffer.begin() + static_cast<std::ptrdiff_t>(m_start));
        m_start = 0;
    }
    m_buffer.insert(m_buffer.end(), data, data + size);
}

FrameDecoder::Status FrameDecoder::fail(CodecError e) {
    m_error = std::move(e);
    m_buffer.clear();
    m_buffer.shrink_to_fit();
    m_start = 0;
    return Status::Error;
}

FrameDecoder::Status FrameDecoder::next(Frame& out) {
    if (failed())
        return Status::Error;
    const std::size_t available = m_buffer.size() - m_start;
    if (!m_header) {
        if (available < kHeaderSize)
            return Status::NeedMore;
        const FrameHeader h = readHeader(m_buffer.data() + m_start);
        if (CodecError e = checkHeader(h); !e.ok)
            return fail(std::move(e));
        if (m_checkSequence && !m_lastSequence && h.sequence != 1u)
            return fail(CodecError::fail(ErrorCode::ProtocolViolation,
                                         "sequence number " + std::to_string(h.sequence) +
                                             " on the first frame (expected 1)"));
        if (m_checkSequence && m_lastSequence && *m_lastSequence == 0xFFFFFFFFu)
            return fail(CodecError::fail(ErrorCode::ProtocolViolation,
                                         "sequence numbers used up (2^32 - 1 frames): "
                                         "reconnect"));
        if (m_checkSequence && m_lastSequence && h.sequence != *m_lastSequence + 1u)
            return fail(CodecError::fail(ErrorCode::ProtocolViolation,
                                         "sequence number " + std::to_string(h.sequence) +
                                             " after " + std::to_string(*m_lastSequence)));
        m_header = h;
    }
    if (available < kHeaderSize + m_header->length)
        return Status::NeedMore;
    const auto type = static_cast<MessageType>(m_header->type);
    Message m;
    if (CodecError e =
            decodePayload(type, m_buffer.data() + m_start + kHeaderSize, m_header->length, m);
        !e.ok)
        return fail(std::move(e));
    out.sequence = m_header->sequence;
    out.message = std::move(m);
    m_lastSequence = m_header->sequence;
    m_start += kHeaderSize + m_header->length;
    m_header.reset();
    if (m_start == m_buffer.size()) {
        m_buffer.clear();
        m_start = 0;
    }
    return Status::Frame;
}

} // namespace hsmu::comms
