#pragma once
// Protocol: constants of the native console <-> hsmu-controller protocol (docs/protocol.md).
//
// Every frame is a 16-byte header followed by a payload, all little-endian:
//
//   offset size field
//   0      4    magic        0x554D5348 (the bytes 'H' 'S' 'M' 'U' on the wire)
//   4      2    version      kProtocolVersion (1)
//   6      2    type         MessageType
//   8      4    sequence     per sender and connection: 1, 2, 3, ... (wraps after 2^32 - 1 to 0)
//   12     4    length       payload bytes, <= kMaxPayload and within the type's bounds
//
// A frame that breaks any rule (magic, version, unknown type, a length outside the type's
// bounds, a payload that does not parse to exactly its length) is answered with an Error
// frame and the connection is closed. Nothing is allocated from a length before it has been
// checked against kMaxPayload.

#include <cstddef>
#include <cstdint>

namespace hsmu::comms {

inline constexpr std::uint32_t kFrameMagic = 0x554D5348u; // "HSMU" in little-endian order
inline constexpr std::uint16_t kProtocolVersion = 1;
inline constexpr std::size_t kHeaderSize = 16;
inline constexpr std::size_t kMaxPayload = 4096;     ///< bytes, any message
inline constexpr std::size_t kMaxStringBytes = 1024; ///< bytes of one UTF-8 string field

/// Message types (header field `type`). Values are part of the protocol: never renumber.
enum class MessageType : std::uint16_t {
    Hello = 1,       ///< console -> controller: version, session id, token, element
    HelloAck = 2,    ///< controller -> console: committed steps, hold state, description
    Configure = 3,   ///< console -> controller: dt and the console's limits
    Target = 4,      ///< console -> controller: step index, target deformation
    Measurement = 5, ///< controller -> console: step, measured deformation and force
    Commit = 6,      ///< console -> controller: the step is accepted
    Ack = 7,         ///< controller -> console: Configure / Commit / Hold / Resume / Reset done
    Hold = 8,        ///< console -> controller: hold the actuator, refuse targets
    Resume = 9,      ///< console -> controller: leave the hold
    Reset = 10,      ///< console -> controller: a fresh (virgin) specimen, step count 0
    Heartbeat = 11,  ///< either way; the controller echoes the console's nonce
    Error = 12,      ///< either way: code and reason text
    Bye = 13,        ///< either way: orderly close, no reply
    // The controller-side RTHS loop (hsmu-controller --rths; docs/rths.md, "The loop on the
    // controller"). Older peers refuse these as unknown types (malformed), as any new type.
    RthsStart = 14,     ///< monitor -> controller: start the loop (telemetry decimation, duration)
    EmergencyHold = 15, ///< monitor -> controller: hold the loop before its next tick, at once
    Telemetry = 16,     ///< controller -> monitor: one decimated tick of the running loop
    RthsEnd = 17,       ///< controller -> monitor: the run's end and its summary (J1..J9, ...)
    // N actuator channels of one specimen (a link2d specimen behind a setup; docs/protocol.md,
    // "Several actuator channels"). Older peers refuse them as unknown types, as any new type.
    Targets = 18,      ///< console -> controller: step index, each channel's mode and command
    Measurements = 19, ///< controller -> console: step, each channel's stroke, force, command
    RthsUpdate = 20,        ///< monitor -> controller: new parameters for the damper's twin
    RthsUpdateApplied = 21, ///< controller -> monitor: a twin update decided at a tick
    RthsProposal = 22,      ///< controller -> monitor: a twin update proposed / decided (approval)
    RthsDecision = 23,      ///< monitor -> controller: approve or reject a proposal
};

/// Channels of one specimen a Targets / Measurements frame may carry (2..kMaxChannels; a
/// one-channel specimen uses Target / Measurement).
inline constexpr std::size_t kMaxChannels = 16;
/// The mode byte of a channel in Targets: its command is a stroke [m] or a force [kN].
inline constexpr std::uint8_t kChannelDisplacement = 0;
inline constexpr std::uint8_t kChannelForce = 1;

/// Error frame codes. "Closes" means the sender closes the connection after the frame.
enum class ErrorCode : std::uint16_t {
    Malformed = 1,          ///< bad magic, length, payload or unknown type (closes)
    UnsupportedVersion = 2, ///< header or hello version is not kProtocolVersion (closes)
    Unauthorized = 3,       ///< wrong token (closes)
    Busy = 4,               ///< another console session holds the controller (closes)
    UnknownElement = 5,     ///< the hello names no specimen the controller has (closes)
    ProtocolViolation = 6,  ///< out-of-order message or sequence number, wrong step index
    Interlock = 7,          ///< a limit tripped: the specimen holds; the text names the limit
    Holding = 8,            ///< a target arrived while the specimen holds
    SpecimenFault = 9,      ///< the specimen's law failed; the specimen holds
    NotConfigured = 10,     ///< a target before Configure
    StateMismatch = 11,     ///< a re-sent target differs from the one already committed
    Timeout = 12,           ///< no hello, or silence past the idle timeout (closes)
    Internal = 13,          ///< anything else (e.g. the state file cannot be written)
    UpdateRefused = 14,     ///< an rths-update refused (unknown name, not finite, out of the box)
};

/// Measurement flags (bit field).
inline constexpr std::uint32_t kFlagFractured = 1u << 0; ///< the fracture event has happened
inline constexpr std::uint32_t kFlagReplayed = 1u << 1;  ///< a repeated answer, not a new trial

/// Words for logs ("target", "interlock", ...); "unknown" for other values.
const char* messageTypeName(MessageType type);
const char* errorCodeName(ErrorCode code);
/// True for the values listed above.
bool isKnownMessageType(std::uint16_t type);

} // namespace hsmu::comms
