#pragma once
// makeControlFactory: the core ControlFactory (core/config/TestFactory.h) for a LinkAddress,
// so that buildHybridTest(cfg, makeControlFactory(address, options)) runs the same test over
// the link:
//   builtin           -> an empty factory: core builds in-process VirtualSpecimens;
//   tcp://HOST:PORT   -> one TcpControl per experimental element, named after the element
//                        (hsmu-controller serves every experimental element of the same
//                        configuration), with the element's limits, all sharing one session
//                        id (options.sessionId, or one drawn here) so the controller sees one
//                        console session.
//   simapp://HOST:PORT, generictcp://HOST:PORT, or tcp:// with link.protocol "simapp" /
//                     "generictcp" -> one SimAppControl / GenericTcpControl per experimental
//                        element (comms/openfresco), with link's dataSize, sizes and init
//                        lines; deadlines from options (connectTimeout, stepDeadline).
// The returned controls connect in prepare(), i.e. when HybridTest::prepare() runs.
// Every call also installs the factory of OpenSees twins (numerical elements with a
// "numericalSite", comms/openfresco/OpenSeesTwinSite.h) with options' connect and step times.

#include "comms/LinkAddress.h"
#include "comms/link/TcpControl.h"
#include "core/config/TestFactory.h"

namespace hsmu::comms {

ControlFactory makeControlFactory(const LinkAddress& address,
                                  const TcpControlOptions& options = {});
/// The same, with the configuration's link section choosing the protocol for tcp://.
ControlFactory makeControlFactory(const LinkAddress& address, const TcpControlOptions& options,
                                  const LinkSpec& link);
/// The configuration's sites (cfg.sites, docs/configuration.md "Sites"): each experimental
/// element a site lists gets a control for that site's address, protocol, sizes, token
/// (options.token otherwise) and timeouts (options' otherwise); one session id per site.
/// A site at "builtin" gets in-process VirtualSpecimens. Every other experimental element
/// belongs to the default site: address with cfg.link, as makeControlFactory(address,
/// options, cfg.link). Without sites this is exactly that factory (empty for builtin).
/// Throws ConfigError naming the configuration and the site when an address does not parse.
ControlFactory makeControlFactory(const LinkAddress& address, const TcpControlOptions& options,
                                  const TestConfig& cfg);
/// The protocol a link to address speaks: "native", "simapp" or "generictcp" ("builtin" for
/// the in-process specimens).
std::string linkProtocol(const LinkAddress& address, const LinkSpec& link);

/// How each site's link is protected (site name -> LinkAddress::security()): the
/// configuration's sites, and kDefaultSiteName for address (the front end's --controller), for
/// the record (RecordStart::siteSecurity, docs/recording.md).
std::vector<std::pair<std::string, std::string>> siteSecurity(const LinkAddress& address,
                                                              const TestConfig& cfg);

/// A random non-zero 64-bit session id.
std::uint64_t newSessionId();

} // namespace hsmu::comms
