#pragma once
// LoopbackProxy: a TCP relay on 127.0.0.1 between the console and a controller, used to
// pull the cable at a precise point of the protocol: cutAfter(type, n) closes every relayed
// connection right after the n-th frame of that type from the console has been delivered to
// the controller (so the controller acts on it, and its answer is lost). New connections
// are relayed again afterwards. Asio on a thread of its own; the public calls are
// thread-safe.

#include "comms/protocol/Protocol.h"

#include <cstdint>
#include <memory>

class LoopbackProxy {
public:
    explicit LoopbackProxy(std::uint16_t upstreamPort);
    ~LoopbackProxy();
    std::uint16_t port() const;
    /// Arm one cut (replaces a previous one that has not fired).
    void cutAfter(hsmu::comms::MessageType type, int count);
    /// Cuts performed so far.
    int cuts() const;

private:
    struct Impl;
    std::unique_ptr<Impl> d;
};
