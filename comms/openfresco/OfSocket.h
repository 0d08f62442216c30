#pragma once
// OfSocket / OfListener: blocking TCP helpers for the OpenFresco protocols, every call bounded
// by a deadline (Asio underneath, kept out of this header). TCP_NODELAY is set on every
// connection, and TCP keep-alive so that a peer whose machine vanished is eventually noticed
// even when nobody is sending. After every read (and at connect) TCP_QUICKACK is re-armed
// (Linux): OpenSees and OpenFresco leave Nagle on and write two frames back to back, and the
// second would otherwise wait for our delayed ACK of the first (about 40-45 ms per step). A read or
// write that times out, fails or is cancelled closes the socket: the fixed-length OpenFresco stream
// has no framing to resynchronize on, so a half-read frame must never be followed by another read.
// Thread rules: one thread per object, except interrupt() (any thread). setCancel()'s predicate is polled about every 0.2 s
// during a wait (a server's stop flag).

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace hsmu::comms::of {

class OfListener;

class OfSocket {
public:
    OfSocket();
    ~OfSocket();
    OfSocket(const OfSocket&) = delete;
    OfSocket& operator=(const OfSocket&) = delete;

    /// Close any connection, then connect within timeout [s].
    bool connect(const std::string& host, std::uint16_t port, double timeout, std::string& error);
    /// Write all n bytes within timeout [s].
    bool write(const void* data, std::size_t n, double timeout, std::string& error);
    /// Read exactly n bytes within timeout [s] (timeout <= 0: no deadline, only cancel()).
    bool read(void* data, std::size_t n, double timeout, std::string& error);
    /// Read up to and including the next '\n' within timeout [s], the line without it (and
    /// without a '\r') into line; fails on a line longer than maxBytes. Bytes after the line
    /// stay buffered for the next readLine(): do not mix read() and readLine() on one
    /// connection (the text protocol of the OpenSees twin, docs/opensees-twins.md).
    bool readLine(std::string& line, std::size_t maxBytes, double timeout, std::string& error);
    /// Whether the last failed read met an orderly close by the peer (EOF).
    bool closedByPeer() const;
    /// Whether the last failed call ran out of time.
    bool timedOut() const;
    void close();
    /// The end of a session after the client's 99: wait up to timeout [s] for the peer to close
    /// (data still arriving is discarded), then close with a reset, so that the server's port
    /// is not left in TIME_WAIT (OpenSees' servers bind without SO_REUSEADDR and could not
    /// listen on it again for a minute). A peer that does not close in time: a plain close.
    void closeAfterPeer(double timeout);
    bool isOpen() const;
    /// "ADDR:PORT" of the peer ("" when closed).
    std::string peer() const;
    void setCancel(std::function<bool()> cancelled);
    /// Any thread: shut the connection down now (the peer sees it closed; a read or write in
    /// progress on the owning thread fails at once and closes the socket). No-op when closed.
    void interrupt();

private:
    struct Impl;
    std::unique_ptr<Impl> d;
    friend class OfListener;
};

class OfListener {
public:
    OfListener();
    ~OfListener();
    OfListener(const OfListener&) = delete;
    OfListener& operator=(const OfListener&) = delete;

    /// Bind and listen on bind:port (port 0: any free one).
    bool listen(const std::string& bind, std::uint16_t port, std::string& error);
    std::uint16_t port() const;
    /// Accept one connection into out within timeout [s]; false with error "" on a timeout or
    /// cancel, with a sentence on a failure.
    bool accept(OfSocket& out, double timeout, std::string& error);
    /// Whether a connection is waiting to be accepted (does not wait, accepts nothing).
    bool pending() const;
    void close();
    void setCancel(std::function<bool()> cancelled);

private:
    struct Impl;
    std::unique_ptr<Impl> d;
};

} // namespace hsmu::comms::of
