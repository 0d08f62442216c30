#pragma once
// OpenSslLibrary: OpenSSL 3 (libssl.so.3 and the libcrypto.so.3 it needs) loaded the first
// time a tls:// link builds its context, not at every start of the program (docs/security.md,
// "TLS"). Linked eagerly they cost every process 1.7 MB of resident memory and their
// relocations, a tenth of a headless `hsmu run` of the strong SDOF that never opens a link
// (issue 27, docs/benchmarks.md). OpenSslLibrary.cpp defines each OpenSSL function comms
// calls (directly or through Boost.Asio's ssl headers) as a forwarder to the loaded library's
// own, resolved on its first call; comms links no OpenSSL library, so a function used
// without a forwarder fails the link, not a run.
//
// Thread rules: any thread; loading happens once (static initialisation).

#include <string>

namespace hsmu::comms {

/// Loads OpenSSL 3 if not yet loaded. False, with a sentence in error naming the library and
/// the loader's reason, when it cannot be loaded (then no TLS context is made).
bool loadOpenSsl(std::string& error);

} // namespace hsmu::comms
