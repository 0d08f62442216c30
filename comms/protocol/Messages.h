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
#include <vector>
#include <variant>
#include <vector>

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
    /// A specimen of N >= 2 actuator channels (optional tail: u16 N, N x f64): the last
    /// committed command of each channel; empty for a one-channel specimen (no tail, so the
    /// frame is byte for byte what a one-channel console has always read).
    std::vector<double> channelCommands;
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

// The controller-side RTHS loop (docs/protocol.md, "RTHS monitoring"; docs/rths.md). A Hold
// (8) from the monitor holds the loop too; lengths [m], forces [N], times [s] (SI: the RTHS
// loop's units, not a specimen's).

struct RthsStartMsg {              // payload: u32 f64
    std::uint32_t decimation = 0;  ///< one telemetry frame every this many ticks; 0: the
                                   ///< controller's default (about 128 frames per second)
    double duration = 0.0;         ///< stop after this many seconds; 0: the whole record
};

struct EmergencyHoldMsg { // payload: str
    std::string reason;
};

struct TelemetryMsg {             // payload: u64 f64 x 5 u64 f64 u64 u8 str
    std::uint64_t tick = 0;       ///< k: the loop's tick (t = k h)
    double time = 0.0;            ///< [s]
    double desired = 0.0;         ///< the numerical substructure's displacement y [m]
    double command = 0.0;         ///< x* after compensation [m]
    double measured = 0.0;        ///< xm [m]
    double force = 0.0;           ///< fm [N]
    std::uint64_t misses = 0;     ///< deadline misses so far
    double worstLateness = 0.0;   ///< [s]
    std::uint64_t dropped = 0;    ///< telemetry frames dropped so far (a slow monitor)
    bool holding = false;         ///< a hold was asked for or the loop stopped on one
    std::string holdReason;
};

struct RthsEndMsg {                      // payload: u64 f64 x 9 u64 f64 u64 u64 f64 x 7 str
    std::uint64_t ticks = 0;             ///< ticks run (sampled)
    double j[9] = {};                    ///< J1 [ms], J2..J9 [%] (RthsBenchmark.h)
    std::uint64_t misses = 0;            ///< deadline misses
    double worstLateness = 0.0;          ///< [s]
    std::uint64_t telemetrySent = 0;     ///< frames queued for the monitor
    std::uint64_t telemetryDropped = 0;  ///< frames dropped (queue full or no monitor)
    double peakForce = 0.0, peakStroke = 0.0, peakVelocity = 0.0; ///< [N], [m], [m/s]
    double trackingIndicator = 0.0;      ///< [m^2]
    double frequencyAmplitude = 0.0, frequencyDelay = 0.0, frequency = 0.0; ///< -, [ms], [Hz]
    std::string hold;                    ///< why the run stopped early; "" when it ran out
};

// N actuator channels of one specimen (docs/protocol.md, "Several actuator channels"): the
// stroke of a displacement-controlled channel in [m], the force of a force-controlled one [kN].

struct ChannelTarget {
    std::uint8_t mode = kChannelDisplacement; ///< kChannelDisplacement | kChannelForce
    double command = 0.0;                     ///< stroke [m] or force [kN]
};

struct TargetsMsg { // payload: u64 u16 N x (u8 f64); 2 <= N <= kMaxChannels
    std::uint64_t step = 0;
    std::vector<ChannelTarget> channels;
};

struct ChannelMeasurement {
    double stroke = 0.0;  ///< measured [m]
    double force = 0.0;   ///< measured [kN]
    double command = 0.0; ///< the channel's command when the step was measured
};

struct MeasurementsMsg { // payload: u64 u32 u16 N x (f64 f64 f64); 2 <= N <= kMaxChannels
    std::uint64_t step = 0;
    std::uint32_t flags = 0; ///< kFlagReplayed
    std::vector<ChannelMeasurement> channels;
};

/// Most parameters one update names (an mrDamper twin has 12).
inline constexpr std::size_t kMaxUpdateParameters = 32;

struct RthsUpdateMsg {             // payload: u16 count, count x (str name, f64 value)
    std::vector<std::string> names; ///< the twin's parameters (MrDamper's names)
    std::vector<double> values;     ///< in the twin's scales (docs/rths.md)
};

struct RthsUpdateAppliedMsg {      // payload: u64 u8 str u16 count x (str f64)
    std::uint64_t tick = 0;        ///< the tick the update came before
    bool applied = false;          ///< false: refused by the loop (message says why)
    std::string message;           ///< its source ("operator", "identification") or the refusal
    std::vector<std::string> names;
    std::vector<double> values;
};

/// The approval queue of the twin's updates (docs/rths.md, "Proposals approved by the console").
struct RthsProposalMsg {           // payload: u32 u64 u8 f64 str u16 count x (str f64)
    std::uint32_t id = 0;          ///< the proposal's id (1, 2, ... per run)
    std::uint64_t tick = 0;        ///< the tick before which the decision was taken
    std::uint8_t decision = 0;     ///< UpdateDecision's index: proposed, superseded, rejected,
                                   ///< refused (never applied) or applied
    double fitError = 0.0;         ///< [-] of the estimate when proposed; NaN: none
    std::string message;           ///< its source, or why (superseded by #N, the refusal)
    std::vector<std::string> names;
    std::vector<double> values;    ///< proposed, in the twin's scales
};

struct RthsDecisionMsg {           // payload: u32 id, u8 approve
    std::uint32_t id = 0;
    bool approve = false;          ///< false: reject
};

using Message =
    std::variant<HelloMsg, HelloAckMsg, ConfigureMsg, TargetMsg, MeasurementMsg, CommitMsg, AckMsg,
                 HoldMsg, ResumeMsg, ResetMsg, HeartbeatMsg, ErrorMsg, ByeMsg, RthsStartMsg,
                 EmergencyHoldMsg, TelemetryMsg, RthsEndMsg, TargetsMsg, MeasurementsMsg,
                 RthsUpdateMsg, RthsUpdateAppliedMsg, RthsProposalMsg, RthsDecisionMsg>;

/// The header type of a message.
MessageType messageTypeOf(const Message& m);

} // namespace hsmu::comms
