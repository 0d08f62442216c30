#pragma once
// FrameCodec: encode a Message into a frame, parse and check a header, decode a payload.
// Pure functions on bytes: no sockets, no allocation beyond the output (a payload is at most
// kMaxPayload bytes). Layouts in Protocol.h, Messages.h and docs/protocol.md.
// Thread rules: none (no shared state).

#include "comms/protocol/Messages.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace hsmu::comms {

struct FrameHeader {
    std::uint32_t magic = kFrameMagic;
    std::uint16_t version = kProtocolVersion;
    std::uint16_t type = 0;
    std::uint32_t sequence = 0;
    std::uint32_t length = 0; ///< payload bytes
};

/// Why a frame was refused (ok == true: it was not).
struct CodecError {
    bool ok = true;
    ErrorCode code = ErrorCode::Malformed;
    std::string reason;
    static CodecError none() { return {}; }
    static CodecError fail(ErrorCode c, std::string why) { return {false, c, std::move(why)}; }
};

/// Append the frame of m (header + payload) to out. Strings longer than kMaxStringBytes are
/// cut at a UTF-8 character boundary, so every encoded frame is valid.
void encodeFrame(const Message& m, std::uint32_t sequence, std::vector<std::uint8_t>& out);
/// Append a frame with arbitrary header fields and payload bytes (tests, fuzzing seeds).
void encodeRawFrame(const FrameHeader& h, const std::vector<std::uint8_t>& payload,
                    std::vector<std::uint8_t>& out);

/// Read the 16 header bytes at p (no checks).
FrameHeader readHeader(const std::uint8_t* p);
/// Check magic, version, type and the length against the type's bounds.
CodecError checkHeader(const FrameHeader& h);
/// Decode exactly `size` payload bytes of a message of the given (checked) type into out:
/// every field present, strings within bounds and the payload, no trailing bytes.
CodecError decodePayload(MessageType type, const std::uint8_t* p, std::size_t size, Message& out);

} // namespace hsmu::comms
