#pragma once
// OpenFrescoControl: an ExperimentalControl over one of OpenFresco's wire protocols
// (docs/openfresco.md), the common part of SimAppControl and GenericTcpControl.
//
// prepare(): connect (TCP_NODELAY), send the 11-int32 sizes header, (GenericTCP) the init
// lines, then one getDaqResponse (6) as a probe: its reply must come back whole within the
// step deadline. A server that does not accept the sizes (ours closes the connection, see
// OfServer) therefore fails prepare() with a message naming the sizes, instead of a stream
// that desynchronizes later. The negotiated sizes are logged on stderr at connect.
// GenericTCP has no commit: against hsmu-controller --protocol simapp (its probe reply carries
// kMarkSimAppServer, OfFrame.h) prepare() fails naming simapp:// as the fix; against a server
// without our mark it warns (stderr and takeNotice(): a Warning alarm at connect).
// Per step:
//   setTarget(d)  [3, d at ctrl disp, zeros, time at ctrl time when sized]   (no reply), then
//                 at once [6] (so that several sites work in parallel: measure() only reads)
//   measure()     the reply to [6]: deformation = daq disp[0], force = daq force[0]. A daq disp of
//                 exactly 0 while the target is not 0 is a dead channel (OpenFresco's element
//                 servers always answer 0: ExperimentalElement::getDisp returns zeros): the
//                 link warns once (stderr and takeNotice(), which the test records as an
//                 alarm) and from then on uses the commanded deformation wherever the channel
//                 reads exactly 0, for identification, limits and the record.
//   commit()      SimApp: [5] (no reply); GenericTCP has no commit (nothing is sent)
// The destructor sends [99] (terminate) on an open link and waits up to 2 s for the server to
// close first (OfSocket::closeAfterPeer: its port stays reusable). Every read and write has a
// deadline; a timeout, a closed or vanished peer or a malformed reply closes the link and
// returns a fault (the test holds with every committed step kept). OpenFresco has no session or
// step count to resume from, so a lost link is not reconnected: resume() on a closed link leaves
// setTarget() reporting it, and the test is restarted instead.
// Emergency hold: OpenFresco's protocols have no hold message. emergencyHold() (any thread)
// shuts the connection down at once (OfSocket::interrupt): the blocked read fails promptly
// and the site server sees its client gone (an OpenFresco site server then stops serving
// its experimental site, which commands nothing more; hsmu-controller's OpenFresco servers
// end the session with the specimen where it is). The session cannot be resumed: restart the test.
// Actuator channels: commanded = the ctrl displacement sent, measured = the daq displacement
// as read (before the dead-channel substitution); no held ticks or flags (-1).
// N actuator channels (a link2d specimen: OfControlOptions::channelModes; OpenFrescoChannels.cpp,
// docs/openfresco.md "Several actuator channels"): OpenFresco's sizes for a setup of N
// actuators, ctrl disp N (and ctrl force N when a channel is force-controlled), daq disp N and
// daq force N. setTargets() sends one trial [3, ...] whose ctrl disp entry i carries channel i's
// stroke [m] when it is displacement-controlled (else 0) and whose ctrl force entry i carries
// its force [kN] when it is force-controlled (else 0), then [6]; measureChannels() reads the
// strokes from daq disp and the forces from daq force. Sizes that cannot carry every channel's
// command, and the adapter protocol (one DOF), are refused by prepare() naming the fix.
// setTarget() / measure() stay the one-channel path. actuatorChannels(): channel 1's command
// and stroke.
// Thread rules: one thread at a time (the test worker), except emergencyHold().

