#pragma once
// Shared by the OpenFresco link tests (TestOpenFrescoLinks: the console's clients;
// TestOpenFrescoServers: hsmu-controller's servers): options, frames built from the documented
// layout (not with the code under test), a raw client and a scripted raw server.
#include "comms/link/TcpControl.h"
#include "comms/openfresco/OpenFrescoControl.h"
#include "comms/openfresco/OfSocket.h"

#include "ControllerProcess.h"
#include "LinkFixture.h"

#include <array>
#include <cstdint>
#include <cstring>
#include <functional>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace ofpeer {

using namespace hsmu::comms;
using namespace hsmu::comms::of;

inline constexpr double kWait = 20.0; // [s] every socket wait (a loaded 2-core machine)

inline TcpControlOptions patientOptions() {
    TcpControlOptions o;
    o.connectTimeout = 20.0;
    o.stepDeadline = 30.0;
    o.reconnectAttempts = 5;
    o.reconnectDelay = 0.2;
    return o;
}

inline OfControlOptions ofOptions(int dataSize = 256) {
    OfControlOptions o;
    o.sizes.dataSize = dataSize;
    o.connectTimeout = kWait;
    o.stepDeadline = kWait;
    o.logConnect = false;
    return o;
}

/// The header a client sends, built here from the documented layout (not with encodeSizes).
inline std::vector<std::uint8_t> header(std::array<std::int32_t, 11> v) {
    std::vector<std::uint8_t> b(44);
    std::memcpy(b.data(), v.data(), 44);
    return b;
}

/// A frame of dataSize doubles: values from index 0, zeros after.
inline std::vector<std::uint8_t> frame(std::vector<double> values, int dataSize) {
    values.resize(static_cast<std::size_t>(dataSize), 0.0);
    std::vector<std::uint8_t> b(values.size() * 8);
    std::memcpy(b.data(), values.data(), b.size());
    return b;
}

inline std::vector<double> doubles(const std::vector<std::uint8_t>& b) {
    std::vector<double> v(b.size() / 8);
    std::memcpy(v.data(), b.data(), v.size() * 8);
    return v;
}

/// A raw client of hsmu-controller.
struct RawPeer {
    OfSocket socket;
    std::string error;
    bool send(const std::vector<std::uint8_t>& b) {
        return socket.write(b.data(), b.size(), kWait, error);
    }
    std::optional<std::vector<double>> receive(int dataSize) {
        std::vector<std::uint8_t> b(static_cast<std::size_t>(dataSize) * 8);
        if (!socket.read(b.data(), b.size(), kWait, error))
            return std::nullopt;
        return doubles(b);
    }
};

/// A scripted server on a thread: accepts one connection and runs script(socket); what it
/// saw goes into notes (checked by the test on the main thread after join()).
class ScriptedServer {
public:
    explicit ScriptedServer(std::function<void(OfSocket&, std::vector<std::string>&)> script) {
        std::string e;
        m_ok = m_listener.listen("127.0.0.1", 0, e);
        m_thread = std::thread([this, script = std::move(script)] {
            OfSocket s;
            std::string error;
            if (!m_listener.accept(s, kWait, error)) {
                notes.push_back("no connection");
                return;
            }
            script(s, notes);
        });
    }
    ~ScriptedServer() { join(); }
    void join() {
        if (m_thread.joinable())
            m_thread.join();
    }
    bool ok() const { return m_ok; }
    std::uint16_t port() const { return m_listener.port(); }
    std::vector<std::string> notes;

private:
    OfListener m_listener;
    bool m_ok = false;
    std::thread m_thread;
};

/// Read n bytes as the raw server; a note on failure.
inline bool readBytes(OfSocket& s, std::vector<std::uint8_t>& b, std::size_t n,
               std::vector<std::string>& notes, const char* what) {
    b.assign(n, 0);
    std::string e;
    if (s.read(b.data(), n, kWait, e))
        return true;
    notes.push_back(std::string(what) + ": " + e);
    return false;
}

inline std::string joined(const std::vector<std::string>& v) {
    std::string s;
    for (const auto& x : v)
        s += x + "; ";
    return s;
}

/// hsmu-controller at fast pace serving `protocol` (simapp, generictcp) with `config`.
inline ControllerProcess ofController(const std::string& config, const QString& protocol,
                                      QStringList extra = {}) {
    return ControllerProcess(QStringList{"--config", QString::fromStdString(config), "--pace",
                                         "fast", "--protocol", protocol} +
                             extra);
}

/// Condition 3 for 0.2 s without force noise or fracture: values computed here match exactly.
inline nlohmann::json quietCondition3() {
    nlohmann::json q = linkfixture::condition3(0.2);
    auto& sp = q["structure"]["elements"][0]["specimen"];
    sp["forceNoiseStd"] = 0.0;
    sp.erase("fracture");
    return q;
}

} // namespace ofpeer
