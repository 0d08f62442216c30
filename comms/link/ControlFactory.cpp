#include "comms/link/ControlFactory.h"

#include "comms/openfresco/AdapterControl.h"
#include "comms/openfresco/GenericTcpControl.h"
#include "comms/openfresco/OpenSeesTwinSite.h"
#include "comms/openfresco/SimAppControl.h"
#include "core/config/JsonCursor.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <random>

namespace hsmu::comms {

std::uint64_t newSessionId() {
    std::random_device rd;
    std::uint64_t id = (std::uint64_t(rd()) << 32) ^ rd() ^
                       std::uint64_t(std::chrono::steady_clock::now().time_since_epoch().count());
    return id == 0 ? 1 : id;
}

std::vector<std::pair<std::string, std::string>> siteSecurity(const LinkAddress& address,
                                                              const TestConfig& cfg) {
    std::vector<std::pair<std::string, std::string>> out{{kDefaultSiteName, address.security()}};
    for (const SiteSpec& site : cfg.sites) {
        const auto a = LinkAddress::parse(site.address);
        out.emplace_back(site.name, a ? a->security() : std::string("unknown"));
    }
    return out;
}

std::string linkProtocol(const LinkAddress& address, const LinkSpec& link) {
    switch (address.kind) {
    case LinkAddress::Kind::Builtin:
        return "builtin";
    case LinkAddress::Kind::SimApp:
        return "simapp";
    case LinkAddress::Kind::GenericTcp:
        return "generictcp";
    case LinkAddress::Kind::Adapter:
        return "adapter";
    case LinkAddress::Kind::Tls:
        return "native";
    case LinkAddress::Kind::Tcp:
        break;
    }
    return link.protocol;
}

ControlFactory makeControlFactory(const LinkAddress& address, const TcpControlOptions& options) {
    return makeControlFactory(address, options, LinkSpec{});
}

ControlFactory makeControlFactory(const LinkAddress& address, const TcpControlOptions& given,
                                  const LinkSpec& link) {
    const std::string protocol = linkProtocol(address, link);
    TcpControlOptions options = given; // the configuration's timeouts, when it sets them
    options.connectTimeout = link.connectTimeout.value_or(options.connectTimeout);
    options.stepDeadline = link.stepDeadline.value_or(options.stepDeadline);
    // Numerical elements on an OpenSees site, for every front end that builds through comms.
    of::installOpenSeesTwins({options.connectTimeout, options.stepDeadline});
    if (protocol == "builtin")
        return {};
    if (protocol == "simapp" || protocol == "generictcp" || protocol == "adapter") {
        of::OfControlOptions o;
        o.sizes.ctrl = link.ctrlSizes;
        o.sizes.daq = link.daqSizes;
        o.sizes.dataSize = link.dataSize;
        o.initLines = link.initLines;
        o.connectTimeout = options.connectTimeout;
        o.stepDeadline = options.stepDeadline;
        o.connectAttempts = std::max(1, options.reconnectAttempts);
        o.retryDelay = options.reconnectDelay;
        return [address, given = o,
                protocol](const ElementSpec& spec) -> std::unique_ptr<ExperimentalControl> {
            of::OfControlOptions o = given;
            // OpenFresco's sizes for a setup of N actuators (OpenFrescoControl.h).
            if (spec.link2d) {
                const int n = static_cast<int>(spec.link2d->actuators.size());
                bool force = false;
                for (const ActuatorSpec& a : spec.link2d->actuators) {
                    o.channelModes.push_back(a.channel.mode);
                    force = force || a.channel.mode == ActuatorMode::Force;
                }
                o.sizes.ctrl[static_cast<std::size_t>(of::Resp::Disp)] = n;
                o.sizes.ctrl[static_cast<std::size_t>(of::Resp::Force)] = force ? n : 0;
                o.sizes.daq[static_cast<std::size_t>(of::Resp::Disp)] = n;
                o.sizes.daq[static_cast<std::size_t>(of::Resp::Force)] = n;
            }
            if (protocol == "simapp")
                return std::make_unique<of::SimAppControl>(address.host, address.port, spec.name,
                                                           o);
            if (protocol == "adapter")
                return std::make_unique<of::AdapterControl>(address.host, address.port, spec.name,
                                                            o);
            return std::make_unique<of::GenericTcpControl>(address.host, address.port, spec.name,
                                                           o);
        };
    }
    TcpControlOptions o = options;
    if (o.sessionId == 0)
        o.sessionId = newSessionId();
    if (address.kind == LinkAddress::Kind::Tls) // no tls block: connecting says what is missing
        o.tls = link.tls.value_or(TlsSpec{});
    return [address, o](const ElementSpec& spec) -> std::unique_ptr<ExperimentalControl> {
        TcpControlOptions mine = o;
        if (spec.link2d) // N actuator channels: each one's mode; the limits are per channel
            for (const ActuatorSpec& a : spec.link2d->actuators)
                mine.channelModes.push_back(a.channel.mode);
        return std::make_unique<TcpControl>(address.host, address.port, spec.name, spec.limits,
                                            mine);
    };
}

ControlFactory makeControlFactory(const LinkAddress& address, const TcpControlOptions& options,
                                  const TestConfig& cfg) {
    ControlFactory fallback = makeControlFactory(address, options, cfg.link);
    if (cfg.sites.empty())
        return fallback;
    std::map<std::string, ControlFactory> bySite;
    for (const SiteSpec& site : cfg.sites) {
        std::string error;
        const auto a = LinkAddress::parse(site.address, &error);
        if (!a)
            throw ConfigError(cfg.sourcePath + ": sites '" + site.name + "': address: " + error);
        TcpControlOptions o = options;
        o.sessionId = 0; // one console session per site
        if (!site.token.empty())
            o.token = site.token;
        if (site.connectTimeout)
            o.connectTimeout = *site.connectTimeout;
        if (site.stepDeadline)
            o.stepDeadline = *site.stepDeadline;
        ControlFactory f = makeControlFactory(*a, o, site.link);
        if (!f)
            f = [](const ElementSpec& spec) { return buildVirtualSpecimen(spec); };
        bySite.emplace(site.name, std::move(f));
    }
    return [fallback, bySite](const ElementSpec& spec) -> std::unique_ptr<ExperimentalControl> {
        if (!spec.site.empty())
            if (auto it = bySite.find(spec.site); it != bySite.end())
                return it->second(spec);
        return fallback ? fallback(spec) : buildVirtualSpecimen(spec);
    };
}

} // namespace hsmu::comms
