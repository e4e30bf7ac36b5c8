#include "model/target/protocol_map.h"

#include <QCoreApplication>

// PL110 MODBUS slave map, RTU or TCP framing (PL110 manual 3.1 and 3.2). Bit addresses serve
// functions 01 / 02 / 05 / 0F, word addresses 03 / 04 / 06 / 10; bit areas appear in both, 16 to a
// word. At most 30 words per request. SM0 bit 0 is RUN (SM0.0 = bit 16000).
// The ranges and their access are the tables of 3.2: the timers reach T48 only (bits
// 4800..4847, words 300..302, values 12000..12047, presets 13000..13047: T49..T64, which run
// only with SM0.13, have no address), the special-marker bits SM129.15 (18079), and the
// inputs are R/W as bits but R as words.
// What the manual marks R (read only) is readOnly here: inputs as words, timer and counter
// bits, AI.

namespace rung::model::detail {

std::vector<ProtocolMap> pl110ProtocolMaps() {
    using P = DevicePart;
    using S = ProtocolSpace;
    ProtocolMap m;
    m.protocol = ProtocolId::Modbus;
    m.description = QT_TRANSLATE_NOOP("rung::model::Target", "PL110 MODBUS slave");
    m.maxReadUnits = 30;
    m.maxWriteUnits = 30;
    m.inputsShareSpaces = true;
    m.modelRegister = 0;
    m.versionRegister = 1;
    m.stationRegister = 5;
    m.anyStationUnit = 0xFF;
    m.runBitStartsStops = true;
    m.illegalValueException = 0x04;
    constexpr bool R = true; // "R" in the manual's READ/WRITE column
    m.ranges = {
        {"I", P::Bit, S::Coils, 1600, 1},
        {"Q", P::Bit, S::Coils, 2400, 1},
        {"B", P::Bit, S::Coils, 3200, 1},
        {"M", P::Bit, S::Coils, 4000, 1},
        {"T", P::Bit, S::Coils, 4800, 1, 48, R},
        {"C", P::Bit, S::Coils, 5600, 1, -1, R},
        {"SM", P::Bit, S::Coils, 16000, 0, 129},
        {"V", P::Bit, S::Coils, 32000, 0},
        {"I", P::Bit, S::HoldingRegisters, 100, 1, -1, R},
        {"Q", P::Bit, S::HoldingRegisters, 150, 1},
        {"B", P::Bit, S::HoldingRegisters, 200, 1},
        {"M", P::Bit, S::HoldingRegisters, 250, 1},
        {"T", P::Bit, S::HoldingRegisters, 300, 1, 48, R},
        {"C", P::Bit, S::HoldingRegisters, 350, 1, -1, R},
        {"SM", P::Value, S::HoldingRegisters, 1000, 0},
        {"V", P::Value, S::HoldingRegisters, 2000, 0},
        {"T", P::Value, S::HoldingRegisters, 12000, 1, 48},
        {"PT", P::Value, S::HoldingRegisters, 13000, 1, 48},
        {"C", P::Value, S::HoldingRegisters, 14000, 1},
        {"PV", P::Value, S::HoldingRegisters, 15000, 1},
        {"AI", P::Value, S::HoldingRegisters, 19000, 1, -1, R},
        {"AQ", P::Value, S::HoldingRegisters, 19400, 1},
        {"EEP", P::Value, S::HoldingRegisters, 20000, 0},
        {"MMC", P::Value, S::HoldingRegisters, 30000, 0},
    };
    // Listed in 3.2, readable, with no device here: a master (mbpoll, an HMI) reads words 0..5
    // in one request and the analog blocks whole. They read 0: the manual gives no codes for
    // the protocols of words 2..4, and the simulated PL110 runs no positioner or PID loop and
    // has no expansion module. Words 0, 1 and 5 are the model, version and station registers.
    m.fixedUnits = {
        {S::HoldingRegisters, 2, 4},         // protocol on COM1, EXP1, COM2 (R, ROM)
        {S::HoldingRegisters, 90, 90},       // POS1..POS2 on/off contacts (R)
        {S::HoldingRegisters, 95, 95},       // POS1..POS2 tuning contacts (R)
        {S::HoldingRegisters, 19004, 19065}, // AI5.. of 19000..19065 (R)
        {S::HoldingRegisters, 19402, 19463}, // AQ3.. of 19400..19463
        {S::HoldingRegisters, 19800, 19815}, // PID1..4 P / I / D / output percentages (R)
        {S::Coils, 1440, 1441},              // POS1..POS2 on/off (R)
        {S::Coils, 1520, 1521},              // POS1..POS2 tuning (R)
    };
    return {m};
}

} // namespace rung::model::detail
