#pragma once

// Omron Host Link C-mode, the PLC's side (Omron CPM1/SRM1 programming manual W353, Host
// Link): RR/WR, RH/WH, RD/WD, RC/WC (present values in BCD), RG, MS, SC, KS/KR/KC, MM and TS
// over the target's Host Link map.
//  - A command for another unit is not answered; a broken one for this unit gets its end code
//    (13 FCS, 14 format, 18 frame length).
//  - Writes and forcing answer 01 in RUN: the master switches to MONITOR (SC 02) first.
//  - 04 for words past the areas the map reaches, 15 for data that is not what the command
//    takes (a non-BCD present value, an unknown mode), 16 for a Host Link command of the PLC
//    that the virtual PLC does not serve, IC for a header Host Link does not have.
//  - A command in parts gets a lone CR after each part but the last; an answer over 131
//    characters goes in parts, each after the master's CR.

#include "comms/protocol/host_link_slave.h"
#include "comms/slave/responder.h"

namespace rung::comms::slave {

class HostLinkResponder final : public Responder {
public:
    HostLinkResponder(const model::Target &target, const model::ProtocolMap &map, int station,
                      std::shared_ptr<DeviceImage> image, int writeTimeoutMs = 2000);

    QByteArrayList feed(QByteArrayView bytes) override;
    QByteArray breakChecksum(QByteArray frame) const override;
    qsizetype buffered() const override {
        qsizetype later = 0;
        for (const QByteArray &part : m_laterParts)
            later += part.size();
        return m_decoder.buffered() + later;
    }

private:
    hostlink::Frame respond(const hostlink::Frame &command);
    hostlink::Frame endCode(const hostlink::Frame &command, int code);
    hostlink::Frame read(const hostlink::Frame &command, model::ProtocolSpace space);
    hostlink::Frame write(const hostlink::Frame &command, model::ProtocolSpace space);
    hostlink::Frame force(const hostlink::Frame &command);
    hostlink::Frame change(const hostlink::Frame &command, const MappedImage::Change &change);

    hostlink::CommandDecoder m_decoder;
    QByteArrayList m_laterParts; // of an answer in parts, each sent after the master's CR
};

} // namespace rung::comms::slave
