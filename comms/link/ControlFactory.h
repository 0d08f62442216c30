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
// The returned controls connect in prepare(), i.e. when HybridTest::prepare() runs.

#include "comms/LinkAddress.h"
#include "comms/link/TcpControl.h"
#include "core/config/TestFactory.h"

namespace hsmu::comms {

ControlFactory makeControlFactory(const LinkAddress& address,
                                  const TcpControlOptions& options = {});

/// A random non-zero 64-bit session id.
std::uint64_t newSessionId();

} // namespace hsmu::comms
