#pragma once

// Protocol address maps as target data (as the manuals give them: Vigor M/VB/VH communication
// manual, B-5-3 and B-3-6; PL110 manual 3.2; Omron CPM1/SRM1 programming manual W353, Host
// Link): where each device of a target sits in the address space of a protocol the PLC
// speaks. The tables live in target_*_maps.cpp and are attached to the Target by its builder;
// the functions below are the only code that reads them, in both directions (the master asks
// for a device, the slave answers an address). target.h includes this header, so it must not
// include target.h.

#include <QString>

#include <cstdint>
#include <optional>
#include <vector>

namespace rung::model {

class Target;
struct Address;

enum class ProtocolId : std::uint8_t { VigorLink, Modbus, HostLink };

// An address space of a protocol. Each has a unit width (unitBits): a Vigor link byte holds 8
// bit devices, a Modbus register or a Host Link word 16, a coil or a completion flag 1.
enum class ProtocolSpace : std::uint8_t {
    LinkBytes,          // Vigor Computer Link byte address (51h / 61h; 70h / 71h: byte << 3 | bit)
    Coils,              // Modbus 0x, 0-based (component 00001 = coil 0)
    DiscreteInputs,     // Modbus 1x, 0-based (component 10000 of the Vigor map = input 0)
    HoldingRegisters,   // Modbus 4x, 0-based (component 40000 of the Vigor map = register 0)
    InputRegisters,     // Modbus 3x, 0-based (function 04; a master's read-only registers)
    HostLinkIr,         // RR / WR, channel number
    HostLinkHr,         // RH / WH
    HostLinkDm,         // RD / WD
    HostLinkTimerPv,    // RC / WC, timer / counter number
    HostLinkCompletion, // RG, timer / counter number
};

int unitBits(ProtocolSpace space);

// Which side of a device a range covers: a bit device, a word's bit or a timer / counter
// contact (Bit); a word or a current value (Value); a Vigor timer / counter coil (Coil).
enum class DevicePart : std::uint8_t { Bit, Value, Coil };

// Elements first..last of the area (Area::key) sit in `space` from `start`, element `origin`
// at `start` itself. Bit parts are packed into the space's units (bit position = element -
// origin, times the word width when the area is a word area); Value parts take
// Area::wordBits / unitBits units each (a Vigor C200 value: 4 link bytes or 2 registers).
// `last` ends the range where the protocol's documented reach ends before the area does
// (CPM1 Host Link: IR/SR to 252, DM to 6655; Omron CPM1/SRM1 programming manual W353, Host
// Link); -1 = the area's last element.
// `readOnly`: the protocol reads the range but refuses writes to it (PL110: inputs as words,
// timer and counter bits, analog inputs; PL110 manual 3.2, the R column).
struct ProtocolRange {
    const char *area = "";
    DevicePart part = DevicePart::Bit;
    ProtocolSpace space = ProtocolSpace::Coils;
    int start = 0;
    int origin = 0;
    int last = -1;
    // The manual marks the range R (read only) for the protocol. The protocol's access, not
    // the program's: PL110 inputs are R/W as bits 1600.. over MODBUS, R as words 100..
    // (PL110 manual 3.2), while no instruction may write them (Area::writable).
    bool readOnly = false;
};

// Units a manual lists as readable that hold no device of the target: the PLC's own figures
// (PL110: the protocol chosen for COM1, EXP1 and COM2, words 2..4), what the simulator does
// not run (the positioners' bits and the PID loops' percentages) and the analog words of
// expansion modules (AI5..AI66, AQ3..AQ64). A slave answers them with `value` and refuses
// writes to them.
struct ProtocolFixedUnits {
    ProtocolSpace space = ProtocolSpace::HoldingRegisters;
    int first = 0;
    int last = 0;
    int value = 0;
};

// Vigor Computer Link: 51h / 61h move at most 128 bytes (Vigor M/VB/VH communication manual,
// B-5-3). The Vigor link map's limit and the codec's frame bounds (comms/protocol/vigor_link.h)
// both read it.
inline constexpr int VigorLinkMaxBytes = 128;

struct ProtocolMap {
    ProtocolId protocol = ProtocolId::Modbus;
    const char *description = nullptr; // QT_TRANSLATE_NOOP("rung::model::Target", ...)
    std::vector<ProtocolRange> ranges;
    // The most one request may read / write, in units of the space (bytes, registers, bits,
    // words); 0 = the protocol's own limit.
    int maxReadUnits = 0;
    int maxWriteUnits = 0;
    // PL110: functions 02 and 04 read the same tables as 01 and 03 (PL110 manual 3.1).
    bool inputsShareSpaces = false;
    // Registers that describe the PLC (PL110: device type 0, firmware version 1, protocol
    // address 5); -1 = none. A slave answers the station it serves in stationRegister.
    int modelRegister = -1;
    int versionRegister = -1;
    int stationRegister = -1;
    // The model code the PLC reports (Host Link MM: 11h for CPM1 / CPM1A / SRM1, W353 6-3-28);
    // -1 = the manual gives none.
    int modelCode = -1;
    // A unit address every slave answers besides its own (PL110: FFh, PL110 manual 3.1); -1 = none.
    int anyStationUnit = -1;
    // Writing the target's SystemRole::Run bit starts (1) and stops (0) the PLC (PL110 SM0 bit 0,
    // PL110 manual, chapter 3); elsewhere the run bit is the PLC's to drive.
    bool runBitStartsStops = false;
    std::vector<ProtocolFixedUnits> fixedUnits;
    // The exception code for an illegal data value (Modbus: 03; the PL110 manual, 3.1, lists
    // 04 as ILLEGAL DATA VALUE).
    int illegalValueException = 0x03;
};

// Where a device sits: the first unit, the bit inside it (-1 when the device is whole units)
// and how many units it takes.
struct ProtocolAddress {
    ProtocolSpace space = ProtocolSpace::Coils;
    int unit = 0;
    int bit = -1;
    int units = 1;
    friend bool operator==(const ProtocolAddress &, const ProtocolAddress &) = default;
};

// Which device part a protocol address holds; unitOffset counts units into a device that
// takes more than one (the high register of a Vigor C200 value).
struct MappedDevice {
    int area = -1;
    int index = 0;
    int bit = -1;
    DevicePart part = DevicePart::Bit;
    int unitOffset = 0;
    bool readOnly = false; // the range's: the protocol refuses writes here
};

const ProtocolMap *findProtocolMap(const Target &target, ProtocolId protocol);

std::optional<ProtocolAddress> toProtocol(const Target &target, const ProtocolMap &map,
                                          const Address &address, DevicePart part);
// bit: the bit inside the unit for bit devices in a packed space; -1 asks for the word (or
// value) that holds the unit; a bit the unit does not have (16 of a register, 8 of a link
// byte) maps to nothing. Spaces of 1-bit units ignore it. Areas that share their numbers
// (CPM1 TIM / CNT, one bank) share addresses too; the way back names the first of them.
std::optional<MappedDevice> fromProtocol(const Target &target, const ProtocolMap &map,
                                         ProtocolSpace space, int unit, int bit = -1);
// The value of a unit in the map's fixedUnits; nullopt for any other unit.
std::optional<int> fixedUnitValue(const ProtocolMap &map, ProtocolSpace space, int unit);

namespace detail {
std::vector<ProtocolMap> vigorProtocolMaps();
std::vector<ProtocolMap> pl110ProtocolMaps();
std::vector<ProtocolMap> cpm1ProtocolMaps();
} // namespace detail

} // namespace rung::model
