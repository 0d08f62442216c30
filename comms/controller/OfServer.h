#pragma once
// OfServer: hsmu-controller speaking an OpenFresco protocol (docs/openfresco.md) instead of
// the native one, with the same SpecimenStations (virtual specimens, actuator, interlock,
// journal). One connection at a time, served with blocking calls (comms/openfresco/OfSocket):
//
//   header   11 int32 sizes within 10 s of the connect. Accepted when dataSize equals the
//            server's, ctrl disp = n (the client's DOFs: one per specimen in configuration
//            order, or as controller.serverDofs maps them, OfDofMap), daq disp / vel / accel /
//            force each 0 or n, daq time 0 or 1, and (element server) dataSize >= n * n.
//            Otherwise the reason (both sides' sizes and the configuration field) is logged and
//            the session is refused politely: every request that expects a reply is answered
//            with a frame of NaN (in the client's dataSize) until 99, the peer closes or 10 s
//            pass without a frame, so that a client that cannot notice a closed socket
//            (OpenSees spins on one) ends with visibly non-finite results; a client that sends
//            nothing more (SimAppControl's probe) sees NaN and reports it. Each accepted session
//            starts from fresh specimens (OpenFresco has no step count to resume from).
//   init     GenericTCP: 16385-byte init lines may come before the first frame; a message
//            whose first 8 bytes are not a double holding an action code is such a line
//            (logged, otherwise ignored).
//   frames   of dataSize doubles, code in element 0:
//            3   trial: station s moves to d = B u (OfDofMap); no reply. GenericTCP (no commit
//                action) commits the previous measured trial first.
//            5   commit every station; no reply.
//            6   reply [daq disp (measured, per DOF), vel (0), accel (0), force (B^T f), time].
//            7-11  reply the daq disp / vel / accel / force / time part alone, at index 0.
//            12-15 element server: reply the n x n column-major initial stiffness
//                (B^T diag(k0) B), tangent stiffness (B^T diag(kt) B, kt the laws' algorithmic
//                tangent of the last trial), damping (0), mass (0);
//                a site server sends nothing (as OpenFresco's site servers do).
//            1, 2, 4  accepted, nothing to do, no reply.
//            99  ends the session: the server closes the connection and waits for the next.
//   idle     a session may wait between frames for as long as its client computes, unless
//            another client is waiting to connect: then a session with no frame for
//            idleTimeout (controller.idleTimeout) is closed (logged) and the next is served.
//   faults   an interlock trip, a non-finite value, an unknown code or a peer that closes
//            mid-frame: logged, the connection is closed, every station holds at its
//            committed state (as after any session that does not end by 99; see below).
// Real-time pace runs a step's ticks at the loop rate when its trial arrives.
// N actuator channels (a link2d specimen, ChannelRig; OfServerChannels.cpp): the specimen is
// served alone and its channels are the client's DOFs, in configuration order, with
// OpenFresco's sizes for a setup of N actuators: ctrl disp N, and ctrl force N when a channel
// is force-controlled (else 0 or N); daq disp and daq force 0 or N. A trial takes each
// displacement-controlled channel's stroke [m] from its ctrl disp entry and each
// force-controlled channel's force [kN] from its ctrl force entry (the channel modes are this
// server's configuration; the other entry of a channel is ignored); the daq reply carries the
// measured strokes and forces; 12-15 (element server) the diagonal of the actuators'
// materials' tangents (damping and mass 0). A session that ends other than by 99 (a dropped or
// shut-down link, a fault) leaves every actuator holding at its committed stroke and force
// (logged with the committed step and each channel's committed command).
// Thread rules: listen() and run() on one thread; stop() from any thread (and SIGINT/SIGTERM).

#include "comms/controller/ControllerServer.h"
#include "comms/controller/OfDofMap.h"
#include "comms/controller/SpecimenStation.h"
#include "comms/openfresco/OpenFrescoControl.h"

