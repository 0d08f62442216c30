#pragma once
// GenericTcpControl: the console as the client OpenFresco's `expControl GenericTCP` is, so a
// lab controller server written for it (or `hsmu-controller --protocol generictcp`) is driven
// directly: sizes header, optional 16385-byte init lines, then per step [3, ctrl] and [6] ->
// daq reply. The protocol has no commit: a step is final once the next trial is sent, so a
// measured step cannot be repeated after a hold (setTarget() refuses). See OpenFrescoControl.

#include "comms/openfresco/OpenFrescoControl.h"

namespace hsmu::comms::of {

class GenericTcpControl final : public OpenFrescoControl {
public:
    GenericTcpControl(std::string host, std::uint16_t port, std::string element,
                      OfControlOptions options)
        : OpenFrescoControl(OfProtocol::GenericTcp, std::move(host), port, std::move(element),
                            std::move(options)) {}
};

} // namespace hsmu::comms::of
