// OfServer's sizes header (OfServer.h): accepted against the DOFs it serves, or refused
// politely (NaN answers until the client ends).
#include "comms/controller/OfServer.h"

#include "comms/openfresco/OfFrame.h"
#include "comms/openfresco/OfSocket.h"

#include <algorithm>
#include <chrono>
#include <limits>

namespace hsmu::comms {

using namespace of;

namespace {

constexpr double kHeaderTimeout = 10.0; // [s] from connect to the sizes header

} // namespace

bool OfServer::acceptHeader(OfSocket& socket, std::string& why) {
    std::uint8_t bytes[kSizesBytes];
    if (!socket.read(bytes, sizeof bytes, kHeaderTimeout, why)) {
        why = "no sizes header: " + why;
        return false;
    }
    m_lastFrame = std::chrono::steady_clock::now();
    const OfSizes s = decodeSizes(bytes);
    m_sizes = OfSizes{};
    m_sizes.dataSize = 0; // no frames can be exchanged (refuse() closes at once)
    if (auto p = s.problem()) {
        why = "sizes header " + s.describe() + ": " + *p;
        return false;
    }
    m_sizes = s;
    const int n = dofCount();
    const std::string N = std::to_string(n);
    auto bad = [&](const std::string& what) {
        why = "sizes header " + s.describe() + " refused: " + what;
        return false;
    };
    if (channelRig()) {
        if (auto p = channelSizesProblem(s))
            return bad(*p);
    }
    if (s.dataSize != m_opt.dataSize)
        return bad("the client's dataSize is " + std::to_string(s.dataSize) + ", this server's " +
                   std::to_string(m_opt.dataSize) +
                   " (--data-size or controller.dataSize; OpenSees: -dataSize)");
    const int c = s.ctrlSize(Resp::Disp);
    if (c != n && !channelRig())
        return bad("the client has " + std::to_string(c) + " control DOF" + (c == 1 ? "" : "s") +
                   " (ctrl disp " + std::to_string(c) + "), this server serves " + N + " (" +
                   m_opt.dofs.describe() + "); list the client's " + std::to_string(c) +
                   " DOFs in controller.serverDofs, one entry per DOF in the client's order, "
                   "e.g. [{\"specimen\": \"" +
                   m_stations[0]->name() + "\", \"factor\": -1}, {\"specimen\": \"" +
                   m_stations[0]->name() + "\"}] for a two-node element");
    for (Resp r : {Resp::Disp, Resp::Vel, Resp::Accel, Resp::Force})
        if (s.daqSize(r) != 0 && s.daqSize(r) != n)
            return bad("daq sizes must be 0 or the " + N + " DOFs of this server (" +
                       (channelRig() ? describe() : m_opt.dofs.describe()) + ")");
    if (s.daqSize(Resp::Time) > 1)
        return bad("daq time must be 0 or 1");
    if (m_opt.protocol == OfProtocol::SimApp && !m_opt.siteServer && s.dataSize < n * n)
        return bad("an element server of " + N +
                   " DOFs needs dataSize >= n * n = " + std::to_string(n * n));
    return true;
}

void OfServer::refuse(OfSocket& socket) {
    if (m_sizes.dataSize < 1)
        return;                           // sizes that cannot frame anything: close
    constexpr double kRefusedIdle = 10.0; // [s] without a frame before a refused session closes
    const bool generic = m_opt.protocol == OfProtocol::GenericTcp;
    const std::size_t frameBytes = static_cast<std::size_t>(m_sizes.dataSize) * sizeof(double);
    std::vector<std::uint8_t> buffer(std::max(frameBytes, kInitLineBytes)), out;
    std::vector<double> frame;
    const std::vector<double> nan(static_cast<std::size_t>(m_sizes.dataSize),
                                  std::numeric_limits<double>::quiet_NaN());
    std::string why, error;
    const std::string peer = socket.peer(); // "" once the socket is closed
    long answered = 0;
    for (bool framesStarted = false;;) {
        if (!socket.read(buffer.data(), 8, kRefusedIdle, why))
            break;
        const bool isFrame = startsWithCode(buffer.data());
        if (!isFrame && (!generic || framesStarted))
            break; // not a frame of these sizes: the stream cannot be followed
        const std::size_t total = isFrame ? frameBytes : kInitLineBytes;
        if (total > 8 && !socket.read(buffer.data() + 8, total - 8, kRefusedIdle, why))
            break;
        m_lastFrame = std::chrono::steady_clock::now();
        if (!isFrame)
            continue;
        framesStarted = true;
        decodeFrame(buffer.data(), m_sizes.dataSize, frame);
        const auto action = actionOf(frame[0]);
        if (!action || *action == Action::Terminate)
            break;
        const int code = static_cast<int>(*action);
        const bool replies = (code >= 6 && code <= 11) ||
                             (code >= 12 && code <= 15 && !generic && !m_opt.siteServer);
        if (!replies)
            continue;
        if (!encodeFrame(nan, m_sizes.dataSize, out, error) ||
            !socket.write(out.data(), out.size(), kWriteTimeout, error))
            break;
        ++answered;
    }
    if (answered > 0 || m_replaced)
        log("refused session " + peer + " ended" + (m_replaced ? " (" + idleText() + ")" : "") +
            "; " + std::to_string(answered) + " request(s) answered with NaN");
}

} // namespace hsmu::comms