#include <atomic>
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace hsmu::comms {

namespace of {
class OfSocket;
class OfListener;
} // namespace of

struct OfServerOptions {
    std::string bind = "127.0.0.1";
    std::uint16_t port = 0;
    of::OfProtocol protocol = of::OfProtocol::SimApp;
    bool siteServer = false; ///< SimApp: a site server (no replies to 12-15)
    int dataSize = 256;
    double dt = 0.01; ///< [s] the step the stations are configured with
    bool realTime = true;
    double rate = 1024.0; ///< loop rate [Hz] (real-time pace)
    bool quiet = false;
    /// [s] a session with no frame for this long is closed when another client is waiting
    double idleTimeout = 10.0;
    /// The client's DOFs onto the stations; default (0 specimens): one DOF per station.
    OfDofMap dofs;
};

class OfServer {
public:
    OfServer(const OfServerOptions& options,
             std::vector<std::unique_ptr<SpecimenStation>> stations);
    ~OfServer();
    OfServer(const OfServer&) = delete;
    OfServer& operator=(const OfServer&) = delete;

    bool listen(std::string& error);
    std::uint16_t port() const;
    /// Serve sessions one after the other until stop(), SIGINT or SIGTERM.
    void run();
    void stop();
    ControllerStatistics statistics() const { return m_stats; }
    /// "simapp element server, dataSize 256"
    std::string describe() const;

private:
    static constexpr double kWriteTimeout = 10.0; ///< [s] for a reply
    void serve(of::OfSocket& socket);
    bool acceptHeader(of::OfSocket& socket, std::string& why);
    /// Answer a refused client's requests with NaN until it ends (see the header).
    void refuse(of::OfSocket& socket);
    bool trial(const std::vector<double>& frame, std::string& why);
    /// Real time: the step's ticks at the loop rate until every station whose result is
    /// still empty has its measurement(s) (fast pace: nothing to do). False if one never came.
    bool tickUntilMeasured(std::vector<std::optional<Message>>& result, std::string& why);
    bool commitAll(std::string& why);
    std::vector<double> daqReply(int first, int last) const;
    std::vector<double> matrix(int action) const;
    void log(const std::string& line) const;
    /// The session's waits end (the socket is closed): a stop, or idle past the timeout while
    /// another client waits (then m_replaced is set).
    bool cancelled();
    std::string idleText() const;
    /// The client's DOFs: the N channels of a link2d specimen, else the OfDofMap's.
    int dofCount() const;
    // N actuator channels (OfServerChannels.cpp; nullptr / unused for one-channel stations).
    const ChannelRig* channelRig() const;
    std::optional<std::string> channelSizesProblem(const of::OfSizes& s) const;
    bool trialChannels(const std::vector<double>& frame, std::string& why);
    /// Per DOF: the measured displacement and force of the last trial.
    void measuredDofs(std::vector<double>& disp, std::vector<double>& force) const;
    /// After a session that did not end by 99: every station holds (logged).
    void holdAfterSession(const std::string& why);

    OfServerOptions m_opt;
    std::vector<std::unique_ptr<SpecimenStation>> m_stations;
    std::unique_ptr<of::OfListener> m_listener;
    std::atomic<bool> m_stop{false};
    of::OfSizes m_sizes;
    std::vector<MeasurementMsg> m_measured;
    MeasurementsMsg m_measuredN;     ///< N channels: the last trial's measurements
    std::vector<double> m_commanded; ///< per station: the last trial's deformation
    std::vector<double> m_ctrl;      ///< per DOF: the last trial's ctrl disp
    bool m_haveTrial = false;        ///< a measured trial not yet committed
    std::chrono::steady_clock::time_point m_lastFrame; ///< the session's last frame (or start)
    bool m_replaced = false; ///< the session was closed for a waiting client
    ControllerStatistics m_stats;
};

} // namespace hsmu::comms
