#include "model/target/protocol_map.h"

#include <QCoreApplication>

// Vigor M / VB / VH address maps (Vigor M/VB/VH communication manual): the Computer Link byte
// map (B-5-3) and the CP2 MODBUS map (B-3-6). Area keys are those of target_vigor.cpp.

namespace rung::model::detail {

std::vector<ProtocolMap> vigorProtocolMaps() {
    using P = DevicePart;
    using S = ProtocolSpace;
    ProtocolMap link;
    link.protocol = ProtocolId::VigorLink;
    link.description = QT_TRANSLATE_NOOP("rung::model::Target", "Vigor Computer Link");
    link.maxReadUnits = VigorLinkMaxBytes; // bytes per 51h / 61h
    link.maxWriteUnits = VigorLinkMaxBytes;
    link.ranges = {
        {"X", P::Bit, S::LinkBytes, 0x0000, 0},       {"Y", P::Bit, S::LinkBytes, 0x0040, 0},
        {"M", P::Bit, S::LinkBytes, 0x0080, 0},       {"ML", P::Bit, S::LinkBytes, 0x0080, 0},
        {"S", P::Bit, S::LinkBytes, 0x0300, 0},       {"SL", P::Bit, S::LinkBytes, 0x0300, 0},
        {"T", P::Bit, S::LinkBytes, 0x0380, 0},       {"C", P::Bit, S::LinkBytes, 0x03A0, 0},
        {"CL", P::Bit, S::LinkBytes, 0x03A0, 0},      {"C32", P::Bit, S::LinkBytes, 0x03A0, 0},
        {"SM", P::Bit, S::LinkBytes, 0x03E0, 9000},   {"T", P::Coil, S::LinkBytes, 0x0780, 0},
        {"C", P::Coil, S::LinkBytes, 0x07A0, 0},      {"CL", P::Coil, S::LinkBytes, 0x07A0, 0},
        {"C32", P::Coil, S::LinkBytes, 0x07A0, 0},    {"T", P::Value, S::LinkBytes, 0x1400, 0},
        {"SD", P::Value, S::LinkBytes, 0x1600, 9000}, {"C", P::Value, S::LinkBytes, 0x1800, 0},
        {"CL", P::Value, S::LinkBytes, 0x1800, 0},    {"C32", P::Value, S::LinkBytes, 0x1A00, 200},
        {"D", P::Value, S::LinkBytes, 0x1C00, 0},     {"DL", P::Value, S::LinkBytes, 0x1C00, 0},
    };
    // The timers of every resolution share T0..T255's places (T10, T1R, TR: target_vigor.cpp).
    for (const char *t : {"T10", "T1R", "TR"}) {
        link.ranges.push_back({t, P::Bit, S::LinkBytes, 0x0380, 0});
        link.ranges.push_back({t, P::Coil, S::LinkBytes, 0x0780, 0});
        link.ranges.push_back({t, P::Value, S::LinkBytes, 0x1400, 0});
    }

    ProtocolMap modbus;
    modbus.protocol = ProtocolId::Modbus;
    modbus.description = QT_TRANSLATE_NOOP("rung::model::Target", "Vigor CP2 MODBUS slave");
    modbus.ranges = {
        {"Y", P::Bit, S::Coils, 0, 0},
        {"M", P::Bit, S::Coils, 512, 0},
        {"ML", P::Bit, S::Coils, 512, 0},
        {"S", P::Bit, S::Coils, 5632, 0},
        {"SL", P::Bit, S::Coils, 5632, 0},
        {"T", P::Bit, S::Coils, 6656, 0},
        {"C", P::Bit, S::Coils, 6912, 0},
        {"CL", P::Bit, S::Coils, 6912, 0},
        {"C32", P::Bit, S::Coils, 6912, 0},
        {"SM", P::Bit, S::Coils, 7424, 9000},
        {"X", P::Bit, S::DiscreteInputs, 0, 0},
        {"D", P::Value, S::HoldingRegisters, 0, 0},
        {"DL", P::Value, S::HoldingRegisters, 0, 0},
        {"T", P::Value, S::HoldingRegisters, 8192, 0},
        {"C", P::Value, S::HoldingRegisters, 8448, 0},
        {"CL", P::Value, S::HoldingRegisters, 8448, 0},
        {"C32", P::Value, S::HoldingRegisters, 8648, 200},
        {"SD", P::Value, S::HoldingRegisters, 8760, 9000},
    };
    for (const char *t : {"T10", "T1R", "TR"}) {
        modbus.ranges.push_back({t, P::Bit, S::Coils, 6656, 0});
        modbus.ranges.push_back({t, P::Value, S::HoldingRegisters, 8192, 0});
    }
    return {link, modbus};
}

} // namespace rung::model::detail
