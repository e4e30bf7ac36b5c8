#include "model/target/protocol_map.h"

#include <QCoreApplication>

// PL110 MODBUS RTU slave map (seed 003 chapter 3; protocols.md). Bit addresses serve
// functions 01 / 02 / 05 / 0F, word addresses 03 / 04 / 06 / 10; bit areas appear in both,
// 16 to a word. At most 30 words per request. SM0 bit 0 is RUN (SM0.0 = bit 16000). What the
// manual marks R (read only) is readOnly here: inputs as words, timer and counter bits, AI.

namespace rung::model::detail {

std::vector<ProtocolMap> pl110ProtocolMaps() {
    using P = DevicePart;
    using S = ProtocolSpace;
    ProtocolMap m;
    m.protocol = ProtocolId::Modbus;
    m.description = QT_TRANSLATE_NOOP("rung::model::Target", "PL110 MODBUS RTU slave");
    m.maxReadUnits = 30;
    m.maxWriteUnits = 30;
    m.inputsShareSpaces = true;
    m.modelRegister = 0;
    m.versionRegister = 1;
    m.stationRegister = 5;
    m.anyStationUnit = 0xFF;
    m.runBitStartsStops = true;
    m.illegalValueException = 0x04;
    m.ranges = {
        {"I", P::Bit, S::Coils, 1600, 1},
        {"Q", P::Bit, S::Coils, 2400, 1},
        {"B", P::Bit, S::Coils, 3200, 1},
        {"M", P::Bit, S::Coils, 4000, 1},
        {"T", P::Bit, S::Coils, 4800, 1, -1, true},
        {"C", P::Bit, S::Coils, 5600, 1, -1, true},
        {"SM", P::Bit, S::Coils, 16000, 0},
        {"V", P::Bit, S::Coils, 32000, 0},
        {"I", P::Bit, S::HoldingRegisters, 100, 1, -1, true},
        {"Q", P::Bit, S::HoldingRegisters, 150, 1},
        {"B", P::Bit, S::HoldingRegisters, 200, 1},
        {"M", P::Bit, S::HoldingRegisters, 250, 1},
        {"T", P::Bit, S::HoldingRegisters, 300, 1, -1, true},
        {"C", P::Bit, S::HoldingRegisters, 350, 1, -1, true},
        {"SM", P::Value, S::HoldingRegisters, 1000, 0},
        {"V", P::Value, S::HoldingRegisters, 2000, 0},
        {"T", P::Value, S::HoldingRegisters, 12000, 1},
        {"PT", P::Value, S::HoldingRegisters, 13000, 1},
        {"C", P::Value, S::HoldingRegisters, 14000, 1},
        {"PV", P::Value, S::HoldingRegisters, 15000, 1},
        {"AI", P::Value, S::HoldingRegisters, 19000, 1, -1, true},
        {"AQ", P::Value, S::HoldingRegisters, 19400, 1},
        {"EEP", P::Value, S::HoldingRegisters, 20000, 0},
        {"MMC", P::Value, S::HoldingRegisters, 30000, 0},
    };
    return {m};
}

} // namespace rung::model::detail
