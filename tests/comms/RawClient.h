#pragma once
// RawClient: speaks the protocol message by message to a real hsmu-controller, for tests
// that need to send what the console never would (wrong versions, bad tokens, late targets).
// Every wait is bounded (kWait seconds).

#include "comms/link/LinkClient.h"

#include <optional>
#include <string>

class RawClient {
public:
    static constexpr double kWait = 20.0; // [s] generous for a loaded CI machine

    bool connect(std::uint16_t port) {
        std::string e;
        return m_link.connect("127.0.0.1", port, kWait, e);
    }
    bool send(const hsmu::comms::Message& m) {
        std::string e;
        return m_link.send(m, e);
    }
    bool sendRaw(std::vector<std::uint8_t> b) {
        std::string e;
        return m_link.sendRaw(std::move(b), e);
    }
    std::optional<hsmu::comms::Message> receive(double wait = kWait) {
        std::string e;
        return m_link.receive(wait, e);
    }
    /// The next message if it is a T.
    template <typename T> std::optional<T> expect(double wait = kWait) {
        const auto m = receive(wait);
        if (!m || !std::holds_alternative<T>(*m))
            return std::nullopt;
        return std::get<T>(*m);
    }
    /// Hello (session id, token, element) answered by a hello-ack.
    bool hello(std::uint64_t session, const std::string& token = {},
               const std::string& element = {}) {
        return send(
                   hsmu::comms::HelloMsg{hsmu::comms::kProtocolVersion, session, token, element}) &&
               expect<hsmu::comms::HelloAckMsg>().has_value();
    }
    /// Wait (bounded) until the controller has closed the connection.
    bool closedByPeer() {
        for (int i = 0; i < 200 && m_link.isOpen(); ++i)
            receive(0.1);
        return !m_link.isOpen();
    }
    void close() { m_link.close(); }
    hsmu::comms::LinkClient& link() { return m_link; }

private:
    hsmu::comms::LinkClient m_link{hsmu::comms::LinkClientOptions{0.25, 60.0, std::nullopt}};
};
