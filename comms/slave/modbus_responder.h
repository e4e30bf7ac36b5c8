#pragma once

// Modbus, the slave's side (Application Protocol V1.1b3, serial line V1.02; the Vigor CP2 map
// of the Vigor M/VB/VH communication manual, B-3-6, and the PL110 map of the PL110 manual,
// 3.2): functions 01 02 03 04 05 06 0F 10 over the target's map.
//  - RTU: a frame with a bad CRC is dropped unanswered (serial line 2.5.1.1); unit 0 is a
//    broadcast: writes are done, nothing is answered; another unit is not answered (the
//    map's any-station unit, PL110 FFh, is answered like the own one).
//  - TCP (MBAP): every connection is a point-to-point link, so units 0 and FFh address this
//    device as its own number does (Messaging on TCP/IP 4.4.2); the transaction is echoed.
//  - Exceptions: 01 a function the map has no space for, 02 a unit with no device or a
//    read-only one written, the map's illegal-value code for counts past the protocol's or the
//    map's limit (PL110: 30 words; its manual numbers the code 04), 04 a write the image
//    refused, 06 a write the image did not take in time.

#include "comms/protocol/modbus_slave.h"
#include "comms/slave/responder.h"
#include "comms/transport/serial_settings.h"

namespace rung::comms::slave {

class ModbusResponder final : public Responder {
public:
    ModbusResponder(const model::Target &target, const model::ProtocolMap &map, int station,
                    std::shared_ptr<DeviceImage> image, modbus::Framing framing,
                    const SerialSettings &line = {}, int writeTimeoutMs = 2000);

    QByteArrayList feed(QByteArrayView bytes) override;
    QByteArrayList silence() override;
    int silenceMicroseconds() const override;
    QByteArray breakChecksum(QByteArray frame) const override;
    qsizetype buffered() const override { return m_decoder.buffered(); }

private:
    QByteArrayList take();
    // The response PDU; empty when nothing is to be answered (a broadcast).
    QByteArray respond(const modbus::ParsedRequest &parsed, bool broadcast);
    QByteArray exception(std::uint8_t function, int code);

    modbus::Framing m_framing;
    SerialSettings m_line;
    modbus::RequestDecoder m_decoder;
    int m_dropped = 0;
};

} // namespace rung::comms::slave
