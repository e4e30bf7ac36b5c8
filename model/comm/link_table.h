#pragma once

// One set of a LINK or MBUS communication table (Vigor M/VB/VH communication manual, B-3-3, B-3-6):
// seven registers read and checked as the PLC does, giving the working area's status codes (2
// length, 4 device type, 5 device number, 6 attributes differ). The engine runs the sets; the
// network's wiring check reads the same table to find the stations it names (one function, two
// rooms).

#include "model/target/protocol_map.h"
#include "model/target/target.h"

#include <cstdint>

namespace rung::model {

enum class LinkTableKind : std::uint8_t { EasyLink, Modbus };

// The working area's status byte (S2's upper 8 bits).
enum class LinkStatus : std::uint8_t {
    Normal = 0x0,
    BadLength = 0x2,
    BadDeviceType = 0x4,
    BadDeviceNumber = 0x5,
    AttributesDiffer = 0x6,
    NoResponse = 0xA,
    Abnormal = 0xB,
};

inline constexpr int kLinkSetRegisters = 7;
inline constexpr int kLinkMaxSets = 255;

struct LinkSet {
    LinkStatus status = LinkStatus::Normal; // Normal: the set can run
    int station = 0;
    bool write = false;
    bool single = false; // MBUS command 3: one device, MODBUS 05 / 06
    int length = 0;      // devices (bits or values)
    bool bits = false;   // bit devices on both sides
    Address master;      // the master's first device
    int masterValueBits = 16;
    // LINK: the slave's first device (a PLC of the same target); MBUS: its MODBUS space and
    // first unit (type 4 number 1000 = holding register 1000).
    Address slave;
    ProtocolSpace space = ProtocolSpace::HoldingRegisters;
    int unit = 0;
};

// The set from its seven registers (station, command, length, master type and number, slave
// type and number).
LinkSet readLinkSet(const Target &target, LinkTableKind kind, const std::int32_t *registers);

// The device `offset` places after `first` as LINK counts them (D10, D11, ...; X7, X10 on an
// octal area), invalid when there is none of that kind.
Address linkDevice(const Target &target, const Address &first, int offset);

} // namespace rung::model
