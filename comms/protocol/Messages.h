#pragma once
// Messages: the payloads of the native protocol as plain structs (docs/protocol.md has the
// byte layouts). Encoding is little-endian: u16/u32/u64 integers, f64 = IEEE 754 binary64
// bit pattern, str = u16 byte count + UTF-8 bytes (<= kMaxStringBytes, no terminator).
// Deformations and forces are in the specimen's units (rad and kN m for a rotational spring,
// m and kN for a lateral one); times in seconds. A limit of +inf (or <= 0) is disabled.
//
// Step indices count the specimen's committed steps over its life: the target for step
// committedSteps + 1 is the next trial; re-sending the target of an uncommitted step, or of
// the last committed one, is answered idempotently (docs/method.md, The lab loop;
// docs/protocol.md).

#include "comms/protocol/Protocol.h"

#include <cstdint>
#include <limits>
#include <string>
#include <variant>

namespace hsmu::comms {

struct HelloMsg {                             // payload: u16 u64 str str
    std::uint16_t version = kProtocolVersion; ///< protocol version the console speaks
    std::uint64_t sessionId = 0;              ///< one console test; its reconnects reuse it
    std::string token;                        ///< shared secret ("" when none)
    std::string element;                      ///< specimen name ("" = the first one)
};

struct HelloAckMsg { // payload: u16 u64 f64 u8 str str str
    std::uint16_t version = kProtocolVersion;
    std::uint64_t committedSteps = 0; ///< steps the specimen has committed
    double lastCommittedTarget = 0.0; ///< target of that last committed step
    bool holding = false;
    std::string element;     ///< the specimen's name
    std::string description; ///< controller and specimen, for logs
    std::string holdReason;  ///< when holding
};

struct ConfigureMsg { // payload: f64 x 4
    double dt = 0.0;  ///< integration step [s], > 0
    double maxDeformation = std::numeric_limits<double>::infinity();
    double maxForce = std::numeric_limits<double>::infinity();
    double maxIncrement = std::numeric_limits<double>::infinity();
};

struct TargetMsg { // payload: u64 f64
    std::uint64_t step = 0;
    double deformation = 0.0;
};

struct MeasurementMsg { // payload: u64 f64 f64 f64 u32 u32
    std::uint64_t step = 0;
    double deformation = 0.0;    ///< measured (with sensor noise)
    double force = 0.0;          ///< measured (with sensor noise)
    double commanded = 0.0;      ///< actuator command when the step was measured
    std::uint32_t heldTicks = 0; ///< predictor-corrector ticks held waiting for it
    std::uint32_t flags = 0;     ///< kFlagFractured | kFlagReplayed
};

struct CommitMsg { // payload: u64
    std::uint64_t step = 0;
};

struct AckMsg { // payload: u16 u64
    MessageType acked = MessageType::Commit;
    std::uint64_t step = 0; ///< committed steps after the acknowledged message
};

struct HoldMsg { // payload: str
    std::string reason;
};

struct ResumeMsg {}; // empty payload
struct ResetMsg {};  // empty payload

struct HeartbeatMsg { // payload: u64
    std::uint64_t nonce = 0;
};

struct ErrorMsg { // payload: u16 str
    ErrorCode code = ErrorCode::Internal;
    std::string reason;
};

struct ByeMsg { // payload: str
    std::string reason;
};

using Message =
    std::variant<HelloMsg, HelloAckMsg, ConfigureMsg, TargetMsg, MeasurementMsg, CommitMsg, AckMsg,
                 HoldMsg, ResumeMsg, ResetMsg, HeartbeatMsg, ErrorMsg, ByeMsg>;

/// The header type of a message.
MessageType messageTypeOf(const Message& m);

} // namespace hsmu::comms