#include "comms/openfresco/AdapterCompensation.h"
#include "comms/openfresco/OfSizes.h"
#include "core/config/LinkConfig.h"
#include "core/experimental/ActuatorChannel.h"
#include "core/experimental/ExperimentalControl.h"

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace hsmu::comms::of {

class OfSocket;

/// SimApp and GenericTCP (OpenFresco), Adapter (OpenSees' adapter element: AdapterControl).
enum class OfProtocol { SimApp, GenericTcp, Adapter };
const char* ofProtocolName(OfProtocol p);

struct OfControlOptions {
    OfSizes sizes;                      ///< must have ctrl disp, daq disp and daq force >= 1
    std::vector<std::string> initLines; ///< GenericTCP: sent after the header
    double connectTimeout = LinkTimeouts::kConnect;    ///< [s] per connection attempt
    double stepDeadline = LinkTimeouts::kStepDeadline; ///< [s] for each read or write
    int connectAttempts = 3;            ///< attempts in prepare() while nobody listens
    double retryDelay = 0.5;            ///< [s] between them
    bool logConnect = true;             ///< one line on stderr with the negotiated sizes
    /// GenericTCP: warn on stderr at connect that the server must commit on its own (a SimApp
    /// site server never does: docs/openfresco.md "Pairings that cannot be right"). The
    /// warning is also the control's notice (takeNotice(): a Warning alarm in the record)
    /// whatever this says.
    bool warnNoCommit = true;
    /// A link2d specimen's actuator channels and their modes (ControlFactory fills them from
    /// the configuration, with the sizes); empty: one channel.
    std::vector<ActuatorMode> channelModes;
    /// Adapter: the penalty compensation (AdapterCompensation; both on by default).
    AdapterCompensation::Options adapter;
};

class OpenFrescoControl : public ExperimentalControl {
public:
    ~OpenFrescoControl() override;

    std::string description() const override;
    ControlResult prepare(double dt) override;
    ControlResult setTarget(double d) override;
    ControlResult measure(ControlMeasurement& out) override;
    ControlResult commit() override;
    void hold(const std::string& reason) override;
    void resume() override;
    /// Once, when the daq displacement channel is found dead (see the header).
    std::string takeNotice() override;
    bool connected() const override { return linkUp(); }
    /// Any thread: closes the connection now (see the header).
    void emergencyHold(const std::string& reason) override;
    std::optional<ActuatorChannels> actuatorChannels() const override;
    int channelCount() const override;
    ControlResult setTargets(const Eigen::VectorXd& commands) override;
    ControlResult measureChannels(Eigen::VectorXd& strokes, Eigen::VectorXd& forces) override;
    /// Whether the daq displacement read exactly 0 while the target was not 0: from then on a
    /// reading of exactly 0 is replaced by the commanded deformation.
    bool commandedDeformationUsed() const { return m_zeroDisp; }

    bool linkUp() const;
    const std::string& linkError() const { return m_linkError; }
    /// After a GenericTCP connect to a server that is not hsmu-controller: the warning that
    /// the server must commit on its own (nothing on OpenFresco's wire tells a GenericTCP
    /// controller from a SimApp site server; hsmu-controller marks its probe reply, and a
    /// SimApp hsmu-controller is refused at connect); "" for SimApp and for our servers.
    const std::string& pairingWarning() const { return m_pairingWarning; }
    std::uint64_t committedSteps() const { return m_committed; }
    OfProtocol protocol() const { return m_protocol; }
    /// "simapp://HOST:PORT" or "generictcp://HOST:PORT".
    std::string where() const;

protected:
    OpenFrescoControl(OfProtocol protocol, std::string host, std::uint16_t port,
                      std::string element, OfControlOptions options);

private:
    ControlResult connectOnce();
    ControlResult linkFault(const std::string& what);
    ControlResult sendRequest(int action, const std::vector<double>& values);
    /// Why no trial may be sent now (emergency, hold, link down, GenericTCP repeat), or success.
    ControlResult trialAllowed();
    /// A trial [3, ctrl] with the time entry filled, then the daq request.
    ControlResult sendTrial(std::vector<double>& ctrl);
    /// The reply to the daq request into m_values.
    ControlResult readReply();
    /// N channels: why these sizes cannot carry them (prepare()), or nullopt.
    std::optional<std::string> channelProblem() const;

    OfProtocol m_protocol;
    std::unique_ptr<OfSocket> m_socket;
    std::string m_host;
    std::uint16_t m_port;
    std::string m_element;
    OfControlOptions m_opt;
    double m_dt = 0.0;
    std::uint64_t m_committed = 0;
    bool m_awaitingMeasurement = false;
    bool m_measuredUncommitted = false;
    bool m_holding = false;
    bool m_connectFailed = false;
    std::string m_holdReason;
    std::string m_linkError;
    std::string m_pairingWarning;
    std::string m_notice;
    bool m_zeroDisp = false;
    double m_target = 0.0;
    Eigen::VectorXd m_targets; ///< N channels: the last commands sent
    std::vector<std::uint8_t> m_buffer;
    std::vector<double> m_values;
    std::optional<ActuatorChannels> m_channels;
    std::atomic<bool> m_emergency{false};
    mutable std::mutex m_emergencyMutex;
    std::string m_emergencyReason;
    std::string emergencyText() const;
};

} // namespace hsmu::comms::of
