#include "comms/openfresco/OfFrame.h"

#include <cmath>
#include <cstring>

namespace hsmu::comms::of {

const char* actionName(Action a) {
    switch (a) {
    case Action::Open:
        return "open";
    case Action::Setup:
        return "setup";
    case Action::SetTrialResponse:
        return "setTrialResponse";
    case Action::Execute:
        return "execute";
    case Action::CommitState:
        return "commitState";
    case Action::GetDaqResponse:
        return "getDaqResponse";
    case Action::GetDisp:
        return "getDisp";
    case Action::GetVel:
        return "getVel";
    case Action::GetAccel:
        return "getAccel";
    case Action::GetForce:
        return "getForce";
    case Action::GetTime:
        return "getTime";
    case Action::GetInitialStiff:
        return "getInitialStiff";
    case Action::GetTangentStiff:
        return "getTangentStiff";
    case Action::GetDamp:
        return "getDamp";
    case Action::GetMass:
        return "getMass";
    case Action::Terminate:
        return "terminate";
    }
    return "?";
}

std::optional<Action> actionOf(double code) {
    if (!std::isfinite(code) || code != std::floor(code))
        return std::nullopt;
    if ((code >= 1.0 && code <= 15.0) || code == 99.0)
        return static_cast<Action>(static_cast<int>(code));
    return std::nullopt;
}

bool encodeFrame(std::span<const double> values, int dataSize, std::vector<std::uint8_t>& out,
                 std::string& error) {
    if (dataSize < 1) {
        error = "dataSize must be positive";
        return false;
    }
    if (values.size() > static_cast<std::size_t>(dataSize)) {
        error = std::to_string(values.size()) + " values do not fit a frame of dataSize " +
                std::to_string(dataSize);
        return false;
    }
    out.assign(static_cast<std::size_t>(dataSize) * sizeof(double), 0);
    if (!values.empty())
        std::memcpy(out.data(), values.data(), values.size() * sizeof(double));
    return true;
}

bool encodeRequest(Action a, std::span<const double> values, int dataSize,
                   std::vector<std::uint8_t>& out, std::string& error) {
    std::vector<double> v;
    v.reserve(values.size() + 1);
    v.push_back(static_cast<double>(static_cast<int>(a)));
    v.insert(v.end(), values.begin(), values.end());
    return encodeFrame(v, dataSize, out, error);
}

void decodeFrame(const std::uint8_t* bytes, int dataSize, std::vector<double>& out) {
    out.resize(static_cast<std::size_t>(dataSize));
    std::memcpy(out.data(), bytes, out.size() * sizeof(double));
}

bool encodeInitLine(const std::string& line, std::vector<std::uint8_t>& out, std::string& error) {
    if (line.size() >= kInitLineBytes) {
        error = "an init line has " + std::to_string(line.size()) + " bytes, more than " +
                std::to_string(kInitLineBytes - 1);
        return false;
    }
    if (line.find('\0') != std::string::npos) {
        error = "an init line holds a NUL character";
        return false;
    }
    out.assign(kInitLineBytes, 0);
    std::memcpy(out.data(), line.data(), line.size());
    return true;
}

std::string decodeInitLine(const std::uint8_t* bytes) {
    const void* nul = std::memchr(bytes, 0, kInitLineBytes);
    const std::size_t n =
        nul ? static_cast<std::size_t>(static_cast<const std::uint8_t*>(nul) - bytes)
            : kInitLineBytes;
    return std::string(reinterpret_cast<const char*>(bytes), n);
}

bool startsWithAction(const std::uint8_t* first8) {
    double code;
    std::memcpy(&code, first8, sizeof code);
    return actionOf(code).has_value();
}

bool startsWithCode(const std::uint8_t* first8) {
    double code;
    std::memcpy(&code, first8, sizeof code);
    return code != 0.0 && std::abs(code) < 2147483648.0 && code == std::trunc(code);
}

} // namespace hsmu::comms::of
