#pragma once

// Shared by the Modbus slave fuzzers (RTU, TCP): the slave of a map the input picks (the Vigor
// CP2 map or the PL110's) over a memory image, and the checks of its PDU.

#include "comms/protocol/modbus_slave.h"
#include "comms/slave/memory_image.h"
#include "comms/slave/modbus_responder.h"
#include "tests/fuzz/fuzz_comms_common.h"

namespace rung::comms::fuzz {

struct ModbusSlave {
    const model::Target &target;
    const model::ProtocolMap &map;
    int station;
    std::shared_ptr<slave::MemoryImage> image;
    slave::ModbusResponder responder;

    ModbusSlave(Input &in, modbus::Framing framing)
        : target(model::Target::get(in.byte() % 2 ? model::Family::Pl110 : model::Family::Vigor))
        , map(*model::findProtocolMap(target, model::ProtocolId::Modbus))
        , station(1 + in.byte() % 247)
        , image(std::make_shared<slave::MemoryImage>(target))
        , responder(target, map, station, image, framing, SerialSettings{}) {}

    // A unit this slave answers as (RTU: its own and the map's any-station unit; TCP also 0
    // and FFh, which name the device itself).
    bool answersAs(int unit, modbus::Framing framing) const {
        return unit == station || unit == map.anyStationUnit ||
               (framing == modbus::Framing::Tcp && (unit == 0 || unit == 0xFF));
    }
};

// A response PDU: a known function, an exception three bytes long with a known code, a read's
// byte count matching its length.
inline bool validResponsePdu(QByteArrayView pdu) {
    if (pdu.size() < 2)
        return false;
    const auto function = std::uint8_t(pdu[0]);
    if (function & 0x80)
        return pdu.size() == 2 && std::uint8_t(pdu[1]) >= 1 && std::uint8_t(pdu[1]) <= 0x0B;
    switch (function) {
    case modbus::ReadCoils:
    case modbus::ReadDiscreteInputs:
    case modbus::ReadHoldingRegisters:
    case modbus::ReadInputRegisters:
        return pdu.size() == 2 + std::uint8_t(pdu[1]);
    case modbus::WriteSingleCoil:
    case modbus::WriteSingleRegister:
    case modbus::WriteMultipleCoils:
    case modbus::WriteMultipleRegisters:
        return pdu.size() == 5;
    default:
        return false;
    }
}

} // namespace rung::comms::fuzz
