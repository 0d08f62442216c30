#include "comms/link/ControlFactory.h"

#include <chrono>
#include <random>

namespace hsmu::comms {

std::uint64_t newSessionId() {
    std::random_device rd;
    std::uint64_t id = (std::uint64_t(rd()) << 32) ^ rd() ^
                       std::uint64_t(std::chrono::steady_clock::now().time_since_epoch().count());
    return id == 0 ? 1 : id;
}

ControlFactory makeControlFactory(const LinkAddress& address, const TcpControlOptions& options) {
    if (address.kind == LinkAddress::Kind::Builtin)
        return {};
    TcpControlOptions o = options;
    if (o.sessionId == 0)
        o.sessionId = newSessionId();
    return [address, o](const ElementSpec& spec) -> std::unique_ptr<ExperimentalControl> {
        return std::make_unique<TcpControl>(address.host, address.port, spec.name, spec.limits, o);
    };
}

} // namespace hsmu::comms
