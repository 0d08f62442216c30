#include "comms/protocol/Messages.h"

#include <type_traits>

namespace hsmu::comms {

const char* messageTypeName(MessageType type) {
    switch (type) {
    case MessageType::Hello:
        return "hello";
    case MessageType::HelloAck:
        return "hello-ack";
    case MessageType::Configure:
        return "configure";
    case MessageType::Target:
        return "target";
    case MessageType::Measurement:
        return "measurement";
    case MessageType::Commit:
        return "commit";
    case MessageType::Ack:
        return "ack";
    case MessageType::Hold:
        return "hold";
    case MessageType::Resume:
        return "resume";
    case MessageType::Reset:
        return "reset";
    case MessageType::Heartbeat:
        return "heartbeat";
    case MessageType::Error:
        return "error";
    case MessageType::Bye:
        return "bye";
    case MessageType::RthsStart:
        return "rths-start";
    case MessageType::EmergencyHold:
        return "emergency-hold";
    case MessageType::Telemetry:
        return "telemetry";
    case MessageType::RthsEnd:
        return "rths-end";
    case MessageType::Targets:
        return "targets";
    case MessageType::Measurements:
        return "measurements";
    case MessageType::RthsUpdate:
        return "rths-update";
    case MessageType::RthsUpdateApplied:
        return "rths-update-applied";
    case MessageType::RthsProposal:
        return "rths-proposal";
    case MessageType::RthsDecision:
        return "rths-decision";
    }
    return "unknown";
}

const char* errorCodeName(ErrorCode code) {
    switch (code) {
    case ErrorCode::Malformed:
        return "malformed frame";
    case ErrorCode::UnsupportedVersion:
        return "unsupported version";
    case ErrorCode::Unauthorized:
        return "unauthorized";
    case ErrorCode::Busy:
        return "busy";
    case ErrorCode::UnknownElement:
        return "unknown element";
    case ErrorCode::ProtocolViolation:
        return "protocol violation";
    case ErrorCode::Interlock:
        return "interlock";
    case ErrorCode::Holding:
        return "holding";
    case ErrorCode::SpecimenFault:
        return "specimen fault";
    case ErrorCode::NotConfigured:
        return "not configured";
    case ErrorCode::StateMismatch:
        return "state mismatch";
    case ErrorCode::Timeout:
        return "timeout";
    case ErrorCode::Internal:
        return "internal error";
    case ErrorCode::UpdateRefused:
        return "update refused";
    }
    return "unknown";
}

bool isKnownMessageType(std::uint16_t type) {
    return type >= static_cast<std::uint16_t>(MessageType::Hello) &&
           type <= static_cast<std::uint16_t>(MessageType::RthsDecision);
}

MessageType messageTypeOf(const Message& m) {
    // The variant's alternatives are in the order of the MessageType values 1..23.
    static_assert(std::variant_size_v<Message> == 23);
    static_assert(std::is_same_v<std::variant_alternative_t<12, Message>, ByeMsg>);
    static_assert(std::is_same_v<std::variant_alternative_t<16, Message>, RthsEndMsg>);
    static_assert(std::is_same_v<std::variant_alternative_t<18, Message>, MeasurementsMsg>);
    static_assert(std::is_same_v<std::variant_alternative_t<20, Message>, RthsUpdateAppliedMsg>);
    static_assert(std::is_same_v<std::variant_alternative_t<22, Message>, RthsDecisionMsg>);
    return static_cast<MessageType>(m.index() + 1);
}

} // namespace hsmu::comms
