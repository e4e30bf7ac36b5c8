#pragma once

// Vigor M / VB / VH Computer Link, the PLC's side (Vigor M/VB/VH communication manual, B-5):
// 51h reads and 61h writes at most 128 bytes of the link byte map, 70h / 71h set and reset one
// bit device (X, Y, M, S: timer and counter contacts are not bit devices of the command, error
// 28h).
// A request for another station gets no answer; a broken one that names this station gets its
// error code: 11h sum, 10h ASCII, 12h command, 28h address or length.

#include "comms/protocol/vigor_link_slave.h"
#include "comms/slave/responder.h"

namespace rung::comms::slave {

class VigorResponder final : public Responder {
public:
    VigorResponder(const model::Target &target, const model::ProtocolMap &map, int station,
                   std::shared_ptr<DeviceImage> image, int writeTimeoutMs = 2000);

    QByteArrayList feed(QByteArrayView bytes) override;
    QByteArray breakChecksum(QByteArray frame) const override;
    qsizetype buffered() const override { return m_decoder.buffered(); }

private:
    QByteArray answer(const vigor::Request &request, int errorCode);
    QByteArray respond(const vigor::Request &request);

    vigor::RequestDecoder m_decoder;
};

} // namespace rung::comms::slave
